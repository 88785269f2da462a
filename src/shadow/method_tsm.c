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
	*lo = fmin(*lo, h.z / h.w), *hi = fmax(*hi, h.z / h.w); /* w > 0 */
}

static void tsm_build(const struct lx_frame *f, const struct lx_atlas *atlas, const struct lx_method_options *opt,
			 struct lx_shadow_result *out)
{
	(void)opt;
	(void)atlas;
	struct lx_light_space ls;
	struct lx_uniform_fit fit;
	if (!lx_uniform_map(f, &ls, out, "tsm", &fit))
		return;
	struct lx_shadow_map *map = &out->maps[0];
	mat4 u = map->light_clip;
	const struct lx_poly wanted = fit.wanted;
	double x0 = fit.x0, x1 = fit.x1, y0 = fit.y0, y1 = fit.y1;
	/* the centre line: the view's near and far centres in the light image */
	const struct lx_view *v = &f->view;
	vec3 dir = v->dir;
	double span = v->far - v->near;
	vec2 top, base, focus;
	if (!to_image(&u, v3_add(v->eye, v3_scale(dir, v->near)), &top) ||
	    !to_image(&u, v3_add(v->eye, v3_scale(dir, v->far)), &base) ||
	    !to_image(&u, v3_add(v->eye, v3_scale(dir, v->near + TSM_FOCUS_FRACTION * span)), &focus)) {
		lx_shadow_warn(out, "tsm: the view reaches behind the point light; uniform this frame");
		return;
	}
	vec2 axis = {base.x - top.x, base.y - top.y};
	double alen = hypot(axis.x, axis.y);
	if (!(alen > 1e-3)) /* the view looks along the light: a trapezoid would be a square */
		return;
	axis.x /= alen, axis.y /= alen;
	/* the wanted rays in the image: C_tot mapped like the uniform map maps its bounds to
	 * [-1, 1]^2 (linearly); the whole square where C_tot is unbounded */
	vec2 pts[LX_POLY_MAX] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
	int np = 4;
	if (isfinite(x0) && isfinite(x1) && isfinite(y0) && isfinite(y1) && x1 > x0 && y1 > y0) {
		np = wanted.n;
		for (int i = 0; i < np; i++)
			pts[i] = (vec2){2 * (wanted.v[i].x - x0) / (x1 - x0) - 1, 2 * (wanted.v[i].y - y0) / (y1 - y0) - 1};
	}
	double tmin = INFINITY, tmax = -INFINITY;
	for (int i = 0; i < np; i++) {
		double t = (pts[i].x - top.x) * axis.x + (pts[i].y - top.y) * axis.y;
		tmin = fmin(tmin, t), tmax = fmax(tmax, t);
	}
	double lambda = tmax - tmin; /* the trapezoid's height: > 0, the square has extent */
	double delta = (focus.x - top.x) * axis.x + (focus.y - top.y) * axis.y - tmin;
	delta = fmin(fmax(delta, 1e-6 * lambda), 0.79 * lambda); /* the focus inside the trapezoid */
	/* the 80% rule; the denominator is > 0 because delta < lambda (1 - xi) / 2 = 0.8 lambda */
	double eta = lambda * delta * (1 + TSM_XI) / (lambda - 2 * delta - lambda * TSM_XI);
	/* frame: origin at the projection centre, y along the centre line */
	vec2 q = {top.x + axis.x * (tmin - eta), top.y + axis.y * (tmin - eta)};
	vec2 side = {axis.y, -axis.x};
	double slo = INFINITY, shi = -INFINITY;
	for (int i = 0; i < np; i++) {
		double px = (pts[i].x - q.x) * side.x + (pts[i].y - q.y) * side.y;
		double py = (pts[i].x - q.x) * axis.x + (pts[i].y - q.y) * axis.y; /* >= eta > 0 */
		slo = fmin(slo, px / py), shi = fmax(shi, px / py);
	}
	double mid = (slo + shi) / 2, half = (shi - slo) / 2, n = eta, fa = eta + lambda;
	if (!(half > 0))
		return;
	/* 3x3 on the image (x, y, 1): X = (s - mid t) / (half t), Y = ((fa + n) t - 2 fa n) / ((fa - n) t)
	 * with s, t the side and axis coordinates; embedded in 4x4 around the uniform map */
	double s0 = -(q.x * side.x + q.y * side.y), t0 = -(q.x * axis.x + q.y * axis.y);
	/* Depth (z - zmid w) / t: along a ray (fixed z / w and t / w) it falls with z / w as
	 * the uniform map's did; across rays it varies with 1 / t, by less the nearer z / w
	 * is to zmid. zmid is the middle of the receivers' depths, which a perspective map
	 * crowds near 1: with z / t (zmid 0) a light on the floor gave depth slopes of ten
	 * times the along-ray gap per lixel, and 16% of the pixels wrong. */
	double zlo0 = INFINITY, zhi0 = -INFINITY;
	for (int i = 0; i < ls.receiver_count; i++)
		depth_range(&u, ls.receiver_pts[i], &zlo0, &zhi0);
	/* (receivers nearer the light than every caster, z / w < -1, cannot be shadowed) */
	zlo0 = fmax(zlo0, -1), zhi0 = fmin(zhi0, 1);
	double zmid = zlo0 <= zhi0 ? 0.5 * (zlo0 + zhi0) : 0;
	/* rows over (x, y, z, w) of the uniform clip space; s = side . (x, y) + s0 w, t likewise */
	double srow[4] = {side.x, side.y, 0, s0}, trow[4] = {axis.x, axis.y, 0, t0};
	mat4 T = {{0}};
	for (int c = 0; c < 4; c++) {
		double sc = c == 0 ? srow[0] : c == 1 ? srow[1] : c == 2 ? 0 : srow[3];
		double tc = c == 0 ? trow[0] : c == 1 ? trow[1] : c == 2 ? 0 : trow[3];
		T.m[c * 4 + 0] = (sc - mid * tc) / half;
		T.m[c * 4 + 1] = ((fa + n) * tc - (c == 3 ? 2 * fa * n : 0)) / (fa - n);
		T.m[c * 4 + 2] = c == 2 ? 1 : c == 3 ? -zmid : 0; /* (z - zmid w) / t: monotone along rays */
		T.m[c * 4 + 3] = tc;
	}
	mat4 m = m4_mul(&T, &u);
	/* depth: (z - zmid w) / t with z / w in [-1, 1] and t / w >= eta inside the
	 * trapezoid, so within [(-1 - zmid) / eta, (1 - zmid) / eta] */
	mat4 crop = m4_crop(-1, 1, -1, 1, (-1 - zmid) / eta, (1 - zmid) / eta);
	lx_shadow_map_warp(map, f, &crop, &m, "tsm", out);
}

const struct lx_shadow_method lx_method_tsm = {.name = "tsm",
	.summary = "trapezoidal shadow map (512x512), 80% rule",
	.build = tsm_build};
