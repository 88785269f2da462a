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

static void psm_build(const struct lx_frame *f, const struct lx_atlas *atlas, const struct lx_method_options *opt,
			 struct lx_shadow_result *out)
{
	(void)opt;
	(void)atlas;
	/* the uniform map first: where PPS cannot hold the light's view, it stands in */
	struct lx_light_space ls;
	if (!lx_uniform_map(f, &ls, out, "psm", NULL))
		return;
	struct lx_shadow_map *map = &out->maps[0];
	const struct lx_camera *cam = &f->scene->camera;
	const struct lx_view *v = &f->view;
	vec3 dir = v->dir;
	/* the virtual camera: slid back until every caster is in front of its near plane */
	double cmin = INFINITY;
	for (int id = 0; id < f->object_count; id++)
		if (ls.casting >> id & 1) /* casters that can reach the receivers: not one far off */
			for (int k = 0; k < 8; k++) {
				vec3 c = v3_box_corner(f->bmin[id], f->bmax[id], k);
				cmin = fmin(cmin, v3_dot(v3_sub(c, cam->eye), dir));
			}
	double slide = fmax(0, v->near - cmin);
	vec3 eye = v3_sub(cam->eye, v3_scale(dir, slide));
	mat4 vv, vp;
	if (!m4_look_at(eye, v3_add(eye, dir), cam->up, &vv) ||
	    !m4_perspective(v->fovy, (double)v->width / v->height, v->near, v->far + slide, &vp)) {
		lx_shadow_warn(out, "psm: no virtual camera; uniform this frame");
		return;
	}
	mat4 pps = m4_mul(&vp, &vv);
	vec4 Lw = f->light.directional ? (vec4){-f->light.direction.x, -f->light.direction.y, -f->light.direction.z, 0}
				       : (vec4){f->light.position.x, f->light.position.y, f->light.position.z, 1};
	vec4 C = m4_mul_v4(&pps, Lw);
	double clen = sqrt(v4_dot(C, C));
	vec4 c = {C.x / clen, C.y / clen, C.z / clen, C.w / clen};
	out->variant = fabs(c.w) < 1e-9 ? LX_PSM_DIRECTIONAL : c.w < 0 ? LX_PSM_INVERTED : LX_PSM_POINT;
	/* receivers: the view frustum in the scene box, in PPS */
	const vec3 *rec = ls.receiver_pts;
	int nrec = ls.receiver_count;
	vec4 centroid = {0, 0, 0, 0};
	vec4 recp[LX_CONVEX_MAX_POINTS];
	for (int i = 0; i < nrec; i++) {
		recp[i] = m4_mul_point(&pps, rec[i]);
		double l = sqrt(v4_dot(recp[i], recp[i]));
		centroid = v4_lin(1, centroid, 1 / l, recp[i]);
	}
	/* the light camera: w along the receivers (an affine camera for a light at infinity),
	 * x and y completing the complement of C */
	vec4 basis[4] = {c};
	vec4 w = out->variant == LX_PSM_DIRECTIONAL ? (vec4){0, 0, 0, 1} : centroid;
	vec4 x = {1, 0, 0, 0}, y = {0, 1, 0, 0}, z = {0, 0, 1, 0};
	if (!orthonormal(&w, basis, 1)) {
		lx_shadow_warn(out, "psm: the light lies on the view's centre line in PPS; uniform this frame");
		return;
	}
	/* w must be positive on every receiver: a hyperplane through C with all of them on one
	 * side (it exists when C lies outside their hull). The centroid's direction usually is
	 * one; otherwise a perceptron walk finds one. */
	if (out->variant != LX_PSM_DIRECTIONAL)
		for (int iter = 0; iter < 200; iter++) {
			int worst = -1;
			double worst_val = 1e-9;
			for (int i = 0; i < nrec; i++) {
				double l = sqrt(v4_dot(recp[i], recp[i]));
				double val = v4_dot(w, recp[i]) / l;
				if (val < worst_val)
					worst = i, worst_val = val;
			}
			if (worst < 0)
				break;
			vec4 u = recp[worst];
			double l = sqrt(v4_dot(u, u));
			u = (vec4){u.x / l, u.y / l, u.z / l, u.w / l};
			w = v4_lin(1, w, 1, u);
			if (!orthonormal(&w, basis, 1))
				break;
		}
	basis[1] = w;
	if (!orthonormal(&x, basis, 2)) { /* x may lie in span(c, w): try the other axes */
		x = z;
		if (!orthonormal(&x, basis, 2)) {
			x = (vec4){0, 0, 0, 1};
			orthonormal(&x, basis, 2);
		}
	}
	basis[2] = x;
	vec4 cand[4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
	for (int i = 0; i < 4; i++) {
		y = cand[i];
		if (orthonormal(&y, basis, 3))
			break;
	}
	vec4 zrow = {-c.x, -c.y, -c.z, -c.w}; /* depth -c.X / w falls towards the light */
	mat4 light = {{0}};
	vec4 rows[4] = {x, y, zrow, w};
	for (int r = 0; r < 4; r++) {
		light.m[0 + r] = rows[r].x, light.m[4 + r] = rows[r].y, light.m[8 + r] = rows[r].z, light.m[12 + r] = rows[r].w;
	}
	mat4 m0 = m4_mul(&light, &pps);
	/* unit cube clipping: receivers' and casters' images intersected; depth from the
	 * casters' nearest to the receivers' farthest */
	double rx0 = INFINITY, rx1 = -INFINITY, ry0 = INFINITY, ry1 = -INFINITY, zfar = -INFINITY, zrec = INFINITY;
	for (int i = 0; i < nrec; i++) {
		vec4 h = m4_mul_point(&m0, rec[i]);
		if (!(h.w > 0)) {
			lx_shadow_warn(out, "psm: receivers lie on both sides of the light in PPS; uniform this frame");
			return;
		}
		rx0 = fmin(rx0, h.x / h.w), rx1 = fmax(rx1, h.x / h.w), ry0 = fmin(ry0, h.y / h.w), ry1 = fmax(ry1, h.y / h.w);
		zfar = fmax(zfar, h.z / h.w);
		zrec = fmin(zrec, h.z / h.w);
	}
	double cx0 = INFINITY, cx1 = -INFINITY, cy0 = INFINITY, cy1 = -INFINITY, znear = INFINITY;
	for (int id = 0; id < f->object_count; id++)
		if (ls.casting >> id & 1) /* casters that can reach the receivers: not one far off */
			for (int k = 0; k < 8; k++) {
				vec3 p = v3_box_corner(f->bmin[id], f->bmax[id], k);
				vec4 h = m4_mul_point(&m0, p);
				if (!(h.w > 1e-12 * (fabs(h.x) + fabs(h.y) + fabs(h.z)))) {
					/* a box reaching the light camera's plane: its image is unbounded and its
					 * depth falls without bound towards the light; the shadow pass
					 * flattens what lies nearer than the near plane onto it */
					cx0 = cy0 = -INFINITY, cx1 = cy1 = INFINITY;
					map->pancake = true;
					continue;
				}
				cx0 = fmin(cx0, h.x / h.w), cx1 = fmax(cx1, h.x / h.w), cy0 = fmin(cy0, h.y / h.w),
				cy1 = fmax(cy1, h.y / h.w), znear = fmin(znear, h.z / h.w);
			}
	double ex0 = fmax(rx0, cx0), ex1 = fmin(rx1, cx1), ey0 = fmax(ry0, cy0), ey1 = fmin(ry1, cy1);
	/* a receiver nearer the light than every caster must still be inside the depth range */
	if (map->pancake)
		znear = fmin(znear, zrec);
	if (!(ex0 < ex1 && ey0 < ey1) || !isfinite(znear) || znear > zfar) {
		map->rendered = false; /* casters and receivers do not overlap from the light */
		return;
	}
	double zpad = (zfar - znear) * 1e-4;
	znear -= zpad, zfar += zpad;
	mat4 crop = m4_crop(ex0, ex1, ey0, ey1, znear, zfar);
	lx_shadow_map_warp(map, f, &crop, &m0, "psm", out);
}

const struct lx_shadow_method lx_method_psm = {.name = "psm",
	.summary = "perspective shadow map (512x512) in a slid-back camera's post-perspective space",
	.build = psm_build};
