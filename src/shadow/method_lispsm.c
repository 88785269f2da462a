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
	d = lx_fmax(d, 0);
	return (z_n + sqrt(z_n * (z_n + d * sin_gamma))) / sin_gamma; /* callers keep sin_gamma >= 0.02 */
}

static double safe_extent(double n, double d) { return lx_fmax(d, 1e-9 * (n + 1)); }

double lx_lispsm_warp(double y, double n, double d)
{
	double f = n + safe_extent(n, d);
	return ((f + n) * y - 2 * f * n) / ((f - n) * y); /* y >= n > 0 on the body */
}

/* Points of B: the receiver volume's vertices and the outlines (lx_frame_object_outline)
 * of the objects that can cast onto it (not one far off: it would stretch the body and
 * the warp). */
static int body_points(const struct lx_frame *f, const struct lx_light_space *ls, vec3 *pts, bool *caster, int max)
{
	int n = 0;
	for (int i = 0; i < ls->receiver_count && n < max; i++, n++)
		pts[n] = ls->receiver_pts[i], caster[n] = false;
	for (int id = 0; id < f->object_count; id++) {
		if (!(ls->casting >> id & 1))
			continue;
		vec3 x[LX_OUTLINE_POINTS];
		for (int k = 0, m = lx_frame_object_outline(f, id, false, x); k < m && n < max; k++) {
			pts[n] = x[k];
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

/* Light space S (rigid for a directional light, which travels along -z there; the
 * uniform map's clip space for a point light, whose rays travel along +z there) turned
 * by R so that y is "up" = (l x v) x l, perpendicular to the light: RS. With it the view's
 * near point a (in S), its near distance z_n there and sin(gamma) between view and light. */
struct light_frame {
	mat4 R, RS;
	vec3 a;
	double z_n, sin_gamma;
};

/* 1, 0 when the view looks along the light (no warp gains anything), -1 after a warning. */
static int light_frame(const struct lx_frame *f, const struct lx_light_space *ls, const mat4 *uniform,
		       struct light_frame *lf, struct lx_shadow_result *out)
{
	mat4 S = ls->directional ? ls->view : *uniform;
	vec3 l = ls->directional ? v3(0, 0, -1) : v3(0, 0, 1), v;
	const struct lx_view *view = &f->view;
	bool oka, okb;
	lf->a = project(&S, v3_add(view->eye, v3_scale(view->dir, view->near)), &oka);
	vec3 b = project(&S, v3_add(view->eye, v3_scale(view->dir, 2 * view->near)), &okb);
	if (!oka || !okb || !v3_normalize(v3_sub(b, lf->a), &v)) {
		lx_shadow_warn(out, "lispsm: the view starts behind the point light; no warp this frame (uniform)");
		return -1;
	}
	lf->z_n = v3_len(v3_sub(b, lf->a)); /* the view's near distance in light space */
	vec3 lxv = v3_cross(l, v), up = v3(0, 0, 0);
	lf->sin_gamma = v3_len(lxv);
	if (lf->sin_gamma < LX_LISPSM_MIN_SIN_GAMMA)
		return 0; /* view along the light: the warp would gain nothing, uniform it is */
	v3_normalize(v3_cross(lxv, l), &up); /* |l x v| >= 0.02 and l is unit: well defined */
	vec3 side = v3_cross(l, up);
	mat4 R = m4_identity(); /* rows side, up, -l */
	R.m[0] = side.x, R.m[4] = side.y, R.m[8] = side.z;
	R.m[1] = up.x, R.m[5] = up.y, R.m[9] = up.z;
	R.m[2] = -l.x, R.m[6] = -l.y, R.m[10] = -l.z;
	lf->R = R;
	lf->RS = m4_mul(&R, &S);
	return 1;
}

/* The warp: a perspective along up whose centre lies n before the body's near side,
 * level with the view's near point; n from the body's depth d (lx_lispsm_n). */
static mat4 warp(const struct light_frame *lf, double ylo, double yhi)
{
	double d = safe_extent(0, yhi - ylo), nn = lx_lispsm_n(lf->z_n, d, lf->sin_gamma), ff = nn + d;
	bool ok;
	vec3 ar = project(&lf->R, lf->a, &ok); /* R is affine: always ok */
	vec3 c = v3(ar.x, ylo - nn, ar.z);
	mat4 W = {{0}};
	W.m[0] = 1;
	W.m[5] = (ff + nn) / (ff - nn), W.m[13] = -2 * ff * nn / (ff - nn); /* ff - nn = d > 0 */
	W.m[10] = 1;
	W.m[7] = 1; /* w = y */
	mat4 T = m4_translate(v3_scale(c, -1));
	return m4_mul(&W, &T);
}

/* Unit cube clipping in the warped space: x, y of receivers and casters intersected;
 * depth from the casters' nearest to the receivers' farthest (the light travels -z).
 * pts are in RS. False when they do not overlap. */
static bool warped_crop(const mat4 *WT, const vec3 *pts, const bool *caster, int n, mat4 *crop)
{
	double r[5] = {INFINITY, INFINITY, -INFINITY, -INFINITY, INFINITY}; /* x0 y0 x1 y1 zmin */
	double c[5] = {INFINITY, INFINITY, -INFINITY, -INFINITY, -INFINITY}; /* x0 y0 x1 y1 zmax */
	for (int i = 0; i < n; i++) {
		vec4 h = m4_mul_v4(WT, (vec4){pts[i].x, pts[i].y, pts[i].z, 1});
		double x = h.x / h.w, y = h.y / h.w, z = h.z / h.w; /* h.w = y - c.y >= n > 0 */
		double *b = caster[i] ? c : r;
		b[0] = lx_fmin(b[0], x), b[2] = lx_fmax(b[2], x), b[1] = lx_fmin(b[1], y), b[3] = lx_fmax(b[3], y);
		b[4] = caster[i] ? lx_fmax(b[4], z) : lx_fmin(b[4], z);
	}
	double ex0 = lx_fmax(r[0], c[0]), ex1 = lx_fmin(r[2], c[2]), ey0 = lx_fmax(r[1], c[1]), ey1 = lx_fmin(r[3], c[3]);
	if (!(ex0 < ex1 && ey0 < ey1 && r[4] < c[4]))
		return false;
	double zpad = (c[4] - r[4]) * 1e-4;
	*crop = m4_crop(ex0, ex1, ey0, ey1, c[4] + zpad, r[4] - zpad); /* z decreases away from the light */
	return true;
}

static void lispsm_warp(const struct lx_frame *f, const struct lx_light_space *ls, const struct lx_uniform_fit *fit,
		struct lx_shadow_map *map, struct lx_shadow_result *out)
{
	(void)fit;
	struct light_frame lf;
	if (light_frame(f, ls, &map->light_clip, &lf, out) <= 0)
		return; /* the uniform map stands */
	vec3 pts[LX_CONVEX_MAX_POINTS + LX_OUTLINE_POINTS * (LX_MAX_PLANES + LX_MAX_CASTERS)];
	bool caster[LX_CONVEX_MAX_POINTS + LX_OUTLINE_POINTS * (LX_MAX_PLANES + LX_MAX_CASTERS)];
	int n = body_points(f, ls, pts, caster, (int)(sizeof pts / sizeof pts[0]));
	double ylo = INFINITY, yhi = -INFINITY;
	for (int i = 0; i < n; i++) {
		bool ok;
		pts[i] = project(&lf.RS, pts[i], &ok);
		if (!ok) {
			lx_shadow_warn(out, "lispsm: part of the body lies behind the point light; no warp this frame (uniform)");
			return;
		}
		ylo = lx_fmin(ylo, pts[i].y), yhi = lx_fmax(yhi, pts[i].y);
	}
	mat4 WT = warp(&lf, ylo, yhi), M0 = m4_mul(&WT, &lf.RS), crop;
	if (!warped_crop(&WT, pts, caster, n, &crop))
		map->rendered = false; /* casters and receivers do not overlap from the light */
	else
		lx_shadow_map_warp(map, f, &crop, &M0, "lispsm", out);
}

const struct lx_shadow_method lx_method_lispsm = {.name = "lispsm",
	.summary = "light space perspective shadow map (512x512)",
	.warp = lispsm_warp};
