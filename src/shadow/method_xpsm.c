/* Extended perspective shadow maps (XPSM), built around what [Kapoulkine]'s notes say of
 * them: light space turned about z by a unit projection vector P, unit cube clipping
 * after a perspective warp, and a floor eps_w on the warped w.
 *
 * Light space S: the light's view for a directional light, the uniform map's clip space
 * for a point light (its rays run parallel there), z growing towards the light. A turn
 * about z (the notes' "Z rotation") lays P, the view direction's part across the light,
 * along +y. The warp keeps x, y and z and sets w = 1 + u / n, u the distance along P from
 * the receivers' nearest point: w is the same all along a light ray, so the light stays
 * directional and depth keeps its order along every ray, while the receivers near the
 * viewer (small w) get more of the 512x512 map. n is [LiSPSM]'s formula with the
 * receivers' extent along P as the body, so casters do not set the warp; they only bound
 * it: every caster keeps w >= eps_w (n grows where one reaches further towards the
 * viewer). Why: the shadow pass flattens a caster vertex nearer than the near plane onto
 * it, which bends the depth of a long triangle's part in the map (a floor lit from below
 * lost its shadows on the table so). With w >= eps_w every caster fits the depth range,
 * its warped depth z / w at most 1 / eps_w times its depth before the warp. (The notes'
 * remedy, keeping the x, y of points under eps_w but not their depth, would leave such
 * vertices nearer than the near plane here.)
 *
 * Unit cube clipping: x, y of receivers and casters intersected, depth from the casters'
 * nearest to the receivers' farthest. Where the warp means nothing (the view along the
 * light's rays; the view, a receiver or a caster behind a point light) the uniform map
 * stands, with a warning. */
#include "light_space.h"
#include "method_lispsm.h"
#include "plane_optimal.h"
#include <math.h>

/* The floor on every caster's warped w (every receiver has w >= 1). */
#define XPSM_EPS_W 0.5

/* Light space turned so that P runs along +y (RS), the view's near centre a there, its
 * near distance z_n there and sin(gamma) between the view and the light's rays. */
struct xpsm_space {
	mat4 RS;
	vec3 a;
	double z_n, sin_gamma;
};

/* p through m; false where it lies at or behind a point light (no image there). */
static bool to_space(const mat4 *m, vec3 p, vec3 *q)
{
	vec4 h = m4_mul_point(m, p);
	if (!(h.w > 1e-12 * (fabs(h.x) + fabs(h.y) + fabs(h.z))))
		return false;
	*q = v3(h.x / h.w, h.y / h.w, h.z / h.w); /* h.w > 0 */
	return true;
}

/* RS and the view in it; false after a warning (the uniform map stands). */
static bool xpsm_space(const struct lx_frame *f, const struct lx_light_space *ls, const mat4 *uniform,
		       struct xpsm_space *xs, struct lx_shadow_result *out)
{
	mat4 S = ls->directional ? ls->view : *uniform;
	if (!ls->directional)
		for (int c = 0; c < 4; c++)
			S.m[c * 4 + 2] = -S.m[c * 4 + 2]; /* clip z grows away from a point light: turned round */
	const struct lx_view *v = &f->view;
	vec3 a, b;
	if (!to_space(&S, v3_add(v->eye, v3_scale(v->dir, v->near)), &a) ||
	    !to_space(&S, v3_add(v->eye, v3_scale(v->dir, 2 * v->near)), &b)) {
		lx_shadow_warn(out, "xpsm: the view starts behind the point light; uniform this frame");
		return false;
	}
	vec3 d = v3_sub(b, a);
	double len = v3_len(d), across = hypot(d.x, d.y);
	if (!(len > 0 && across >= LX_LISPSM_MIN_SIN_GAMMA * len)) {
		lx_shadow_warn(out, "xpsm: the view runs along the light's rays (within %.1f degrees, the light %s the viewer); no warp, uniform this frame",
			       asin(LX_LISPSM_MIN_SIN_GAMMA) * 180 / M_PI, d.z > 0 ? "facing" : "behind");
		return false;
	}
	vec3 p = v3(d.x / across, d.y / across, 0); /* across >= 0.02 len > 0 */
	mat4 R = m4_identity(); /* rows (p.y, -p.x, 0), (p.x, p.y, 0), (0, 0, 1): a turn about z, P onto +y */
	R.m[0] = p.y, R.m[4] = -p.x;
	R.m[1] = p.x, R.m[5] = p.y;
	xs->RS = m4_mul(&R, &S);
	xs->a = v3(p.y * a.x - p.x * a.y, p.x * a.x + p.y * a.y, a.z);
	xs->z_n = len;
	xs->sin_gamma = across / len; /* len > 0 */
	return true;
}

/* The receivers (the receiver volume's vertices) and the box corners of the casters
 * that can shadow them, in RS; false after a warning (one lies behind a point light). */
struct xpsm_points {
	int nrec, ncas;
	vec3 rec[LX_CONVEX_MAX_POINTS], cas[LX_OUTLINE_POINTS * (LX_MAX_PLANES + LX_MAX_CASTERS)];
};

static bool xpsm_points(const struct lx_frame *f, const struct lx_light_space *ls, const mat4 *RS,
			struct xpsm_points *pt, struct lx_shadow_result *out)
{
	pt->nrec = ls->receiver_count, pt->ncas = 0;
	for (int i = 0; i < ls->receiver_count; i++)
		if (!to_space(RS, ls->receiver_pts[i], &pt->rec[i])) {
			lx_shadow_warn(out, "xpsm: receivers reach behind the point light (it lies among them or on a plane); uniform this frame");
			return false;
		}
	for (int id = 0; id < f->object_count; id++) {
		vec3 x[LX_OUTLINE_POINTS];
		int n = ls->casting >> id & 1 ? lx_frame_object_outline(f, id, false, x) : 0;
		for (int k = 0; k < n; k++)
			if (!to_space(RS, x[k], &pt->cas[pt->ncas++])) {
				lx_shadow_warn(out, "xpsm: a caster reaches behind the point light; uniform this frame");
				return false;
			}
	}
	return true;
}

/* The warp's origin o (level with the view's near centre across P, at the receivers'
 * nearest point along P, at their middle depth) and n: [LiSPSM]'s over the receivers'
 * extent along P, larger where a caster would fall under eps_w. */
static double warp_parameter(const struct xpsm_space *xs, const struct xpsm_points *pt, vec3 *o)
{
	double ylo = INFINITY, yhi = -INFINITY, zlo = INFINITY, zhi = -INFINITY, clo = INFINITY;
	for (int i = 0; i < pt->nrec; i++) {
		ylo = lx_fmin(ylo, pt->rec[i].y), yhi = lx_fmax(yhi, pt->rec[i].y);
		zlo = lx_fmin(zlo, pt->rec[i].z), zhi = lx_fmax(zhi, pt->rec[i].z);
	}
	for (int i = 0; i < pt->ncas; i++)
		clo = lx_fmin(clo, pt->cas[i].y);
	*o = v3(xs->a.x, ylo, 0.5 * (zlo + zhi));
	/* z_n > 0 and sin gamma in [0.02, 1]: n >= 2 z_n > 0 */
	double n = lx_lispsm_n(xs->z_n, yhi - ylo, xs->sin_gamma);
	/* w = 1 + (clo - ylo) / n >= eps_w */
	return lx_fmax(n, (ylo - clo) / (1 - XPSM_EPS_W));
}

/* Bounds in the warped space: image x, y and the depth extreme that matters (the
 * receivers' farthest: least z; the casters' nearest: greatest z). */
struct extent {
	double x0, y0, x1, y1, z;
};

/* The bounds of pts[0..n-1] moved by -o and warped (w = 1 + u / nn >= eps_w > 0). */
static struct extent warped_extent(const vec3 *pts, int n, vec3 o, double nn, bool caster)
{
	struct extent e = {INFINITY, INFINITY, -INFINITY, -INFINITY, caster ? -INFINITY : INFINITY};
	for (int i = 0; i < n; i++) {
		vec3 q = v3_sub(pts[i], o);
		double w = 1 + q.y / nn; /* nn > 0 */
		double x = q.x / w, y = q.y / w, z = q.z / w;
		e.x0 = lx_fmin(e.x0, x), e.x1 = lx_fmax(e.x1, x);
		e.y0 = lx_fmin(e.y0, y), e.y1 = lx_fmax(e.y1, y);
		e.z = caster ? lx_fmax(e.z, z) : lx_fmin(e.z, z);
	}
	return e;
}

/* The warp W T: T moves the origin to o, W keeps x, u, z and sets w = 1 + u / n. */
static mat4 warp(vec3 o, double n)
{
	mat4 W = m4_identity(), T = m4_translate(v3_scale(o, -1));
	W.m[7] = 1 / n; /* row w, column u; n > 0 */
	return m4_mul(&W, &T);
}

/* A point light lying on a plane of the scene (lx_plane_near_limit, as plane-optimal judges it):
 * its rays graze that plane and what stands on it, where the warped depth decides the side
 * by rounding (a spotlight on the floor put false shadows on a cone's lit side, 16% of the
 * compared pixels, found by test_extremes). False after a warning: the uniform map stands. */
static bool light_off_the_planes(const struct lx_frame *f, struct lx_shadow_result *out)
{
	if (f->light.directional)
		return true;
	for (int i = 0; i < f->scene->plane_count; i++) {
		const struct lx_plane *P = &f->scene->planes[i];
		double limit = lx_plane_near_limit(P);
		if (fabs(v4_dot_point(lx_plane_equation(P), f->light.position)) < limit) {
			lx_shadow_warn(out, "xpsm: the point light lies within %.3g m of plane %s; uniform this frame", limit,
				       P->name);
			return false;
		}
	}
	return true;
}

static void xpsm_warp(const struct lx_frame *f, const struct lx_light_space *ls, const struct lx_uniform_fit *fit,
		struct lx_shadow_map *map, struct lx_shadow_result *out)
{
	(void)fit;
	struct xpsm_space xs;
	struct xpsm_points pt;
	if (!light_off_the_planes(f, out) || !xpsm_space(f, ls, &map->light_clip, &xs, out) ||
	    !xpsm_points(f, ls, &xs.RS, &pt, out))
		return; /* the uniform map stands */
	vec3 o;
	double n = warp_parameter(&xs, &pt, &o);
	struct extent r = warped_extent(pt.rec, pt.nrec, o, n, false), c = warped_extent(pt.cas, pt.ncas, o, n, true);
	double x0 = lx_fmax(r.x0, c.x0), x1 = lx_fmin(r.x1, c.x1), y0 = lx_fmax(r.y0, c.y0), y1 = lx_fmin(r.y1, c.y1);
	if (!(x0 < x1 && y0 < y1 && r.z < c.z)) {
		map->rendered = false; /* casters and receivers do not overlap from the light */
		return;
	}
	double zpad = (c.z - r.z) * 1e-4;
	mat4 crop = m4_crop(x0, x1, y0, y1, c.z + zpad, r.z - zpad); /* depth falls away from the light */
	mat4 WT = warp(o, n), M0 = m4_mul(&WT, &xs.RS);
	lx_shadow_map_warp(map, f, &crop, &M0, "xpsm", out);
}

const struct lx_shadow_method lx_method_xpsm = {.name = "xpsm",
	.summary = "extended perspective shadow map (512x512): a warp across the light, unit cube clipping after it",
	.warp = xpsm_warp};
