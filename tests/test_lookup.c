/* Where the main pass looks a map up (lookup_region.c), GL-free: the spans cut a window
 * into pieces that cover it once, every point a caster shadows is inside a lookup span,
 * a plane's pieces cover it once, the maps left to a caster are the ones its points
 * read, the parts of a caster called out of reach of every shadow are, and the shadow
 * pass leaves a caster out of a map only where no lookup reads it, and where a plane is
 * drawn without one as surely shadowed (sure_shadow.c), a caster does shadow it; spans
 * merged into taller rectangles (span_merge.c) keep their pixels. Over the standard
 * configurations of both built-in scenes and some extremes. */
#include "configs.h"
#include "lookup_region.h"
#include "plane_cover.h"
#include "plane_optimal.h"
#include "shadow_filter.h"
#include "span_merge.h"
#include "sure_shadow.h"
#include "test_util.h"
#include "method_fixture.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { W = 160, H = 120 };
/* every method of the registry with maps (none has no lookup to check) */
#define FOR_METHODS(m) \
	for (int m##_i = 0; m##_i < lx_shadow_method_count(); m##_i++) \
		for (const char *m = lx_shadow_method_at(m##_i)->name; m && strcmp(m, "none"); m = NULL)

/* Coverage of the window by the spans: each pixel once. Returns the lookup pixels. */
static long check_partition(const struct lx_span *s, int n, struct lx_rect within, uint8_t *hit)
{
	memset(hit, 0, (size_t)W * H);
	long looked = 0;
	for (int i = 0; i < n; i++) {
		assert_true(s[i].box.x0 >= within.x0 && s[i].box.x1 <= within.x1 && s[i].box.x0 < s[i].box.x1);
		assert_true(s[i].box.y0 >= within.y0 && s[i].box.y1 <= within.y1 && s[i].box.y0 < s[i].box.y1);
		for (int y = s[i].box.y0; y < s[i].box.y1; y++)
			for (int x = s[i].box.x0; x < s[i].box.x1; x++) {
				assert_int_equal(hit[y * W + x], 0);
				hit[y * W + x] = s[i].lookup ? 2 : 1;
				looked += s[i].lookup;
			}
	}
	for (int y = within.y0; y < within.y1; y++)
		for (int x = within.x0; x < within.x1; x++)
			assert_int_not_equal(hit[y * W + x], 0);
	return looked;
}

/* Whether the segment from p towards the light (to the light, or on for a directional
 * one) meets caster c: its sphere, or its box (for a cylinder or cone, a first cut). */
static bool caster_box_shadows(const struct lx_frame *f, int c, vec3 p)
{
	const struct lx_light *l = &f->light;
	vec3 d = l->directional ? v3_scale(l->direction, -1) : v3_sub(l->position, p);
	double tmax = l->directional ? 1e9 : 1;
	const struct lx_caster *cs = &f->scene->casters[c - f->scene->plane_count];
	if (cs->shape == LX_SPHERE) {
		vec3 centre = v3_add(f->offset[c], v3(0, cs->size.x, 0)), o = v3_sub(p, centre);
		double a = v3_dot(d, d), b = v3_dot(o, d), cc = v3_dot(o, o) - cs->size.x * cs->size.x;
		double disc = b * b - a * cc;
		if (disc < 0)
			return false;
		double t1 = (-b + sqrt(disc)) / a, t0 = (-b - sqrt(disc)) / a;
		return t1 > 1e-9 && t0 < tmax;
	}
	double t0 = 1e-9, t1 = tmax, o[3] = {p.x, p.y, p.z}, dd[3] = {d.x, d.y, d.z};
	double lo[3] = {f->bmin[c].x, f->bmin[c].y, f->bmin[c].z}, hi[3] = {f->bmax[c].x, f->bmax[c].y, f->bmax[c].z};
	for (int k = 0; k < 3; k++) {
		if (dd[k] == 0) {
			if (o[k] < lo[k] || o[k] > hi[k])
				return false;
			continue;
		}
		double a = (lo[k] - o[k]) / dd[k], b = (hi[k] - o[k]) / dd[k];
		t0 = fmax(t0, fmin(a, b)), t1 = fmin(t1, fmax(a, b));
	}
	return t0 <= t1;
}

/* How far q lies outside cylinder or cone id, across its axis (<= 0: within its radius
 * at q's height). */
static double round_gap(const struct lx_frame *f, int id, vec3 q)
{
	vec3 o = f->offset[id];
	return hypot(q.x - o.x, q.z - o.z) - caster_radius_at(f, id, q.y);
}

/* Whether the segment from p towards the light meets caster c's exact shape (its mesh
 * lies inside it): the sphere and the box as caster_box_shadows; a cylinder or cone
 * where the gap across its axis, convex along the segment, falls to 0 between its
 * bottom and top (the least gap found by ternary search). */
static bool caster_shadows(const struct lx_frame *f, int c, vec3 p)
{
	const struct lx_caster *cs = &f->scene->casters[c - f->scene->plane_count];
	bool box = caster_box_shadows(f, c, p);
	if (!box || cs->shape == LX_SPHERE || cs->shape == LX_BOX)
		return box;
	const struct lx_light *l = &f->light;
	vec3 d = l->directional ? v3_scale(l->direction, -1) : v3_sub(l->position, p), o = f->offset[c];
	double lo = 1e-9, hi = l->directional ? 1e9 : 1, y0 = o.y, y1 = o.y + cs->size.y;
	if (d.y != 0) {
		double a = (y0 - p.y) / d.y, b = (y1 - p.y) / d.y;
		lo = fmax(lo, fmin(a, b)), hi = fmin(hi, fmax(a, b));
	} else if (p.y < y0 || p.y > y1)
		return false;
	if (!(lo <= hi))
		return false;
	for (int i = 0; i < 200; i++) {
		double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
		if (round_gap(f, c, v3_add(p, v3_scale(d, m1))) < round_gap(f, c, v3_add(p, v3_scale(d, m2))))
			hi = m2;
		else
			lo = m1;
	}
	return round_gap(f, c, v3_add(p, v3_scale(d, 0.5 * (lo + hi)))) <= 1e-9;
}

/* What check_scene counted. */
struct tally {
	long checked, looked; /* shadowed plane pixels checked; pixels looked up */
	long fronts;          /* of those checked, shadowed by a flat box in no map: its fronts' tests */
	long yes, no;         /* receivers lx_lookup_any says a shadow can fall on, and not */
	long long_thin;       /* casters' volumes bounded along their images' long axes too */
	long sixteen;         /* casters' volumes bounded in sixteen directions */
};

/* lx_lookup_any stops at the first face of a receiver that meets a caster's volume; it
 * must answer as the whole computation does: a receiver it says no shadow can fall on
 * gets no lookup span, and one it says may be shadowed gets one, in a window that holds
 * every hull (here eight screens wide). */
static void check_lookup_any(const struct lx_lookup_volumes *v, const struct setup *s, const char *what,
			     struct lx_span *span, int room, struct tally *t)
{
	struct lx_rect wide = {-8 * W, -8 * H, 9 * W, 9 * H};
	for (int id = 0; id < s->frame.object_count; id++) {
		unsigned mask = lx_shadow_receiver_maps(&s->res, id);
		if (!mask)
			continue;
		int n = lx_lookup_spans(v, id, mask, wide, span, room);
		assert_true(n >= 1);
		bool looked = false;
		for (int i = 0; i < n; i++)
			looked |= span[i].lookup;
		bool any = lx_lookup_any(v, id, mask);
		if (any != looked)
			fail_msg("%s, object %d: lx_lookup_any says %d, the spans %d", what, id, any, looked);
		t->yes += any, t->no += !any;
	}
}

/* Every plane pixel whose point a caster shadows, and which a map of the plane serves,
 * lies in a lookup span, or, where that caster is a flat box in no map
 * (lx_shadow_result.slab_out), in its fronts' tests' shadow; the spans partition the window; lx_lookup_any agrees with the
 * spans (check_lookup_any). */
static void check_scene(struct setup *s, const char *what, struct tally *tally)
{
	uint8_t *hit = malloc((size_t)W * H);
	assert_non_null(hit);
	struct lx_rect screen = {0, 0, W, H};
	static struct lx_span span[4096];
	static struct lx_lookup_volumes v;
	lx_lookup_prepare(&s->frame, &s->atlas, &s->res, LX_LOOKUP_MARGIN_HIGHP, &v);
	for (int m = 0; m < s->res.map_count; m++)
		for (int c = 0; c < s->frame.object_count; c++) {
			/* an octagon's eight planes (a caster's 16-gon's sixteen), depth, light, eye */
			bool caster = c >= s->scene.plane_count;
			tally->long_thin += v.count[m][c] > (caster ? 19 : 11);
			tally->sixteen += caster && v.count[m][c] > 11;
		}
	for (int id = 0; id < s->scene.plane_count; id++) {
		unsigned mask = lx_shadow_receiver_maps(&s->res, id);
		if (!mask)
			continue;
		int n = lx_lookup_spans(&v, id, mask, screen, span, 4096);
		assert_true(n >= 1);
		tally->looked += check_partition(span, n, screen, hit);
		for (int k = 0; k < n; k++) /* a lookup span ends on whole blocks, or where the screen does */
			if (span[k].lookup && ((span[k].box.x0 % LX_SPAN_ALIGN && span[k].box.x0 != screen.x0) ||
					       (span[k].box.x1 % LX_SPAN_ALIGN && span[k].box.x1 != screen.x1)))
				fail_msg("%s: plane %d's lookup span [%d, %d) ends inside a block", what, id, span[k].box.x0,
					 span[k].box.x1);
		vec4 pe = lx_plane_equation(&s->scene.planes[id]);
		for (int y = 0; y < H; y++)
			for (int x = 0; x < W; x++) {
				vec3 q;
				double t;
				if (!lx_window_on_plane(&s->frame.view, pe, x + 0.5, y + 0.5, &q, &t) ||
				    !lx_plane_contains(&s->scene.planes[id], q) || lx_shadow_select_map(&s->res, id, q) < 0)
					continue;
				for (int c = s->scene.plane_count; c < s->frame.object_count; c++)
					if (caster_shadows(&s->frame, c, q)) {
						/* a flat box in no map: its fronts' tests shadow the pixel instead */
						bool fronts = s->res.slab_out[c] && lx_plane_covers_shadow(&s->res.covers, id, q);
						if (s->res.slab_out[c] && !fronts)
							fail_msg("%s: plane %d pixel (%d, %d) is shadowed by object %d, in no map, "
								 "but not by its fronts' tests", what, id, x, y, c);
						if (!fronts && hit[y * W + x] != 2)
							fail_msg("%s: plane %d pixel (%d, %d) is shadowed by object %d but not looked up",
								 what, id, x, y, c);
						tally->checked++, tally->fronts += fronts;
						break;
					}
			}
	}
	free(hit);
	check_lookup_any(&v, s, what, span, 4096, tally);
}

/* fn on every method with maps over both built-in scenes and every standard
 * configuration, set up at W x H at time 0.4; `what` names the three. */
static void each_standard_setup(void (*fn)(struct setup *s, const char *what, void *ctx), void *ctx)
{
	for (const char *const *sn = (const char *const[]){"default", "table", NULL}; *sn; sn++)
		FOR_METHODS(method)
			for (int c = 0; c < lx_config_count; c++) {
				struct setup s;
				assert_true(lx_scene_builtin(*sn, &s.scene));
				lx_config_apply(&lx_configs[c], &s.scene);
				if (!build(&s, method, W, H, 0.4))
					continue;
				char what[96];
				snprintf(what, sizeof what, "%s scene, %s, %s", *sn, lx_configs[c].name, method);
				fn(&s, what, ctx);
				lx_meshes_free(&s.meshes);
			}
}

static void check_scene_tally(struct setup *s, const char *what, void *tally) { check_scene(s, what, tally); }

static void shadowed_points_are_looked_up(void **state)
{
	(void)state;
	struct tally t = {0};
	each_standard_setup(check_scene_tally, &t);
	print_message("%ld shadowed plane pixels, every one inside a lookup span or, %ld of them, shadowed by a flat box "
		      "in no map and by its fronts' tests; %ld pixels looked up in all\n", t.checked, t.fronts, t.looked);
	print_message("%ld receivers a shadow can fall on, %ld none can, alike by lx_lookup_any and the spans; %ld "
		      "casters' volumes bounded along a long image's axes as well, %ld casters' in sixteen "
		      "directions\n", t.yes, t.no, t.long_thin, t.sixteen);
	assert_true(t.checked > 10000 && t.fronts > 1000); /* there were shadows to check, the slab's among them */
	assert_true(t.long_thin > 10 && t.sixteen > 100);
	/* the casters' 16-gons: with their octagons, 570,688 pixels looked up; with the
	 * 16-gons 555,712; a box's volume ended at its lit faces too, 519,232 */
	assert_true(t.looked < 530000);
	assert_true(t.yes > 100 && t.no > 10);
}

static long assert_unread(const struct setup *s, const struct lx_lookup_volumes *v, int id, int m, const char *what,
			  long *unlit);

/* The extremes, on the default scene: the eye a millimetre above the floor, the light
 * inside a caster, on the floor, under it, far away, and a directional light along the
 * floor (light: its direction then). */
static const struct {
	const char *name;
	vec3 eye, at, light;
	bool directional;
} extremes[] = {
	{"eye 1 mm above the floor", {0.5, 0.001, 3.5}, {0, 0.5, -3}, {1, 4, 2}, false},
	{"light inside the sphere", {0, 2.5, 6}, {0, 0.5, 0}, {-1.2, 0.6, 0.4}, false},
	{"light on the floor", {0, 2.5, 6}, {0, 0.5, 0}, {2, 0, 1}, false},
	{"light under the floor", {0, 2.5, 6}, {0, 0.5, 0}, {0, -2, 0}, false},
	{"light far away", {0, 2.5, 6}, {0, 0.5, 0}, {1e6, 2e6, 1e6}, false},
	{"directional light along the floor", {0, 2.5, 6}, {0, 0.5, 0}, {1, -0.01, 0.2}, true},
};
enum { EXTREMES = sizeof extremes / sizeof extremes[0] };

/* Extreme k set up for `method` into s, its name in what; false where the method makes
 * no frame of it. */
static bool build_extreme(struct setup *s, size_t k, const char *method, char *what, size_t len)
{
	lx_scene_default(&s->scene);
	s->scene.camera.eye = extremes[k].eye, s->scene.camera.at = extremes[k].at;
	s->scene.light = (struct lx_light){.directional = extremes[k].directional, .position = extremes[k].light,
					   .direction = v3(0, -1, 0)};
	if (extremes[k].directional)
		v3_normalize(extremes[k].light, &s->scene.light.direction);
	snprintf(what, len, "%s, %s", extremes[k].name, method);
	return build(s, method, W, H, 0.0);
}

/* At the extremes each receiver is still a partition with every shadowed pixel in it,
 * and every caster the shadow pass leaves out of a map unread there. */
static void extremes_stay_conservative(void **state)
{
	(void)state;
	struct tally t = {0};
	long left_out = 0, unread_points = 0, unlit = 0;
	for (size_t k = 0; k < EXTREMES; k++)
		FOR_METHODS(method) {
			struct setup s;
			char what[96];
			if (!build_extreme(&s, k, method, what, sizeof what))
				continue;
			check_scene(&s, what, &t);
			/* and the shadow pass leaves a caster out of a map only where nothing reads it */
			static struct lx_lookup_volumes v;
			lx_lookup_prepare(&s.frame, &s.atlas, &s.res, LX_LOOKUP_MARGIN_HIGHP + 2, &v);
			for (int id = 0; id < s.frame.object_count; id++) {
				unsigned drawn = lx_lookup_caster_maps(&v, id, false);
				for (int m = 0; m < s.res.map_count; m++)
					if (v.count[m][id] >= 0 && !(drawn & 1u << m))
						left_out++, unread_points += assert_unread(&s, &v, id, m, what, &unlit);
			}
			lx_meshes_free(&s.meshes);
		}
	print_message("%ld shadowed plane pixels at the extremes, every one looked up; %ld (object, map) pairs left "
		      "out of the shadow pass, %ld points of their receivers outside their volumes (%ld points of box "
		      "receivers' faces turned from the light inside)\n",
		      t.checked, left_out, unread_points, unlit);
	assert_true(left_out > 0);
}

/* A plane cut along window lines: the pieces' areas on the screen add up to the whole
 * plane's, so nothing is drawn twice or left out. */
static double window_area(const struct lx_view *v, const vec3 *p, int n)
{
	double a = 0, x[LX_WINDOW_POLY_MAX], y[LX_WINDOW_POLY_MAX];
	for (int i = 0; i < n; i++) {
		vec4 c = m4_mul_point(&v->view_proj, p[i]);
		x[i] = (c.x / c.w + 1) * 0.5 * v->width, y[i] = (c.y / c.w + 1) * 0.5 * v->height;
	}
	for (int i = 0; i < n; i++)
		a += x[i] * y[(i + 1) % n] - x[(i + 1) % n] * y[i];
	return fabs(a) / 2;
}

static void plane_pieces_cover_the_plane_once(void **state)
{
	(void)state;
	for (int c = 0; c < lx_config_count; c++) {
		struct setup s;
		lx_scene_default(&s.scene);
		lx_config_apply(&lx_configs[c], &s.scene);
		assert_true(build(&s, "uniform", W, H, 0.0));
		for (int id = 0; id < s.scene.plane_count; id++) {
			vec3 p[LX_WINDOW_POLY_MAX];
			double whole = window_area(&s.frame.view, p, lx_plane_in_window(&s.frame, id, (struct lx_rect){0, 0, W, H}, p));
			double parts = 0;
			int cut[3] = {0, 37, W}, cuty[3] = {0, 81, H};
			for (int i = 0; i < 2; i++)
				for (int j = 0; j < 2; j++) {
					int n = lx_plane_in_window(&s.frame, id, (struct lx_rect){cut[i], cuty[j], cut[i + 1], cuty[j + 1]}, p);
					assert_true(n == 0 || n >= 3);
					parts += n ? window_area(&s.frame.view, p, n) : 0;
				}
			assert_near(parts, whole, 1e-6 * W * H);
		}
		lx_meshes_free(&s.meshes);
	}
}

/* The sum lx_span_merge minimises. */
static long merge_cost(const struct lx_rect *r, int n)
{
	long c = 0;
	for (int i = 0; i < n; i++)
		c += (long)(r[i].x1 - r[i].x0) + (r[i].y1 - r[i].y0) + LX_SPAN_RECT_COST;
	return c;
}

/* How many of rectangles r[0..n) hold each pixel of an MW x MH window, into count. */
enum { MW = 512, MH = 512 };
static void coverage(const struct lx_rect *r, int n, uint8_t *count)
{
	memset(count, 0, (size_t)MW * MH);
	for (int i = 0; i < n; i++) {
		assert_true(r[i].x0 >= 0 && r[i].y0 >= 0 && r[i].x1 <= MW && r[i].y1 <= MH);
		for (int y = r[i].y0; y < r[i].y1; y++)
			for (int x = r[i].x0; x < r[i].x1; x++)
				count[y * MW + x]++;
	}
}

/* Spans in the lookup region's bands, merged, cover the same pixels once each, in at most
 * three rectangles per span, at no higher cost: random layouts (a few intervals per band,
 * some spans several bands tall, some empty), a staircase of lit spans beside a shadow
 * (rectangles four bands tall and the steps beside them, at under 60% of the cost), and
 * the refusals. */
static void merged_spans_keep_their_pixels(void **state)
{
	(void)state;
	static struct lx_rect in[LX_SPAN_MERGE_MAX + 1], out[3 * (LX_SPAN_MERGE_MAX + 1)];
	uint8_t *before = malloc((size_t)MW * MH), *after = malloc((size_t)MW * MH);
	assert_true(before && after);
	uint64_t seed = 11;
	long spans = 0, rects = 0, cost_in = 0, cost_out = 0;
	for (int trial = 0; trial < 300; trial++) {
		int n = 0;
		for (int y = 0; y < MH && n < LX_SPAN_MERGE_MAX - 8;) {
			int h = test_rand(&seed) < 0.2 ? 64 + 32 * (int)(test_rand(&seed) * 4) : 32;
			h = y + h <= MH ? h : MH - y;
			int x = (int)(test_rand(&seed) * 40), parts = 1 + (int)(test_rand(&seed) * 4);
			for (int k = 0; k < parts && x < MW; k++) {
				int w = (int)(test_rand(&seed) * (trial % 3 ? 300 : 20)), x1 = x + w < MW ? x + w : MW;
				in[n++] = (struct lx_rect){x, y, test_rand(&seed) < 0.03 ? x : x1, y + h}; /* some empty */
				x = x1 + 1 + (int)(test_rand(&seed) * 60);
			}
			y += h;
		}
		int k = lx_span_merge(in, n, out, 3 * n);
		assert_true(k >= 0 && k <= 3 * n);
		coverage(in, n, before);
		coverage(out, k, after);
		assert_memory_equal(before, after, (size_t)MW * MH);
		for (long i = 0; i < (long)MW * MH; i++)
			assert_true(after[i] <= 1);
		assert_true(merge_cost(out, k) <= merge_cost(in, n));
		spans += n, rects += k, cost_in += merge_cost(in, n), cost_out += merge_cost(out, k);
	}
	print_message("%ld spans in 300 layouts drawn as %ld rectangles, cost %ld of %ld\n", spans, rects, cost_out,
		      cost_in);
	assert_true(cost_out < cost_in);
	/* lit spans left of a shadow, eight bands: [0, a) with a wandering */
	static const int a[8] = {215, 169, 185, 204, 223, 241, 260, 303};
	for (int i = 0; i < 8; i++)
		in[i] = (struct lx_rect){0, 64 + 32 * i, a[i], 96 + 32 * i};
	int k = lx_span_merge(in, 8, out, 24);
	coverage(in, 8, before);
	coverage(out, k, after);
	assert_memory_equal(before, after, (size_t)MW * MH);
	bool tall = false;
	for (int i = 0; i < k; i++)
		tall |= out[i].x0 == 0 && out[i].x1 >= 169 && out[i].y1 - out[i].y0 >= 4 * 32;
	assert_true(tall);
	assert_true(10 * merge_cost(out, k) < 6 * merge_cost(in, 8)); /* 1328 against 2312 */
	assert_int_equal(lx_span_merge(in, 0, out, 0), 0);
	assert_int_equal(lx_span_merge(in, 8, out, 23), -1); /* room short of 3 n */
	assert_int_equal(lx_span_merge(in, LX_SPAN_MERGE_MAX + 1, out, 3 * (LX_SPAN_MERGE_MAX + 1)), -1);
	free(before), free(after);
}

/* A window rectangle lx_plane_window_holds calls inside a plane's image is the piece
 * lx_plane_in_window gives, its four corners: on both scenes' configurations, random
 * rectangles, some held and some not (the plane's outline, the near plane). */
static void held_rectangles_are_whole_pieces(void **state)
{
	(void)state;
	uint64_t seed = 5;
	long held = 0, refused = 0;
	for (int sc = 0; sc < 2; sc++)
		for (int c = 0; c < lx_config_count; c++) {
			struct setup s;
			lx_scene_builtin(sc ? "table" : "default", &s.scene);
			lx_config_apply(&lx_configs[c], &s.scene);
			if (!build(&s, "uniform", W, H, 0.4))
				continue;
			for (int id = 0; id < s.scene.plane_count; id++) {
				struct lx_poly win;
				lx_plane_window(&s.frame, id, &win);
				for (int t = 0; t < 200; t++) {
					int x0 = (int)(test_rand(&seed) * W), y0 = (int)(test_rand(&seed) * H);
					struct lx_rect b = {x0, y0, x0 + 1 + (int)(test_rand(&seed) * (W - x0)),
							    y0 + 1 + (int)(test_rand(&seed) * (H - y0))};
					if (!lx_plane_window_holds(&win, b)) {
						refused++;
						continue;
					}
					held++;
					vec3 p[LX_WINDOW_POLY_MAX];
					int n = lx_plane_in_window(&s.frame, id, b, p);
					assert_int_equal(n, 4);
					for (int k = 0; k < n; k++) { /* in front of the near plane, on a corner */
						vec4 q = m4_mul_point(&s.frame.view.view_proj, p[k]);
						assert_true(q.z > -q.w && q.w > 0);
						vec2 w = lx_view_window_point(&s.frame.view, q);
						double dx = fmin(fabs(w.x - b.x0), fabs(w.x - b.x1)), dy = fmin(fabs(w.y - b.y0), fabs(w.y - b.y1));
						assert_true(dx < 1e-3 && dy < 1e-3);
					}
				}
			}
			lx_meshes_free(&s.meshes);
		}
	print_message("%ld rectangles held whole by their plane, %ld not\n", held, refused);
	assert_true(held > 100 && refused > 100);
}

/* The first map of a mask that serves a point. */
static int first_serving(const struct lx_shadow_result *r, unsigned mask, vec3 p)
{
	for (int i = 0; i < r->map_count; i++) {
		const struct lx_shadow_map *m = &r->maps[i];
		if (!m->rendered || !(mask & 1u << i))
			continue;
		vec4 c = m4_mul_point(&m->light_clip, p);
		if (c.w > 0 && c.x / c.w >= m->bounds[0] && c.y / c.w >= m->bounds[1] && c.x / c.w < m->bounds[2] &&
		    c.y / c.w < m->bounds[3])
			return i;
	}
	return -1;
}

/* The maps left to a caster read the same map at every point of it in view. */
static void casters_keep_the_maps_they_read(void **state)
{
	(void)state;
	uint64_t seed = 7;
	long points = 0, fewer = 0;
	for (int c = 0; c < lx_config_count; c++) {
		struct setup s;
		lx_scene_builtin("table", &s.scene);
		lx_config_apply(&lx_configs[c], &s.scene);
		assert_true(build(&s, "plane", W, H, 0.4));
		static struct lx_lookup_volumes v;
		lx_lookup_prepare(&s.frame, &s.atlas, &s.res, LX_LOOKUP_MARGIN_HIGHP, &v);
		for (int id = s.scene.plane_count; id < s.frame.object_count; id++) {
			unsigned full = lx_shadow_receiver_maps(&s.res, id);
			unsigned kept = lx_lookup_maps(&v, id, full);
			assert_int_equal(kept & ~full, 0);
			fewer += kept != full;
			for (int k = 0; k < 400; k++) {
				vec3 lo = s.frame.bmin[id], hi = s.frame.bmax[id];
				vec3 p = v3(lo.x + (hi.x - lo.x) * test_rand(&seed), lo.y + (hi.y - lo.y) * test_rand(&seed),
					    lo.z + (hi.z - lo.z) * test_rand(&seed));
				vec4 v = m4_mul_point(&s.frame.view.view_proj, p);
				if (!(v.w > 0) || fabs(v.x) > v.w || fabs(v.y) > v.w || fabs(v.z) > v.w)
					continue; /* not in view */
				assert_int_equal(first_serving(&s.res, kept, p), first_serving(&s.res, full, p));
				points++;
			}
		}
		lx_meshes_free(&s.meshes);
	}
	print_message("%ld caster points read the same map; %ld casters read fewer maps\n", points, fewer);
	assert_true(points > 1000 && fewer > 0);
}

/* Whether point p lies in a volume of lx_lookup_prepare (its half-spaces, a little grown). */
static bool in_volume(const vec4 *pl, int np, vec3 p)
{
	for (int j = 0; j < np; j++)
		if (pl[j].x * p.x + pl[j].y * p.y + pl[j].z * p.z + pl[j].w < -1e-9)
			return false;
	return true;
}

/* Whether p lies in a volume of another object than `receiver` through a map of mask:
 * a point a lookup may find shadowed (by that object). */
static bool in_other_volume(const struct lx_lookup_volumes *v, int receiver, unsigned mask, vec3 p)
{
	for (int m = 0; m < v->res->map_count; m++)
		for (int c = 0; c < v->frame->object_count && (mask & 1u << m); c++)
			if (c != receiver && v->count[m][c] >= 0 && in_volume(v->plane[m][c], v->count[m][c], p))
				return true;
	return false;
}

/* What caster_parts_out_of_reach counts. */
struct reach {
	uint64_t seed;
	long out, in, points;
};

static void check_reach(struct setup *s, const char *what, void *ctx)
{
	struct reach *t = ctx;
	static struct lx_lookup_volumes v;
	lx_lookup_prepare(&s->frame, &s->atlas, &s->res, LX_LOOKUP_MARGIN_HIGHP, &v);
	for (int id = s->scene.plane_count; id < s->frame.object_count; id++) {
		unsigned mask = lx_shadow_receiver_maps(&s->res, id);
		vec3 lo = s->frame.bmin[id], hi = s->frame.bmax[id], d = v3_scale(v3_sub(hi, lo), 0.25);
		if (lx_lookup_any(&v, id, mask) && !lx_lookup_box_may_meet(&v, id, mask, lo, hi))
			fail_msg("%s, object %d: a shadow can fall on it, its box out of reach", what, id);
		for (int k = 0; k < 64; k++) {
			vec3 a = v3_add(lo, v3(d.x * (k & 3), d.y * (k >> 2 & 3), d.z * (k >> 4))), b = v3_add(a, d);
			if (lx_lookup_box_may_meet(&v, id, mask, a, b)) {
				t->in++;
				continue;
			}
			t->out++;
			for (int i = 0; i < 40; i++, t->points++) {
				vec3 p = v3(a.x + (b.x - a.x) * test_rand(&t->seed), a.y + (b.y - a.y) * test_rand(&t->seed),
					    a.z + (b.z - a.z) * test_rand(&t->seed));
				if (in_other_volume(&v, id, mask, p))
					fail_msg("%s, object %d: part %d out of reach holds a point in a volume", what, id, k);
			}
		}
	}
}

/* lx_lookup_box_may_meet, which the main pass asks of each run of a caster's faces
 * turned to the light: a part of a caster's box (4x4x4 of them) it calls out of reach
 * holds no point inside another object's volume (so no lookup there can find a shadow),
 * and the whole box of a caster lx_lookup_any says a shadow can fall on is in reach.
 * Every method, both scenes, every standard configuration. */
static void caster_parts_out_of_reach(void **state)
{
	(void)state;
	struct reach t = {.seed = 11};
	each_standard_setup(check_reach, &t);
	print_message("%ld parts of casters out of reach (%ld points in none of the volumes), %ld in reach\n", t.out,
		      t.points, t.in);
	assert_true(t.out > 1000 && t.in > 1000); /* both answers were given often */
}

/* Points of object id: a grid over a plane's quad, a caster's mesh vertices. */
static int object_points(const struct setup *s, int id, vec3 *out, int max)
{
	const struct lx_frame *f = &s->frame;
	int n = 0;
	if (id < s->scene.plane_count) {
		const struct lx_plane *p = &s->scene.planes[id];
		for (int i = 0; i <= 40; i++)
			for (int j = 0; j <= 40 && n < max; j++)
				out[n++] = v3_add(v3_add(v3_add(p->corner, f->offset[id]), v3_scale(p->edge1, i / 40.0)),
						  v3_scale(p->edge2, j / 40.0));
		return n;
	}
	const struct lx_mesh *m = &s->meshes.mesh[id];
	for (int i = 0; i < m->vertex_count && n < max; i++) {
		const float *v = m->v + (size_t)i * LX_VERTEX_FLOATS;
		out[n++] = v3_add(v3(v[0], v[1], v[2]), f->offset[id]);
	}
	return n;
}

/* Whether object id is a box caster (its mesh its box). */
static bool is_box(const struct lx_frame *f, int id)
{
	return id >= f->scene->plane_count && f->scene->casters[id - f->scene->plane_count].shape == LX_BOX;
}

/* A 33 x 33 grid of points on each face of box caster id that the light shines on (`lit`:
 * the light strictly on the face's outer side), or on each of the others. */
static int box_face_points(const struct lx_frame *f, int id, bool lit, vec3 *out, int max)
{
	double lo[3] = {f->bmin[id].x, f->bmin[id].y, f->bmin[id].z}, hi[3] = {f->bmax[id].x, f->bmax[id].y, f->bmax[id].z};
	const struct lx_light *l = &f->light;
	int n = 0;
	for (int face = 0; face < 6; face++) {
		int a = face / 2, b = (a + 1) % 3, c = (a + 2) % 3;
		double q[3], nrm[3] = {0, 0, 0};
		q[a] = face % 2 ? hi[a] : lo[a], nrm[a] = face % 2 ? 1 : -1;
		q[b] = 0.5 * (lo[b] + hi[b]), q[c] = 0.5 * (lo[c] + hi[c]);
		vec3 centre = v3(q[0], q[1], q[2]), normal = v3(nrm[0], nrm[1], nrm[2]);
		vec3 to = l->directional ? v3_scale(l->direction, -1) : v3_sub(l->position, centre);
		if ((v3_dot(normal, to) > 0) != lit)
			continue;
		for (int i = 0; i <= 32; i++)
			for (int j = 0; j <= 32 && n < max; j++) {
				q[b] = lo[b] + (hi[b] - lo[b]) * i / 32.0, q[c] = lo[c] + (hi[c] - lo[c]) * j / 32.0;
				out[n++] = v3(q[0], q[1], q[2]);
			}
	}
	return n;
}

/* Object id, left out of map m: no point of another receiver that reads the map lies in
 * its volume; of a box caster, no point of its faces the light shines on (the shadow
 * rule darkens the others, whatever the map holds), and *unlit counts the points of the
 * others inside it, which kept casters in maps before. Returns the points checked. */
static long assert_unread(const struct setup *s, const struct lx_lookup_volumes *v, int id, int m, const char *what,
			  long *unlit)
{
	static vec3 pts[6 * 33 * 33];
	long points = 0;
	for (int r = 0; r < s->frame.object_count; r++) {
		if (r == id || !(lx_shadow_receiver_maps(&s->res, r) & 1u << m))
			continue;
		bool box = is_box(&s->frame, r);
		int n = box ? box_face_points(&s->frame, r, true, pts, 6 * 33 * 33) : object_points(s, r, pts, 4096);
		for (int k = 0; k < n; k++, points++)
			if (in_volume(v->plane[m][id], v->count[m][id], pts[k]))
				fail_msg("%s: object %d left out of map %d, but a point of object %d lies in its volume", what, id,
					 m, r);
		n = box ? box_face_points(&s->frame, r, false, pts, 6 * 33 * 33) : 0;
		for (int k = 0; k < n; k++)
			*unlit += in_volume(v->plane[m][id], v->count[m][id], pts[k]);
	}
	return points;
}

/* Whether the corners of the box of a receiver other than id that reads map m lie on the
 * inner side of every half-space of id's volume, some corner for each: the test that
 * kept casters in maps before the receivers' faces were clipped by the volume. */
static bool corners_meet_volume(const struct setup *s, const struct lx_lookup_volumes *v, int id, int m)
{
	for (int r = 0; r < s->frame.object_count; r++) {
		if (r == id || !(lx_shadow_receiver_maps(&s->res, r) & 1u << m))
			continue;
		bool meets = true;
		for (int k = 0; k < v->count[m][id] && meets; k++) {
			bool some = false;
			for (int c = 0; c < 8 && !some; c++)
				some = v4_dot_point(v->plane[m][id][k], v3_box_corner(s->frame.bmin[r], s->frame.bmax[r], c)) >= 0;
			meets = some;
		}
		if (meets)
			return true;
	}
	return false;
}

/* The shadow pass leaves a caster out of a map only where no lookup can read it there:
 * no point of another receiver that reads the map lies in the caster's volume (and, with
 * --lookup-region all, the caster does not read the map itself). */
static void casters_left_out_only_where_unread(void **state)
{
	(void)state;
	long left_out = 0, points = 0, default_left_out = 0, tris[2][2][2] = {{{0}}}; /* [scene][plane][before, after] */
	long by_faces = 0; /* pairs left out that the receivers' box corners kept in */
	long unlit = 0;    /* points of box receivers' faces turned from the light inside their volumes */
	for (const char *const *sn = (const char *const[]){"default", "table", NULL}; *sn; sn++)
		FOR_METHODS(method)
			for (int c = 0; c < lx_config_count; c++)
				for (int everywhere = 0; everywhere < 2; everywhere++) {
					struct setup s;
					assert_true(lx_scene_builtin(*sn, &s.scene));
					lx_config_apply(&lx_configs[c], &s.scene);
					if (!build(&s, method, W, H, 0.4))
						continue;
					static struct lx_lookup_volumes v;
					lx_lookup_prepare(&s.frame, &s.atlas, &s.res, LX_LOOKUP_MARGIN_HIGHP + 2, &v);
					for (int id = 0; id < s.frame.object_count; id++) {
						unsigned drawn = lx_lookup_caster_maps(&v, id, everywhere), reads = lx_shadow_receiver_maps(&s.res, id);
						/* the triangles the pass draws: before, every object a map sees */
						int kind = !strcmp(method, "plane") ? 1 : !strcmp(method, "uniform") ? 0 : -1;
						for (int m = 0; m < s.res.map_count && kind >= 0 && !everywhere; m++) {
							long t = s.meshes.mesh[id].vertex_count / 3;
							tris[strcmp(*sn, "default") != 0][kind][0] += (s.res.maps[m].rendered && lx_shadow_map_draws(&s.res.maps[m], &s.frame, id)) * t;
							tris[strcmp(*sn, "default") != 0][kind][1] += (drawn >> m & 1) * t;
						}
						for (int m = 0; m < s.res.map_count; m++) {
							if (v.count[m][id] < 0 || (drawn & 1u << m))
								continue;
							left_out++;
							default_left_out += !strcmp(*sn, "default") && c == 0 && !strcmp(method, "plane");
							by_faces += corners_meet_volume(&s, &v, id, m);
							if (reads & 1u << m)
								assert_false(everywhere); /* all reads its own texels */
							char what[96];
							snprintf(what, sizeof what, "%s scene, %s, %s", *sn, lx_configs[c].name, method);
							points += assert_unread(&s, &v, id, m, what, &unlit);
						}
					}
					lx_meshes_free(&s.meshes);
				}
	print_message("%ld (object, map) pairs left out of the shadow pass (%ld that the receivers' box corners kept in), "
		      "%ld points of their receivers outside their volumes (%ld points of box receivers' faces turned from "
		      "the light inside); %ld on plane's default view\n", left_out, by_faces, points, unlit, default_left_out);
	for (int sc = 0; sc < 2; sc++)
		for (int k = 0; k < 2; k++)
			print_message("%s scene, %s, every configuration: %ld triangles drawn into the maps, against %ld when every "
				      "object a map sees was drawn\n", sc ? "table" : "default", k ? "plane" : "uniform", tris[sc][k][1],
				      tris[sc][k][0]);
	assert_true(default_left_out > 0);
	/* a receiver's box can have corners on the inner side of every half-space of a caster's
	 * volume and its faces still miss the volume: the faces are what count (the corners
	 * alone kept the table's ball in plane-optimal's fallback under the low light, until
	 * the fallback left the ball out, as nothing reaches it) */
	assert_true(by_faces > 0);
}

/* The case that brought in the rule that a box receiver's faces turned from the light do
 * not keep a caster in a map: under the table scene's low light, at 1024x1024, the slab's
 * underside touches the legs' tops, and the slab alone reads plane-optimal's fallback
 * map: the pass leaves those legs out of the fallback (it drew all four before). The
 * underside lay inside their volumes until a box's volume ended at its lit faces (the
 * legs' tops among them, the underside in their plane: only where it touches one). And
 * under that light the slab's lit faces lie in no leg's volume through the floor's maps,
 * where the depth bound alone let its side beside the legs' tops read two of them. */
static void legs_left_out_under_the_slab(void **state)
{
	(void)state;
	struct setup s;
	assert_true(lx_scene_builtin("table", &s.scene));
	lx_config_apply(lx_config_find("low"), &s.scene);
	assert_true(build(&s, "plane", 1024, 1024, 0.4));
	double margin = 0; /* the shadow pass's: the widest filter's (renderer.c) */
	for (int k = 0; k < LX_FILTER_COUNT; k++)
		margin = fmax(margin, LX_LOOKUP_MARGIN_HIGHP + lx_filter_reach((enum lx_filter)k));
	static struct lx_lookup_volumes v;
	lx_lookup_prepare(&s.frame, &s.atlas, &s.res, margin, &v);
	int fallback = -1;
	for (int m = 0; m < s.res.map_count; m++)
		if (s.res.maps[m].rendered && s.res.maps[m].plane < 0)
			fallback = m;
	assert_true(fallback >= 0);
	/* the legs stand on the floor; the slab's underside touches their tops */
	bool leg[LX_MAX_PLANES + LX_MAX_CASTERS] = {false};
	int slab = -1, legs_n = 0;
	for (int id = s.scene.plane_count; id < s.frame.object_count; id++)
		if (is_box(&s.frame, id) && s.frame.bmin[id].y < 1e-6)
			leg[id] = true, legs_n++;
	for (int id = s.scene.plane_count; id < s.frame.object_count; id++)
		for (int l = 0; l < s.frame.object_count && slab < 0; l++)
			if (leg[l] && !leg[id] && is_box(&s.frame, id) && fabs(s.frame.bmin[id].y - s.frame.bmax[l].y) < 1e-6)
				slab = id;
	assert_int_equal(legs_n, 4);
	assert_true(slab >= 0);
	long left = 0, unlit = 0;
	for (int id = 0; id < s.frame.object_count; id++)
		if (leg[id] && v.count[fallback][id] >= 0 && !(lx_lookup_caster_maps(&v, id, false) >> fallback & 1)) {
			assert_unread(&s, &v, id, fallback, "table scene, low, plane", &unlit);
			left++;
		}
	/* the legs' volumes alone through the plane maps */
	static struct lx_lookup_volumes legs;
	legs = v;
	unsigned plane_maps = 0;
	long leg_volumes = 0;
	for (int m = 0; m < s.res.map_count; m++) {
		plane_maps |= (unsigned)(s.res.maps[m].rendered && s.res.maps[m].plane >= 0) << m;
		for (int id = 0; id < s.frame.object_count; id++) {
			if (!leg[id] || !(plane_maps >> m & 1))
				legs.count[m][id] = -1;
			leg_volumes += legs.count[m][id] >= 0;
		}
	}
	bool read = lx_lookup_any(&legs, slab, plane_maps);
	print_message("table scene, low light, 1024x1024: %ld legs left out of the fallback, %ld points of the slab's "
		      "underside inside their volumes; the slab's lit faces inside one of %ld legs' volumes through the "
		      "plane maps: %s\n", left, unlit, leg_volumes, read ? "yes" : "no");
	assert_true(left >= 3);
	assert_true(leg_volumes >= 2 && !read);
	lx_meshes_free(&s.meshes);
}

/* What box_volumes_hold_their_drawn_faces counts. */
struct drawn_faces {
	long points; /* points of faces a shadow pass draws, each inside its caster's volume */
	long past;   /* (box, map) pairs whose volume leaves out the box's nearest corner */
};

/* Whether clip point c lies in front of the eye's near plane and inside the rays a map
 * serves (its bounds), where a caster's volume is cut. */
static bool served_in_view(const struct setup *s, const struct lx_shadow_map *map, vec3 p)
{
	vec4 e = m4_mul_point(&s->frame.view.view_proj, p), c = m4_mul_point(&map->light_clip, p);
	if (!(e.z + e.w > 1e-9) || !(c.w > 0))
		return false;
	double x = c.x / c.w, y = c.y / c.w;
	return x >= map->bounds[0] && x <= map->bounds[2] && y >= map->bounds[1] && y <= map->bounds[3];
}

static void check_drawn_faces(struct setup *s, const char *what, void *ctx)
{
	struct drawn_faces *t = ctx;
	static struct lx_lookup_volumes v;
	lx_lookup_prepare(&s->frame, &s->atlas, &s->res, LX_LOOKUP_MARGIN_HIGHP, &v);
	for (int id = 0; id < s->frame.object_count; id++)
		for (int m = 0; m < s->res.map_count && is_box(&s->frame, id); m++) {
			const struct lx_shadow_map *map = &s->res.maps[m];
			const mat4 *lc = &map->light_clip;
			bool front = v.count[m][id] >= 0;
			double z_near = INFINITY;
			vec3 nearest = v3(0, 0, 0);
			for (int k = 0; k < 8 && front; k++) {
				vec4 c = m4_mul_point(lc, v3_box_corner(s->frame.bmin[id], s->frame.bmax[id], k));
				front = c.w > 0;
				if (front && c.z / c.w < z_near)
					z_near = c.z / c.w, nearest = v3_box_corner(s->frame.bmin[id], s->frame.bmax[id], k);
			}
			if (!front)
				continue; /* in no map, or reaching behind its light: bounded by its box */
			const struct lx_mesh *mesh = &s->meshes.mesh[id];
			for (int tri = 0; tri < mesh->vertex_count / 3; tri++) {
				vec3 p[3];
				vec4 c[3];
				for (int i = 0; i < 3; i++) {
					const float *f = mesh->v + (size_t)(3 * tri + i) * LX_VERTEX_FLOATS;
					p[i] = v3_add(v3(f[0], f[1], f[2]), s->frame.offset[id]);
					c[i] = m4_mul_point(lc, p[i]);
				}
				/* the GL culls what winds counter-clockwise in the map (CullFace(GL_FRONT)) */
				double area = (c[1].x / c[1].w - c[0].x / c[0].w) * (c[2].y / c[2].w - c[0].y / c[0].w) -
					      (c[2].x / c[2].w - c[0].x / c[0].w) * (c[1].y / c[1].w - c[0].y / c[0].w);
				if (!(area < 0))
					continue;
				for (int i = 0; i <= 6; i++)
					for (int j = 0; i + j <= 6; j++) {
						vec3 q = v3_add(v3_add(v3_scale(p[0], (6 - i - j) / 6.0), v3_scale(p[1], i / 6.0)),
								v3_scale(p[2], j / 6.0));
						if (!served_in_view(s, map, q))
							continue;
						if (!in_volume(v.plane[m][id], v.count[m][id], q))
							fail_msg("%s: a point of box %d's face the pass draws into map %d lies outside its volume",
								 what, id, m);
						t->points++;
					}
			}
			t->past += served_in_view(s, map, nearest) && !in_volume(v.plane[m][id], v.count[m][id], nearest);
		}
}

/* A box caster's volume starts at the faces the shadow pass draws of it, not at its
 * nearest corner: every point of those faces (the depths the map can hold of it) lies
 * inside it, where the map serves it in front of the eye, and some volumes leave the
 * nearest corner out (a box lit on three faces). Every method, both scenes, every
 * standard configuration: the warps' matrices decide the winding, as the GL's culling. */
static void box_volumes_hold_their_drawn_faces(void **state)
{
	(void)state;
	struct drawn_faces t = {0};
	each_standard_setup(check_drawn_faces, &t);
	print_message("%ld points of boxes' faces drawn into maps, each inside its volume; %ld volumes leave out the "
		      "box's nearest corner\n", t.points, t.past);
	assert_true(t.points > 10000 && t.past > 10);
}

/* Whether the light's ray from x crosses front p's parallelogram (cov's corners: a plane's
 * or a flat box's face) before x, in double, the direct way; *near: the crossing lies
 * within 1e-9 of the parallelogram's edges or of x (a rounding there may go either way). */
static bool ray_crosses_front(const struct lx_frame *f, const struct lx_plane_covers *cov, int p, vec3 x, bool *near)
{
	const vec3 *q = cov->corner[p];
	struct lx_plane pp = {.edge1 = v3_sub(q[1], q[0]), .edge2 = v3_sub(q[3], q[0])}, *pl = &pp;
	vec3 n = v3_cross(pl->edge1, pl->edge2);
	const struct lx_light *L = &f->light;
	vec3 to = L->directional ? v3_scale(L->direction, -1) : v3_sub(L->position, x);
	double dn = v3_dot(n, to);
	*near = false;
	if (dn == 0)
		return false;
	double t = v3_dot(n, v3_sub(q[0], x)) / dn; /* x + t to lies on the plane */
	if (!(t > 0) || (!L->directional && !(t < 1)))
		return false;
	vec3 y = v3_sub(v3_add(x, v3_scale(to, t)), q[0]);
	double nn = v3_dot(n, n);
	double u = v3_dot(v3_cross(pl->edge2, n), y) / nn, v = v3_dot(v3_cross(n, pl->edge1), y) / nn;
	*near = fabs(u) < 1e-9 || fabs(u - 1) < 1e-9 || fabs(v) < 1e-9 || fabs(v - 1) < 1e-9 || t < 1e-9;
	return u >= 0 && u <= 1 && v >= 0 && v <= 1;
}

/* A plane lit on its front (the side its mesh faces) is culled from the shadow pass; the
 * main pass tests what it shadows with its cover matrix (plane_cover.h). The matrix
 * against the direct ray test at random points, the objects it is drawn for, and the
 * lights that leave it out. */
static void lit_plane_fronts_shadow_what_lies_beyond(void **state)
{
	(void)state;
	uint64_t seed = 0x5eedc0fe11ull;
	long covered = 0, tested = 0, extra = 0, windowed = 0;
	for (int sc = 0; sc < 2; sc++)
		for (int c = 0; c < lx_config_count; c++) {
			struct setup s;
			lx_scene_builtin(sc ? "table" : "default", &s.scene);
			lx_config_apply(&lx_configs[c], &s.scene);
			assert_true(build(&s, "none", W, H, 0.4));
			const struct lx_frame *f = &s.frame;
			int np = f->scene->plane_count;
			struct lx_plane_covers cov;
			lx_plane_covers(f, &cov);
			assert_int_equal(cov.count, np + sc); /* the table's slab has a front */
			for (int p = 0; p < cov.count; p++) {
				mat4 m = cov.m[p];
				const vec3 *q = cov.corner[p];
				vec3 n = v3_cross(v3_sub(q[1], q[0]), v3_sub(q[3], q[0]));
				double side = f->light.directional ? -v3_dot(n, f->light.direction)
								    : v3_dot(n, v3_sub(f->light.position, q[0]));
				bool has = cov.lit[p];
				assert_true(has == (side > 0)); /* no light of these grazes a front */
				if (p < np) { /* a plane's: lx_plane_cover_matrix's */
					mat4 pm;
					assert_true(lx_plane_cover_matrix(f, p, &pm) == has && (!has || !memcmp(&pm, &m, sizeof m)));
				} else { /* the slab's face turned away from the light, facing it */
					assert_int_equal(cov.owner[p], np);
					assert_true(has && fabs(q[0].y - (side > 0 ? f->bmin[np].y : f->bmax[np].y)) < 1e-12);
				}
				for (int k = 0; has && k < 4000; k++) {
					/* half over the scene, half around the table and under it */
					vec3 lo = k & 1 ? v3(-1.4, 0, -1) : f->scene_min, hi = k & 1 ? v3(1.4, 0.8, 1) : f->scene_max;
					vec3 x = v3(lo.x + (hi.x - lo.x) * test_rand(&seed), lo.y + (hi.y - lo.y) * test_rand(&seed),
						    lo.z + (hi.z - lo.z) * test_rand(&seed));
					bool near, want = ray_crosses_front(f, &cov, p, x, &near);
					bool got = lx_plane_cover_shadows(&m, x);
					if (near)
						continue;
					if (got != want)
						fail_msg("%s scene, %s, plane %d at (%g, %g, %g): the matrix says %d, the ray %d",
							 sc ? "table" : "default", lx_configs[c].name, p, x.x, x.y, x.z, got, want);
					covered += got, tested++;
				}
			}
			/* a covered point of another plane lies inside the cover's window rectangle */
			for (int p = 0; p < cov.count; p++)
				for (int q = 0; q < np; q++) {
					struct lx_poly image;
					if (cov.owner[p] == q || !cov.lit[p] || !lx_plane_cover_image(f, &cov, p, q, &image))
						continue;
					const struct lx_plane *pq = &f->scene->planes[q];
					vec3 qc[4];
					lx_frame_plane_corners(f, q, qc);
					for (int k = 0; k < 4000; k++) {
						vec3 x = v3_add(qc[0], v3_add(v3_scale(pq->edge1, test_rand(&seed)),
									    v3_scale(pq->edge2, test_rand(&seed))));
						bool near;
						vec4 e = m4_mul_point(&f->view.view_proj, x);
						if (!ray_crosses_front(f, &cov, p, x, &near) || !(e.w > 0) || fabs(e.x) > e.w || fabs(e.y) > e.w)
							continue; /* not covered, or out of the view */
						double wx = (e.x / e.w * 0.5 + 0.5) * f->view.width, wy = (e.y / e.w * 0.5 + 0.5) * f->view.height;
						if (!lx_poly_contains(&image, (vec2){wx, wy}, -1e-6))
							fail_msg("%s scene, %s: plane %d's point at pixel (%g, %g) in plane %d's cover is outside "
								 "its shadow's image", sc ? "table" : "default", lx_configs[c].name, q, wx, wy, p);
						windowed++;
					}
					/* and a point of it outside the image is outside the cover (a pixel in, or
					 * out, then decides alike with the test and without) */
					for (int k = 0; k < 4000; k++) {
						vec3 x = v3_add(qc[0], v3_add(v3_scale(pq->edge1, test_rand(&seed)),
									    v3_scale(pq->edge2, test_rand(&seed))));
						bool near;
						vec4 e = m4_mul_point(&f->view.view_proj, x);
						if (!(e.w > 0) || fabs(e.x) > e.w || fabs(e.y) > e.w)
							continue;
						double wx = (e.x / e.w * 0.5 + 0.5) * f->view.width, wy = (e.y / e.w * 0.5 + 0.5) * f->view.height;
						bool crosses = ray_crosses_front(f, &cov, p, x, &near);
						if (!near && !lx_poly_contains(&image, (vec2){wx, wy}, -1e-6) && crosses)
							fail_msg("%s scene, %s: plane %d's point at pixel (%g, %g) outside plane %d's shadow's image "
								 "is in its cover", sc ? "table" : "default", lx_configs[c].name, q, wx, wy, p);
					}
				}
			/* the table top covers its slab wherever the light is above it, and the legs
			 * and the floor under the slab the top and the slab's underside; nothing in
			 * the default scene lies beyond a lit front */
			bool above = f->light.directional ? f->light.direction.y < 0 : f->light.position.y > 0.75;
			for (int id = 0; id < f->object_count; id++) {
				int p = cov.of[id][0];
				bool slab_front = cov.of[id][0] == np || cov.of[id][1] == np; /* front np: the slab's */
				bool want = sc == 1 && above && (id == 1 || (id > np && id <= np + 4)); /* floor, legs */
				if (sc == 0 ? p != -1 : (id == np && above && p != 0) || (want && !slab_front))
					fail_msg("%s scene, %s: object %d covered by fronts %d, %d", sc ? "table" : "default",
						 lx_configs[c].name, id, p, cov.of[id][1]);
				extra += p >= 0;
				/* and none of an object's points is in the shadow of a front it does not test */
				for (int q = 0; q < cov.count; q++)
					for (int k = 0; cov.owner[q] != id && cov.of[id][0] != q && cov.of[id][1] != q && k < 300 &&
							cov.lit[q];
					     k++) {
						vec3 x = v3(f->bmin[id].x + (f->bmax[id].x - f->bmin[id].x) * test_rand(&seed),
							    f->bmin[id].y + (f->bmax[id].y - f->bmin[id].y) * test_rand(&seed),
							    f->bmin[id].z + (f->bmax[id].z - f->bmin[id].z) * test_rand(&seed));
						bool near;
						assert_false(ray_crosses_front(f, &cov, q, x, &near) && !near);
					}
			}
			lx_meshes_free(&s.meshes);
		}
	print_message("cover matrices: %ld of %ld random points shadowed, each as the ray test has it; %ld objects of the "
		      "table scene's %d views drawn with a front's test\n", covered, tested, extra, lx_config_count);
	assert_true(covered > 10000 && covered < tested);
	print_message("%ld covered points of the floor under the table inside the image of the top's shadow\n", windowed);
	assert_true(windowed > 1000);
	/* the renderer builds the cover's variants at the start for the table, not the default scene */
	for (int sc = 0; sc < 2; sc++) {
		struct lx_scene sn;
		struct lx_scene_meshes mm;
		lx_scene_builtin(sc ? "table" : "default", &sn);
		assert_true(lx_meshes_build(&sn, &mm));
		assert_int_equal(lx_scene_covers_needed(&sn, &mm), 2 * sc); /* the top and the slab */
		lx_meshes_free(&mm);
	}
	/* lights that leave the cover out: on the table top's plane, below the floor (its back
	 * lit: it casts through the maps), a directional light along the table top */
	const vec3 lights[3] = {{0.3, 0.75, 0.2}, {0, -2, 0}, {1, 0, 0}};
	for (int i = 0; i < 3; i++) {
		struct setup s;
		mat4 m;
		lx_scene_table(&s.scene);
		if (i == 2)
			s.scene.light.directional = true, s.scene.light.direction = lights[i];
		else
			s.scene.light.position = lights[i];
		assert_true(build(&s, "none", W, H, 0));
		assert_false(lx_plane_cover_matrix(&s.frame, i == 1 ? 1 : 0, &m));
		lx_meshes_free(&s.meshes);
	}
}

/* Two shelves stacked over the floor (tests/data/two-shelves.scene): the floor gets both
 * fronts' tests, and a point of it is in their shadows exactly where the light's ray
 * crosses either shelf; part of the upper shelf's shadow falls outside the lower one's,
 * which one front per object lost. */
static void two_fronts_over_an_object_are_both_tested(void **state)
{
	(void)state;
	struct setup s;
	test_scene_load("two-shelves.scene", &s.scene);
	assert_true(build(&s, "none", W, H, 0));
	const struct lx_frame *f = &s.frame;
	assert_int_equal(lx_scene_covers_needed(&s.scene, &s.meshes), 2);
	struct lx_plane_covers cov;
	lx_plane_covers(f, &cov);
	int box = f->scene->plane_count;
	assert_int_equal(lx_plane_cover_count(&cov, 0), 2); /* the floor */
	assert_int_equal(cov.of[0][0], 1);
	assert_int_equal(cov.of[0][1], 2);
	assert_int_equal(lx_plane_cover_count(&cov, 1), 1); /* the lower shelf, under the upper */
	assert_int_equal(cov.of[1][0], 2);
	assert_int_equal(lx_plane_cover_count(&cov, 2), 0);
	assert_int_equal(cov.of[box][0], 1); /* the box: the upper shelf's rays to it pass the lower one */
	uint64_t seed = 0x5e1f5e1full;
	long upper_only = 0, shadowed = 0;
	const struct lx_plane *fl = &f->scene->planes[0];
	for (int k = 0; k < 20000; k++) {
		vec3 x = v3_add(fl->corner, v3_add(v3_scale(fl->edge1, 0.3 + 0.4 * test_rand(&seed)),
						   v3_scale(fl->edge2, 0.3 + 0.4 * test_rand(&seed))));
		bool n1, n2, a = ray_crosses_front(f, &cov, 1, x, &n1), b = ray_crosses_front(f, &cov, 2, x, &n2);
		if (n1 || n2)
			continue;
		if (lx_plane_covers_shadow(&cov, 0, x) != (a || b))
			fail_msg("floor point (%g, %g, %g): the tests say %d, the rays %d and %d", x.x, x.y, x.z,
				 lx_plane_covers_shadow(&cov, 0, x), a, b);
		shadowed += a || b, upper_only += b && !a;
	}
	print_message("two shelves: %ld of 20000 floor points in their shadows, %ld in the upper one's alone\n", shadowed,
		      upper_only);
	assert_true(upper_only > 100 && shadowed > upper_only);
	lx_meshes_free(&s.meshes);
}

/* Whether the light's ray from x passes through box [lo, hi] (the slab method, in
 * double); *near where it only grazes it, within a billionth. */
static bool ray_hits_box(const struct lx_frame *f, vec3 lo, vec3 hi, vec3 x, bool *near)
{
	const struct lx_light *L = &f->light;
	vec3 to = L->directional ? v3_scale(L->direction, -1) : v3_sub(L->position, x);
	double o[3] = {x.x, x.y, x.z}, d[3] = {to.x, to.y, to.z}, b0[3] = {lo.x, lo.y, lo.z}, b1[3] = {hi.x, hi.y, hi.z};
	double t0 = 0, t1 = L->directional ? 1e9 : 1;
	*near = false;
	for (int a = 0; a < 3; a++) {
		if (d[a] == 0) {
			*near |= fabs(o[a] - b0[a]) < 1e-9 || fabs(o[a] - b1[a]) < 1e-9;
			if (o[a] < b0[a] || o[a] > b1[a])
				return false;
			continue;
		}
		double u = (b0[a] - o[a]) / d[a], w = (b1[a] - o[a]) / d[a]; /* d[a] != 0 */
		t0 = fmax(t0, fmin(u, w)), t1 = fmin(t1, fmax(u, w));
	}
	*near |= fabs(t1 - t0) < 1e-9;
	return t1 > t0;
}

/* A flat box's pair of fronts (plane_cover.h): over an object that tests both, a point is
 * in their shadow exactly where the light's ray passes through the box or crosses the
 * plane on its top. The table's slab and its top, for the floor and the legs, under every
 * standard configuration's light and three more (low, level with the top, and a grazing
 * directional light); some of those rays pass through the slab's thin sides only, which
 * neither face's test alone shadows. Every floor point the pair shadows lies, seen by the
 * eye, inside the pair's image (lx_plane_cover_pair_image), which the main pass tests the
 * floor over, some outside both fronts' own images (those the main pass once left lit). */
static void a_flat_box_pair_is_its_box(void **state)
{
	(void)state;
	uint64_t seed = 0x51abull;
	long shadowed = 0, sides = 0, points = 0, imaged_points = 0, beside = 0;
	const vec3 extra[3] = {{3.5, 0.9, 1.0}, {-2.5, 0.8, -1.5}, {0, 0, 0}};
	for (int c = 0; c < lx_config_count + 3; c++) {
		struct setup s;
		lx_scene_table(&s.scene);
		if (c < lx_config_count)
			lx_config_apply(&lx_configs[c], &s.scene);
		else if (c < lx_config_count + 2)
			s.scene.light.position = extra[c - lx_config_count];
		else
			s.scene.light.directional = true, s.scene.light.direction = v3(-0.8, -0.15, -0.3);
		assert_true(build(&s, "none", W, H, 0));
		const struct lx_frame *f = &s.frame;
		struct lx_plane_covers cov;
		lx_plane_covers(f, &cov);
		int np = f->scene->plane_count, slab = np;
		for (int id = 1; id <= np + 4; id++) { /* the floor, then the slab (skipped) and the legs */
			if (id == slab || !cov.paired[id])
				continue;
			int top = cov.of[id][0], bottom = cov.of[id][1];
			assert_true(cov.top[bottom] == top && cov.owner[bottom] == slab && top == 0); /* the table top */
			struct lx_poly img[2], pair;
			bool imaged = id == 1 && lx_plane_cover_pair_image(f, &cov, id, &img[0], &img[1], &pair);
			for (int k = 0; k < 2000; k++) {
				vec3 lo = f->bmin[id], hi = f->bmax[id], x;
				if (id == 1 && k % 2) { /* the floor around a slab corner's shadow: where the sides' rays fall */
					vec3 cn = v3_box_corner(f->bmin[slab], f->bmax[slab], k / 2 % 8), L = f->light.position,
					     d = f->light.direction;
					vec3 sh = f->light.directional ? v3_sub(cn, v3_scale(d, cn.y / d.y)) /* d.y < 0 here */
								       : v3_add(L, v3_scale(v3_sub(cn, L), L.y / (L.y - cn.y)));
					x = v3(sh.x - 0.05 + 0.1 * test_rand(&seed), 0, sh.z - 0.05 + 0.1 * test_rand(&seed));
				} else if (id == 1) /* the floor under and around the table */
					x = v3(-3 + 6 * test_rand(&seed), 0, -3 + 6 * test_rand(&seed));
				else
					x = v3(lo.x + (hi.x - lo.x) * test_rand(&seed), lo.y + (hi.y - lo.y) * test_rand(&seed),
					       lo.z + (hi.z - lo.z) * test_rand(&seed));
				bool n1, n2;
				bool box = ray_hits_box(f, f->bmin[slab], f->bmax[slab], x, &n1),
				     plane = ray_crosses_front(f, &cov, top, x, &n2);
				if (n1 || n2)
					continue;
				bool want = box || plane, got = lx_plane_covers_shadow(&cov, id, x);
				if (got != want)
					fail_msg("configuration %d, object %d, point (%g, %g, %g): the tests say %d, the box %d, the top %d",
						 c, id, x.x, x.y, x.z, got, box, plane);
				points++, shadowed += want;
				sides += want && !lx_plane_cover_shadows(&cov.m[top], x) && !lx_plane_cover_shadows(&cov.m[bottom], x);
				/* the main pass tests the floor over the pair's image: a point the tests
				 * shadow lies inside it, though perhaps in neither front's own */
				vec4 e = m4_mul_point(&f->view.view_proj, x);
				if (!imaged || !got || !(e.w > 0))
					continue;
				vec2 at = lx_view_window_point(&f->view, e);
				if (!lx_poly_contains(&pair, at, -1e-6 * (1 + fabs(at.x) + fabs(at.y))))
					fail_msg("configuration %d: floor point (%g, %g, %g) in the pair's shadow, pixel (%g, %g), "
						 "lies outside the pair's image", c, x.x, x.y, x.z, at.x, at.y);
				imaged_points++;
				beside += !lx_poly_contains(&img[0], at, 0) && !lx_poly_contains(&img[1], at, 0);
			}
		}
		lx_meshes_free(&s.meshes);
	}
	print_message("the table's pair: %ld points, %ld in the slab's or the top's shadow, %ld of them by rays through "
		      "the slab's thin sides alone; %ld floor points of it in the pair's image, %ld outside both fronts' "
		      "own\n", points, shadowed, sides, imaged_points, beside);
	assert_true(shadowed > 1000 && sides > 10 && imaged_points > 500 && beside > 10);
}

/* Caster c's mesh corners as lx_sure_shadow_window takes them (x, y, z floats); returns
 * how many (its triangles' corners, repeats and all). */
static int mesh_corners(const struct setup *s, int c, float *pts, int room)
{
	const struct lx_mesh *me = &s->meshes.mesh[c];
	int n = me->vertex_count < room ? me->vertex_count : room;
	for (int k = 0; k < n; k++)
		memcpy(pts + 3 * k, me->v + (size_t)k * LX_VERTEX_FLOATS, 3 * sizeof(float));
	return n;
}

struct sure_tally {
	long windows, pixels, boxes, beside_wall, beside_pixels;
};

/* Every pixel of `win` (caster c's sure shadow on plane id in map m) is in that caster's
 * exact shadow, and its point's image lies inside the rays the map serves. Returns the
 * pixels checked. */
static long check_sure_pixels(struct setup *s, const char *what, int id, int m, int c, const struct lx_poly *win)
{
	const struct lx_shadow_map *map = &s->res.maps[m];
	vec4 pe = lx_plane_equation(&s->scene.planes[id]);
	long pixels = 0;
	for (int y = 0; y < H; y++)
		for (int x = 0; x < W; x++) {
			vec3 q;
			double dist;
			if (!lx_poly_contains(win, (vec2){x + 0.5, y + 0.5}, 0) ||
			    !lx_window_on_plane(&s->frame.view, pe, x + 0.5, y + 0.5, &q, &dist) ||
			    !lx_plane_contains(&s->scene.planes[id], q))
				continue;
			vec4 l = m4_mul_point(&map->light_clip, q);
			if (!caster_shadows(&s->frame, c, q) || !(l.w > 0) || l.x / l.w < map->bounds[0] ||
			    l.y / l.w < map->bounds[1] || l.x / l.w >= map->bounds[2] || l.y / l.w >= map->bounds[3])
				fail_msg("%s: plane %d pixel (%d, %d), in caster %d's sure shadow in map %d, is not "
					 "in its shadow or not served by the map", what, id, x, y, c, m);
			pixels++;
		}
	return pixels;
}

/* Each caster's sure shadows on each plane in each map, from its mesh's corners and, for
 * a box, from its bounds as the renderer asks (the same window where both give one; the
 * bounds alone give one where the box reaches behind a plane map's light): every pixel
 * inside in the caster's exact shadow. */
static void check_sure(struct setup *s, const char *what, void *ctx)
{
	struct sure_tally *t = ctx;
	static float pts[3 * 4096];
	bool beside_wall = strstr(what, "near-wall") || strstr(what, "facing");
	for (int id = 0; id < s->scene.plane_count; id++)
		for (int m = 0; m < s->res.map_count; m++) {
			const struct lx_shadow_map *map = &s->res.maps[m];
			const struct lx_region *g = &s->atlas.regions[map->region];
			if (!map->rendered || g->w < 1 || g->h < 1)
				continue;
			for (int c = s->scene.plane_count; c < s->frame.object_count; c++) {
				if (s->res.slab_face_out[c])
					continue;
				struct lx_poly win, box;
				bool got = lx_sure_shadow_window(&s->frame, map, g->w, g->h, c, pts, NULL,
								 mesh_corners(s, c, pts, 4096), id, LX_LOOKUP_MARGIN_HIGHP,
								 1e-6, &win);
				bool is_box = s->scene.casters[c - s->scene.plane_count].shape == LX_BOX;
				bool got_box = is_box && lx_sure_shadow_window(&s->frame, map, g->w, g->h, c, NULL, NULL, 8, id,
										LX_LOOKUP_MARGIN_HIGHP, 1e-6, &box);
				if (got && is_box) { /* the renderer's way for a box: its bounds' corners, no points */
					assert_true(got_box);
					assert_int_equal(box.n, win.n);
					for (int k = 0; k < win.n; k++)
						assert_true(fabs(box.v[k].x - win.v[k].x) + fabs(box.v[k].y - win.v[k].y) < 1e-3);
					t->boxes++;
				}
				long px = got ? check_sure_pixels(s, what, id, m, c, &win)
					      : got_box ? check_sure_pixels(s, what, id, m, c, &box) : 0;
				t->pixels += px;
				t->windows += got || got_box;
				if (beside_wall && map->plane >= 0)
					t->beside_wall += got || got_box, t->beside_pixels += px;
			}
		}
}

static void sure_shadows_lie_in_the_casters_shadows(void **state)
{
	(void)state;
	struct sure_tally t = {0};
	each_standard_setup(check_sure, &t);
	/* and at the animation's start, where the light near the wall and the light facing
	 * the camera have the default scene's casters reach behind the floor map's light */
	struct setup s;
	for (int c = 0; c < lx_config_count; c++)
		FOR_METHODS(method) {
			assert_true(lx_scene_builtin("default", &s.scene));
			lx_config_apply(&lx_configs[c], &s.scene);
			if (!build(&s, method, W, H, 0.0))
				continue;
			char what[96];
			snprintf(what, sizeof what, "default scene at time 0, %s, %s", lx_configs[c].name, method);
			check_sure(&s, what, &t);
			lx_meshes_free(&s.meshes);
		}
	/* and at the extremes */
	for (size_t k = 0; k < EXTREMES; k++)
		FOR_METHODS(method) {
			char what[96];
			if (!build_extreme(&s, k, method, what, sizeof what))
				continue;
			check_sure(&s, what, &t);
			lx_meshes_free(&s.meshes);
		}
	print_message("%ld sure shadows of a caster on a plane in a map (%ld of a box, the same from its bounds; %ld in "
		      "a plane map under a light near the wall or facing the camera, %ld pixels); %ld plane pixels inside "
		      "them, each in the caster's exact shadow and served by the map\n",
		      t.windows, t.boxes, t.beside_wall, t.beside_pixels, t.pixels);
	assert_true(t.boxes > 10);
	/* tested ray by ray, a box by its part in front of the light, and the polygon cut
	 * where the shadow runs past the eye: by the casters' farthest depth against the
	 * plane's nearest alone, 811 windows and 81,498 pixels, 2 and 1,187 of them beside
	 * the wall or facing the camera */
	assert_true(t.windows > 1000 && t.pixels > 120000);
	assert_true(t.beside_wall >= 6 && t.beside_pixels > 3000);
}

/* No sure shadow where it could be wrong: a table leg standing on the floor (the floor
 * meets its bottom, as deep in the map as the leg's nearest faces over it), a caster moved
 * below the floor (the floor then lies between it and the light), nor for a depth gap
 * wider than the whole depth range; and a caster well above the floor has one. */
static void no_sure_shadow_where_a_caster_touches_or_passes_the_plane(void **state)
{
	(void)state;
	static float pts[3 * 4096];
	struct setup s;
	assert_true(lx_scene_builtin("table", &s.scene));
	assert_true(build(&s, "uniform", W, H, 0.4));
	const struct lx_shadow_map *map = &s.res.maps[0];
	const struct lx_region *g = &s.atlas.regions[map->region];
	const int floor = 1, sphere = 7;
	assert_string_equal(s.scene.planes[floor].name, "floor");
	assert_int_equal(s.scene.casters[sphere - s.scene.plane_count].shape, LX_SPHERE);
	struct lx_poly win;
	for (int leg = 3; leg <= 6; leg++)
		assert_false(lx_sure_shadow_window(&s.frame, map, g->w, g->h, leg, pts, NULL, mesh_corners(&s, leg, pts, 4096),
						  floor, LX_LOOKUP_MARGIN_HIGHP, 1e-6, &win));
	int n = mesh_corners(&s, sphere, pts, 4096);
	assert_true(lx_sure_shadow_window(&s.frame, map, g->w, g->h, sphere, pts, NULL, n, floor, LX_LOOKUP_MARGIN_HIGHP,
					  1e-6, &win));
	assert_true(win.n >= 3);
	assert_false(lx_sure_shadow_window(&s.frame, map, g->w, g->h, sphere, pts, NULL, n, floor, LX_LOOKUP_MARGIN_HIGHP,
					   2.0, &win));
	assert_int_equal(win.n, 0);
	double down = s.frame.offset[sphere].y + 5; /* 5 m under the floor */
	s.frame.offset[sphere].y -= down, s.frame.bmin[sphere].y -= down, s.frame.bmax[sphere].y -= down;
	assert_false(lx_sure_shadow_window(&s.frame, map, g->w, g->h, sphere, pts, NULL, n, floor, LX_LOOKUP_MARGIN_HIGHP,
					   1e-6, &win));
	lx_meshes_free(&s.meshes);
}

/* A plane map's screen rectangle as the main pass cuts the plane at it: every pixel whose
 * centre lies in the map's rectangle inside, a pixel of margin, and edges on whole blocks
 * (LX_SPAN_ALIGN) but at the window's own edges, no more than a block out. */
static void check_map_rect(const struct lx_shadow_map *map, int width, int height, const char *what)
{
	struct lx_rect r;
	assert_true(lx_map_screen_rect(map, width, height, &r));
	double want[4] = {fmax(0, floor(map->screen[0]) - 1), fmax(0, floor(map->screen[1]) - 1),
			  fmin(width, ceil(map->screen[2]) + 1), fmin(height, ceil(map->screen[3]) + 1)};
	int got[4] = {r.x0, r.y0, r.x1, r.y1}, lim[4] = {0, 0, width, height};
	for (int k = 0; k < 4; k++) {
		bool out = k < 2 ? got[k] <= want[k] : got[k] >= want[k];
		bool near = fabs(got[k] - want[k]) < LX_SPAN_ALIGN;
		bool whole = got[k] % LX_SPAN_ALIGN == 0 || got[k] == lim[k];
		if (!out || !near || !whole)
			fail_msg("%s: the map's rectangle %.2f %.2f %.2f %.2f in a %dx%d window cut at %d %d %d %d", what,
				 map->screen[0], map->screen[1], map->screen[2], map->screen[3], width, height, r.x0, r.y0,
				 r.x1, r.y1);
	}
}

static void check_map_rects(struct setup *s, const char *what, void *ctx)
{
	long *n = ctx, *sure = n + 1;
	for (int m = 0; m < s->res.map_count; m++) {
		const struct lx_shadow_map *map = &s->res.maps[m];
		struct lx_rect r;
		if (!map->rendered || map->plane < 0 || !lx_map_screen_rect(map, W, H, &r))
			continue; /* the main pass cuts a plane only at these (plane_spans) */
		check_map_rect(map, W, H, what);
		check_map_rect(map, W + 3, H + 1, what); /* a window whose sides are not whole blocks */
		/* its sure part: on whole blocks, inside the rectangle a pixel and two lixels in */
		struct lx_rect q = lx_map_sure_rect(map, W, H);
		if (q.x1 > q.x0 && q.y1 > q.y0) {
			int got[4] = {q.x0, q.y0, q.x1, q.y1};
			for (int k = 0; k < 4; k++)
				if (got[k] % LX_SPAN_ALIGN != 0 || (k < 2 ? got[k] < map->screen[k] + 2 : got[k] > map->screen[k] - 2))
					fail_msg("%s: the map's sure rectangle %d %d %d %d of %.2f %.2f %.2f %.2f", what, q.x0,
						 q.y0, q.x1, q.y1, map->screen[0], map->screen[1], map->screen[2],
						 map->screen[3]);
			(*sure)++;
		}
		(*n)++;
	}
}

static void map_rects_end_on_whole_blocks(void **state)
{
	(void)state;
	long n[2] = {0, 0}; /* maps, and those with a sure part */
	each_standard_setup(check_map_rects, n);
	/* by hand: 5.5 -> 4 (the margin's 4), 7.2 -> 6 -> 4, 100.1 -> 102 -> 104, past the
	 * window's 102, 50 -> 51 -> 52 */
	struct lx_shadow_map map = {.has_screen = true, .screen = {5.5, 7.2, 100.1, 50.0}};
	struct lx_rect r;
	assert_true(lx_map_screen_rect(&map, 102, 60, &r));
	assert_int_equal(r.x0, 4), assert_int_equal(r.y0, 4), assert_int_equal(r.x1, 102), assert_int_equal(r.y1, 52);
	/* a rectangle reaching off the window on every side: the window */
	map = (struct lx_shadow_map){.has_screen = true, .screen = {-1e30, -3.5, 1e30, 1e9}};
	assert_true(lx_map_screen_rect(&map, 102, 60, &r));
	assert_int_equal(r.x0, 0), assert_int_equal(r.y0, 0), assert_int_equal(r.x1, 102), assert_int_equal(r.y1, 60);
	/* one that does not say where it reaches: no rectangle */
	map.screen[2] = NAN;
	assert_false(lx_map_screen_rect(&map, 102, 60, &r));
	map = (struct lx_shadow_map){.has_screen = true, .screen = {10, 20, 5, 30}};
	assert_false(lx_map_screen_rect(&map, 102, 60, &r));
	map.screen[2] = 15, map.has_screen = false;
	assert_false(lx_map_screen_rect(&map, 102, 60, &r));
	print_message("%ld plane maps' screen rectangles cut the plane on whole blocks, %ld sure parts inside them\n",
		      n[0], n[1]);
	assert_true(n[0] >= 20);
	assert_true(n[1] >= 10);
	/* not served where its screen rectangle lies: no sure part */
	map = (struct lx_shadow_map){.has_screen = true, .screen = {0, 0, 100, 50}, .lixel_scale = 1, .lixel_stretch = 1};
	r = lx_map_sure_rect(&map, 102, 60);
	assert_true(r.x1 <= r.x0 || r.y1 <= r.y0);
	/* served at a lixel per pixel: 4 pixels in (two and two lixels), then blocks */
	map.screen_served = true;
	r = lx_map_sure_rect(&map, 102, 60);
	assert_int_equal(r.x0, 4), assert_int_equal(r.y0, 4), assert_int_equal(r.x1, 96), assert_int_equal(r.y1, 44);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(shadowed_points_are_looked_up),
		cmocka_unit_test(extremes_stay_conservative),
		cmocka_unit_test(plane_pieces_cover_the_plane_once),
		cmocka_unit_test(merged_spans_keep_their_pixels),
		cmocka_unit_test(held_rectangles_are_whole_pieces),
		cmocka_unit_test(casters_keep_the_maps_they_read),
		cmocka_unit_test(caster_parts_out_of_reach),
		cmocka_unit_test(casters_left_out_only_where_unread),
		cmocka_unit_test(legs_left_out_under_the_slab),
		cmocka_unit_test(box_volumes_hold_their_drawn_faces),
		cmocka_unit_test(lit_plane_fronts_shadow_what_lies_beyond),
		cmocka_unit_test(two_fronts_over_an_object_are_both_tested),
		cmocka_unit_test(a_flat_box_pair_is_its_box),
		cmocka_unit_test(sure_shadows_lie_in_the_casters_shadows),
		cmocka_unit_test(no_sure_shadow_where_a_caster_touches_or_passes_the_plane),
		cmocka_unit_test(map_rects_end_on_whole_blocks),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
