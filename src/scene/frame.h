/* One frame's pure geometry: the camera for a view size, where every object is at
 * time t, and the bounds every shadow method works from. GL-free. */
#ifndef LX_FRAME_H
#define LX_FRAME_H
#include "mesh.h"
#include "polygon2d.h"

struct lx_view {
	int width, height;
	vec3 eye, dir; /* dir: the unit view direction */
	double near, far, fovy; /* fovy in radians */
	mat4 view, proj, view_proj, inv_view_proj;
};

#define LX_FRAME_NOTES 4
/* A point light this many scene diagonals away is taken as directional: its rays then
 * spread by less than a microradian over the scene. */
#define LX_FAR_LIGHT_RATIO 1e6
/* The nearest the near plane comes, as a share of the far plane's distance. */
#define LX_NEAR_MIN_RATIO 1e-6

struct lx_frame {
	const struct lx_scene *scene;
	const struct lx_scene_meshes *meshes;
	double time;
	struct lx_view view;
	/* the light this frame's maps are for: the scene's light light_index as the set-up
	 * takes it (a point light far enough away becomes directional) */
	int light_index;
	struct lx_light light;
	int object_count;
	vec3 offset[LX_MAX_PLANES + LX_MAX_CASTERS]; /* object translation at time t */
	vec3 bmin[LX_MAX_PLANES + LX_MAX_CASTERS], bmax[LX_MAX_PLANES + LX_MAX_CASTERS]; /* world bounds */
	vec3 scene_min, scene_max;
	vec3 view_min, view_max; /* the box of the objects whose boxes reach the view (receivers) */
	/* the part of that box a projective light reaches (its frustum's part of it, as a box);
	 * the view box itself for other lights; empty (min > max) when the light reaches none of
	 * it: no shadow map needs to cover more */
	vec3 lit_min, lit_max;
	/* what the set-up changed or found that a user should hear of (a point light so far
	 * away it is taken as directional, the light inside a caster, ...); every method's
	 * result repeats them among its warnings */
	int note_count, view_note_count; /* the view's notes first, then the light's */
	char notes[LX_FRAME_NOTES][160];
};

/* Sets up the frame; false with a reason when the camera is degenerate. The near and
 * far planes are fitted to the scene bounds (far reaches the farthest corner; near is
 * the distance to the bounds, at least far / 1000). */
/* The view frustum's corners in world space: the near face (0-3), then the far face
 * (4-7), in the same winding, as lx_frustum_box_points takes them. */
void lx_view_frustum_corners(const struct lx_view *v, vec3 fc[8]);
/* Whether all of box [lo, hi] lies beyond the view's near plane: then each of a closed
 * convex mesh's faces turned away from the eye is hidden behind one turned towards it
 * (the main pass culls them); one the near plane cuts shows its inner faces. */
bool lx_view_box_beyond_near(const struct lx_view *v, vec3 lo, vec3 hi);
/* Clip-space point c (c.w > 0, view_proj's image) in window pixels, GL's origin. */
static inline vec2 lx_view_window_point(const struct lx_view *v, vec4 c)
{
	return (vec2){(c.x / c.w * 0.5 + 0.5) * v->width, (c.y / c.w * 0.5 + 0.5) * v->height};
}

bool lx_frame_setup(struct lx_frame *f, const struct lx_scene *s, const struct lx_scene_meshes *m, double t,
		    int width, int height, char *err, size_t errlen);
/* *out: frame f (set up for any light) for the scene's light `light` (0 to
 * lx_scene_light_count - 1) instead; out may be f. lx_frame_setup gives light 0. */
void lx_frame_for_light(const struct lx_frame *f, int light, struct lx_frame *out);

/* Plane of interest id's quad in world space at the frame's time: corner, +edge1,
 * +edge1+edge2, +edge2. */
void lx_frame_plane_corners(const struct lx_frame *f, int id, vec3 out[4]);
/* The objects in the order the main pass draws them, so that fewer pixels are shaded and
 * then covered (a fragment behind one drawn already fails the depth test, which on
 * llvmpipe still costs about half of its shading): casters first, since they stand in
 * front of the planes they shadow, except those wholly behind a plane seen from the eye
 * (a table's own slab and legs under its top), which follow that plane. Writes
 * f->object_count ids to order. */
void lx_frame_draw_order(const struct lx_frame *f, int *order);
/* Whether plane `front` hides plane `back` wherever its image covers it: its quad lies
 * wholly on the eye's side of back's plane (strictly), and beyond the near plane, so that
 * it is drawn whole. *win: that image in the window (pixels, GL's origin), convex. */
bool lx_frame_plane_hides(const struct lx_frame *f, int front, int back, struct lx_poly *win);
/* Whether object id's box lies wholly on the eye's side of plane `back`'s plane (touching
 * it counts: a caster standing on the floor hides what is behind it) and in front of the
 * eye, so that whatever of back its image covers is hidden. window: the box's corners in
 * the window (pixels, GL's origin), in v3_box_corner's order. */
bool lx_frame_box_hides(const struct lx_frame *f, int id, int back, vec2 window[8]);
/* Points whose convex hull holds object id (and so its mesh, which lies inside its
 * shape): its box's corners, or for a round caster a polytope tighter than its box in
 * the light's image: the octagonal prism around a cylinder, the octagonal pyramid around
 * a cone, and around a sphere the frustum of the octagonal cone drawn around the rays
 * from the light that touch it (a prism along a directional light's direction), whose
 * image is an octagon around the sphere's. The prism and pyramid lie within the box; the
 * frustum's corners may not, so a caller checks each point as it would the corners
 * (in front of the light or not). image_only: the points for the image from the light
 * alone (a sphere's near octagon: the far one lies on its rays). Returns the count, at
 * most LX_OUTLINE_POINTS. */
#define LX_OUTLINE_POINTS 16
int lx_frame_object_outline(const struct lx_frame *f, int id, bool image_only, vec3 pts[LX_OUTLINE_POINTS]);

#endif
