/* Silhouettes of closed, indexed triangle meshes, GL-free: which triangle lies across each
 * edge, and a set of a mesh's triangles (those turned away from a light) drawn again as
 * a fan over its boundary from one point.
 *
 * A shadow pass draws a caster's faces turned away from the light; on a rasterizer that
 * pays for each triangle (llvmpipe: a few hundred nanoseconds) a round caster's hundreds
 * of them cost more than the lixels they fill. For a convex caster those faces' image is
 * the convex polygon of its silhouette, and a fan from a point inside the caster to the
 * silhouette's edges covers the same lixels (the same outer edges) at depths between the
 * caster's near and far sides: every point outside the caster compares with it as it
 * compares with the far side. */
#ifndef LX_SILHOUETTE_H
#define LX_SILHOUETTE_H
#include "linalg.h"
#include <stdbool.h>

/* rep[i]: the first of the np positions (x, y, z floats) within eps of position i in every
 * coordinate, through a chain of such (a mesh's seam, where sin(2 pi) is not 0, makes
 * two positions of one point). False out of memory (rep[i] = i then). */
bool lx_mesh_weld(const float *pos, int np, double eps, int *rep);

/* adj[3 t + e]: the triangle across edge e of triangle t (its corners e and (e + 1) % 3),
 * for `triangles` triangles of 16-bit indices; -1 for each edge of a triangle with two
 * corners the same (no area), which is left out. True when the rest is closed, each edge
 * between two triangles that run it in opposite directions, false otherwise or out of
 * memory (adj unusable). */
bool lx_mesh_adjacency(const unsigned short *index, int triangles, int *adj);

/* The triangles `kept` marks (but those of no area), as a fan: the triangle (apex, a, b)
 * for each edge a -> b of a kept triangle whose neighbour across it is not kept, wound as
 * that kept triangle; adj as lx_mesh_adjacency gives it.
 * next: scratch of one int per position, each -1, left so. Returns the indices written
 * (3 per edge), or -1 when no triangle is kept, the boundary is not one simple loop
 * (the kept triangles are not one disk), or the fan needs more than max_out indices. */
int lx_silhouette_fan(const unsigned short *index, const int *adj, int triangles, const bool *kept,
		      unsigned short apex, int *next, unsigned short *out, int max_out);

/* A fan lx_silhouette_fan wrote (count indices), each of its triangles facing one way as
 * seen from the light (centre: its centre of projection, homogeneous, a point or a
 * direction, of either sign: the sign of v4_dot(centre, v4_cross3 of a triangle's
 * corners)), drawn instead as its boundary's polygon where that polygon is convex: where
 * every three corners in a row face that way as well (the fan's triangles all facing one
 * way make the polygon star-shaped round the apex's image, and a closed convex caster's
 * faces turned away have an image that covers itself nowhere, so it turns once).
 * Cut by short diagonals: the corners (0, 1, 2), (2, 3, 4), ... as triangles, then every
 * other corner again the same way, down to three. A rasterizer shades each block an inner
 * edge crosses once for each triangle beside it; against the fan's spokes, one from the
 * apex to each corner, these edges are about half as long in all (20 radii for 32
 * corners, 23 for 46), and there are two triangles fewer. The triangles lie inside a
 * convex caster (their corners are its vertices), as the apex's did. A polygon of at most
 * eight corners (a box's silhouette has four or six), all in front of the light, is cut
 * instead at the inner edges shortest in all as light_clip (not NULL) projects them, its
 * image's units what counts (the map's lixels): a box's image as long as a table leg's
 * shadow under a low light has one inner edge along it, against two the other way. pos:
 * the indices' positions (x, y, z floats); next:
 * scratch of one int per position, each -1, left so; loop: scratch of count / 3 indices.
 * Returns the new count of indices, or count with the fan unchanged where the polygon is
 * not convex. */
int lx_fan_as_polygon(unsigned short *fan, int count, const float *pos, vec4 centre, const mat4 *light_clip, int *next,
		      unsigned short *loop);

/* The band between two fans lx_silhouette_fan wrote over nested sets of one convex mesh's
 * triangles (outer: a set, inner: a part of it, each one disk, so each fan's boundary is
 * one loop and both loops turn the same way), drawn as a strip of triangles from corner
 * to corner of the two loops in place of the band's own triangles: one triangle for each
 * edge of either loop, wound as the fans' triangles. The loops are walked together by
 * angle round a point inside both images (light_clip: the caster's light clip matrix),
 * from the outer loop's first corner, each step along the loop whose triangle's image
 * turns as the fans' do, and where both do, to whichever loop's next corner comes first
 * round. The triangles lie inside a convex caster (their corners are its vertices),
 * between its sides. next: scratch of one int per position, each -1, left so; loop:
 * scratch of outer_count / 3 + inner_count / 3 indices; work: of outer_count +
 * inner_count doubles (each corner's image and angle, found once). Returns the indices written to
 * out, or -1 where a fan is not one loop of three corners or more, a corner lies behind
 * the light, the strip needs more than max_out, or at some step neither triangle turns as
 * the fans' (3 of 600 lights round the default scene's casters in test_scene). */
int lx_fan_band_strip(const unsigned short *outer, int outer_count, const unsigned short *inner, int inner_count,
		      const float *pos, const mat4 *light_clip, int *next, unsigned short *loop, double *work,
		      unsigned short *out, int max_out);

#endif
