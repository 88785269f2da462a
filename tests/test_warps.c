/* The warping methods (PSM, LiSPSM, XPSM, TSM): LiSPSM's 1-D error oracle, its
 * parameter's pitfalls and fade to uniform, TSM's 80% rule, PSM's three kinds of light in
 * post-perspective space, XPSM's degenerate cases, depth range and sampling near the
 * viewer, and for each the coverage of every shadow over the standard and random
 * configurations. GL-free. */
#include "configs.h"
#include "light_space.h"
#include "method_lispsm.h"
#include "metrics.h"
#include "shadow_method.h"
#include "test_util.h"
#include "method_fixture.h"
#include "shadow_coverage.h"
#include <stdio.h>
#include <string.h>

/* The 1-D model of sampling error ([LiSPSM], section on the optimal n): a directional light perpendicular to the view,
 * view depths z in [z_n, z_f]. A pixel at depth z covers a length proportional to z; a
 * lixel covers 1 / (N du/dz). The worst m, max over z of 1 / (z du/dz), is (z_f - z_n) / z_n
 * for a uniform map and (z_f - z_n) / sqrt(z_n z_f) with LiSPSM's n_opt: 99 against 9.9
 * for z_n = 1, z_f = 100. */
static void one_dimensional_oracle(void **state)
{
	(void)state;
	const double zn = 1, zf = 100, d = zf - zn;
	double n = lx_lispsm_n(zn, d, 1.0);
	assert_near(n, zn + sqrt(zn * zf), 1e-12); /* n_opt in the perpendicular case */
	double worst_uniform = 0, worst_lispsm = 0;
	for (int i = 0; i <= 100000; i++) {
		double z = zn + d * i / 100000.0, h = 1e-6 * z;
		double du_uniform = 1.0 / d;
		/* warp coordinate in [-1, 1] along the view; u = (warp + 1) / 2 */
		double du_lispsm = (lx_lispsm_warp(z - zn + n + h, n, d) - lx_lispsm_warp(z - zn + n - h, n, d)) / (4 * h);
		worst_uniform = fmax(worst_uniform, 1 / (z * du_uniform));
		worst_lispsm = fmax(worst_lispsm, 1 / (z * du_lispsm));
	}
	print_message("1-D model: worst m uniform %.3f, LiSPSM %.3f (expected 99 and 9.9)\n", worst_uniform, worst_lispsm);
	assert_near(worst_uniform, 99, 1e-9);
	assert_near(worst_lispsm, (zf - zn) / sqrt(zn * zf), 0.01);
}

static void parameter_pitfalls(void **state)
{
	(void)state;
	/* a flat body (d = 0) gives a finite n and a finite warp */
	double n = lx_lispsm_n(0.5, 0, 0.7);
	assert_true(isfinite(n) && n > 0);
	assert_true(isfinite(lx_lispsm_warp(n, n, 0)));
	/* n grows without bound as the view turns parallel to the light: the warp fades */
	assert_true(lx_lispsm_n(0.5, 10, LX_LISPSM_MIN_SIN_GAMMA) > 10 * lx_lispsm_n(0.5, 10, 1));
	assert_true(lx_lispsm_n(0.5, 10, 1e-6) > 1e5);
	/* the warp maps the body's ends to -1 and 1 */
	assert_near(lx_lispsm_warp(3, 3, 7), -1, 1e-12);
	assert_near(lx_lispsm_warp(10, 3, 7), 1, 1e-12);
}


/* A directional light along the view: no warp, the uniform map exactly. */
static void parallel_view_and_light_is_uniform(void **state)
{
	(void)state;
	struct setup a, b;
	memset(&a, 0, sizeof a);
	lx_scene_default(&a.scene);
	a.scene.light.directional = true;
	assert_true(v3_normalize(v3_sub(a.scene.camera.at, a.scene.camera.eye), &a.scene.light.direction));
	b = a;
	assert_true(build(&a, "lispsm", 320, 240, 0.3));
	assert_true(build(&b, "uniform", 320, 240, 0.3));
	assert_true(a.res.maps[0].rendered);
	assert_memory_equal(&a.res.maps[0].light_clip, &b.res.maps[0].light_clip, sizeof(mat4));
	lx_meshes_free(&a.meshes);
	lx_meshes_free(&b.meshes);
}

static void covered(const char *method)
{
	uint64_t seed = 31;
	long pairs = 0;
	int warped = 0;
	for (int k = 0; k < 200; k++) {
		struct setup s, u;
		memset(&s, 0, sizeof s);
		lx_scene_default(&s.scene);
		if (k < lx_config_count)
			lx_config_apply(&lx_configs[k], &s.scene);
		else
			test_random_view(&s.scene, &seed, k % 3 == 0, 0.05);
		u = s;
		assert_true(build(&s, method, 320, 240, 0.3));
		assert_true(build(&u, "uniform", 320, 240, 0.3));
		assert_true(m4_finite(&s.res.maps[0].light_clip));
		bool wide = s.res.warning_count && strstr(s.res.warnings[0], "150 degrees");
		char what[64];
		snprintf(what, sizeof what, "%s configuration %d", method, k);
		if (!wide)
			pairs += check_coverage(&s.frame, &s.res, s.scene.plane_count, &seed, 40, what);
		warped += memcmp(&s.res.maps[0].light_clip, &u.res.maps[0].light_clip, sizeof(mat4)) != 0;
		lx_meshes_free(&s.meshes);
		lx_meshes_free(&u.meshes);
	}
	print_message("%s: %ld caster/receiver pairs covered; %d of 200 maps warped\n", method, pairs, warped);
	assert_true(pairs > 10000 && warped > 100);
}

static void lispsm_covers_every_shadow(void **state)
{
	(void)state;
	covered("lispsm");
}

static void psm_covers_every_shadow(void **state)
{
	(void)state;
	covered("psm");
}

/* PSM: a point light in front of the viewer, an inverted light behind it, and a
 * directional light orthogonal to the view (directional in PPS too) each take their
 * branch and still cover every shadow. */
static void psm_branches(void **state)
{
	(void)state;
	struct {
		const char *what;
		vec3 eye, at;
		bool directional;
		vec3 light;
		int variant;
	} cases[] = {
		{"point light in front", {0, 2, 6}, {0, 0.8, 0}, false, {2.5, 6, 3}, LX_PSM_POINT},
		{"light behind the viewer", {0, 2, 6}, {0, 0.8, 0}, false, {0.8, 4, 8.5}, LX_PSM_INVERTED},
		{"directional, orthogonal to the view", {0, 1, 4.5}, {0, 1, -5}, true, {0, -1, 0}, LX_PSM_DIRECTIONAL},
		/* a light travelling along the view comes from behind the viewer: inverted */
		{"directional, from behind", {0, 2, 6}, {0, 0.8, 0}, true, {0.1, -0.5, -1}, LX_PSM_INVERTED},
		{"directional, from the front", {0, 2, 6}, {0, 0.8, 0}, true, {0.1, -0.5, 1}, LX_PSM_POINT},
	};
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		struct setup s;
		memset(&s, 0, sizeof s);
		lx_scene_default(&s.scene);
		s.scene.camera.eye = cases[i].eye;
		s.scene.camera.at = cases[i].at;
		s.scene.light.directional = cases[i].directional;
		if (cases[i].directional)
			assert_true(v3_normalize(cases[i].light, &s.scene.light.direction));
		else
			s.scene.light.position = cases[i].light;
		assert_true(build(&s, "psm", 320, 240, 0.3));
		uint64_t seed = i + 7;
		long n = check_coverage(&s.frame, &s.res, s.scene.plane_count, &seed, 400, cases[i].what);
		print_message("%-40s variant %d, %ld pairs, %s\n", cases[i].what, s.res.variant, n,
			      s.res.warning_count ? s.res.warnings[0] : "no warning");
		assert_int_equal(s.res.variant, cases[i].variant);
		assert_int_equal(s.res.warning_count, 0);
		assert_true(n > 500);
		lx_meshes_free(&s.meshes);
	}
}

static void tsm_covers_every_shadow(void **state)
{
	(void)state;
	covered("tsm");
}

static void xpsm_covers_every_shadow(void **state)
{
	(void)state;
	covered("xpsm");
}

/* One of the scenes the XPSM tests use: the default scene under configuration k (past
 * the standard ones, a random eye and light), or the table lit from below, where the
 * floor is the caster of every shadow. */
static void xpsm_scene(struct setup *s, int k, uint64_t *seed)
{
	memset(s, 0, sizeof *s);
	lx_scene_default(&s->scene);
	if (k < lx_config_count)
		lx_config_apply(&lx_configs[k], &s->scene);
	else if (k == lx_config_count) {
		assert_true(lx_scene_builtin("table", &s->scene));
		s->scene.light.directional = true;
		assert_true(v3_normalize(v3(0.44, 0.888, -0.131), &s->scene.light.direction));
	} else {
		s->scene.camera.eye = v3(test_rand(seed) * 10 - 5, 0.3 + test_rand(seed) * 5, test_rand(seed) * 10 - 3);
		s->scene.camera.at = v3(test_rand(seed) * 4 - 2, test_rand(seed) * 1.5, test_rand(seed) * 4 - 3);
		s->scene.light.directional = k % 2;
		if (k % 2)
			assert_true(v3_normalize(v3(test_rand(seed) - 0.5, 2 * test_rand(seed) - 1, test_rand(seed) - 0.5),
						 &s->scene.light.direction));
		else
			s->scene.light.position = v3(test_rand(seed) * 12 - 6, 3.5 + test_rand(seed) * 5, test_rand(seed) * 12 - 4);
	}
}

/* The shadow pass flattens a caster vertex nearer than a one-map method's near plane onto
 * it, which bends the depth of a long triangle's part in the map: XPSM keeps every
 * caster that can reach the receivers within its depth range and in front of its w = 0
 * plane (w >= eps_w), so no vertex of their meshes is flattened. Its first version clipped casters where
 * w < 1 and kept their x, y only: a floor lit from below (the table scene here) lost
 * every shadow it cast on the table, 1.04% of the pixels. */
static void xpsm_flattens_no_caster(void **state)
{
	(void)state;
	uint64_t seed = 77;
	int warped = 0;
	for (int k = 0; k < 120; k++) {
		struct setup s;
		xpsm_scene(&s, k, &seed);
		assert_true(build(&s, "xpsm", 320, 240, k == lx_config_count ? 7.353 : 0.3));
		const struct lx_shadow_map *map = &s.res.maps[0];
		assert_true(m4_finite(&map->light_clip));
		if (s.res.warning_count || !map->rendered) { /* the uniform map stands, or no map */
			lx_meshes_free(&s.meshes);
			continue;
		}
		struct lx_light_space ls;
		lx_light_space_build(&s.frame, &ls);
		for (int id = 0; id < s.frame.object_count; id++) {
			const struct lx_mesh *mesh = &s.meshes.mesh[id];
			for (int c = 0; (ls.casting >> id & 1) && c < mesh->vertex_count; c++) {
				const float *v = mesh->v + (size_t)c * LX_VERTEX_FLOATS;
				vec4 q = m4_mul_point(&map->light_clip, v3_add(v3(v[0], v[1], v[2]), s.frame.offset[id]));
				if (!(q.w > 0 && q.z >= -q.w * (1 + 1e-9)))
					fail_msg("configuration %d: vertex %d of object %d at clip depth %g, w %g: the shadow pass would flatten it",
						 k, c, id, q.z / q.w, q.w);
			}
		}
		warped++;
		lx_meshes_free(&s.meshes);
	}
	print_message("xpsm: %d of 120 maps warped, no caster nearer than the near plane\n", warped);
	assert_true(warped > 60);
}

/* Where the warp means nothing XPSM keeps the uniform map, finite, and says so. */
static void xpsm_degenerate_cases_warn(void **state)
{
	(void)state;
	const struct {
		const char *what;
		vec3 eye, at;
		int light; /* 0: point at v, 1: directional along v, 2: point at the eye + v */
		vec3 v;
		const char *warning;
	} cases[] = {
		{"directional light along the view (behind the viewer)", {0, 2, 6}, {0, 0.8, 0}, 1, {0, -1.2, -6},
		 "the view runs along the light's rays (within 1.1 degrees, the light behind"},
		{"directional light against the view (dueling frusta)", {0, 2, 6}, {0, 0.8, 0}, 1, {0, 1.2, 6},
		 "the light facing the viewer"},
		/* 1 cm above the eye: at the eye no map is drawn at all (lx_shadows_hidden) */
		{"miner's lamp: the point light 1 cm above the eye", {0, 2, 6}, {0, 0.8, 0}, 2, {0, 0.01, 0},
		 "runs along the light's rays"},
		{"the point light on the floor", {0, 2, 6}, {0, 0.8, 0}, 0, {0.5, 0, 1}, "lies within 0.02 m of plane floor"},
		{"a point light 1e-9 m above the floor", {0, 2, 6}, {0, 0.8, 0}, 0, {0.5, 1e-9, 1}, "lies within 0.02 m of plane floor"},
		{"the point light inside the box", {0, 2, 6}, {0, 0.8, 0}, 0, {1.4, 1.0, -0.6}, "behind the point light"},
		{"the view starts behind the point light", {2.26, 3.03, 6.66}, {1.12, 0.29, -2.46}, 0, {1.3, 3.98, 2.87},
		 "the view starts behind the point light"},
	};
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		struct setup s, u;
		memset(&s, 0, sizeof s);
		lx_scene_default(&s.scene);
		s.scene.camera.eye = cases[i].eye, s.scene.camera.at = cases[i].at;
		s.scene.light.directional = cases[i].light == 1;
		if (cases[i].light == 1)
			assert_true(v3_normalize(cases[i].v, &s.scene.light.direction));
		else
			s.scene.light.position = cases[i].light == 2 ? v3_add(cases[i].eye, cases[i].v) : cases[i].v;
		u = s;
		assert_true(build(&s, "xpsm", 320, 240, 0.3));
		assert_true(build(&u, "uniform", 320, 240, 0.3));
		const char *said = "";
		for (int w = 0; w < s.res.warning_count; w++)
			if (!strncmp(s.res.warnings[w], "xpsm: ", 6))
				said = s.res.warnings[w];
		print_message("%-52s %s\n", cases[i].what, said);
		if (!strstr(said, cases[i].warning))
			fail_msg("%s: expected the warning '%s'", cases[i].what, cases[i].warning);
		assert_true(s.res.maps[0].rendered && m4_finite(&s.res.maps[0].light_clip));
		assert_memory_equal(&s.res.maps[0].light_clip, &u.res.maps[0].light_clip, sizeof(mat4));
		lx_meshes_free(&s.meshes);
		lx_meshes_free(&u.meshes);
	}
}

/* Lixels per pixel (lpp) at window pixel (x, y) of plane p, through map 0. */
static double lpp_at(const struct setup *s, int p, int x, int y)
{
	mat3 h;
	double smax, smin;
	vec3 q;
	assert_true(lx_pixel_on_plane(&s->frame, p, x, y, &q));
	assert_true(lx_plane_homography(&s->frame, &s->atlas, &s->res.maps[0], p, &h));
	assert_true(lx_homography_jacobian(&h, x + 0.5, y + 0.5, &smax, &smin));
	return smax * smin;
}

/* XPSM's warp on the default view: the floor nearest the viewer (the bottom of the
 * window) gets more lixels per pixel than from the uniform map, the far floor fewer,
 * and the floor's worst lixel spans fewer pixels (m_max). */
static void xpsm_samples_more_near_the_viewer(void **state)
{
	(void)state;
	enum { w = 640, h = 480 };
	const char *names[2] = {"uniform", "xpsm"};
	double near[2], far[2], m_max[2];
	for (int k = 0; k < 2; k++) {
		struct setup s;
		memset(&s, 0, sizeof s);
		lx_scene_default(&s.scene);
		assert_true(build(&s, names[k], w, h, 0.3));
		assert_int_equal(s.res.warning_count, 0);
		int top = 0; /* the floor's farthest row in the window's centre column */
		for (int y = 0; y < h; y++)
			if (lx_pixel_on_plane(&s.frame, 0, w / 2, y, &(vec3){0, 0, 0}))
				top = y;
		near[k] = lpp_at(&s, 0, w / 2, 0), far[k] = lpp_at(&s, 0, w / 2, top);
		struct lx_plane_sampling ps;
		assert_true(lx_plane_sampling(&s.frame, &s.atlas, &s.res, 0, NULL, NULL, NULL, &ps));
		m_max[k] = ps.m_max;
		print_message("%-8s floor: lpp %.3f nearest the viewer, %.3f at its far end (row %d); m_max %.3f\n", names[k],
			      near[k], far[k], top, m_max[k]);
		lx_meshes_free(&s.meshes);
	}
	assert_true(near[1] > 1.5 * near[0]);
	assert_true(far[1] < far[0]);
	assert_true(m_max[1] < m_max[0]);
}

/* TSM's 80% rule: the focus point (the view's centre at half its depth) lands on the
 * map's 80% line: 80% of the map lies between the trapezoid's top (y = -1) and it. */
static void tsm_focus_on_the_80_percent_line(void **state)
{
	(void)state;
	struct setup s;
	memset(&s, 0, sizeof s);
	lx_scene_default(&s.scene);
	s.scene.light.directional = true;
	assert_true(v3_normalize(v3(0.2, -1, -0.1), &s.scene.light.direction));
	assert_true(build(&s, "tsm", 320, 240, 0.3));
	const struct lx_view *v = &s.frame.view;
	vec3 dir = v3(0, 0, 0);
	assert_true(v3_normalize(v3_sub(s.scene.camera.at, s.scene.camera.eye), &dir));
	vec4 top = m4_mul_point(&s.res.maps[0].light_clip, v3_add(v->eye, v3_scale(dir, v->near)));
	vec4 focus = m4_mul_point(&s.res.maps[0].light_clip, v3_add(v->eye, v3_scale(dir, v->near + 0.5 * (v->far - v->near))));
	print_message("near centre at y %.4f, focus at y %.4f\n", top.y / top.w, focus.y / focus.w);
	assert_near(focus.y / focus.w, 0.6, 1e-6);
	lx_meshes_free(&s.meshes);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(one_dimensional_oracle),
		cmocka_unit_test(parameter_pitfalls),
		cmocka_unit_test(parallel_view_and_light_is_uniform),
		cmocka_unit_test(lispsm_covers_every_shadow),
		cmocka_unit_test(tsm_covers_every_shadow),
		cmocka_unit_test(psm_covers_every_shadow),
		cmocka_unit_test(psm_branches),
		cmocka_unit_test(tsm_focus_on_the_80_percent_line),
		cmocka_unit_test(xpsm_covers_every_shadow),
		cmocka_unit_test(xpsm_flattens_no_caster),
		cmocka_unit_test(xpsm_degenerate_cases_warn),
		cmocka_unit_test(xpsm_samples_more_near_the_viewer),
	};
	return cmocka_run_group_tests_name("warps", tests, NULL, NULL);
}
