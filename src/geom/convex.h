/* Convex volumes as point sets, GL-free: the receiver volume of a view is the view
 * frustum clipped to the scene's bounding box. */
#ifndef LX_CONVEX_H
#define LX_CONVEX_H
#include "linalg.h"

#define LX_CONVEX_MAX_POINTS 256

/* Vertices of the intersection of the frustum with corners fc[8] (near face 0-3 then
 * far face 4-7, both in the same winding) and the box [bmin, bmax]. Returns the count
 * (0 when they do not meet). Duplicates are possible and harmless. */
int lx_frustum_box_points(const vec3 fc[8], vec3 bmin, vec3 bmax, vec3 *out, int max_out);

/* The corners of box [lo, hi]'s six faces, each clipped by the np half-spaces
 * planes[j] . (x, y, z, 1) >= 0 (a convex part of the box: the hull of these points),
 * repeats and all, into out (at most max_out); returns their count. */
int lx_box_clip_points(vec3 lo, vec3 hi, const vec4 *planes, int np, vec3 *out, int max_out);

/* Box [lo, hi] as the half-spaces p . (x, y, z, 1) >= 0 on the inner sides of its faces,
 * one a face in the order -x, +x, -y, +y, -z, +z (a flat box keeps both of its flat
 * axis's). */
void lx_box_halfspaces(vec3 lo, vec3 hi, vec4 out[6]);

/* Sutherland-Hodgman: the part of convex polygon in[n] where p . (x, y, z, 1) >= 0, into
 * out (at most max_out vertices); returns its count. */
int lx_clip_polygon(const vec3 *in, int n, vec4 p, vec3 *out, int max_out);

#endif
