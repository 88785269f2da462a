/* The light's view of a frame, shared by the methods that need a conventional map:
 * a light view whose image plane G (z = -1 in light view space) charts the light rays
 * (tangents x/depth, y/depth for a point light; x, y for a directional light), the
 * hulls on G of what receivers and casters project to, and their depth range
 * ([Kapoulkine]'s unit cube clipping; [Chong-Gortler]'s C_tot). GL-free. */
#ifndef LX_LIGHT_SPACE_H
#define LX_LIGHT_SPACE_H
#include "convex.h"
#include "frame.h"
#include "polygon2d.h"
#include "shadow_method.h"

struct lx_light_space {
	bool directional;
	mat4 view;              /* world -> light view (looking down -z) */
	double tiny;            /* depth below which a point counts as at the light */
	bool empty;             /* nothing to shadow: no receivers in front, or no casters */
	bool receivers_behind;  /* the point light is inside the receiver volume */
	bool casters_unbounded; /* a caster box reaches behind the point light */
	struct lx_poly receivers, casters; /* hulls on G; meaningful unless the flag above says unbounded */
	double znear, zfar;     /* casters' minimum depth, receivers' maximum depth */
	double size;            /* scene diagonal */
	unsigned long long casting; /* bit id: object id can cast onto the receivers (a conservative test) */
	/* for each object that casts (bit in casting), its outline's bounds on G (x0, y0, x1,
	 * y1): what it can shadow; all of G where part of it lies behind the point light */
	double caster_g[LX_MAX_PLANES + LX_MAX_CASTERS][4];
	int receiver_count;     /* the receiver volume's vertices, world space */
	vec3 receiver_pts[LX_CONVEX_MAX_POINTS];
};

/* Whether object id can cast: casters always, planes only when their back face is lit
 * (the shadow passes write back faces). */
bool lx_object_can_cast(const struct lx_frame *f, int id);
/* Whether no shadow of the frame's light can be seen: a point light at the eye (a
 * miner's lamp, a flash on the camera) lights every point the eye sees along the very
 * ray the eye sees it by, so each shadow lies behind what casts it. Holds when the light
 * is so near the eye that a shadow's edge stands off its caster's outline by at most
 * LX_HIDDEN_SHADOW_PX pixels anywhere in the image, and no object that casts reaches into
 * the pyramid from the eye to the near plane's window (such an object is clipped from the
 * view yet blocks the light; the eye inside a caster's box is such a case). Every method
 * then draws no map: no pass, no lookup. */
#define LX_HIDDEN_SHADOW_PX 1e-3
bool lx_shadows_hidden(const struct lx_frame *f);
/* The receiver volume's vertices (the view frustum clipped to the box of what is in view
 * and lit, f->lit_min and lit_max); returns
 * the count, at most LX_CONVEX_MAX_POINTS. */
int lx_light_space_receivers(const struct lx_frame *f, vec3 *pts);
/* Whether an object that casts, other than id, may shadow a receiver of id whose points'
 * bounds on G are own (x0, y0, x1, y1): a ray from the light to a point it shadows passes
 * through that object, so their images on G meet (caster_g), and its box meets the rays
 * from the light to id's box (f->bmin, bmax). */
bool lx_light_space_shadowed_by_other(const struct lx_light_space *ls, const struct lx_frame *f, int id,
				      const double own[4]);
/* Receivers are the view frustum clipped to the scene bounds; casters the objects'
 * bounds (planes only where their back face is lit). */
void lx_light_space_build(const struct lx_frame *f, struct lx_light_space *ls);
/* The light ray through homogeneous world point X on G. X's sign says which way the ray
 * leaves the light: for a point light the ray runs along X.xyz - light * X.w, for a
 * directional light X must have X.w > 0. lx_light_space_front() is the linear function
 * whose sign says whether that ray meets G (> 0); the chart fails where it is <= 0. */
bool lx_light_space_chart(const struct lx_light_space *ls, const struct lx_frame *f, vec4 X, vec2 *g);
double lx_light_space_front(const struct lx_light_space *ls, const struct lx_frame *f, vec4 X);
/* C_tot: the rays both receivers and casters need, as a polygon on G; false (with
 * *unbounded set) when one frustum cannot hold them without clamping. */
bool lx_light_space_wanted(const struct lx_light_space *ls, struct lx_poly *out);
/* Rectangle r (x0, y0, x1, y1 on G) cut to the cone of 150 degrees that a point light's
 * map covers at most; true when it was cut. */
bool lx_light_space_clamp(const struct lx_light_space *ls, double r[4]);
/* The light-clip matrix of a conventional map covering the rectangle [x0, x1] x [y0, y1]
 * of G and the depth range; clamps a point light's cone to 150 degrees and warns
 * (prefix names the method). False when no valid frustum exists. */
bool lx_light_space_map(const struct lx_light_space *ls, double x0, double x1, double y0, double y1, mat4 *clip,
			struct lx_shadow_result *warn, const char *prefix);

/* The one-map methods' common start: resets *out to one full map in region 0, builds
 * the light space, and fills the map with the uniform map focused on C_tot (unit cube
 * clipping). Returns whether that map is rendered; *wanted and the bounds on G it used
 * (infinite where C_tot is unbounded) are given back for the warping methods. */
struct lx_uniform_fit {
	struct lx_poly wanted;
	double x0, x1, y0, y1;
};
bool lx_uniform_map(const struct lx_frame *f, struct lx_light_space *ls, struct lx_shadow_result *out,
		    const char *prefix, struct lx_uniform_fit *fit);

#endif
