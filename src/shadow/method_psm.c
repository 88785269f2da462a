/* Perspective shadow maps ([PSM], as [Martin-PSM] and [Kapoulkine] build it, with
 * [Kozlov]'s care): the shadow map is taken in the post-perspective space (PPS) of a virtual
 * camera, the real one slid back until every caster lies in front of it.
 *
 * In PPS the light L' = PPS L is a homogeneous point of any kind: in front (w > 0), an
 * "inverted" light behind the viewer (w < 0: its rays arrive from beyond the plane at
 * infinity, so along a ray the point farther from L' is nearer the light), or at
 * infinity (w = 0: a directional light orthogonal to the view stays directional, its
 * own branch with an affine light camera). One construction serves all three: the light
 * camera's rows span the complement of L' in R^4, so L' is its centre whatever its
 * kind, and depth is -L'.X / w, which falls towards the light along every ray. Only the
 * casters that can shadow a receiver are bounded (they lie in front of that camera);
 * unit cube clipping in the light's image and depth (Kozlov: casters nearer than the
 * near plane are clamped onto it, not clipped). Where PPS cannot hold the light's
 * view (receivers on both sides of the light, the light facing the camera among them)
 * the uniform map stands in, with a warning. */
#include "light_space.h"
#include <math.h>
#include <string.h>


/* Removes from v its components along the unit vectors u[0..n-1]; normalises. */
static bool orthonormal(vec4 *v, const vec4 *u, int n)
{
	for (int i = 0; i < n; i++)
		*v = v4_lin(1, *v, -v4_dot(*v, u[i]), u[i]);
	double l = sqrt(v4_dot(*v, *v));
	if (!(l > 1e-9))
		return false;
	*v = (vec4){v->x / l, v->y / l, v->z / l, v->w / l};
	return true;
}

/* The virtual camera's view-projection (post-perspective space, PPS): the real camera
 * slid back along its view until every caster that can reach the receivers is in front
 * of its near plane. */
static bool virtual_camera(const struct lx_frame *f, const struct lx_light_space *ls, mat4 *pps)
{
	const struct lx_camera *cam = &f->scene->camera;
	const struct lx_view *v = &f->view;
	double cmin = INFINITY;
	for (int id = 0; id < f->object_count; id++)
		if (ls->casting >> id & 1) /* casters that can reach the receivers: not one far off */
			for (int k = 0; k < 8; k++)
				cmin = lx_fmin(cmin, v3_dot(v3_sub(v3_box_corner(f->bmin[id], f->bmax[id], k), cam->eye), v->dir));
	double slide = lx_fmax(0, v->near - cmin);
	vec3 eye = v3_sub(cam->eye, v3_scale(v->dir, slide));
	mat4 vv, vp;
	if (!m4_look_at(eye, v3_add(eye, v->dir), cam->up, &vv) ||
	    !m4_perspective(v->fovy, (double)v->width / v->height, v->near, v->far + slide, &vp))
		return false;
	*pps = m4_mul(&vp, &vv);
	return true;
}

/* The light camera's w row in PPS, orthogonal to the light's image c: along the
 * receivers (an affine camera for a light at infinity), positive on every one of them,
 * a hyperplane through c with all of them on one side (it exists when c lies outside
 * their hull). The centroid of their directions usually is one; otherwise a perceptron
 * walk finds one. False when the light lies on the view's centre line. */
static bool receivers_side(vec4 c, const vec4 *recp, int nrec, bool directional, vec4 *w)
{
	vec4 centroid = {0, 0, 0, 0};
	for (int i = 0; i < nrec; i++)
		centroid = v4_lin(1, centroid, 1 / v4_len(recp[i]), recp[i]); /* a receiver is no 0 vector */
	*w = directional ? (vec4){0, 0, 0, 1} : centroid;
	if (!orthonormal(w, &c, 1))
		return false;
	for (int iter = 0; !directional && iter < 200; iter++) {
		int worst = -1;
		double worst_val = 1e-9;
		for (int i = 0; i < nrec; i++) {
			double val = v4_dot(*w, recp[i]) / v4_len(recp[i]);
			if (val < worst_val)
				worst = i, worst_val = val;
		}
		if (worst < 0)
			break;
		*w = v4_lin(1, *w, 1 / v4_len(recp[worst]), recp[worst]);
		if (!orthonormal(w, &c, 1))
			break;
	}
	return true;
}

/* The light camera in PPS: x and y completing c and w to a basis, depth -c . X / w
 * falling towards the light, then w. */
static mat4 light_camera(vec4 c, vec4 w)
{
	vec4 basis[4] = {c, w}, x = {1, 0, 0, 0}, y;
	if (!orthonormal(&x, basis, 2)) { /* x may lie in span(c, w): try the other axes */
		x = (vec4){0, 0, 1, 0};
		if (!orthonormal(&x, basis, 2)) {
			x = (vec4){0, 0, 0, 1};
			orthonormal(&x, basis, 2);
		}
	}
	basis[2] = x;
	static const vec4 cand[4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
	for (int i = 0; i < 4; i++) {
		y = cand[i];
		if (orthonormal(&y, basis, 3))
			break;
	}
	vec4 rows[4] = {x, y, {-c.x, -c.y, -c.z, -c.w}, w};
	mat4 light = {{0}};
	for (int r = 0; r < 4; r++)
		light.m[0 + r] = rows[r].x, light.m[4 + r] = rows[r].y, light.m[8 + r] = rows[r].z, light.m[12 + r] = rows[r].w;
	return light;
}

/* Unit cube clipping in the light camera's space: the receivers' and the casters'
 * images intersected, depth from the casters' nearest to the receivers' farthest. 1 with
 * *crop; 0 when casters and receivers do not overlap (no map); -1 after a warning. The
 * casters by their boxes, not their outlines (lx_frame_object_outline) as the other
 * methods: with those a scale-100 view of test_extremes kept 1.20% of its pixels wrong
 * without a coarse-map warning (docs/results.md, "Round casters' outlines"). */
static int psm_crop(const struct lx_frame *f, const struct lx_light_space *ls, const mat4 *m0,
		    struct lx_shadow_map *map, mat4 *crop, struct lx_shadow_result *out)
{
	double r[4] = {INFINITY, INFINITY, -INFINITY, -INFINITY}, zfar = -INFINITY, zrec = INFINITY;
	for (int i = 0; i < ls->receiver_count; i++) {
		vec4 h = m4_mul_point(m0, ls->receiver_pts[i]);
		if (!(h.w > 0)) {
			lx_shadow_warn(out, "psm: receivers lie on both sides of the light in PPS; uniform this frame");
			return -1;
		}
		r[0] = lx_fmin(r[0], h.x / h.w), r[2] = lx_fmax(r[2], h.x / h.w), r[1] = lx_fmin(r[1], h.y / h.w), r[3] = lx_fmax(r[3], h.y / h.w);
		zfar = lx_fmax(zfar, h.z / h.w), zrec = lx_fmin(zrec, h.z / h.w);
	}
	double cb[4] = {INFINITY, INFINITY, -INFINITY, -INFINITY}, znear = INFINITY;
	for (int id = 0; id < f->object_count; id++)
		for (int k = 0; (ls->casting >> id & 1) && k < 8; k++) {
			vec4 h = m4_mul_point(m0, v3_box_corner(f->bmin[id], f->bmax[id], k));
			if (!(h.w > 1e-12 * (fabs(h.x) + fabs(h.y) + fabs(h.z)))) {
				/* a box reaching the light camera's plane: its image is unbounded and its
				 * depth falls without bound towards the light; the shadow pass flattens
				 * what lies nearer than the near plane onto it */
				cb[0] = cb[1] = -INFINITY, cb[2] = cb[3] = INFINITY;
				map->pancake = true;
				continue;
			}
			cb[0] = lx_fmin(cb[0], h.x / h.w), cb[2] = lx_fmax(cb[2], h.x / h.w), cb[1] = lx_fmin(cb[1], h.y / h.w);
			cb[3] = lx_fmax(cb[3], h.y / h.w), znear = lx_fmin(znear, h.z / h.w);
		}
	double ex0 = lx_fmax(r[0], cb[0]), ex1 = lx_fmin(r[2], cb[2]), ey0 = lx_fmax(r[1], cb[1]), ey1 = lx_fmin(r[3], cb[3]);
	/* a receiver nearer the light than every caster must still be inside the depth range */
	if (map->pancake)
		znear = lx_fmin(znear, zrec);
	if (!(ex0 < ex1 && ey0 < ey1) || !isfinite(znear) || znear > zfar)
		return 0;
	double zpad = (zfar - znear) * 1e-4;
	*crop = m4_crop(ex0, ex1, ey0, ey1, znear - zpad, zfar + zpad);
	return 1;
}

/* Where PPS cannot hold the light's view, the uniform map stands in. */
static void psm_warp(const struct lx_frame *f, const struct lx_light_space *ls, const struct lx_uniform_fit *fit,
		struct lx_shadow_map *map, struct lx_shadow_result *out)
{
	(void)fit;
	mat4 pps;
	if (!virtual_camera(f, ls, &pps)) {
		lx_shadow_warn(out, "psm: no virtual camera; uniform this frame");
		return;
	}
	const struct lx_light *l = &f->light;
	vec4 C = m4_mul_v4(&pps, l->directional ? (vec4){-l->direction.x, -l->direction.y, -l->direction.z, 0}
						: (vec4){l->position.x, l->position.y, l->position.z, 1});
	vec4 c = v4_lin(1 / v4_len(C), C, 0, C); /* the light's image in PPS, a unit 4-vector */
	out->variant = fabs(c.w) < 1e-9 ? LX_PSM_DIRECTIONAL : c.w < 0 ? LX_PSM_INVERTED : LX_PSM_POINT;
	vec4 recp[LX_CONVEX_MAX_POINTS], w;
	for (int i = 0; i < ls->receiver_count; i++)
		recp[i] = m4_mul_point(&pps, ls->receiver_pts[i]);
	if (!receivers_side(c, recp, ls->receiver_count, out->variant == LX_PSM_DIRECTIONAL, &w)) {
		lx_shadow_warn(out, "psm: the light lies on the view's centre line in PPS; uniform this frame");
		return;
	}
	mat4 light = light_camera(c, w), m0 = m4_mul(&light, &pps), crop;
	int held = psm_crop(f, ls, &m0, map, &crop, out);
	if (held == 0)
		map->rendered = false; /* casters and receivers do not overlap from the light */
	else if (held > 0)
		lx_shadow_map_warp(map, f, &crop, &m0, "psm", out);
}

const struct lx_shadow_method lx_method_psm = {.name = "psm",
	.summary = "perspective shadow map (512x512) in a slid-back camera's post-perspective space",
	.warp = psm_warp};
