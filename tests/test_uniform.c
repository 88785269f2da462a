#include "configs.h"
#include "light_space.h"
#include "shadow_method.h"
#include "test_util.h"
#include "method_fixture.h"
#include "shadow_coverage.h"
#include <stdio.h>
#include <string.h>



static void cleanup(struct setup *s) { lx_meshes_free(&s->meshes); }

static void every_configuration_covers_every_shadow(void **state)
{
	(void)state;
	uint64_t seed = 1234;
	for (int i = 0; i < lx_config_count; i++) {
		struct setup s;
		lx_scene_default(&s.scene);
		lx_config_apply(&lx_configs[i], &s.scene);
		assert_true(build(&s, "uniform", 640, 480, 0.4));
		assert_int_equal(s.res.map_count, 1);
		assert_true(m4_finite(&s.res.maps[0].light_clip));
		long n = check_coverage(&s.frame, &s.res, s.scene.plane_count, &seed, 300, lx_configs[i].name);
		print_message("%-12s rendered %d, %ld caster/receiver pairs checked, %d warnings%s%s\n", lx_configs[i].name,
			      s.res.maps[0].rendered, n, s.res.warning_count, s.res.warning_count ? ": " : "",
			      s.res.warning_count ? s.res.warnings[0] : "");
		cleanup(&s);
	}
}

static void random_lights(void **state)
{
	(void)state;
	uint64_t seed = 77;
	int rendered = 0, too_wide = 0;
	for (int i = 0; i < 300; i++) {
		struct setup s;
		lx_scene_default(&s.scene);
		if (i % 3 == 0) {
			vec3 d = v3(test_rand(&seed) * 2 - 1, -0.05 - test_rand(&seed), test_rand(&seed) * 2 - 1);
			s.scene.light = (struct lx_light){.directional = true};
			assert_true(v3_normalize(d, &s.scene.light.direction));
		} else
			s.scene.light = (struct lx_light){
				.position = v3(test_rand(&seed) * 16 - 8, 2.5 + test_rand(&seed) * 8, test_rand(&seed) * 16 - 8)};
		assert_true(build(&s, "uniform", 640, 480, 0.4));
		assert_true(m4_finite(&s.res.maps[0].light_clip));
		/* The documented fallback for a point light among the casters: one frustum
		 * cannot see more than 150 degrees, so coverage is not promised there. */
		bool wide = s.res.warning_count && strstr(s.res.warnings[0], "150 degrees");
		if (wide) {
			print_message("light %d at (%g, %g, %g): %s\n", i, s.scene.light.position.x, s.scene.light.position.y,
				      s.scene.light.position.z, s.res.warnings[0]);
			too_wide++;
		} else {
			char what[160];
			vec3 L = s.scene.light.directional ? s.scene.light.direction : s.scene.light.position;
			snprintf(what, sizeof what, "random light %d (%s %g, %g, %g)", i,
				 s.scene.light.directional ? "direction" : "at", L.x, L.y, L.z);
			check_coverage(&s.frame, &s.res, s.scene.plane_count, &seed, 40, what);
		}
		rendered += s.res.maps[0].rendered;
		cleanup(&s);
	}
	assert_true(rendered > 250);
	assert_true(too_wide <= 15);
}

/* Degenerate and extreme cases: finite matrices, a documented warning, no crash. */
static void extremes_stay_finite(void **state)
{
	(void)state;
	struct {
		const char *what;
		struct lx_light light;
		vec3 eye, at;
		double scale;
		bool expect_warning;
	} cases[] = {
		{"light on the floor plane", {.position = {0, 0, 0}}, {0, 2, 6}, {0, 0.8, 0}, 1, true},
		{"light inside the scene", {.position = {0, 1.0, 0.5}}, {0, 2, 6}, {0, 0.8, 0}, 1, true},
		{"grazing directional light", {.directional = true, .direction = {0, 0, -1}}, {0, 2, 6}, {0, 0.8, 0}, 1, false},
		{"directional light from below", {.directional = true, .direction = {0, 1, 0}}, {0, 2, 6}, {0, 0.8, 0}, 1, false},
		{"camera looking away", {.position = {2.5, 6, 3}}, {0, 2, 6}, {0, 2, 20}, 1, false},
		{"huge scene", {.position = {2.5, 6, 3}}, {0, 2, 6}, {0, 0.8, 0}, 1e4, false},
		{"tiny scene", {.position = {2.5, 6, 3}}, {0, 2, 6}, {0, 0.8, 0}, 1e-4, false},
	};
	uint64_t seed = 5;
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		struct setup s;
		lx_scene_default(&s.scene);
		double k = cases[i].scale;
		for (int p = 0; p < s.scene.plane_count; p++) {
			s.scene.planes[p].corner = v3_scale(s.scene.planes[p].corner, k);
			s.scene.planes[p].edge1 = v3_scale(s.scene.planes[p].edge1, k);
			s.scene.planes[p].edge2 = v3_scale(s.scene.planes[p].edge2, k);
		}
		for (int c = 0; c < s.scene.caster_count; c++) {
			struct lx_caster *ca = &s.scene.casters[c];
			ca->size = v3_scale(ca->size, k), ca->x *= k, ca->z *= k, ca->low *= k, ca->high *= k;
		}
		s.scene.light = cases[i].light;
		s.scene.light.position = v3_scale(s.scene.light.position, k);
		s.scene.camera.eye = v3_scale(cases[i].eye, k);
		s.scene.camera.at = v3_scale(cases[i].at, k);
		assert_true(build(&s, "uniform", 640, 480, 0.4));
		if (!m4_finite(&s.res.maps[0].light_clip))
			fail_msg("%s: non-finite light matrix", cases[i].what);
		long n = check_coverage(&s.frame, &s.res, s.scene.plane_count, &seed, cases[i].expect_warning ? 0 : 200, cases[i].what);
		print_message("%-30s rendered %d, %ld pairs, warnings: %s\n", cases[i].what, s.res.maps[0].rendered, n,
			      s.res.warning_count ? s.res.warnings[0] : "none");
		if (cases[i].expect_warning)
			assert_true(s.res.warning_count > 0);
		cleanup(&s);
	}
}

static void none_has_no_maps(void **state)
{
	(void)state;
	struct setup s;
	lx_scene_default(&s.scene);
	assert_true(build(&s, "none", 640, 480, 0.4));
	assert_int_equal(s.res.map_count, 0);
	assert_int_equal(s.atlas.count, 0);
	cleanup(&s);
}

/* The registry: each method found by its name, and each either builds its maps or warps
 * the uniform map (lx_shadow_method_frame calls one of the two, never both). */
static void registry_methods_build_or_warp(void **state)
{
	(void)state;
	int warping = 0;
	for (int i = 0; i < lx_shadow_method_count(); i++) {
		const struct lx_shadow_method *m = lx_shadow_method_at(i);
		assert_ptr_equal(lx_shadow_method_find(m->name), m);
		if (!m->build == !m->warp)
			fail_msg("method %s gives %s", m->name, m->build ? "both build and warp" : "neither build nor warp");
		warping += m->warp != NULL;
	}
	assert_null(lx_shadow_method_at(lx_shadow_method_count()));
	assert_int_equal(warping, 4); /* psm, lispsm, xpsm, tsm */
}

/* The texture matrix sends region clip space onto the region's texels. */
static void texture_matrix_lands_in_the_region(void **state)
{
	(void)state;
	struct lx_region_request req[] = {{"a", 100, 50, 0, false, 0}, {"b", 30, 70, 0, false, 0}};
	struct lx_atlas a;
	char err[128];
	assert_true(lx_atlas_layout(&a, req, 2, 1, 2048, err, sizeof err));
	mat4 id = m4_identity();
	for (int r = 0; r < 2; r++) {
		mat4 t = lx_shadow_texture_matrix(&a, r, &id);
		vec4 lo = m4_mul_v4(&t, (vec4){-1, -1, -1, 1}), hi = m4_mul_v4(&t, (vec4){1, 1, 1, 1});
		assert_near(lo.x * a.width, a.regions[r].x, 1e-9);
		assert_near(lo.y * a.height, a.regions[r].y, 1e-9);
		assert_near(hi.x * a.width, a.regions[r].x + a.regions[r].w, 1e-9);
		assert_near(hi.y * a.height, a.regions[r].y + a.regions[r].h, 1e-9);
		assert_near(lo.z, 0, 1e-15);
		assert_near(hi.z, 1, 1e-15);
	}
}

/* Every object that casts widens the casters' hull: with 7 planes' back faces lit and
 * 32 casters, the 39 boxes' 312 corners all count. The light space once kept the
 * first 256 and dropped the rest in silence; the last 8 casters stand apart here, so
 * that the hull without them would leave their corners out. */
static void every_casting_corner_counts(void **state)
{
	(void)state;
	char text[8192];
	int n = snprintf(text, sizeof text, "camera eye 0 9 12  at 0 0 0  fov 60\nlight point 0 30 0\n"
					  "plane floor corner -8 0 8 edge1 16 0 0 edge2 0 0 -16\n");
	for (int i = 1; i < LX_MAX_PLANES; i++) /* facing down: their upper, back faces lit */
		n += snprintf(text + n, sizeof text - (size_t)n, "plane shelf%d corner %g %g -3 edge1 0.5 0 0 edge2 0 0 0.5\n",
			      i, -3.0 + 0.6 * i, 0.5 * i);
	for (int i = 0; i < LX_MAX_CASTERS; i++)
		n += snprintf(text + n, sizeof text - (size_t)n, "box size 0.2 0.2 0.2 at %g %g\n",
			      i < LX_MAX_CASTERS - 8 ? -1.5 + 0.1 * i : 5.5, i < LX_MAX_CASTERS - 8 ? 0.0 : 2.0 + 0.3 * (i % 8));
	assert_true(n < (int)sizeof text);
	struct setup s;
	char err[256];
	assert_true(lx_scene_parse(text, "many.scene", &s.scene, err, sizeof err));
	assert_true(build(&s, "uniform", 320, 240, 0));
	struct lx_light_space ls;
	lx_light_space_build(&s.frame, &ls);
	assert_false(ls.empty || ls.casters_unbounded);
	int casting = 0;
	for (int id = 0; id < s.frame.object_count; id++) {
		if (!(ls.casting >> id & 1))
			continue;
		casting++;
		for (int c = 0; c < 8; c++) {
			vec4 q = m4_mul_point(&ls.view, v3_box_corner(s.frame.bmin[id], s.frame.bmax[id], c));
			vec2 g = {q.x / -q.z, q.y / -q.z}; /* in front of the light: the hull is bounded */
			if (!lx_poly_contains(&ls.casters, g, -1e-9 * (1 + fabs(g.x) + fabs(g.y))))
				fail_msg("corner %d of object %d at (%g, %g) lies outside the casters' hull", c, id, g.x, g.y);
		}
	}
	print_message("%d of %d objects cast, every corner inside the casters' hull\n", casting, s.frame.object_count);
	assert_int_equal(casting, LX_MAX_PLANES + LX_MAX_CASTERS - 1); /* all but the floor, lit from above */
	assert_true(8 * casting > 256);
	cleanup(&s);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(every_configuration_covers_every_shadow),
		cmocka_unit_test(random_lights),
		cmocka_unit_test(extremes_stay_finite),
		cmocka_unit_test(none_has_no_maps),
		cmocka_unit_test(registry_methods_build_or_warp),
		cmocka_unit_test(texture_matrix_lands_in_the_region),
		cmocka_unit_test(every_casting_corner_counts),
	};
	return cmocka_run_group_tests_name("uniform", tests, NULL, NULL);
}
