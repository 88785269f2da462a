/* Trapezoidal shadow maps ([Martin-Tan]). In the
 * uniform map's post-perspective space (where light rays are parallel to z), the rays
 * the view needs are enclosed in a trapezoid whose centre line runs from the view's
 * near plane to its far plane, and the trapezoid is mapped onto the 512x512 square by a
 * perspective transform. The 80% rule places the projection centre so that a focus
 * region (the nearer half of the view's depth) gets 80% of the map. Depth is z / y of
 * that transform: monotone along each ray, which is all the comparison needs. */
#include "light_space.h"
#include <math.h>
#include <string.h>

#define TSM_XI (-0.6)         /* the focus point's place in [-1, 1]: the 80% line */
#define TSM_FOCUS_FRACTION 0.5 /* the focus region: this part of the view's depth */

static bool to_image(const mat4 *u, vec3 p, vec2 *q)
{
	vec4 h = m4_mul_point(u, p);
	if (!(h.w > 1e-12 * (fabs(h.x) + fabs(h.y) + fabs(h.z))))
		return false;
	*q = (vec2){h.x / h.w, h.y / h.w};
	return true;
}

/* Widens [*lo, *hi] to the depth z / w of p under m, where p is in front (w > 0). */
static void depth_range(const mat4 *m, vec3 p, double *lo, double *hi)
{
	vec4 h = m4_mul_point(m, p);
	if (!(h.w > 0))
		return;
	*lo = lx_fmin(*lo, h.z / h.w), *hi = lx_fmax(*hi, h.z / h.w); /* w > 0 */
}

/* The trapezoid in the uniform map's image: its projection centre q, its axis (from
 * the view's near end to its far end) and side, its top distance eta and height lambda
 * (the 80% rule puts the focus at TSM_XI), and its sides' slopes mid +- half. */
struct trapezoid {
	vec2 q, axis, side;
	double eta, lambda, mid, half;
};

/* The wanted rays in the image: C_tot mapped like the uniform map maps its bounds to
 * [-1, 1]^2 (linearly); the whole square where C_tot is unbounded. Returns the count. */
static int wanted_points(const struct lx_uniform_fit *fit, vec2 *pts)
{
	static const vec2 square[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
	if (!(isfinite(fit->x0) && isfinite(fit->x1) && isfinite(fit->y0) && isfinite(fit->y1) && fit->x1 > fit->x0 &&
	      fit->y1 > fit->y0)) {
		memcpy(pts, square, sizeof square);
		return 4;
	}
	for (int i = 0; i < fit->wanted.n; i++)
		pts[i] = (vec2){2 * (fit->wanted.v[i].x - fit->x0) / (fit->x1 - fit->x0) - 1,
				2 * (fit->wanted.v[i].y - fit->y0) / (fit->y1 - fit->y0) - 1};
	return fit->wanted.n;
}

/* The trapezoid around the wanted points along the view's centre line. 1, 0 when the
 * view looks along the light (a square would do), -1 after a warning. */
static int fit_trapezoid(const struct lx_frame *f, const mat4 *u, const vec2 *pts, int np, struct trapezoid *tz,
			 struct lx_shadow_result *out)
{
	const struct lx_view *v = &f->view;
	double span = v->far - v->near;
	vec2 top, base, focus;
	if (!to_image(u, v3_add(v->eye, v3_scale(v->dir, v->near)), &top) ||
	    !to_image(u, v3_add(v->eye, v3_scale(v->dir, v->far)), &base) ||
	    !to_image(u, v3_add(v->eye, v3_scale(v->dir, v->near + TSM_FOCUS_FRACTION * span)), &focus)) {
		lx_shadow_warn(out, "tsm: the view reaches behind the point light; uniform this frame");
		return -1;
	}
	vec2 axis = {base.x - top.x, base.y - top.y};
	double alen = hypot(axis.x, axis.y);
	if (!(alen > 1e-3)) /* the view looks along the light: a trapezoid would be a square */
		return 0;
	tz->axis = axis = (vec2){axis.x / alen, axis.y / alen};
	double tmin = INFINITY, tmax = -INFINITY;
	for (int i = 0; i < np; i++) {
		double t = (pts[i].x - top.x) * axis.x + (pts[i].y - top.y) * axis.y;
		tmin = lx_fmin(tmin, t), tmax = lx_fmax(tmax, t);
	}
	double lambda = tz->lambda = tmax - tmin; /* the trapezoid's height: > 0, the square has extent */
	double delta = (focus.x - top.x) * axis.x + (focus.y - top.y) * axis.y - tmin;
	delta = lx_fmin(lx_fmax(delta, 1e-6 * lambda), 0.79 * lambda); /* the focus inside the trapezoid */
	/* the 80% rule; the denominator is > 0 because delta < lambda (1 - xi) / 2 = 0.8 lambda */
	tz->eta = lambda * delta * (1 + TSM_XI) / (lambda - 2 * delta - lambda * TSM_XI);
	/* frame: origin at the projection centre, y along the centre line */
	tz->q = (vec2){top.x + axis.x * (tmin - tz->eta), top.y + axis.y * (tmin - tz->eta)};
	tz->side = (vec2){axis.y, -axis.x};
	double slo = INFINITY, shi = -INFINITY;
	for (int i = 0; i < np; i++) {
		double px = (pts[i].x - tz->q.x) * tz->side.x + (pts[i].y - tz->q.y) * tz->side.y;
		double py = (pts[i].x - tz->q.x) * axis.x + (pts[i].y - tz->q.y) * axis.y; /* >= eta > 0 */
		slo = lx_fmin(slo, px / py), shi = lx_fmax(shi, px / py);
	}
	tz->mid = (slo + shi) / 2, tz->half = (shi - slo) / 2;
	return tz->half > 0;
}

/* The middle of the receivers' depths under the uniform map, within [-1, 1].
 * Depth (z - zmid w) / t: along a ray (fixed z / w and t / w) it falls with z / w as the
 * uniform map's did; across rays it varies with 1 / t, by less the nearer z / w is to
 * zmid. A perspective map crowds the receivers' z / w near 1: with z / t (zmid 0) a light
 * on the floor gave depth slopes of ten times the along-ray gap per lixel, and 16% of
 * the pixels wrong. */
static double receivers_mid_depth(const struct lx_light_space *ls, const mat4 *u)
{
	double lo = INFINITY, hi = -INFINITY;
	for (int i = 0; i < ls->receiver_count; i++)
		depth_range(u, ls->receiver_pts[i], &lo, &hi);
	/* (receivers nearer the light than every caster, z / w < -1, cannot be shadowed) */
	lo = lx_fmax(lo, -1), hi = lx_fmin(hi, 1);
	return lo <= hi ? 0.5 * (lo + hi) : 0;
}

/* The trapezoid's transform on the uniform clip space: on the image (x, y, 1),
 * X = (s - mid t) / (half t), Y = ((fa + n) t - 2 fa n) / ((fa - n) t) with s, t the
 * side and axis coordinates, depth (z - zmid w) / t. */
static mat4 trapezoid_matrix(const struct trapezoid *tz, double zmid)
{
	double n = tz->eta, fa = tz->eta + tz->lambda;
	double s0 = -(tz->q.x * tz->side.x + tz->q.y * tz->side.y), t0 = -(tz->q.x * tz->axis.x + tz->q.y * tz->axis.y);
	/* rows over (x, y, z, w) of the uniform clip space; s = side . (x, y) + s0 w, t likewise */
	double srow[4] = {tz->side.x, tz->side.y, 0, s0}, trow[4] = {tz->axis.x, tz->axis.y, 0, t0};
	mat4 T = {{0}};
	for (int c = 0; c < 4; c++) {
		T.m[c * 4 + 0] = (srow[c] - tz->mid * trow[c]) / tz->half; /* half > 0 */
		T.m[c * 4 + 1] = ((fa + n) * trow[c] - (c == 3 ? 2 * fa * n : 0)) / (fa - n); /* lambda > 0 */
		T.m[c * 4 + 2] = c == 2 ? 1 : c == 3 ? -zmid : 0;
		T.m[c * 4 + 3] = trow[c];
	}
	return T;
}

static void tsm_warp(const struct lx_frame *f, const struct lx_light_space *ls, const struct lx_uniform_fit *fit,
		struct lx_shadow_map *map, struct lx_shadow_result *out)
{
	mat4 u = map->light_clip;
	vec2 pts[LX_POLY_MAX];
	int np = wanted_points(fit, pts);
	struct trapezoid tz;
	if (fit_trapezoid(f, &u, pts, np, &tz, out) <= 0)
		return; /* the uniform map stands */
	double zmid = receivers_mid_depth(ls, &u);
	mat4 T = trapezoid_matrix(&tz, zmid), m = m4_mul(&T, &u);
	/* depth: (z - zmid w) / t with z / w in [-1, 1] and t / w >= eta inside the
	 * trapezoid, so within [(-1 - zmid) / eta, (1 - zmid) / eta] */
	mat4 crop = m4_crop(-1, 1, -1, 1, (-1 - zmid) / tz.eta, (1 - zmid) / tz.eta);
	lx_shadow_map_warp(map, f, &crop, &m, "tsm", out);
}

const struct lx_shadow_method lx_method_tsm = {.name = "tsm",
	.summary = "trapezoidal shadow map (512x512), 80% rule",
	.warp = tsm_warp};
