/* The coverage check shared by the method tests: every shadow that can fall on a
 * visible receiver is captured. For caster points c (sampled in the casters' shapes) and
 * receiver points r beyond c on the same light ray inside the view frustum and the
 * scene box (on a plane, or on another caster: visible_lit_point), the map that serves r
 * (lx_shadow_select_map for r's object, the shader's choice) holds c
 * on the same lixel with -1 <= depth(c) <= depth(r) <= 1 (a map that declares pancaking
 * clamps depth(c) to -1 as its shadow pass does). With the light at the eye
 * (lx_shadows_hidden) every such r lies behind its c as the eye sees it: no map may be
 * drawn, and no pair is checked (test_reference's hidden_shadows_are_hidden checks that
 * rule against the reference). A plane's receiver no map serves passes where the lit
 * front the renderer tests over it shadows it (coverage_left_to_cover counts those:
 * plane-optimal leaves them to that test), or where another object hides it from the eye
 * (coverage_hidden). Include after test_util.h and method_fixture.h. */
#ifndef LX_SHADOW_COVERAGE_H
#define LX_SHADOW_COVERAGE_H
#include "light_space.h"
#include "plane_cover.h"
#include "plane_optimal.h"
#include "reference.h"
#include "shadow_method.h"

static bool in_receivers(const struct lx_frame *f, vec3 p)
{
	vec4 c = m4_mul_point(&f->view.view_proj, p);
	double e = 1e-9;
	return c.w > 0 && fabs(c.x) <= c.w && fabs(c.y) <= c.w && fabs(c.z) <= c.w && p.x >= f->scene_min.x - e &&
	       p.x <= f->scene_max.x + e && p.y >= f->scene_min.y - e && p.y <= f->scene_max.y + e &&
	       p.z >= f->scene_min.z - e && p.z <= f->scene_max.z + e;
}

/* The point where the ray from c along dir meets plane p's parallelogram beyond c. */
static bool ray_on_plane(const struct lx_plane *P, vec3 c, vec3 dir, vec3 *r)
{
	vec4 e = lx_plane_equation(P);
	double den = e.x * dir.x + e.y * dir.y + e.z * dir.z;
	if (!(fabs(den) > 1e-12))
		return false;
	double t = -(e.x * c.x + e.y * c.y + e.z * c.z + e.w) / den;
	if (!(t > 1e-9))
		return false;
	*r = v3_add(c, v3_scale(dir, t));
	return lx_plane_contains(P, *r);
}

/* Receivers no map serves that the cover test shadows (plane_cover.h: the lit front the
 * renderer tests over their plane lies between them and the light), since the last reset:
 * plane-optimal leaves those to the test. */
static long coverage_left_to_cover;

/* Whether plane receiver r lies in the shadow of a front the renderer tests over its
 * plane, exactly as the shader decides it. */
static bool covered_by_front(const struct lx_plane_covers *cv, int object, vec3 r)
{
	return object < LX_MAX_PLANES && lx_plane_covers_shadow(cv, object, r);
}

/* Plane receivers no map serves that the eye cannot see, since the last reset: the eye's
 * ray to them meets another object's triangle beyond the near plane (the exact
 * reference's ray caster, over the triangles the renderer draws). Plane-optimal's maps
 * leave out what casters hide (method_plane.c, take_hidden). */
static long coverage_hidden;

/* The frame check_coverage checks, and its ray caster (made when first asked). */
static const struct lx_frame *coverage_frame;
static struct lx_raycaster *coverage_rays;

/* Whether receiver r of object `object` is hidden from the eye by another object. */
static bool hidden_from_eye(int object, vec3 r)
{
	const struct lx_view *v = &coverage_frame->view;
	vec3 d = v3_sub(r, v->eye);
	double along = v3_dot(d, v->dir);
	if (!(along > v->near))
		return false; /* not beyond the near plane: the check holds it */
	if (!coverage_rays)
		assert_non_null(coverage_rays = lx_raycaster_create(coverage_frame));
	return lx_raycast_blocked(coverage_rays, v->eye, d, v->near / along, 1 - 1e-9, object);
}

/* Checks the map that serves receiver r of object `object` holds caster point c; a plane
 * receiver in a lit front's shadow may be left to the cover test (cv), one hidden from the
 * eye needs no map. */
static void check_pair(const struct lx_shadow_result *res, const struct lx_plane_covers *cv, int object, vec3 c, vec3 r,
		       const char *what)
{
	int m = lx_shadow_select_map(res, object, r);
	if (m < 0 && cv && covered_by_front(cv, object, r)) {
		coverage_left_to_cover++;
		return;
	}
	if (m < 0 && cv && hidden_from_eye(object, r)) {
		coverage_hidden++;
		return;
	}
	if (m < 0)
		fail_msg("%s: receiver (%g, %g, %g) of object %d behind caster point (%g, %g, %g) is served by no map (%s)",
			 what, r.x, r.y, r.z, object, c.x, c.y, c.z, res->warning_count ? res->warnings[0] : "no warning");
	const mat4 *lc = &res->maps[m].light_clip;
	vec4 pc = m4_mul_point(lc, c), pr = m4_mul_point(lc, r);
	if (!(pc.w > 0 && pr.w > 0))
		fail_msg("%s: map %d: caster or receiver behind the light image", what, m);
	double zc = pc.z / pc.w, zr = pr.z / pr.w;
	if (res->maps[m].pancake)
		zc = fmax(zc, -1); /* the shadow pass flattens it onto the near plane */
	if (!(zc >= -1 - 1e-7 && zr <= 1 + 1e-7 && zc <= zr + 1e-9))
		fail_msg("%s: map %d: depths caster %g, receiver %g (expected -1 <= caster <= receiver <= 1)", what, m, zc, zr);
	assert_near(pc.x / pc.w, pr.x / pr.w, 1e-6); /* same ray, same lixel */
}

/* A round caster's axis point nearest p (a sphere's centre; on a cylinder's or cone's axis
 * at p's height) and the shape's radius there. */
static double round_reach(const struct lx_frame *f, int id, vec3 p, vec3 *axis)
{
	const struct lx_caster *cs = &f->scene->casters[id - f->scene->plane_count];
	vec3 o = f->offset[id];
	*axis = cs->shape == LX_SPHERE ? v3(o.x, o.y + cs->size.x, o.z) : v3(o.x, p.y, o.z);
	return cs->shape == LX_SPHERE ? cs->size.x : caster_radius_at(f, id, p.y);
}

/* A point of caster id's exact shape (its mesh lies inside it), drawn in its box: inside
 * it, or every other one on its surface, where the footprints' outlines are tightest
 * (lx_frame_object_outline). False when 64 draws found none. */
static bool caster_point(const struct lx_frame *f, int id, uint64_t *seed, vec3 *out)
{
	const struct lx_caster *cs = &f->scene->casters[id - f->scene->plane_count];
	bool surface = test_rand(seed) < 0.5;
	for (int tries = 0; tries < 64; tries++) {
		vec3 c = v3(f->bmin[id].x + test_rand(seed) * (f->bmax[id].x - f->bmin[id].x),
			    f->bmin[id].y + test_rand(seed) * (f->bmax[id].y - f->bmin[id].y),
			    f->bmin[id].z + test_rand(seed) * (f->bmax[id].z - f->bmin[id].z));
		if (cs->shape == LX_BOX) {
			*out = c;
			return true;
		}
		vec3 axis;
		double reach = round_reach(f, id, c, &axis);
		vec3 d = v3_sub(c, axis);
		double len = v3_len(d);
		if (!(len <= reach) || !(len > 1e-9))
			continue;
		*out = surface ? v3_add(axis, v3_scale(d, reach / len)) : c;
		return true;
	}
	return false;
}

/* The point of caster id a lookup serves where the ray from c along dir, past c, reaches
 * r in its box: of a round caster, r where it lies in the shape (its box's corners are
 * none of it); of a box wholly beyond the near plane, the point where the ray enters it
 * through a face turned towards the eye (the renderer culls the faces turned away, and a
 * face turned away from the light reads no map); of a box the near plane cuts, whose
 * inner faces show, r. False where there is none: outside the shape, or the entry is
 * hidden or lies before c. */
static bool visible_lit_point(const struct lx_frame *f, int id, vec3 c, vec3 dir, vec3 *r)
{
	if (f->scene->casters[id - f->scene->plane_count].shape != LX_BOX) {
		vec3 axis;
		double reach = round_reach(f, id, *r, &axis);
		return v3_len(v3_sub(*r, axis)) <= reach;
	}
	if (!lx_view_box_beyond_near(&f->view, f->bmin[id], f->bmax[id]))
		return true;
	double lo[3] = {f->bmin[id].x, f->bmin[id].y, f->bmin[id].z}, hi[3] = {f->bmax[id].x, f->bmax[id].y, f->bmax[id].z};
	double o[3] = {c.x, c.y, c.z}, d[3] = {dir.x, dir.y, dir.z}, t_in = -INFINITY;
	int axis = -1;
	for (int a = 0; a < 3; a++) {
		if (!(fabs(d[a]) > 1e-12))
			continue; /* parallel to these faces: it enters through another */
		double t = ((d[a] > 0 ? lo[a] : hi[a]) - o[a]) / d[a];
		if (t > t_in)
			t_in = t, axis = a;
	}
	if (axis < 0 || !(t_in > 1e-9))
		return false;
	vec3 e = v3_add(c, v3_scale(dir, t_in));
	double n[3] = {0, 0, 0};
	n[axis] = d[axis] > 0 ? -1 : 1; /* the entry face's outward normal */
	if (!(v3_dot(v3(n[0], n[1], n[2]), v3_sub(f->view.eye, e)) > 0) || !in_receivers(f, e))
		return false;
	*r = e;
	return true;
}

/* Returns the number of caster/receiver pairs checked; fails the test on the first miss.
 * Receivers are the points of the planes' parallelograms and the other casters' points a
 * lookup serves (visible_lit_point), each looked up in the maps its object reads
 * (lx_shadow_receiver_maps). */
static long check_coverage(const struct lx_frame *f, const struct lx_shadow_result *res, int plane_count,
			   uint64_t *seed, int samples, const char *what)
{
	long checked = 0;
	double size = v3_len(v3_sub(f->scene_max, f->scene_min));
	if (lx_shadows_hidden(f)) {
		for (int m = 0; m < res->map_count; m++)
			if (res->maps[m].rendered)
				fail_msg("%s: the light is at the eye, yet map %d is drawn", what, m);
		return 0;
	}
	struct lx_plane_covers cv;
	lx_plane_covers(f, &cv);
	coverage_frame = f, coverage_rays = NULL;
	for (int id = plane_count; id < f->object_count; id++)
		for (int k = 0; k < samples; k++) {
			vec3 c;
			if (!caster_point(f, id, seed, &c))
				continue;
			vec3 dir = f->light.directional ? f->light.direction : v3_sub(c, f->light.position);
			if (!v3_normalize(dir, &dir))
				continue;
			for (int p = 0; p < plane_count; p++) {
				vec3 r;
				if (ray_on_plane(&f->scene->planes[p], c, dir, &r) && in_receivers(f, r)) {
					check_pair(res, &cv, p, c, r, what);
					checked++;
				}
			}
			for (int j = 1; j <= 40; j++) {
				vec3 r = v3_add(c, v3_scale(dir, size * j / 40.0));
				if (!in_receivers(f, r))
					continue;
				int on = -1; /* the caster whose box holds r: an off-plane receiver */
				for (int o = plane_count; o < f->object_count && on < 0; o++)
					if (r.x >= f->bmin[o].x && r.x <= f->bmax[o].x && r.y >= f->bmin[o].y && r.y <= f->bmax[o].y &&
					    r.z >= f->bmin[o].z && r.z <= f->bmax[o].z)
						on = o;
				/* a caster is convex: it never shadows its own lit faces */
				if (on < 0 || on == id || !visible_lit_point(f, on, c, dir, &r))
					continue;
				check_pair(res, NULL, on, c, r, what);
				checked++;
			}
		}
	lx_raycaster_destroy(coverage_rays);
	coverage_rays = NULL;
	return checked;
}

#endif
