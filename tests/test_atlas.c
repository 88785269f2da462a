#include "atlas.h"
#include "test_util.h"
#include <stdio.h>
#include <string.h>

/* Each region, grown by the guard on every side, lies inside the texture and overlaps
 * no other region; budgets are exactly as requested. */
static void check_layout(const struct lx_atlas *a, const struct lx_region_request *req, int n)
{
	assert_int_equal(a->count, n);
	for (int i = 0; i < n; i++) {
		const struct lx_region *r = lx_atlas_find(a, req[i].name);
		assert_non_null(r);
		assert_int_equal(r->w, req[i].w);
		assert_int_equal(r->h, req[i].h);
		assert_true(r->x - a->guard >= 0 && r->y - a->guard >= 0);
		assert_true(r->x + r->w + a->guard <= a->width && r->y + r->h + a->guard <= a->height);
		for (int j = 0; j < a->count; j++) {
			const struct lx_region *o = &a->regions[j];
			if (o == r)
				continue;
			bool apart = r->x + r->w + a->guard <= o->x || o->x + o->w + a->guard <= r->x ||
				     r->y + r->h + a->guard <= o->y || o->y + o->h + a->guard <= r->y;
			if (!apart)
				fail_msg("regions %s and %s overlap or share a guard band", r->name, o->name);
		}
	}
}

static void plane_optimal_layout(void **state)
{
	(void)state;
	struct lx_region_request req[] = {{"floor", 350, 350, 0}, {"wall", 350, 350, 0}, {"fallback", 128, 128, 0}};
	struct lx_atlas a;
	char err[256];
	assert_true(lx_atlas_layout(&a, req, 3, 1, 2048, err, sizeof err));
	check_layout(&a, req, 3);
	assert_int_equal(lx_atlas_lixels(&a), 350 * 350 * 2 + 128 * 128);
	/* the paper's budget is about one 512x512 map */
	assert_true(lx_atlas_lixels(&a) <= 512 * 512);
	print_message("plane-optimal atlas: %dx%d, %ld lixels\n", a.width, a.height, lx_atlas_lixels(&a));
	/* within a small board's 2048 limit and not wasteful: at most 15%% guard and slack */
	assert_true((double)a.width * a.height <= 1.15 * lx_atlas_lixels(&a) + 4 * 1024);
}

static void uniform_layout_has_its_guard(void **state)
{
	(void)state;
	struct lx_region_request req[] = {{"uniform", 512, 512, 0}};
	struct lx_atlas a;
	char err[256];
	assert_true(lx_atlas_layout(&a, req, 1, 1, 2048, err, sizeof err));
	check_layout(&a, req, 1);
	assert_int_equal(a.width, 514);
	assert_int_equal(a.height, 514);
	assert_int_equal(a.regions[0].x, 1);
	assert_int_equal(a.regions[0].y, 1);
}

static void many_regions_and_guards(void **state)
{
	(void)state;
	uint64_t s = 99;
	for (int trial = 0; trial < 500; trial++) {
		struct lx_region_request req[LX_ATLAS_MAX_REGIONS];
		char names[LX_ATLAS_MAX_REGIONS][8];
		int n = 1 + (int)(test_rand(&s) * LX_ATLAS_MAX_REGIONS);
		for (int i = 0; i < n; i++) {
			snprintf(names[i], sizeof names[i], "r%d", i);
			req[i] = (struct lx_region_request){names[i], 1 + (int)(test_rand(&s) * 400), 1 + (int)(test_rand(&s) * 400), 0};
		}
		int guard = (int)(test_rand(&s) * 4);
		struct lx_atlas a;
		char err[256];
		if (lx_atlas_layout(&a, req, n, guard, 2048, err, sizeof err))
			check_layout(&a, req, n);
		else /* only when the regions' area exceeds the texture can it fail */
			assert_true(strstr(err, "do not fit") != NULL);
	}
}

static void size_limits_give_clear_errors(void **state)
{
	(void)state;
	struct lx_atlas a;
	char err[256];
	struct lx_region_request big[] = {{"huge", 2048, 2048, 0}};
	assert_false(lx_atlas_layout(&a, big, 1, 1, 2048, err, sizeof err)); /* the guard does not fit */
	assert_non_null(strstr(err, "huge"));
	assert_non_null(strstr(err, "2048"));
	struct lx_region_request three[] = {{"a", 1100, 1100, 0}, {"b", 1100, 1100, 0}, {"c", 1100, 1100, 0}};
	assert_false(lx_atlas_layout(&a, three, 3, 1, 2048, err, sizeof err));
	assert_non_null(strstr(err, "do not fit"));
	assert_true(lx_atlas_layout(&a, three, 3, 1, 4096, err, sizeof err));
	check_layout(&a, three, 3);
	struct lx_region_request bad[] = {{"zero", 0, 10, 0}};
	assert_false(lx_atlas_layout(&a, bad, 1, 1, 2048, err, sizeof err));
	assert_non_null(strstr(err, "zero"));
	struct lx_region_request dup[] = {{"x", 10, 10, 0}, {"x", 10, 10, 0}};
	assert_false(lx_atlas_layout(&a, dup, 2, 1, 2048, err, sizeof err));
	assert_non_null(strstr(err, "twice"));
	/* no regions (method none): a valid 1x1 texture */
	assert_true(lx_atlas_layout(&a, NULL, 0, 1, 2048, err, sizeof err));
	assert_int_equal(a.width, 1);
	assert_int_equal(lx_atlas_lixels(&a), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(plane_optimal_layout),
		cmocka_unit_test(uniform_layout_has_its_guard),
		cmocka_unit_test(many_regions_and_guards),
		cmocka_unit_test(size_limits_give_clear_errors),
	};
	return cmocka_run_group_tests_name("atlas", tests, NULL, NULL);
}
