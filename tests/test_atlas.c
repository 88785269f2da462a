#include "atlas.h"
#include "test_util.h"
#include <math.h>
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
	struct lx_region_request req[] = {{"floor", 350, 350, 0, false}, {"wall", 350, 350, 0, false}, {"fallback", 128, 128, 0, false}};
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
	struct lx_region_request req[] = {{"uniform", 512, 512, 0, false}};
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
		char names[LX_ATLAS_MAX_REGIONS][16];
		int n = 1 + (int)(test_rand(&s) * LX_ATLAS_MAX_REGIONS);
		for (int i = 0; i < n; i++) {
			snprintf(names[i], sizeof names[i], "r%d", i);
			req[i] = (struct lx_region_request){names[i], 1 + (int)(test_rand(&s) * 400), 1 + (int)(test_rand(&s) * 400), 0, false};
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


/* This frame's regions lie inside the texture, guard bands included, apart from each
 * other; a variable region holds at most its budget, within the longest side. */
static void check_frame(const struct lx_atlas *a, const int *w, const int *h, bool exact)
{
	for (int i = 0; i < a->count; i++) {
		const struct lx_region *r = &a->regions[i];
		if (r->w == 0 && r->h == 0)
			continue;
		if (r->variable) {
			assert_true((long)r->w * r->h <= r->budget);
			assert_true(r->w <= a->max_side && r->h <= a->max_side);
			assert_true(r->w >= r->h); /* laid landscape */
			int ow = r->turned ? r->h : r->w, oh = r->turned ? r->w : r->h;
			if (exact && (ow != w[i] || oh != h[i]))
				fail_msg("region %s: asked %dx%d, placed %dx%d%s", r->name, w[i], h[i], r->w, r->h,
					 r->turned ? " turned" : "");
		}
		assert_true(r->x - a->guard >= 0 && r->y - a->guard >= 0);
		assert_true(r->x + r->w + a->guard <= a->width && r->y + r->h + a->guard <= a->height);
		for (int j = 0; j < a->count; j++) {
			const struct lx_region *o = &a->regions[j];
			if (o == r || (o->w == 0 && o->h == 0))
				continue;
			bool apart = r->x + r->w + a->guard <= o->x || o->x + o->w + a->guard <= r->x ||
				     r->y + r->h + a->guard <= o->y || o->y + o->h + a->guard <= r->y;
			if (!apart)
				fail_msg("regions %s and %s overlap or share a guard band", r->name, o->name);
		}
	}
}

/* The largest w x h of aspect w:h within a budget. */
static void shape(long budget, double aspect, int *w, int *h)
{
	*w = (int)floor(sqrt(budget * aspect));
	*h = (int)floor(*w / aspect);
	if (*h < 1)
		*h = 1;
	while ((long)*w * *h > budget)
		(*w)--;
}

static void plane_budgets_fit_every_aspect(void **state)
{
	(void)state;
	struct lx_region_request req[] = {{"floor", 350, 350, 350 * 350, false}, {"wall", 350, 350, 350 * 350, false}, {"fallback", 128, 128, 0, false}};
	struct lx_atlas start;
	char err[256];
	assert_true(lx_atlas_layout(&start, req, 3, 1, 4096, err, sizeof err));
	print_message("fitted plane-optimal atlas: %dx%d (%.1f lixels per budget lixel)\n", start.width, start.height,
		      (double)start.width * start.height / lx_atlas_lixels(&start));
	assert_true(start.width <= LX_ATLAS_MAX_SIDE && start.height <= LX_ATLAS_MAX_SIDE);
	int w[3], h[3], frames = 0;
	/* every aspect from 1:32 to 32:1 in steps of 2^(1/4) for each map, alone and together */
	for (int a = -20; a <= 20; a++)
		for (int b = -21; b <= 20; b++) {
			struct lx_atlas at = start;
			shape(350 * 350, pow(2, a / 4.0), &w[0], &h[0]);
			if (b == -21)
				w[1] = h[1] = 0; /* the wall not placed this frame */
			else
				shape(350 * 350, pow(2, b / 4.0), &w[1], &h[1]);
			w[2] = h[2] = 128;
			assert_int_equal(lx_atlas_pack(&at, w, h), 0); /* nothing shrunk */
			check_frame(&at, w, h, true);
			/* deterministic: the same sizes give the same places */
			struct lx_atlas again = start;
			lx_atlas_pack(&again, w, h);
			assert_memory_equal(&again, &at, sizeof at);
			frames++;
		}
	/* one lixel wide, empty, one lixel in all */
	struct lx_atlas at = start;
	int thin_w[3] = {1, 350 * 350 > start.max_side ? start.max_side : 1, 0}, thin_h[3] = {1, 1, 0};
	assert_int_equal(lx_atlas_pack(&at, thin_w, thin_h), 0);
	check_frame(&at, thin_w, thin_h, true);
	int none[3] = {0, 0, 0};
	assert_int_equal(lx_atlas_pack(&at, none, none), 0);
	assert_int_equal(at.regions[0].w, 0);
	assert_int_equal(at.regions[2].w, 128); /* a fixed region keeps its size */
	/* asked beyond the budget or the texture: clamped, never overlapping */
	int big_w[3] = {5000, 400, 0}, big_h[3] = {300, 400, 0};
	at = start;
	lx_atlas_pack(&at, big_w, big_h);
	check_frame(&at, big_w, big_h, false);
	print_message("%d frames of aspects packed\n", frames);
}

/* Shared budgets: one map may take both plane budgets, in any aspect. */
static void shared_budgets_fit(void **state)
{
	(void)state;
	long pool = 2L * 350 * 350;
	struct lx_region_request req[] = {{"floor", 350, 350, pool, false}, {"wall", 350, 350, pool, false}, {"fallback", 128, 128, 0, false}};
	struct lx_atlas start;
	char err[256];
	assert_true(lx_atlas_layout(&start, req, 3, 1, 2048, err, sizeof err));
	uint64_t s = 7;
	for (int trial = 0; trial < 2000; trial++) {
		struct lx_atlas at = start;
		double share = test_rand(&s);
		int w[3], h[3];
		shape((long)(pool * share), pow(32, 2 * test_rand(&s) - 1), &w[0], &h[0]);
		shape(pool - (long)(pool * share), pow(32, 2 * test_rand(&s) - 1), &w[1], &h[1]);
		w[2] = h[2] = 128;
		for (int i = 0; i < 2; i++) /* the texture's longest side bounds the most elongated */
			if (w[i] > start.max_side || h[i] > start.max_side)
				w[i] = h[i] = 0;
		assert_int_equal(lx_atlas_pack(&at, w, h), 0);
		check_frame(&at, w, h, true);
	}
}

/* A texture too small for a frame: the regions shrink until they fit, never overlap. */
static void a_frame_that_cannot_fit_shrinks(void **state)
{
	(void)state;
	struct lx_region_request req[] = {{"a", 100, 100, 100 * 100, false}, {"b", 100, 100, 100 * 100, false}};
	struct lx_atlas at;
	char err[256];
	assert_true(lx_atlas_layout(&at, req, 2, 1, 256, err, sizeof err));
	at.height = 60; /* as if the texture were smaller than the bound asks */
	int w[2] = {250, 250}, h[2] = {40, 40};
	assert_true(lx_atlas_pack(&at, w, h) > 0);
	check_frame(&at, w, h, false);
	/* a texture that holds nothing: the packing ends, the regions left unplaced */
	at.height = 2;
	assert_int_equal(lx_atlas_pack(&at, w, h), -1);
	assert_int_equal(at.regions[0].w, 0);
	assert_int_equal(at.regions[1].h, 0);
}

static void size_limits_give_clear_errors(void **state)
{
	(void)state;
	struct lx_atlas a;
	char err[256];
	struct lx_region_request big[] = {{"huge", 2048, 2048, 0, false}};
	assert_false(lx_atlas_layout(&a, big, 1, 1, 2048, err, sizeof err)); /* the guard does not fit */
	assert_non_null(strstr(err, "huge"));
	assert_non_null(strstr(err, "2048"));
	struct lx_region_request three[] = {{"a", 1100, 1100, 0, false}, {"b", 1100, 1100, 0, false}, {"c", 1100, 1100, 0, false}};
	assert_false(lx_atlas_layout(&a, three, 3, 1, 2048, err, sizeof err));
	assert_non_null(strstr(err, "do not fit"));
	assert_true(lx_atlas_layout(&a, three, 3, 1, 4096, err, sizeof err));
	check_layout(&a, three, 3);
	struct lx_region_request bad[] = {{"zero", 0, 10, 0, false}};
	assert_false(lx_atlas_layout(&a, bad, 1, 1, 2048, err, sizeof err));
	assert_non_null(strstr(err, "zero"));
	struct lx_region_request dup[] = {{"x", 10, 10, 0, false}, {"x", 10, 10, 0, false}};
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
		cmocka_unit_test(plane_budgets_fit_every_aspect),
		cmocka_unit_test(shared_budgets_fit),
		cmocka_unit_test(a_frame_that_cannot_fit_shrinks),
	};
	return cmocka_run_group_tests_name("atlas", tests, NULL, NULL);
}
