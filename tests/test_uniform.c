#include "configs.h"
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
		} else
			check_coverage(&s.frame, &s.res, s.scene.plane_count, &seed, 40, "random light");
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

/* The texture matrix sends region clip space onto the region's texels. */
static void texture_matrix_lands_in_the_region(void **state)
{
	(void)state;
	struct lx_region_request req[] = {{"a", 100, 50, 0, false}, {"b", 30, 70, 0, false}};
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

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(every_configuration_covers_every_shadow),
		cmocka_unit_test(random_lights),
		cmocka_unit_test(extremes_stay_finite),
		cmocka_unit_test(none_has_no_maps),
		cmocka_unit_test(texture_matrix_lands_in_the_region),
	};
	return cmocka_run_group_tests_name("uniform", tests, NULL, NULL);
}
