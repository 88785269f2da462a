/* Light space perspective shadow maps ([LiSPSM]). In light space (world seen from a
 * directional light; the light's post-perspective space for a point light, where its
 * rays are parallel) a perspective frustum along up = (l x v) x l, perpendicular to the
 * light, encloses the body B (the receivers and the casters): near objects get more of
 * the 512x512 map. n from the general formula with the angle gamma between view and
 * light; the warp fades out (uniform) as the view becomes parallel to the light. Unit
 * cube clipping in the warped space ([Kapoulkine]). */
#include "method_lispsm.h"
#include "light_space.h"
#include <math.h>
#include <string.h>

double lx_lispsm_n(double z_n, double d, double sin_gamma)
{
	d = fmax(d, 0);
	return (z_n + sqrt(z_n * (z_n + d * sin_gamma))) / sin_gamma; /* callers keep sin_gamma >= 0.02 */
}

static double safe_extent(double n, double d) { return fmax(d, 1e-9 * (n + 1)); }

double lx_lispsm_warp(double y, double n, double d)
{
	double f = n + safe_extent(n, d);
	return ((f + n) * y - 2 * f * n) / ((f - n) * y); /* y >= n > 0 on the body */
}

/* Points of B: the receiver volume's vertices and the box corners of the objects that
 * can cast onto it (not one far off: it would stretch the body and the warp). */
static int body_points(const struct lx_frame *f, const struct lx_light_space *ls, vec3 *pts, bool *caster, int max)
{
	int n = 0;
	for (int i = 0; i < ls->receiver_count && n < max; i++, n++)
		pts[n] = ls->receiver_pts[i], caster[n] = false;
	for (int id = 0; id < f->object_count; id++) {
		if (!(ls->casting >> id & 1))
			continue;
		for (int k = 0; k < 8 && n < max; k++) {
			pts[n] = v3_box_corner(f->bmin[id], f->bmax[id], k);
			caster[n++] = true;
		}
	}
	return n;
}

static vec3 project(const mat4 *m, vec3 p, bool *ok)
{
	vec4 q = m4_mul_point(m, p);
	*ok = q.w > 1e-12 * (fabs(q.x) + fabs(q.y) + fabs(q.z));
	return *ok ? v3(q.x / q.w, q.y / q.w, q.z / q.w) : v3(0, 0, 0);
}

static void lispsm_build(const struct lx_frame *f, const struct lx_atlas *atlas, const struct lx_method_options *opt,
			 struct lx_shadow_result *out)
{
	(void)opt;
	(void)atlas;
	struct lx_light_space ls;
	if (!lx_uniform_map(f, &ls, out, "lispsm", NULL))
		return;
	struct lx_shadow_map *map = &out->maps[0];
	mat4 uniform = map->light_clip;
	/* Light space S: rigid for a directional light (the light travels along -z); the
	 * uniform map's clip space for a point light (its rays travel along +z there). */
	mat4 S = ls.directional ? ls.view : uniform;
	vec3 l = ls.directional ? v3(0, 0, -1) : v3(0, 0, 1);
	const struct lx_view *view = &f->view;
	vec3 vdir = view->dir;
	bool oka, okb;
	vec3 a = project(&S, v3_add(view->eye, v3_scale(vdir, view->near)), &oka);
	vec3 b = project(&S, v3_add(view->eye, v3_scale(vdir, 2 * view->near)), &okb);
	vec3 v;
	if (!oka || !okb || !v3_normalize(v3_sub(b, a), &v)) {
		lx_shadow_warn(out, "lispsm: the view starts behind the point light; no warp this frame (uniform)");
		return;
	}
	double z_n = v3_len(v3_sub(b, a)); /* the view's near distance in light space */
	vec3 lxv = v3_cross(l, v);
	double sin_gamma = v3_len(lxv);
	if (sin_gamma < LX_LISPSM_MIN_SIN_GAMMA)
		return; /* view along the light: the warp would gain nothing, uniform it is */
	vec3 up, side;
	v3_normalize(v3_cross(lxv, l), &up); /* |l x v| >= 0.02 and l is unit: well defined */
	side = v3_cross(l, up);
	/* R: rows side, up, -l; then the body's bounds there */
	mat4 R = m4_identity();
	R.m[0] = side.x, R.m[4] = side.y, R.m[8] = side.z;
	R.m[1] = up.x, R.m[5] = up.y, R.m[9] = up.z;
	R.m[2] = -l.x, R.m[6] = -l.y, R.m[10] = -l.z;
	mat4 RS = m4_mul(&R, &S);
	vec3 pts[LX_CONVEX_MAX_POINTS + 8 * (LX_MAX_PLANES + LX_MAX_CASTERS)];
	bool caster[LX_CONVEX_MAX_POINTS + 8 * (LX_MAX_PLANES + LX_MAX_CASTERS)];
	int n = body_points(f, &ls, pts, caster, (int)(sizeof pts / sizeof pts[0]));
	double ylo = INFINITY, yhi = -INFINITY;
	int valid = 0;
	for (int i = 0; i < n; i++) {
		bool ok;
		vec3 q = project(&RS, pts[i], &ok);
		if (!ok) {
			continue; /* behind a point light: counted below */
		}
		pts[i] = q;
		valid++;
		ylo = fmin(ylo, q.y), yhi = fmax(yhi, q.y);
	}
	if (valid < n) {
		lx_shadow_warn(out, "lispsm: part of the body lies behind the point light; no warp this frame (uniform)");
		return;
	}
	double d = safe_extent(0, yhi - ylo), nn = lx_lispsm_n(z_n, d, sin_gamma), ff = nn + d;
	vec3 ar = project(&R, a, &oka); /* R is affine: always ok */
	/* the projection centre: n before the body's near side along up, level with the view's near point */
	vec3 c = v3(ar.x, ylo - nn, ar.z);
	mat4 W = {{0}};
	W.m[0] = 1;
	W.m[5] = (ff + nn) / (ff - nn), W.m[13] = -2 * ff * nn / (ff - nn);
	W.m[10] = 1;
	W.m[7] = 1; /* w = y */
	mat4 T = m4_translate(v3_scale(c, -1)), WT = m4_mul(&W, &T), M0 = m4_mul(&WT, &RS);
	/* unit cube clipping in the warped space: x, y of receivers and casters intersected;
	 * depth from the casters' nearest to the receivers' farthest (the light travels -z) */
	double rx0 = INFINITY, rx1 = -INFINITY, ry0 = INFINITY, ry1 = -INFINITY, rz0 = INFINITY;
	double cx0 = INFINITY, cx1 = -INFINITY, cy0 = INFINITY, cy1 = -INFINITY, cz1 = -INFINITY;
	for (int i = 0; i < n; i++) {
		vec4 h = m4_mul_v4(&WT, (vec4){pts[i].x, pts[i].y, pts[i].z, 1});
		double x = h.x / h.w, y = h.y / h.w, z = h.z / h.w; /* h.w = y - c.y >= n > 0 */
		if (caster[i]) {
			cx0 = fmin(cx0, x), cx1 = fmax(cx1, x), cy0 = fmin(cy0, y), cy1 = fmax(cy1, y), cz1 = fmax(cz1, z);
		} else {
			rx0 = fmin(rx0, x), rx1 = fmax(rx1, x), ry0 = fmin(ry0, y), ry1 = fmax(ry1, y), rz0 = fmin(rz0, z);
		}
	}
	double ex0 = fmax(rx0, cx0), ex1 = fmin(rx1, cx1), ey0 = fmax(ry0, cy0), ey1 = fmin(ry1, cy1);
	if (!(ex0 < ex1 && ey0 < ey1 && rz0 < cz1)) {
		map->rendered = false; /* casters and receivers do not overlap from the light */
		return;
	}
	double zpad = (cz1 - rz0) * 1e-4;
	double zn = cz1 + zpad, zf = rz0 - zpad; /* z decreases away from the light */
	mat4 crop = m4_crop(ex0, ex1, ey0, ey1, zn, zf);
	lx_shadow_map_warp(map, f, &crop, &M0, "lispsm", out);
}

const struct lx_shadow_method lx_method_lispsm = {.name = "lispsm",
	.summary = "light space perspective shadow map (512x512)",
	.build = lispsm_build};
