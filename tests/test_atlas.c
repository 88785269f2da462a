#include "atlas.h"
#include "scene.h"
#include "shadow_method.h"
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
	struct lx_region_request req[] = {{"floor", 350, 350, 0, false, 0}, {"wall", 350, 350, 0, false, 0}, {"fallback", 128, 128, 0, false, 0}};
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
	struct lx_region_request req[] = {{"uniform", 512, 512, 0, false, 0}};
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
			req[i] = (struct lx_region_request){names[i], 1 + (int)(test_rand(&s) * 400), 1 + (int)(test_rand(&s) * 400), 0, false, 0};
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
 * other; a variable region holds at most its budget (its limit alone, alone in the
 * frame), within the longest side. */
static void check_frame(const struct lx_atlas *a, const int *w, const int *h, bool exact)
{
	int placed = 0;
	for (int i = 0; i < a->count; i++)
		placed += a->regions[i].w > 0 && a->regions[i].h > 0;
	for (int i = 0; i < a->count; i++) {
		const struct lx_region *r = &a->regions[i];
		if (r->w == 0 && r->h == 0)
			continue;
		if (r->variable) {
			assert_true((long)r->w * r->h <= (placed == 1 && r->alone > 0 ? r->alone : r->budget));
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
	struct lx_region_request req[] = {{"floor", 350, 350, 350 * 350, false, 0}, {"wall", 350, 350, 350 * 350, false, 0}, {"fallback", 128, 128, 0, false, 0}};
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

/* Shared budgets: one map may take both plane budgets, in any aspect, and the fallback,
 * a square, what the plane maps leave (method_plane.c's requests). */
static void shared_budgets_fit(void **state)
{
	(void)state;
	long pool = 2L * 350 * 350;
	struct lx_region_request req[] = {{"floor", 350, 350, pool, false, 0}, {"wall", 350, 350, pool, false, 0},
					  {"fallback", 128, 128, pool + 128 * 128, false, 0}};
	struct lx_atlas start;
	char err[256];
	assert_true(lx_atlas_layout(&start, req, 3, 1, 2048, err, sizeof err));
	uint64_t s = 7;
	for (int trial = 0; trial < 2000; trial++) {
		struct lx_atlas at = start;
		double share = test_rand(&s);
		int w[3], h[3];
		double used = test_rand(&s); /* what the plane maps take of the pool; the fallback the rest */
		shape((long)(pool * share * used), pow(32, 2 * test_rand(&s) - 1), &w[0], &h[0]);
		shape((long)(pool * (1 - share) * used), pow(32, 2 * test_rand(&s) - 1), &w[1], &h[1]);
		w[2] = h[2] = (int)floor(sqrt(128.0 * 128 + pool * (1 - used)));
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
	struct lx_region_request req[] = {{"a", 100, 100, 100 * 100, false, 0}, {"b", 100, 100, 100 * 100, false, 0}};
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

/* A variable region with a limit alone (plane-optimal's fallback with fixed budgets)
 * takes up to it only in a frame where no other region is placed, else its budget; the
 * layout lowers the limit to the square that fits the area alone, never growing the
 * atlas for it; a limit on a fixed region, or below zero, is refused. */
static void alone_takes_more(void **state)
{
	(void)state;
	char err[256];
	struct lx_region_request req[] = {{"a", 100, 100, 100 * 100, false, 0}, {"b", 50, 50, 50 * 50, false, 0}};
	struct lx_atlas plain, at;
	assert_true(lx_atlas_layout(&plain, req, 2, 1, 2048, err, sizeof err));
	req[1].alone_lixels = 100000000; /* more than any texture holds */
	assert_true(lx_atlas_layout(&at, req, 2, 1, 2048, err, sizeof err));
	assert_int_equal(at.width, plain.width);
	assert_int_equal(at.height, plain.height);
	long side = (at.width < at.height ? at.width : at.height) - 2;
	assert_int_equal(at.regions[1].alone, side * side);
	int w[2] = {0, 4000}, h[2] = {0, 4000};
	assert_int_equal(lx_atlas_pack(&at, w, h), 0); /* alone: as large as fits */
	assert_int_equal(at.regions[1].w, side);
	assert_int_equal(at.regions[1].h, side);
	check_frame(&at, w, h, false);
	w[0] = h[0] = 10; /* with another: its budget */
	assert_int_equal(lx_atlas_pack(&at, w, h), 0);
	assert_true((long)at.regions[1].w * at.regions[1].h <= 50 * 50);
	check_frame(&at, w, h, false);
	req[1].alone_lixels = 60 * 60; /* a limit that fits is kept */
	assert_true(lx_atlas_layout(&at, req, 2, 1, 2048, err, sizeof err));
	assert_int_equal(at.regions[1].alone, 60 * 60);
	w[0] = h[0] = 0;
	assert_int_equal(lx_atlas_pack(&at, w, h), 0);
	assert_true((long)at.regions[1].w * at.regions[1].h <= 60 * 60 && at.regions[1].w * at.regions[1].h > 50 * 50);
	struct lx_region_request fixed[] = {{"f", 10, 10, 0, false, 400}}, negative[] = {{"n", 10, 10, 100, false, -1}};
	assert_false(lx_atlas_layout(&at, fixed, 1, 1, 2048, err, sizeof err));
	assert_non_null(strstr(err, "'f'"));
	assert_false(lx_atlas_layout(&at, negative, 1, 1, 2048, err, sizeof err));
	assert_non_null(strstr(err, "'n'"));
}

static void size_limits_give_clear_errors(void **state)
{
	(void)state;
	struct lx_atlas a;
	char err[256];
	struct lx_region_request big[] = {{"huge", 2048, 2048, 0, false, 0}};
	assert_false(lx_atlas_layout(&a, big, 1, 1, 2048, err, sizeof err)); /* the guard does not fit */
	assert_non_null(strstr(err, "huge"));
	assert_non_null(strstr(err, "2048"));
	struct lx_region_request three[] = {{"a", 1100, 1100, 0, false, 0}, {"b", 1100, 1100, 0, false, 0}, {"c", 1100, 1100, 0, false, 0}};
	assert_false(lx_atlas_layout(&a, three, 3, 1, 2048, err, sizeof err));
	assert_non_null(strstr(err, "do not fit"));
	assert_true(lx_atlas_layout(&a, three, 3, 1, 4096, err, sizeof err));
	check_layout(&a, three, 3);
	struct lx_region_request bad[] = {{"zero", 0, 10, 0, false, 0}};
	assert_false(lx_atlas_layout(&a, bad, 1, 1, 2048, err, sizeof err));
	assert_non_null(strstr(err, "zero"));
	struct lx_region_request dup[] = {{"x", 10, 10, 0, false, 0}, {"x", 10, 10, 0, false, 0}};
	assert_false(lx_atlas_layout(&a, dup, 2, 1, 2048, err, sizeof err));
	assert_non_null(strstr(err, "twice"));
	/* no regions (method none): a valid 1x1 texture */
	assert_true(lx_atlas_layout(&a, NULL, 0, 1, 2048, err, sizeof err));
	assert_int_equal(a.width, 1);
	assert_int_equal(lx_atlas_lixels(&a), 0);
}

/* Stacking: several lights' atlases (parts) in one texture. */

enum part_kind { PART_PLANE, PART_UNIFORM, PART_KINDS };

/* A light's atlas as the method lays it out for the default scene (floor and wall), with
 * method_run's guard and the given options. */
static void method_part(const char *method, const struct lx_method_options *o, struct lx_atlas *a)
{
	struct lx_scene s;
	lx_scene_default(&s);
	struct lx_region_request req[LX_MAX_MAPS];
	const struct lx_shadow_method *m = lx_shadow_method_find(method);
	assert_non_null(m);
	int n = lx_shadow_method_regions(m, &s, o, req);
	char err[256];
	if (!lx_atlas_layout(a, req, n, 1, 2048, err, sizeof err))
		fail_msg("%s", err);
}

/* With the default options: plane-optimal's variable floor and wall budgets of 350^2, its
 * 128^2 fallback (all three budgets when alone) and its four borrowed spare pieces;
 * uniform's 512^2. */
static void real_part(enum part_kind kind, struct lx_atlas *a)
{
	method_part(kind == PART_PLANE ? "plane" : "uniform", &LX_METHOD_OPTIONS_DEFAULT, a);
	if (kind == PART_PLANE) { /* the shapes named in the design: what the parts below stand for */
		assert_int_equal(a->count, 7);
		assert_true(a->regions[0].variable && a->regions[0].budget == 350 * 350);
		assert_true(a->regions[1].variable && a->regions[1].budget == 350 * 350);
		/* the fallback: 128^2 at start, up to a plane's budget in a frame with a plane
		 * without a map, and in a frame without a plane map every lixel of the three */
		assert_true(a->regions[2].variable && a->regions[2].budget == 350 * 350 && a->regions[2].w == 128 &&
			    a->regions[2].h == 128 && a->regions[2].alone == 2 * 350 * 350 + 128 * 128);
		for (int r = 3; r < 7; r++)
			assert_true(a->regions[r].variable && a->regions[r].counted == 0);
	} else {
		assert_int_equal(a->count, 1);
		assert_true(!a->regions[0].variable && a->regions[0].w == 512 && a->regions[0].h == 512);
	}
}

/* Plane-optimal's own regions (real_part): each plane map cut into up to four pieces, of
 * the four spare regions, its budget shared among them in any shares and aspects from
 * 1:32 to 32:1; or, in a third of the frames, the wall without a map, the floor holding
 * up to both budgets in pieces of at most one each, and the fallback what the floor
 * leaves of the wall's, up to 350x350 (fallback_side); every frame packs without
 * shrinking anything, apart and in the texture. */
static void plane_pieces_fit(void **state)
{
	(void)state;
	struct lx_atlas start;
	real_part(PART_PLANE, &start);
	uint64_t s = 11;
	int frames = 0, most = 0;
	for (int trial = 0; trial < 3000; trial++) {
		struct lx_atlas at = start;
		int w[7] = {0}, h[7] = {0}, spare = 4, pieces = 0;
		bool mapless = trial % 3 == 2; /* the wall */
		double borrowed = mapless ? test_rand(&s) : 0; /* of the wall's budget, by the floor */
		w[2] = h[2] = 128;
		if (mapless) { /* what the floor leaves, as far as the one-map density asks */
			double side = sqrt(128.0 * 128 + 350.0 * 350 * (1 - borrowed)) * (0.3 + 0.7 * test_rand(&s));
			w[2] = h[2] = side < 128 ? 128 : side > 350 ? 350 : (int)side;
		}
		for (int p = 0; p < (mapless ? 1 : 2); p++) {
			int n = 1 + (int)(test_rand(&s) * (1 + (spare < 3 ? spare : 3)));
			double share[4], total = 0, used = (0.5 + 0.5 * test_rand(&s)) * (1 + borrowed); /* of the budget */
			if (used > 1 && n < 2)
				n = 2; /* a region holds one budget at most: more is cut into a spare piece */
			for (int k = 0; k < n; k++)
				total += share[k] = 0.05 + test_rand(&s);
			for (int k = 0; k < n && used > 1; k++) /* each piece within one budget */
				share[k] = fmin(share[k], total / used);
			for (int k = 0; k < n; k++) {
				int r = k == 0 ? p : 3 + pieces++;
				shape((long)(350.0 * 350 * used * share[k] / total), pow(32, 2 * test_rand(&s) - 1), &w[r], &h[r]);
				if (w[r] > start.max_side || h[r] > start.max_side) /* the fit keeps within the side */
					w[r] = h[r] = 0;
			}
			spare -= n - 1;
		}
		most = pieces > most ? pieces : most;
		assert_int_equal(lx_atlas_pack(&at, w, h), 0);
		check_frame(&at, w, h, true);
		frames++;
	}
	print_message("%d frames packed, up to %d spare pieces in one\n", frames, most);
	assert_int_equal(most, 4);
}

/* The parts lie inside the texture and apart; each region, grown by its guard, inside its
 * own part (so inside the texture) and apart from every region of every part. */
static void check_stack(struct lx_atlas *const *parts, int n)
{
	int tw = parts[0]->texture_width, th = parts[0]->texture_height;
	for (int i = 0; i < n; i++) {
		const struct lx_atlas *a = parts[i];
		assert_int_equal(a->texture_width, tw);
		assert_int_equal(a->texture_height, th);
		assert_true(a->x0 >= 0 && a->y0 >= 0 && a->x0 + a->width <= tw && a->y0 + a->height <= th);
		for (int j = 0; j < i; j++) {
			const struct lx_atlas *b = parts[j];
			if (!(a->x0 + a->width <= b->x0 || b->x0 + b->width <= a->x0 || a->y0 + a->height <= b->y0 ||
			      b->y0 + b->height <= a->y0))
				fail_msg("parts %d and %d overlap", j, i);
		}
		for (int r = 0; r < a->count; r++) {
			const struct lx_region *g = &a->regions[r];
			if (g->w == 0 && g->h == 0)
				continue;
			int gd = a->guard;
			if (g->x - gd < a->x0 || g->y - gd < a->y0 || g->x + g->w + gd > a->x0 + a->width ||
			    g->y + g->h + gd > a->y0 + a->height)
				fail_msg("part %d: region %s %dx%d at (%d, %d) leaves its part %dx%d at (%d, %d)", i,
					 g->name, g->w, g->h, g->x, g->y, a->width, a->height, a->x0, a->y0);
			for (int j = 0; j <= i; j++)
				for (int q = 0; q < parts[j]->count; q++) {
					const struct lx_region *o = &parts[j]->regions[q];
					if ((j == i && q == r) || (o->w == 0 && o->h == 0))
						continue;
					int og = parts[j]->guard;
					bool apart = g->x + g->w + gd + og <= o->x || o->x + o->w + og + gd <= g->x ||
						     g->y + g->h + gd + og <= o->y || o->y + o->h + og + gd <= g->y;
					if (j != i && !apart) /* across parts, both guard rings must be free */
						fail_msg("region %s of part %d and %s of part %d overlap", g->name, i,
							 o->name, j);
					if (j == i && !(g->x + g->w + gd <= o->x || o->x + o->w + gd <= g->x ||
							g->y + g->h + gd <= o->y || o->y + o->h + gd <= g->y))
						fail_msg("regions %s and %s of part %d overlap", g->name, o->name, i);
				}
		}
	}
}

/* One part alone: stacking leaves a fresh layout exactly as it is; a part that had been
 * stacked elsewhere goes back to the origin with its regions. */
static void one_part_stays_alone(void **state)
{
	(void)state;
	char err[256];
	for (int k = 0; k < PART_KINDS; k++) {
		struct lx_atlas a, fresh, other;
		real_part(k, &a);
		assert_int_equal(a.x0, 0);
		assert_int_equal(a.y0, 0);
		assert_int_equal(a.texture_width, a.width);
		assert_int_equal(a.texture_height, a.height);
		fresh = a;
		struct lx_atlas *one[] = {&a};
		assert_true(lx_atlas_stack(one, 1, 2048, err, sizeof err));
		assert_memory_equal(&a, &fresh, sizeof a);
		real_part(k, &other); /* the same size, first: a goes second */
		struct lx_atlas *two[] = {&other, &a};
		assert_true(lx_atlas_stack(two, 2, 2048, err, sizeof err));
		assert_true(a.x0 > 0 || a.y0 > 0); /* else this says nothing about going back */
		assert_true(lx_atlas_stack(one, 1, 2048, err, sizeof err));
		assert_memory_equal(&a, &fresh, sizeof a);
	}
}

/* A few lixels per frame: the aspect 2^(a/4) of a budget, as plane_budgets_fit_every_aspect. */
static void part_frame(const struct lx_atlas *a, int ea, int eb, int *w, int *h)
{
	for (int r = 0; r < a->count; r++) {
		w[r] = a->regions[r].w, h[r] = a->regions[r].h;
		if (a->regions[r].variable && a->regions[r].counted == 0)
			w[r] = h[r] = 0; /* the borrowed piece: its lixels are the others' */
		else if (a->regions[r].variable)
			shape(a->regions[r].budget, pow(2, (r ? eb : ea) / 4.0), &w[r], &h[r]);
	}
}

/* Frames in aspects 1:32 to 32:1 packed in every stacked part: each packing, deterministic
 * and nothing shrunk, is the one the part has alone (`alone`) moved by its origin, and
 * leaves the stack apart (check_stack). Returns the frames packed. */
static int pack_stacked_frames(const struct lx_atlas *alone, struct lx_atlas *const *parts, int n)
{
	int frames = 0;
	for (int ea = -20; ea <= 20; ea += 5)
		for (int eb = -20; eb <= 20; eb += 5) {
			for (int i = 0; i < n; i++) {
				struct lx_atlas *a = parts[i];
				int w[LX_ATLAS_MAX_REGIONS], h[LX_ATLAS_MAX_REGIONS];
				part_frame(a, ea + i, eb - i, w, h);
				assert_int_equal(lx_atlas_pack(a, w, h), 0);
				struct lx_atlas again = *a, lone = alone[i];
				assert_int_equal(lx_atlas_pack(&again, w, h), 0);
				assert_memory_equal(&again, a, sizeof again);
				assert_int_equal(lx_atlas_pack(&lone, w, h), 0);
				for (int r = 0; r < lone.count; r++) { /* unplaced ones too: at the origin */
					const struct lx_region *p = &a->regions[r], *l = &lone.regions[r];
					assert_true(p->w == l->w && p->h == l->h && p->turned == l->turned);
					assert_int_equal(p->x, l->x + a->x0);
					assert_int_equal(p->y, l->y + a->y0);
				}
			}
			check_stack(parts, n);
			frames++;
		}
	return frames;
}

/* Every mix of 1 to 4 plane-optimal and uniform parts that can share a 2048 texture does,
 * and every frame's packing stays in its own part and apart from the other parts' regions. */
static void stacked_parts_pack_apart(void **state)
{
	(void)state;
	char err[512];
	int stacks = 0, frames = 0;
	for (int n = 1; n <= LX_ATLAS_MAX_PARTS; n++)
		for (unsigned mix = 0; mix < 1u << n; mix++) {
			struct lx_atlas alone[LX_ATLAS_MAX_PARTS], part[LX_ATLAS_MAX_PARTS], *parts[LX_ATLAS_MAX_PARTS];
			int planes = 0;
			for (int i = 0; i < n; i++) {
				real_part(mix >> i & 1 ? PART_PLANE : PART_UNIFORM, &alone[i]);
				planes += mix >> i & 1;
				part[i] = alone[i];
				parts[i] = &part[i];
			}
			/* a plane part is wider than half of 2048, so parts cannot sit beside it: each
			 * takes a band of its height; three of them leave no room for a fourth part */
			bool fits = !(n == 4 && planes >= 3);
			if (!fits) {
				assert_false(lx_atlas_stack(parts, n, 2048, err, sizeof err));
				continue;
			}
			if (!lx_atlas_stack(parts, n, 2048, err, sizeof err))
				fail_msg("%d parts, %d plane-optimal: %s", n, planes, err);
			check_stack(parts, n);
			assert_true(part[0].texture_width <= 2048 && part[0].texture_height <= 2048);
			stacks++;
			frames += pack_stacked_frames(alone, parts, n);
		}
	print_message("%d stacks, %d frames of each stack's parts packed\n", stacks, frames);
	assert_int_equal(stacks, 30 - 5); /* 2 + 4 + 8 + 16 mixes, 5 of them with 3 or 4 plane parts of 4 */
}

/* Smaller plane-optimal budgets (160^2 maps, a 64^2 fallback) make parts narrow enough to
 * sit beside another: two of them in a column beside a fixed part as tall, so their
 * frames pack from origins off both axes. */
static void variable_parts_side_by_side(void **state)
{
	(void)state;
	char err[512];
	struct lx_method_options o = LX_METHOD_OPTIONS_DEFAULT;
	o.plane_lixels = 160, o.fallback_lixels = 64;
	struct lx_atlas alone[3], part[3], *parts[3];
	method_part("plane", &o, &alone[1]);
	method_part("plane", &o, &alone[2]);
	assert_int_equal(alone[1].width, 908);
	assert_int_equal(alone[1].height, 300);
	struct lx_region_request wide[] = {{"wide", 998, 598, 0, false, 0}}; /* 1000 x twice 300 */
	assert_true(lx_atlas_layout(&alone[0], wide, 1, 1, 2048, err, sizeof err));
	for (int i = 0; i < 3; i++) {
		part[i] = alone[i];
		parts[i] = &part[i];
	}
	assert_true(lx_atlas_stack(parts, 3, 2048, err, sizeof err));
	/* 1908x600 turned beats the best shelves, all in a column 1000x1200 */
	assert_int_equal(part[0].texture_width, 1908);
	assert_int_equal(part[0].texture_height, 600);
	assert_true(part[0].x0 == 0 && part[0].y0 == 0);
	assert_true(part[1].x0 == 1000 && part[1].y0 == 0 && part[2].x0 == 1000 && part[2].y0 == 300);
	check_stack(parts, 3);
	assert_int_equal(pack_stacked_frames(alone, parts, 3), 81);
}

/* The arrangement: the smallest texture, then the squarest, then the first tried (a row). */
static void stack_arrangements(void **state)
{
	(void)state;
	char err[512];
	struct lx_atlas u[4], pl[2];
	for (int i = 0; i < 4; i++)
		real_part(PART_UNIFORM, &u[i]);
	struct lx_atlas *pair[] = {&u[0], &u[1]};
	assert_true(lx_atlas_stack(pair, 2, 2048, err, sizeof err));
	/* a row and a column tie: the narrowest shelves are tried first, a column wins */
	assert_int_equal(u[0].texture_width, 514);
	assert_int_equal(u[0].texture_height, 1028);
	assert_true(u[0].x0 == 0 && u[0].y0 == 0 && u[1].x0 == 0 && u[1].y0 == 514);
	assert_int_equal(u[1].regions[0].x, 1);
	assert_int_equal(u[1].regions[0].y, 514 + 1);
	struct lx_atlas *four[] = {&u[0], &u[1], &u[2], &u[3]};
	assert_true(lx_atlas_stack(four, 4, 2048, err, sizeof err));
	assert_int_equal(u[0].texture_width, 1028); /* two shelves of two: square */
	assert_int_equal(u[0].texture_height, 1028);
	check_stack(four, 4);
	/* four 514 parts in at most 600 a side: no arrangement, nothing moved */
	struct lx_atlas kept = u[3];
	assert_false(lx_atlas_stack(four, 4, 600, err, sizeof err));
	assert_memory_equal(&u[3], &kept, sizeof kept);
	real_part(PART_PLANE, &pl[0]);
	real_part(PART_PLANE, &pl[1]);
	print_message("plane-optimal part %dx%d, uniform part %dx%d\n", pl[0].width, pl[0].height, u[0].width,
		      u[0].height);
	struct lx_atlas *mixed[] = {&u[0], &pl[0], &u[1], &pl[1]};
	assert_true(lx_atlas_stack(mixed, 4, 2048, err, sizeof err));
	check_stack(mixed, 4);
	int tw = u[0].texture_width, th = u[0].texture_height;
	/* no worse than all in a column (the widest part's width) */
	assert_true((long)tw * th <= (long)pl[0].width * (2 * pl[0].height + 2 * u[0].height));
	assert_true((long)tw * th >= 2L * pl[0].width * pl[0].height + 2L * u[0].width * u[0].height);
	/* deterministic: the same sizes, the same places */
	struct lx_atlas again[4] = {u[0], pl[0], u[1], pl[1]};
	struct lx_atlas *mixed2[] = {&again[0], &again[1], &again[2], &again[3]};
	assert_true(lx_atlas_stack(mixed2, 4, 2048, err, sizeof err));
	for (int i = 0; i < 4; i++)
		assert_memory_equal(mixed2[i], mixed[i], sizeof again[i]);
	/* tall parts: columns side by side beat one row or one column */
	struct lx_region_request tall[] = {{"t", 98, 998, 0, false, 0}};
	struct lx_atlas t[3];
	for (int i = 0; i < 3; i++)
		assert_true(lx_atlas_layout(&t[i], tall, 1, 1, 4096, err, sizeof err));
	struct lx_atlas *three[] = {&t[0], &t[1], &t[2]};
	assert_true(lx_atlas_stack(three, 3, 4096, err, sizeof err));
	assert_int_equal(t[0].texture_width, 300);
	assert_int_equal(t[0].texture_height, 1000);
	check_stack(three, 3);
	/* one tall part and two half as tall: the best shelves give 100x2000, the turned
	 * packing (a column of the two beside the tall one) the squarer 200x1000 */
	struct lx_region_request half[] = {{"h", 98, 498, 0, false, 0}};
	assert_true(lx_atlas_layout(&t[1], half, 1, 1, 4096, err, sizeof err));
	assert_true(lx_atlas_layout(&t[2], half, 1, 1, 4096, err, sizeof err));
	assert_true(lx_atlas_stack(three, 3, 4096, err, sizeof err));
	assert_int_equal(t[0].texture_width, 200);
	assert_int_equal(t[0].texture_height, 1000);
	assert_true(t[0].x0 == 0 && t[1].x0 == 100 && t[2].x0 == 100 && t[1].y0 + t[2].y0 == 500);
	check_stack(three, 3);
	/* 1000x200, 500x1000, 1000x500: no prefix of widths makes a shelf as wide as the widest
	 * part (turned, 1000 tall); that shelf stacks the two wide parts beside the tall one */
	struct lx_region_request sizes[3][1] = {{{"a", 998, 198, 0, false, 0}}, {{"b", 498, 998, 0, false, 0}},
						 {{"c", 998, 498, 0, false, 0}}};
	for (int i = 0; i < 3; i++)
		assert_true(lx_atlas_layout(&t[i], sizes[i], 1, 1, 4096, err, sizeof err));
	assert_true(lx_atlas_stack(three, 3, 4096, err, sizeof err));
	assert_int_equal(t[0].texture_width, 1500);
	assert_int_equal(t[0].texture_height, 1000);
	assert_true(t[0].x0 == 0 && t[0].y0 == 0 && t[2].x0 == 0 && t[2].y0 == 200 && t[1].x0 == 1000 && t[1].y0 == 0);
	check_stack(three, 3);
}

/* Region clip space lands on the region's texels in the shared texture. */
static void stacked_texture_matrix(void **state)
{
	(void)state;
	char err[256];
	struct lx_atlas u, p;
	real_part(PART_UNIFORM, &u);
	real_part(PART_PLANE, &p);
	struct lx_atlas *two[] = {&u, &p};
	assert_true(lx_atlas_stack(two, 2, 2048, err, sizeof err));
	assert_true(u.texture_width != u.width || u.texture_height != u.height);
	mat4 id = m4_identity();
	for (int k = 0; k < 2; k++)
		for (int r = 0; r < two[k]->count; r++) {
			const struct lx_atlas *a = two[k];
			const struct lx_region *g = &a->regions[r];
			mat4 t = lx_shadow_texture_matrix(a, r, &id);
			vec4 lo = m4_mul_v4(&t, (vec4){-1, -1, -1, 1}), hi = m4_mul_v4(&t, (vec4){1, 1, 1, 1});
			assert_near(lo.x * a->texture_width, g->x, 1e-9);
			assert_near(lo.y * a->texture_height, g->y, 1e-9);
			assert_near(hi.x * a->texture_width, g->x + g->w, 1e-9);
			assert_near(hi.y * a->texture_height, g->y + g->h, 1e-9);
		}
}

/* Parts that cannot share a texture: false, a reason naming their sizes and the limit,
 * the parts as they were. */
static void stack_that_cannot_fit_fails(void **state)
{
	(void)state;
	char err[512];
	struct lx_region_request big[] = {{"big", 1998, 1998, 0, false, 0}};
	struct lx_atlas b[4], before[4];
	struct lx_atlas *parts[] = {&b[0], &b[1], &b[2], &b[3]};
	for (int i = 0; i < 4; i++) {
		assert_true(lx_atlas_layout(&b[i], big, 1, 1, 2048, err, sizeof err));
		assert_int_equal(b[i].width, 2000);
	}
	memcpy(before, b, sizeof b);
	err[0] = 0;
	assert_false(lx_atlas_stack(parts, 4, 2048, err, sizeof err));
	print_message("%s\n", err);
	assert_non_null(strstr(err, "2000x2000, 2000x2000, 2000x2000, 2000x2000"));
	assert_non_null(strstr(err, "2048"));
	assert_null(strchr(err, '\n'));
	assert_memory_equal(b, before, sizeof b);
	/* a short buffer: cut, still a string */
	char small[24];
	assert_false(lx_atlas_stack(parts, 4, 2048, small, sizeof small));
	assert_int_equal(strlen(small), sizeof small - 1);
	/* the GL's limit holds fixed parts... */
	assert_true(lx_atlas_stack(parts, 4, 4096, err, sizeof err));
	assert_int_equal(b[0].texture_width, 4000);
	check_stack(parts, 4);
	/* ...but variable ones keep to LX_ATLAS_MAX_SIDE whatever the GL allows */
	struct lx_atlas p[4], pbefore[4];
	struct lx_atlas *planes[] = {&p[0], &p[1], &p[2], &p[3]};
	for (int i = 0; i < 4; i++)
		real_part(PART_PLANE, &p[i]);
	memcpy(pbefore, p, sizeof p);
	assert_false(lx_atlas_stack(planes, 4, 8192, err, sizeof err));
	assert_non_null(strstr(err, "2048"));
	assert_memory_equal(p, pbefore, sizeof p);
	assert_true(lx_atlas_stack(planes, 3, 8192, err, sizeof err));
	assert_true(p[0].texture_width <= LX_ATLAS_MAX_SIDE && p[0].texture_height <= LX_ATLAS_MAX_SIDE);
}

/* Out-of-range counts and parts that are not laid out: errors, nothing moved. */
static void stack_bad_requests(void **state)
{
	(void)state;
	char err[256];
	struct lx_atlas u[5], before[5], zero = {0};
	for (int i = 0; i < 5; i++)
		real_part(PART_UNIFORM, &u[i]);
	memcpy(before, u, sizeof u);
	struct lx_atlas *five[] = {&u[0], &u[1], &u[2], &u[3], &u[4]};
	err[0] = 0;
	assert_false(lx_atlas_stack(five, 0, 2048, err, sizeof err));
	assert_non_null(strstr(err, "expected 1 to 4"));
	err[0] = 0;
	assert_false(lx_atlas_stack(five, 5, 8192, err, sizeof err));
	assert_non_null(strstr(err, "expected 1 to 4"));
	assert_false(lx_atlas_stack(five, -1, 2048, err, sizeof err));
	assert_false(lx_atlas_stack(NULL, 1, 2048, err, sizeof err));
	assert_false(lx_atlas_stack(five, 2, 0, err, sizeof err));
	struct lx_atlas *twice[] = {&u[0], &u[1], &u[0]};
	err[0] = 0;
	assert_false(lx_atlas_stack(twice, 3, 2048, err, sizeof err));
	assert_non_null(strstr(err, "again"));
	struct lx_atlas *unset[] = {&u[0], &zero};
	err[0] = 0;
	assert_false(lx_atlas_stack(unset, 2, 2048, err, sizeof err));
	assert_non_null(strstr(err, "not laid out"));
	struct lx_atlas *gap[] = {&u[0], NULL};
	assert_false(lx_atlas_stack(gap, 2, 2048, err, sizeof err));
	assert_memory_equal(u, before, sizeof u);
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
		cmocka_unit_test(plane_pieces_fit),
		cmocka_unit_test(a_frame_that_cannot_fit_shrinks),
		cmocka_unit_test(alone_takes_more),
		cmocka_unit_test(one_part_stays_alone),
		cmocka_unit_test(stacked_parts_pack_apart),
		cmocka_unit_test(variable_parts_side_by_side),
		cmocka_unit_test(stack_arrangements),
		cmocka_unit_test(stacked_texture_matrix),
		cmocka_unit_test(stack_that_cannot_fit_fails),
		cmocka_unit_test(stack_bad_requests),
	};
	return cmocka_run_group_tests_name("atlas", tests, NULL, NULL);
}
