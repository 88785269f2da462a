/* The plane-optimal light camera of Chong and Gortler, "A Lixel for every Pixel"
 * ([Chong-Gortler]), GL-free. For a plane of interest P, a light L and the view, the light
 * image samples P exactly where the view's pixels do: for every point of P its light
 * image (x, y) equals its window coordinates. */
#ifndef LX_PLANE_OPTIMAL_H
#define LX_PLANE_OPTIMAL_H
#include "frame.h"
#include <math.h>
#include "polygon2d.h"

enum lx_plane_camera_status {
	LX_PLANE_CAMERA_OK,
	LX_PLANE_CAMERA_LIGHT_ON_PLANE, /* the light lies (nearly) in P: the construction is singular */
	LX_PLANE_CAMERA_EDGE_ON,        /* the eye lies in P: the screen corners' rays meet P in one point */
	LX_PLANE_CAMERA_SINGULAR,       /* the 4x4 systems are singular or the residual is too large */
};

struct lx_plane_camera {
	mat4 m;          /* world -> (x q, y q, z q, q); z: -1 at the lifted point, +1 on P */
	double residual; /* worst angle (radians) between M X_i and its target image point */
};

/* The homogeneous light point: (position, 1), or (-direction, 0) for a directional light. */
vec4 lx_light_point(const struct lx_light *l);
/* Plane of interest as (n, d) with n . x + d = 0, n the unit front normal. */
vec4 lx_plane_equation(const struct lx_plane *p);
/* How near a point light may come to plane p's surface before it counts as lying in it (its
 * rays graze the plane and what stands on it): a thousandth of the plane's size, so that
 * one caster far from the rest does not make a light a few metres up count as in it. */
double lx_plane_near_limit(const struct lx_plane *p);

/* Solves the five point constraints (the paper's equations 1 and 7-10): L -> [0, 0, 1, 0];
 * the points where the eye's rays through the window corners (0, 0), (0, H), (W, H) meet
 * P keep their window x, y at depth +1; the fourth corner's point, lifted along its light
 * ray towards the light, keeps them at depth -1. Two 4x4 systems solved with partial
 * pivoting, then a residual check. The sign is chosen so that `inside` (a homogeneous
 * point the map must see) gets q > 0, and depth increases away from the light. */
enum lx_plane_camera_status lx_plane_camera_solve(const struct lx_view *v, vec4 light, vec4 plane, vec4 inside,
						   struct lx_plane_camera *out);

/* The eye rays of one row of the window, wy: window point (wx, wy) unprojects to the
 * homogeneous near point near + nx col and far point far + nx col, nx = sx wx - 1 its x
 * in NDC. Made once a row, so that what visits every pixel (the metrics) pays per pixel
 * only for its x. */
struct lx_window_row {
	vec4 near, far, col; /* inv_view_proj (0, ny, -1, 1), (0, ny, 1, 1) and its first column */
	double sx;           /* 2 / width */
};
struct lx_window_row lx_window_row(const struct lx_view *v, double wy);
/* Where the eye ray through window point (wx, row r) meets the plane (n . x + d = 0): the
 * point, and t, its place on the ray from the near plane (0) to the far plane (1). False
 * when the ray runs along the plane (or a point is at infinity). */
static inline bool lx_window_row_on_plane(const struct lx_window_row *r, vec4 plane, double wx, vec3 *q, double *t)
{
	double nx = r->sx * wx - 1;
	vec4 a = v4_lin(1, r->near, nx, r->col), b = v4_lin(1, r->far, nx, r->col);
	if (!(fabs(a.w) > 1e-300) || !(fabs(b.w) > 1e-300))
		return false;
	double ia = 1 / a.w, ib = 1 / b.w; /* finite: |w| > 1e-300 */
	vec3 pn = v3(a.x * ia, a.y * ia, a.z * ia), d = v3_sub(v3(b.x * ib, b.y * ib, b.z * ib), pn);
	double den = plane.x * d.x + plane.y * d.y + plane.z * d.z;
	if (!(fabs(den) > 1e-300))
		return false; /* the ray runs along the plane */
	*t = -v4_dot_point(plane, pn) / den;
	*q = v3_add(pn, v3_scale(d, *t));
	return true;
}
/* The same for window point (wx, wy) alone. */
bool lx_window_on_plane(const struct lx_view *v, vec4 plane, double wx, double wy, vec3 *q, double *t);
/* Whether point q of the plane lies on its parallelogram (corner + s edge1 + u edge2,
 * s, u in [0, 1]). */
bool lx_plane_contains(const struct lx_plane *p, vec3 q);
/* The same test with the edges' Gram matrix worked out once, for a caller that tests a
 * pixel's worth of points (the metrics): lx_plane_contains's arithmetic step for step. */
struct lx_plane_gram {
	vec3 corner, edge1, edge2;
	double e11, e12, e22, det; /* det > 0: the scene parser refuses parallel edges */
};
struct lx_plane_gram lx_plane_gram(const struct lx_plane *p);
static inline bool lx_plane_gram_contains(const struct lx_plane_gram *g, vec3 q)
{
	vec3 r = v3_sub(q, g->corner);
	double r1 = v3_dot(r, g->edge1), r2 = v3_dot(r, g->edge2);
	/* s = ns / det and u = nu / det in [0, 1], compared without dividing (det > 0) */
	double ns = r1 * g->e22 - r2 * g->e12, nu = r2 * g->e11 - r1 * g->e12;
	return g->det > 0 && ns >= 0 && ns <= g->det && nu >= 0 && nu <= g->det;
}

/* The part of a plane's parallelogram inside the view frustum: window-coordinate
 * polygon (counter-clockwise) and its world vertices; false when nothing is visible. */
bool lx_plane_visible(const struct lx_view *v, const struct lx_plane *p, struct lx_poly *window, vec3 *world,
		      int *world_count);

/* Vertices of the intersection of half-spaces a x + b y + c z + d >= 0 (bounded), by
 * solving every triple of planes; with `box` (its lo and hi corners), only those within
 * tol of it (a triple's point is tested against the box before the n half-spaces: the
 * corners of lookup volumes of up to 26 planes inside a receiver's box were 44% of the
 * default view's lookup work, timed in a loop). Returns the count. */
int lx_halfspace_vertices(const vec4 *planes, int n, const vec3 *box, double tol, vec3 *out, int max_out);

#endif
