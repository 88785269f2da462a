/* What a plane of interest's lit front shadows, and a flat box's (below), GL-free.
 *
 * The shadow pass draws back faces only (second-depth maps: a lit face never compares
 * against itself), and a plane's mesh is one quad facing along edge1 x edge2. Lit on that
 * side, the quad is culled from every map, so it casts nothing through them; yet what
 * lies beyond it from the light is in its shadow (the table's slab top, 1 mm under the
 * table top, seen through the gap at the table's edge). The main pass tests that exactly,
 * per fragment, for the objects that need it: the light's ray from a point crosses the
 * plane's parallelogram before reaching the point. Lit on its back, a plane casts through
 * the maps as a caster does, and needs no test. */
#ifndef LX_PLANE_COVER_H
#define LX_PLANE_COVER_H
#include "frame.h"

/* A light within this share of its distance (to the parallelogram's corner, plus the
 * edges' lengths) of a plane's plane, or a directional light this close to parallel to
 * it, grazes the plane: its parallelogram covers no solid angle worth a test, and the
 * matrix would divide by about 0. */
#define LX_COVER_GRAZING 1e-6

/* A box reaching less than this beyond a plane (a share of the light's distance from
 * it, or of a directional light's parallelogram's size) only touches it: nothing of it is
 * shadowed by it, yet its corners on the plane may round to either side. */
#define LX_COVER_TOUCH 1e-9

/* Plane p's cover matrix for the frame's light: world X -> h = M (X, 1), with X shadowed
 * by p's front exactly where h.w > 0 (p lies between the light and X; h.w is in
 * the light's distance from the plane, or for a directional light in the parallelogram's
 * size) and 0 <= h.x <= h.z,
 * 0 <= h.y <= h.z (the crossing lies in the parallelogram: h.x / h.z and h.y / h.z are its
 * coordinates along edge1 and edge2). Affine in X, so a varying carries it exactly.
 * False where p's front is not lit (its back faces the light, or the light grazes it). */
bool lx_plane_cover_matrix(const struct lx_frame *f, int p, mat4 *out);
/* Whether world point x lies in the shadow of the front whose cover matrix is m, as the
 * shader decides it (main.frag, LX_COVER): the CPU's mirror, in double. */
bool lx_plane_cover_shadows(const mat4 *m, vec3 x);

/* The most lit fronts the main pass tests over one object (LX_COVER, LX_COVER2): two
 * shelves stacked over the floor. A third front over the same object is not tested: its
 * shadow there is lost, where it falls outside the first two's. */
#define LX_MAX_COVERS 2

/* A flat box (a table's slab, a shelf board: its thinnest side at most 1/LX_SLAB_FLATNESS
 * of each other) has two fronts: its bottom, the broad face turned away from the light,
 * and its top, the broad face towards it, each as a parallelogram lit on the side towards
 * the light. A ray from a point beyond the bottom that crosses either face passes through
 * the box, so each test is exact where it shadows; tested together (a pair, below) they
 * also take the rays that enter and leave by the thin sides, and then the box's whole
 * shadow is exact. Where a plane lies on the top face (the table top, 1 mm over its slab)
 * that plane's front is the top: the two make one prism, with a gap only a nearly level
 * ray could pass. The first LX_MAX_SLAB_FRONTS flat boxes have fronts. */
#define LX_SLAB_FLATNESS 8.0
#define LX_MAX_SLAB_FRONTS 4
#define LX_MAX_FRONTS (LX_MAX_PLANES + 2 * LX_MAX_SLAB_FRONTS)
/* Box caster id's bottom front in frame f, when it is flat: corner c and edges e1, e2
 * (e1 x e2 towards the light's side), and t, its thickness towards the light (the top
 * face is c + t, e1, e2). */
bool lx_slab_front(const struct lx_frame *f, int id, vec3 *c, vec3 *e1, vec3 *e2, vec3 *t);

/* A frame's covers: its fronts, the planes' (front p is plane p), then the flat boxes'
 * bottoms, then the tops of those with no plane lying on them; each one's owner, corners
 * and matrix where it is lit (lx_plane_cover_matrix); for a bottom, the front on its
 * top's side (top, else -1) and the box's outline on that front's plane; fronts
 * [plane count, plane count + slabs) are the bottoms. For each object, the fronts that
 * may shadow it (some of its box lies beyond one from the light, and the light's rays to
 * that part cross the parallelogram's bounds; never its own): of[id][0], of[id][1], ...
 * in the fronts' order, -1 after the last; an object whose rays may pass through a flat
 * box gets its bottom and top both where there is room; paired[id] where those two are
 * one flat box's bottom and top. */
struct lx_plane_covers {
	int count, slabs;
	int owner[LX_MAX_FRONTS];
	int top[LX_MAX_FRONTS];
	vec3 corner[LX_MAX_FRONTS][4];
	bool lit[LX_MAX_FRONTS];
	mat4 m[LX_MAX_FRONTS];
	double outline[LX_MAX_FRONTS][4]; /* a bottom's box on its top's plane, the top's coordinates' bounds */
	int of[LX_MAX_PLANES + LX_MAX_CASTERS][LX_MAX_COVERS];
	bool paired[LX_MAX_PLANES + LX_MAX_CASTERS];
};
/* Whether world point x beyond bottom front `bottom` has its ray to the light pass through
 * the box between it and its top front `top` (their matrices) by the box's thin sides:
 * the ray's crossings of the two faces' planes, in their shared coordinates, span a
 * segment that meets the unit square while neither end lies in it (each end inside is
 * its own front's test). As the shader decides it (main.frag, u_cover_pair). */
bool lx_slab_sides_shadow(const mat4 *top, const mat4 *bottom, vec3 x);
/* How many fronts the main pass tests over object id (0 to LX_MAX_COVERS). */
int lx_plane_cover_count(const struct lx_plane_covers *c, int id);
/* Whether world point x of object id lies in the shadow of a front the main pass tests
 * over it, as the shader decides it. */
bool lx_plane_covers_shadow(const struct lx_plane_covers *c, int id, vec3 x);
void lx_plane_covers(const struct lx_frame *f, struct lx_plane_covers *out);
/* No front tested over any object: a method without maps shadows nothing, by fronts
 * neither. */
void lx_plane_covers_none(struct lx_plane_covers *out);
/* Whether every object the main pass must test p's front over does test it: some of
 * whose box lies beyond it with rays crossing its bounds (false where LX_MAX_COVERS
 * fronts over an object left p's out). c: the frame's covers (lx_plane_covers). */
bool lx_plane_cover_complete(const struct lx_frame *f, const struct lx_plane_covers *c, int p);
/* The flat boxes' faces the maps leave out. A face that is a lit bottom front, when the
 * main pass tests that front over every object that needs it (lx_plane_cover_complete):
 * a ray that leaves the box through it shadows only what lies beyond it, which its test
 * shadows exactly; drawn, the maps held the slab's underside at their resolution, a row
 * or two past the test's exact edge on the table's legs, and its fill under the table.
 * The whole box, when every object whose box reaches below its top (with rays crossing the
 * top's bounds) tests the pair and has nothing between the two faces' planes: its shadow
 * is then the pair's, exact to the pixel, and the maps' band along its edges (a lixel of
 * false shadow past them, the worst error on the table seen near the wall) is gone with
 * its footprint from the planes' wanted regions. has[id]: object id has such a face,
 * front[id] its plane in the object's own space (unit normal n, n . x + w = 0); whole[id]:
 * none of it is drawn. cv: the frame's covers (lx_plane_covers). */
void lx_slab_faces_left_out(const struct lx_frame *f, const struct lx_plane_covers *cv, vec4 *front, bool *has,
			    bool *whole);

/* The shadow front p's parallelogram (cv's) throws on plane q's plane, as the eye sees it: a
 * convex quadrilateral in the window (pixels, GL's origin), where every point of q is in
 * p's cover, and outside which none is. False when there is none to give (the shadow
 * reaches behind the eye, or runs off to infinity): then anywhere. A plane as large on
 * the screen as a floor is drawn in its own shadow inside it (no lookup, no test), with
 * the test along its edges, and as before elsewhere. */
bool lx_plane_cover_image(const struct lx_frame *f, const struct lx_plane_covers *cv, int p, int q,
			  struct lx_poly *win);
/* The shadow a flat box's pair of fronts (cv->paired[q]: fronts of[q][0] and of[q][1])
 * throws on plane q's plane, as the eye sees it: the hull of the two fronts' images (the
 * box's corners all lie on the two parallelograms), holding what the rays through the
 * box's thin sides shadow between and beside them, which neither image holds. Where the
 * pair's tests shadow a point of q, its image lies inside. False where there is none to
 * give (not a pair, or lx_plane_cover_image gives none for a front); *img0 and *img1 then
 * hold what it gave, as lx_plane_cover_image leaves them. */
bool lx_plane_cover_pair_image(const struct lx_frame *f, const struct lx_plane_covers *cv, int q, struct lx_poly *img0,
			       struct lx_poly *img1, struct lx_poly *win);

/* How many covers any frame of the scene's animation may test over one object (0 to
 * LX_MAX_COVERS): the most planes' planes some object's box, anywhere on its path,
 * reaches beyond on the side their back faces (for a light that lights their fronts),
 * and every flat box but itself (whose front may face any way, as the light moves).
 * The renderer builds the cover's variants at the start only for those (a warmed
 * renderer builds nothing later). */
int lx_scene_covers_needed(const struct lx_scene *s, const struct lx_scene_meshes *m);

#endif
