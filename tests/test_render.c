/* Render tests on both GL platforms against the exact reference. */
#include "configs.h"
#include "depth_rgba.h"
#include "gl_program.h"
#include "method_run.h"
#include "metrics.h"
#include "overlay.h"
#include "png_in.h"
#include "png_out.h"
#include "embedded.h"
#include "platform.h"
#include "reference.h"
#include "render_job.h"
#include "renderer.h"
#include "test_util.h"
#include "gl_fixture.h"
#include "lookup_check.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>


static const char *const platforms[] = {"osmesa", "egl"};
enum { W = 320, H = 240 };

/* The platform run_path renders on, made once per test and per kind (a new context and
 * its start-up cost for every render made most of this file's time); the teardown
 * closes it, so tests that make platforms of their own find none current. */
static struct lx_platform *shared;

static struct lx_platform *shared_platform(const char *name)
{
	char err[512];
	if (shared && strcmp(shared->name, name)) {
		lx_platform_destroy(shared);
		shared = NULL;
	}
	if (!shared && !(shared = lx_platform_create(name, err, sizeof err)))
		fail_msg("%s: %s", name, err);
	return shared;
}

static int close_shared_platform(void **state)
{
	(void)state;
	lx_platform_destroy(shared);
	shared = NULL;
	return 0;
}

/* The exact references cast so far, by scene, size, time and drawn lights: this file
 * measures each view with many methods and on two platforms, and casting the same
 * reference again was a third of its time. An entry serves only a scene byte for byte
 * the same (padding that differs costs a cast, never a wrong reference). */
struct cached_reference {
	struct lx_scene scene;
	double time;
	struct lx_reference_images images;
};
enum { REFERENCE_CACHE = 48 };
static struct cached_reference reference_cache[REFERENCE_CACHE];
static int reference_cache_next;
static long reference_hits, reference_casts;

static int drawn_lights(const struct lx_render_job *job)
{
	struct lx_method_options o = LX_METHOD_OPTIONS_DEFAULT;
	char err[256];
	if (!lx_shadow_method_spec(job->method, &o, err, sizeof err))
		fail_msg("%s", err);
	return lx_method_lights(&o, &job->scene);
}

static const struct lx_reference_images *cached_reference(const struct lx_render_job *job)
{
	int lights = drawn_lights(job);
	for (int i = 0; i < REFERENCE_CACHE; i++) {
		const struct cached_reference *c = &reference_cache[i];
		if (c->images.object && c->images.width == job->width && c->images.height == job->height &&
		    c->images.lights == lights && c->time == job->time && !memcmp(&c->scene, &job->scene, sizeof c->scene))
			return &c->images;
	}
	return NULL;
}

static void reference_cache_free(struct cached_reference *c)
{
	free((void *)c->images.object), free((void *)c->images.shadow), free((void *)c->images.rgba);
	c->images = (struct lx_reference_images){0};
}

/* The reference a measured report with its pixels kept has just cast, for the next runs. */
static void reference_cache_add(const struct lx_render_job *job, const struct lx_render_report *r)
{
	struct cached_reference *c = &reference_cache[reference_cache_next++ % REFERENCE_CACHE];
	reference_cache_free(c);
	size_t n = (size_t)job->width * job->height;
	int16_t *object = malloc(n * sizeof(int16_t));
	uint8_t *shadow = malloc(n * r->light_count), *rgba = malloc(n * 4);
	assert_true(object && shadow && rgba);
	memcpy(object, r->ref_object, n * sizeof(int16_t));
	memcpy(shadow, r->ref_shadow, n * r->light_count);
	memcpy(rgba, r->ref_rgba, n * 4);
	memcpy(&c->scene, &job->scene, sizeof c->scene);
	c->time = job->time;
	c->images = (struct lx_reference_images){job->width, job->height, r->light_count, object, shadow, rgba};
}

static int reference_cache_clear(void **state)
{
	(void)state;
	for (int i = 0; i < REFERENCE_CACHE; i++)
		reference_cache_free(&reference_cache[i]);
	print_message("references: %ld cast, %ld taken from the cache\n", reference_casts, reference_hits);
	return 0;
}

/* lx_render_run with the job's reference from the cache when it was cast before (a
 * measured job that keeps its pixels), and into the cache when not. */
static int render_run_cached(struct lx_render_job *job, struct lx_render_report *rep, char *err, size_t errlen)
{
	bool cacheable = job->measure && job->keep_pixels && !job->reference;
	if (cacheable)
		job->reference = cached_reference(job);
	int st = lx_render_run(job, rep, err, errlen);
	if (cacheable && !st) {
		if (job->reference)
			reference_hits++;
		else
			reference_casts++, reference_cache_add(job, rep);
	}
	return st;
}

static void run_path(const char *platform, const char *method, const struct lx_scene *scene, bool mediump,
		     struct lx_render_report *rep)
{
	struct lx_render_job job = {.method = method, .platform = platform, .platform_in_use = shared_platform(platform),
				    .scene = *scene, .width = W, .height = H,
				    .time = 0.4, .warmup_frames = 0, .timed_frames = 1, .measure = true,
				    .keep_pixels = true, .bias_codes = LX_DEFAULT_BIAS_CODES, .reference_threads = 2,
				    .depth_precision = mediump ? LX_DEPTH_MEDIUMP : LX_DEPTH_AUTO};
	char err[512];
	int st = render_run_cached(&job, rep, err, sizeof err);
	if (st)
		fail_msg("%s/%s: %s", platform, method, err);
}

static void run(const char *platform, const char *method, const struct lx_scene *scene, struct lx_render_report *rep)
{
	run_path(platform, method, scene, false, rep);
}

/* One frame of a method on OSMesa at w x h, at `time`, on a depth path, measured or not
 * (the decision is kept either way). */
static void run_frame(const char *method, const struct lx_scene *scene, int w, int h, double time,
		      enum lx_depth_precision path, bool measure, struct lx_render_report *rep)
{
	struct lx_render_job job = {.method = method, .platform = "osmesa", .scene = *scene, .width = w, .height = h,
				    .time = time, .timed_frames = 1, .measure = measure, .keep_pixels = true,
				    .bias_codes = LX_DEFAULT_BIAS_CODES, .reference_threads = 2, .depth_precision = path};
	char err[512];
	if (render_run_cached(&job, rep, err, sizeof err))
		fail_msg("%s %dx%d: %s", method, w, h, err);
}

/* One measured frame of a method on OSMesa at a size of its own, at time 0. */
static void run_sized(const char *method, const struct lx_scene *scene, int w, int h, struct lx_render_report *rep)
{
	run_frame(method, scene, w, h, 0, LX_DEPTH_AUTO, true, rep);
}

/* A method's mismatch (%) on the scene at w x h (run_sized). */
static double mismatch_pct_of(const char *method, const struct lx_scene *scene, int w, int h)
{
	struct lx_render_report r;
	run_sized(method, scene, w, h, &r);
	double pct = r.mismatch.mismatch_pct;
	lx_render_report_free(&r);
	return pct;
}

/* Chessboard distance from each pixel to the nearest reference edge of light l (a pixel
 * whose 4-neighbour differs in visible object or shadow state), capped at `cap`. A pixel
 * on the image's border counts as one: its neighbour past the border is out of sight,
 * and a shadow's edge there (half a pixel out, on the paper's bad case) is still an edge. */
static void edge_distance(const struct lx_render_report *r, int l, uint8_t *dist, int cap)
{
	const uint8_t *ref_shadow = r->ref_shadow + (size_t)l * W * H;
	for (int y = 0; y < H; y++)
		for (int x = 0; x < W; x++) {
			long i = (long)y * W + x;
			bool edge = false;
			static const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
			for (int k = 0; k < 4; k++) {
				int nx = x + dx[k], ny = y + dy[k];
				if (nx < 0 || ny < 0 || nx >= W || ny >= H) {
					edge = true;
					continue;
				}
				long j = (long)ny * W + nx;
				edge |= r->ref_object[j] != r->ref_object[i] || ref_shadow[j] != ref_shadow[i];
			}
			dist[i] = edge ? 0 : (uint8_t)cap;
		}
	for (int pass = 0; pass < cap; pass++) /* grow the edge set one ring per pass */
		for (int y = 0; y < H; y++)
			for (int x = 0; x < W; x++) {
				long i = (long)y * W + x;
				if (dist[i] != pass)
					continue;
				for (int oy = -1; oy <= 1; oy++)
					for (int ox = -1; ox <= 1; ox++) {
						int nx = x + ox, ny = y + oy;
						if (nx >= 0 && ny >= 0 && nx < W && ny < H && dist[(long)ny * W + nx] > pass + 1)
							dist[(long)ny * W + nx] = (uint8_t)(pass + 1);
					}
			}
}

/* The uniform map against the reference on the standard configurations.
 * Bounds: a lixel spans at most m_max pixels on a plane, so a shadow edge sampled by
 * the map can be misplaced by about m_max pixels; every mismatch must lie within
 * ceil(m_max) + 2 pixels of a true edge (the 2 covers the edge pixel itself and the
 * lixel-centre rounding). No mismatch far from an edge means no acne, no leaks and no
 * clipped caster. In total they stay under 0.5% of the compared pixels (0.16% at
 * worst measured at this size, in the configuration facing the light). */
/* The largest number of pixels one lixel spans on any plane pixel, whichever of light l's
 * maps serves it: the report's plane figures (lx_measure samples each pixel with the map
 * the shader reads for it), at least 1. */
static double worst_m(const struct lx_render_report *r, int l)
{
	double worst = 1;
	for (int p = 0; p < r->plane_count; p++)
		if (r->light[l].planes[p].present)
			worst = fmax(worst, r->light[l].planes[p].s.m_max);
	return worst;
}

/* The pixels whose visible object differs from the exact reference's away from the
 * reference's own object edges (no pixel within two of it shows another object there):
 * none may, since what the main pass leaves out (a plane's part another plane in front
 * hides, lx_frame_plane_hides) must be hidden indeed. */
static long objects_off_edges(const struct lx_render_report *r)
{
	long off = 0;
	for (int y = 0; y < H; y++)
		for (int x = 0; x < W; x++) {
			long i = (long)y * W + x;
			if (r->ref_object[i] == r->object[i])
				continue;
			bool edge = false;
			for (int dy = -2; dy <= 2 && !edge; dy++)
				for (int dx = -2; dx <= 2 && !edge; dx++) {
					int u = x + dx, v = y + dy;
					edge = u < 0 || v < 0 || u >= W || v >= H || r->ref_object[(long)v * W + u] != r->ref_object[i];
				}
			off += !edge;
		}
	return off;
}

/* Light l's mismatches of a report: each within the edge bound, their count the
 * report's, under max_pct of the compared pixels, which are at least min_share of the
 * view; the visible objects the reference's but along its edges. Returns the mismatch. */
static double check_light(const struct lx_render_report *r, int l, const char *what,
			  uint8_t *dist, double max_pct, double min_share)
{
	const struct lx_mismatch *mm = &r->light[l].mismatch;
	for (int k = 0; k < r->light[l].result.map_count; k++)
		assert_true(m4_finite(&r->light[l].result.maps[k].light_clip));
	double m_max = worst_m(r, l);
	int reach = (int)ceil(m_max) + 2;
	if (reach > 250)
		reach = 250;
	edge_distance(r, l, dist, reach + 1);
	const uint8_t *ref_shadow = r->ref_shadow + (size_t)l * W * H, *shadow = r->shadow + (size_t)l * W * H;
	long far = 0, n = 0;
	int worst = 0;
	for (long i = 0; i < (long)W * H; i++)
		if (r->ref_object[i] >= 0 && r->ref_object[i] == r->object[i] && ref_shadow[i] != LX_REF_EDGE_ON &&
		    ref_shadow[i] != LX_REF_UNLIT && ref_shadow[i] != shadow[i]) {
			n++;
			worst = dist[i] > worst ? dist[i] : worst;
			far += dist[i] > reach;
		}
	print_message("%s light %d: mismatch %.3f%% (false %.3f%%, missing %.3f%%) of %ld; m_max %.2f; "
		      "worst distance to an edge %d px (allowed %d); %ld beyond\n",
		      what, l + 1, mm->mismatch_pct, mm->false_shadow_pct, mm->missing_shadow_pct, mm->compared, m_max, worst,
		      reach, far);
	assert_int_equal(n, mm->false_shadow + mm->missing_shadow);
	long off = objects_off_edges(r);
	if (off)
		fail_msg("%s: %ld pixels show another object than the reference's away from its edges", what, off);
	assert_true(mm->compared > min_share * W * H);
	assert_int_equal(far, 0);
	assert_true(mm->mismatch_pct < max_pct);
	return mm->mismatch_pct;
}

/* The share of the pixels compared must be at least min_share (the scene's receivers in
 * view, less what the light does not reach); *colour_error, when given, gets the frame's. */
static double check_against_reference_where(const char *platform, const char *method, const struct lx_scene *scene,
					    const char *config, bool mediump, uint8_t *dist, double max_pct,
					    double min_share, double *colour_error)
{
	struct lx_render_report r;
	run_path(platform, method, scene, mediump, &r);
	if (colour_error)
		*colour_error = r.colour_error;
	char what[96];
	snprintf(what, sizeof what, "%-6s %-7s %-7s %-12s", platform, method, mediump ? "mediump" : "highp", config);
	double pct = check_light(&r, 0, what, dist, max_pct, min_share);
	lx_render_report_free(&r);
	return pct;
}

static double check_against_reference(const char *platform, const char *method, const struct lx_scene *scene,
				      const char *config, bool mediump, uint8_t *dist, double max_pct)
{
	return check_against_reference_where(platform, method, scene, config, mediump, dist, max_pct, 0.25, NULL);
}

/* A spotlight and a projector [Segal], with every method of the registry but none: the
 * shadows against the exact reference, as for a point light (only near true edges, under
 * 0.5% of the compared pixels, PSM 2%), and the shaded frame against the reference's
 * shading of the light's beam or slide (colour_error under half a level of 255). */
static void projective_lights_match_reference(void **state)
{
	(void)state;
	uint8_t *dist = malloc((size_t)W * H);
	assert_non_null(dist);
	for (int sc = 0; sc < 2; sc++)
		for (int m = 0; m < lx_shadow_method_count(); m++) {
			const char *name = lx_shadow_method_at(m)->name, *scene_name = sc ? "projector" : "spotlight";
			if (!strcmp(name, "none"))
				continue;
			struct lx_scene scene;
			assert_true(lx_scene_builtin(scene_name, &scene));
			double colour;
			/* each light reaches a sixth of the view or more, and most of what it misses is unlit */
			check_against_reference_where("osmesa", name, &scene, scene_name, false, dist,
						      strcmp(name, "psm") ? 0.5 : 2.0, 1.0 / 8, &colour);
			print_message("%-9s %-7s colour_error %.4f levels\n", scene_name, name, colour);
			assert_true(colour < 0.5);
		}
	free(dist);
}

/* One method on a two-light scene (see two_lights_add_up): figures and images; `reach`
 * the least share of the view the second light reaches. */
static void two_lights_case(const struct lx_scene *two, const char *name, const char *dir, uint8_t *dist, double reach)
{
	struct lx_scene one = *two;
	one.light_count = 1;
	char spec[3][32], path[4][64]; /* the images; path[3] the reference's */
	const struct lx_scene *scenes[3] = {two, two, &one};
	snprintf(spec[0], sizeof spec[0], "%s", name);
	snprintf(spec[1], sizeof spec[1], "%s/lights1", name);
	snprintf(spec[2], sizeof spec[2], "%s", name);
	struct lx_image im[4];
	long wrong = 0; /* the pixels a decision or the visible object may make differ */
	snprintf(path[3], sizeof path[3], "%s/ref.png", dir);
	for (int k = 0; k < 3; k++) {
		snprintf(path[k], sizeof path[k], "%s/%d.png", dir, k);
		struct lx_render_job job = {.method = spec[k], .platform = "osmesa", .platform_in_use = shared_platform("osmesa"),
					    .scene = *scenes[k], .width = W, .height = H, .time = 0.4, .timed_frames = 1,
					    .measure = k == 0, .keep_pixels = k == 0, .bias_codes = LX_DEFAULT_BIAS_CODES,
					    .reference_threads = 2, .out_png = path[k], .reference_png = k == 0 ? path[3] : NULL};
		struct lx_render_report r;
		char err[512];
		if (render_run_cached(&job, &r, err, sizeof err))
			fail_msg("%s: %s", spec[k], err);
		assert_int_equal(r.light_count, k == 0 ? 2 : 1);
		if (k == 0)
			wrong = r.mismatch.false_shadow + r.mismatch.missing_shadow + r.mismatch.silhouette;
		if (k == 0) {
			/* each light warns or matches: a light the method warns about (PSM's spotlight
			 * behind the eye: "one lixel spans 187 pixels") keeps only the edge bound */
			for (int l = 0; l < 2 && strcmp(name, "none"); l++)
				check_light(&r, l, name, dist,
					    r.light[l].result.warning_count ? INFINITY : strcmp(name, "psm") ? 0.5 : 2.0, reach);
			struct lx_mismatch sum = r.light[0].mismatch;
			lx_mismatch_add(&sum, &r.light[1].mismatch);
			assert_int_equal(r.mismatch.compared, sum.compared);
			assert_int_equal(r.mismatch.false_shadow + r.mismatch.missing_shadow, sum.false_shadow + sum.missing_shadow);
			print_message("two lights %-7s colour_error %.4f levels\n", name, r.colour_error);
			if (strcmp(name, "none") && !r.light[0].result.warning_count && !r.light[1].result.warning_count)
				assert_true(r.colour_error < 0.5);
			lx_render_report_free(&r);
		}
		if (!lx_png_read(path[k], &im[k], err, sizeof err))
			fail_msg("%s", err);
		assert_true(im[k].width == W && im[k].height == H);
	}
	char err[512];
	if (!lx_png_read(path[3], &im[3], err, sizeof err))
		fail_msg("%s", err);
	/* against the reference's sum, pixel by pixel: off by more than 8 levels only where a
	 * decision or the visible object differs (a light lost over a part of the view shows) */
	long gross = 0;
	for (long i = 0; i < (long)W * H; i++) {
		int d = 0;
		for (int c = 0; c < 3; c++)
			d = abs(im[0].rgba[i * 4 + c] - im[3].rgba[i * 4 + c]) > d ? abs(im[0].rgba[i * 4 + c] - im[3].rgba[i * 4 + c]) : d;
		gross += d > 8;
	}
	print_message("two lights %-7s %ld pixels off by more than 8 levels, %ld decisions or objects differ\n", name, gross,
		      wrong);
	if (strcmp(name, "none"))
		assert_true(gross <= wrong);
	assert_memory_equal(im[1].rgba, im[2].rgba, (size_t)W * H * 4);
	long brighter = 0;
	for (long i = 0; i < (long)W * H * 4; i++) {
		if (im[0].rgba[i] < im[1].rgba[i])
			fail_msg("%s: the second light darkened byte %ld (%d < %d)", name, i, im[0].rgba[i], im[1].rgba[i]);
		brighter += im[0].rgba[i] > im[1].rgba[i];
	}
	assert_true(brighter > reach * W * H); /* bytes: the second light brightens its pixels */
	for (int k = 0; k < 4; k++)
		lx_image_free(&im[k]), remove(path[k]);
}

/* Two lights [Segal's additive passes], every method: each light's shadows against its
 * own reference as for one light (PSM 2%), the summed frame against the reference's sum
 * (colour_error under half a level), and the first light's pass untouched by the second:
 * the scene drawn with /lights1 is the scene of the first light alone, pixel for pixel,
 * and the second light only ever adds (it never darkens a channel, and it brightens the
 * pixels it reaches). Three times: the built-in scene's wide spotlight; a narrow one whose
 * pass is drawn only over its lit box's image (a cut that must lose no lit pixel); and a
 * spotlight behind the eye, lighting the floor around it, whose lit box reaches behind
 * the eye (no cut can be made from its corners then). */
static void two_lights_add_up(void **state)
{
	(void)state;
	uint8_t *dist = malloc((size_t)W * H);
	assert_non_null(dist);
	char dir[] = "/tmp/lixel-two-XXXXXX";
	assert_non_null(mkdtemp(dir));
	struct lx_scene wide, narrow;
	assert_true(lx_scene_builtin("twolights", &wide));
	narrow = wide;
	struct lx_light *spot = &narrow.lights[1];
	spot->position = v3(-1, 4.5, 1), spot->at = v3(-1, 0, 0), spot->fov_deg = 25, spot->range_far = 0;
	struct lx_scene behind = wide;
	behind.camera.eye = v3(0, 1.5, 2.5), behind.camera.at = v3(0, 0.8, -5);
	spot = &behind.lights[1];
	spot->position = v3(0.5, 4, 6), spot->at = v3(0, 0, 1), spot->fov_deg = 60, spot->range_far = 0;
	for (int m = 0; m < lx_shadow_method_count(); m++) {
		two_lights_case(&wide, lx_shadow_method_at(m)->name, dir, dist, 1.0 / 8);
		two_lights_case(&narrow, lx_shadow_method_at(m)->name, dir, dist, 1.0 / 100);
		two_lights_case(&behind, lx_shadow_method_at(m)->name, dir, dist, 1.0 / 8);
	}
	rmdir(dir);
	free(dist);
}

static double check_config(const char *platform, const char *method, const char *config, bool mediump, uint8_t *dist)
{
	struct lx_scene scene;
	lx_scene_default(&scene);
	lx_config_apply(lx_config_find(config), &scene);
	/* PSM is known to deteriorate ([Martin-PSM]): with the camera level, the wall's lixels
	 * span up to 15 pixels; its edge bound stays as strict, its total bound is 2% */
	return check_against_reference(platform, method, &scene, config, mediump, dist, strcmp(method, "psm") ? 0.5 : 2.0);
}

static void uniform_matches_reference(void **state)
{
	(void)state;
	uint8_t *dist = malloc((size_t)W * H);
	for (size_t p = 0; p < 2; p++)
		for (int c = 0; c < lx_config_count; c++) /* every standard configuration */
			check_config(platforms[p], "uniform", lx_configs[c].name, false, dist);
	free(dist);
}

/* The plane-optimal method under the same bounds, on every configuration and the table
 * scene; and where the paper says it wins (long shadows, the light facing the camera,
 * a light near a plane, the camera low over the floor) it must beat uniform. At this
 * size every plane map has a lixel for every pixel. */
static void plane_matches_reference_and_wins(void **state)
{
	(void)state;
	static const char *const wins[] = {"low", "facing", "near-wall", "floor-close"};
	uint8_t *dist = malloc((size_t)W * H);
	for (size_t p = 0; p < 2; p++) {
		for (int c = 0; c < lx_config_count; c++)
			check_config(platforms[p], "plane", lx_configs[c].name, false, dist);
		struct lx_scene table;
		lx_scene_table(&table);
		check_against_reference(platforms[p], "plane", &table, "table", false, dist, 0.5);
		for (size_t c = 0; c < sizeof wins / sizeof wins[0]; c++) {
			double plane = check_config(platforms[p], "plane", wins[c], false, dist);
			double uniform = check_config(platforms[p], "uniform", wins[c], false, dist);
			if (!(plane < uniform))
				fail_msg("%s %s: plane-optimal mismatch %.4f%% is not below uniform's %.4f%%", platforms[p], wins[c],
					 plane, uniform);
		}
	}
	free(dist);
}

/* The table top is lit on the side its quad faces, so the shadow pass culls it and it
 * casts nothing through the maps; yet at 1920x1080 a row of pixels sees the slab's top
 * through the 1 mm gap under it, which the top hides from the light (the exact reference
 * shadows it). The cover test (plane_cover.h) shadows it in every method: no pixel of the
 * slab the reference shadows is lit, where without the test a row of about 580 was. */
/* Of the pixels showing objects lo..hi (the same object in the render) that the exact
 * reference has shadowed (in_shadow) or lit, how many the render decided otherwise;
 * *count counts them all. */
static long against_reference(const struct lx_render_report *r, int lo, int hi, bool in_shadow, long *count)
{
	long wrong = 0, n = (long)r->width * r->height;
	*count = 0;
	for (long i = 0; i < n; i++)
		if (r->ref_object[i] >= lo && r->ref_object[i] <= hi && r->object[i] == r->ref_object[i] &&
		    !r->ref_shadow[i] == !in_shadow) {
			(*count)++;
			wrong += !r->shadow[i] != !r->ref_shadow[i];
		}
	return wrong;
}

/* Of the pixels showing objects lo..hi in the exact reference's shadow, how many the
 * render lit; *shadowed counts them all. */
static long lit_in_reference_shadow(const struct lx_render_report *r, int lo, int hi, long *shadowed)
{
	return against_reference(r, lo, hi, true, shadowed);
}

static void a_lit_plane_front_shadows_what_lies_under_it(void **state)
{
	(void)state;
	static const char *const methods[] = {"uniform", "lispsm", "plane"};
	struct lx_scene table;
	lx_scene_table(&table);
	for (size_t k = 0; k < sizeof methods / sizeof methods[0]; k++) {
		struct lx_render_report r;
		run_sized(methods[k], &table, 1920, 1080, &r);
		long slab, lit = lit_in_reference_shadow(&r, table.plane_count, table.plane_count, &slab);
		print_message("table at 1920x1080, %s: %ld pixels of the slab in the exact reference's shadow, %ld of them "
			      "lit\n", methods[k], slab, lit);
		assert_true(slab >= 500);
		assert_int_equal(lit, 0);
		lx_render_report_free(&r);
	}
}

/* A flat box's pair of fronts (plane_cover.h) decides its whole shadow, and the slab is in
 * no map. The maps once decided the band the slab's thin sides throw on the legs' tops,
 * seen from close to the floor (over the whole image plane-optimal missed 117 shadowed
 * pixels, uniform 51, LiSPSM 39); the underside's test alone left them the rays that
 * enter and leave by the thin sides, and a lixel of false shadow along the slab's shadow
 * wherever its sides were drawn. The table with its slab and one leg (the other casters
 * gone, so that every shadow on the leg is the slab's or the table top's) from close to
 * the floor: not one of the leg's pixels in the exact reference's shadow is lit. The slab
 * alone under five standard configurations' lights: the floor is exact both ways, every
 * method (without the term for rays that pass through the thin sides, 2 floor pixels at
 * the shadow's corners lit on the default view, where the test stopped). */
static void a_flat_box_pair_decides_its_shadow(void **state)
{
	(void)state;
	static const char *const methods[] = {"uniform", "lispsm", "plane"};
	struct lx_scene table;
	lx_scene_table(&table);
	int np = table.plane_count, leg = np + 1;
	assert_true(table.casters[1].shape == LX_BOX && table.casters[1].size.x < 0.1); /* the first leg */
	table.caster_count = 2; /* the slab and that leg */
	struct lx_scene one_leg = table;
	lx_config_apply(lx_config_find("floor-close"), &one_leg);
	for (size_t k = 0; k < sizeof methods / sizeof methods[0]; k++) {
		struct lx_render_report r;
		run_sized(methods[k], &one_leg, 1024, 1024, &r);
		long shadowed, lit = lit_in_reference_shadow(&r, leg, leg, &shadowed);
		print_message("table with one leg, floor-close, 1024x1024, %s: %ld pixels of the leg in the exact "
			      "reference's shadow, %ld of them lit\n", methods[k], shadowed, lit);
		assert_true(shadowed > 1000);
		assert_int_equal(lit, 0);
		lx_render_report_free(&r);
	}
	table.caster_count = 1; /* the slab alone */
	/* and a low light from the side, whose rays through the thin sides shadow a wedge of
	 * floor between the two fronts' shadows, outside each: at 640x480 uniform left 68 of
	 * its pixels untested and lit (and plane-optimal 108 in the whole table) until the main
	 * pass tested the floor over the pair's hull (cover_spans) */
	static const char *const configs[] = {"default", "low", "floor-close", "near-wall", "directional", "side-low"};
	for (size_t c = 0; c < sizeof configs / sizeof configs[0]; c++)
		for (size_t k = 0; k < sizeof methods / sizeof methods[0]; k++) {
			struct lx_scene s = table;
			if (lx_config_find(configs[c]))
				lx_config_apply(lx_config_find(configs[c]), &s);
			else
				s.light.position = v3(4, 1.2, 1);
			struct lx_render_report r;
			bool side = !lx_config_find(configs[c]);
			run_sized(methods[k], &s, side ? 640 : 512, side ? 480 : 512, &r);
			long shadowed, lit, missing = lit_in_reference_shadow(&r, 1, 1, &shadowed),
					    false_shadow = against_reference(&r, 1, 1, false, &lit);
			print_message("the slab alone, %-11s %dx%d, %-7s floor: %ld of %ld shadowed pixels lit, %ld of %ld lit "
				      "ones shadowed\n", configs[c], r.width, r.height, methods[k], missing, shadowed,
				      false_shadow, lit);
			assert_true(shadowed > 100);
			assert_int_equal(missing, 0);
			assert_int_equal(false_shadow, 0);
			lx_render_report_free(&r);
		}
}

/* A shelf with nothing under it that casts into the maps (tests/data/shelf.scene): its
 * shadow on the floor and on the box is the cover test's alone, and exact, where every
 * method lit it all (3.87% of the compared pixels at 320x240). */
static void a_shelf_shadows_the_floor_without_a_caster(void **state)
{
	(void)state;
	static const char *const methods[] = {"uniform", "tsm", "plane"};
	struct lx_scene shelf;
	test_scene_load("shelf.scene", &shelf);
	for (size_t k = 0; k < sizeof methods / sizeof methods[0]; k++) {
		struct lx_render_report r;
		run_sized(methods[k], &shelf, 320, 240, &r);
		long shadowed = 0, n = (long)r.width * r.height;
		for (long i = 0; i < n; i++)
			shadowed += r.ref_object[i] == 0 && r.ref_shadow[i]; /* the floor in the reference's shadow */
		print_message("shelf at 320x240, %s: mismatch %.4f%% (%ld floor pixels in the shelf's and the box's shadow)\n",
			      methods[k], r.mismatch.mismatch_pct, shadowed);
		assert_true(shadowed > 1000);
		assert_true(r.mismatch.mismatch_pct <= 0.01);
		lx_render_report_free(&r);
	}
}

/* A slab alone over the floor: its pair of fronts decides its whole shadow, so
 * plane-optimal draws no map at all, and the floor, reading none, is still cut into
 * spans where the fronts' shadow has its edges (object_draws: drawn whole with their
 * tests it cost a 1024x1024 main pass 5.21 ms against 3.42). Every method's decision is
 * the reference's. */
static void a_slab_alone_needs_no_map(void **state)
{
	(void)state;
	static const char *const methods[] = {"uniform", "lispsm", "plane"};
	struct lx_scene s;
	memset(&s, 0, sizeof s);
	s.planes[s.plane_count++] = (struct lx_plane){.name = "floor", .corner = {-5, 0, 5}, .edge1 = {10, 0, 0},
						      .edge2 = {0, 0, -10}, .color = {0.8, 0.78, 0.72}};
	s.casters[s.caster_count++] = (struct lx_caster){.shape = LX_BOX, .size = {2, 0.04, 1.2}, .low = 1, .high = 1,
							 .period = 1, .color = {0.6, 0.5, 0.4}};
	s.light = lx_light_white(v3(1, 5, 2));
	s.light_count = 1;
	s.camera = (struct lx_camera){.eye = {0, 2.5, 4}, .at = {0, 0.3, 0}, .up = {0, 1, 0}, .fovy_deg = 60};
	for (size_t k = 0; k < sizeof methods / sizeof methods[0]; k++) {
		struct lx_render_report r;
		run_sized(methods[k], &s, 320, 240, &r);
		long shadowed = 0, n = (long)r.width * r.height;
		for (long i = 0; i < n; i++)
			shadowed += r.ref_object[i] == 0 && r.ref_shadow[i];
		int maps = 0;
		for (int m = 0; m < r.light[0].result.map_count; m++)
			maps += r.light[0].result.maps[m].rendered;
		print_message("a slab alone at 320x240, %s: mismatch %.4f%%, %ld floor pixels in its shadow, %d maps\n",
			      methods[k], r.mismatch.mismatch_pct, shadowed, maps);
		assert_true(shadowed > 1000);
		assert_true(r.mismatch.mismatch_pct <= 0.01);
		if (!strcmp(methods[k], "plane"))
			assert_int_equal(maps, 0);
		lx_render_report_free(&r);
	}
}

/* Inside the casters' shadows on the default view's floor plane-optimal draws without a
 * lookup (sure_shadow.h): of the pixels a map decides (lx_decision_served) a twentieth or
 * more ran none (at 640x480 the shadows span few of the 32-row bands the cut works in),
 * and the decisions stay exact against the reference. That they are the same as with
 * every pixel looked up is lookup_region_changes_no_decision's to check. */
static void sure_shadows_skip_lookups(void **state)
{
	(void)state;
	static const char *const methods[] = {"uniform", "plane"};
	struct lx_scene s;
	lx_scene_default(&s);
	for (size_t k = 0; k < sizeof methods / sizeof methods[0]; k++) {
		struct lx_render_report r;
		run_sized(methods[k], &s, 640, 480, &r);
		long n = (long)r.width * r.height, served = 0, looked = lround(r.lookup_pct / 100 * n);
		for (long i = 0; i < n; i++)
			served += r.served[i];
		print_message("default view at 640x480, %s: %ld pixels decided by a map, %ld of them by a lookup; "
			      "mismatch %.4f%%\n", methods[k], served, looked, r.mismatch.mismatch_pct);
		assert_true(served >= looked && looked > 0);
		if (!strcmp(methods[k], "plane")) /* uniform's coarser lixels leave it none here */
			assert_true(served - looked > served / 20);
		assert_true(r.mismatch.mismatch_pct <= 0.05);
		lx_render_report_free(&r);
	}
}

/* Two shelves stacked over the floor (tests/data/two-shelves.scene): the floor tests both
 * fronts, so the upper shelf's shadow where it falls outside the lower one's is kept (one
 * front per object lit a row of 275 pixels, 0.159% at 640x480, for every method). */
static void two_shelves_shadow_the_floor_both(void **state)
{
	(void)state;
	static const char *const methods[] = {"uniform", "lispsm", "plane"};
	struct lx_scene sh;
	test_scene_load("two-shelves.scene", &sh);
	for (size_t k = 0; k < sizeof methods / sizeof methods[0]; k++) {
		struct lx_render_report r;
		run_sized(methods[k], &sh, 320, 240, &r);
		print_message("two shelves at 320x240, %s: mismatch %.4f%%, missing %.4f%%\n", methods[k],
			      r.mismatch.mismatch_pct, r.mismatch.missing_shadow_pct);
		assert_true(r.mismatch.missing_shadow_pct <= 0.01);
		lx_render_report_free(&r);
	}
}

/* The paper's known bad case: the camera close to the (optimised) floor, looking at
 * shadows on a plane that is not optimised (a side wall, the scene's third plane, which
 * only the 128x128 fallback map serves). Measured and reported; asserted only that the
 * fallback map serves it and every mismatch stays within the edge bound. */
static void paper_bad_case_is_measured(void **state)
{
	(void)state;
	struct lx_scene s;
	lx_scene_default(&s);
	struct lx_plane *side = &s.planes[s.plane_count++];
	*side = (struct lx_plane){.name = "side", .corner = {5, 0, 5}, .edge1 = {0, 5, 0}, .edge2 = {0, 0, -10},
				  .color = {0.7, 0.8, 0.7}};
	s.camera.eye = v3(-0.5, 0.12, 2.5);
	s.camera.at = v3(5, 1.2, -1.5);
	s.light.position = v3(-2.5, 2.6, 1.5);
	uint8_t *dist = malloc((size_t)W * H);
	for (size_t p = 0; p < 2; p++) {
		/* no total bound here beyond the edge rule: a fallback lixel spans ~20 pixels */
		double plane = check_against_reference(platforms[p], "plane", &s, "bad-case", false, dist, 100);
		double uniform = check_against_reference(platforms[p], "uniform", &s, "bad-case", false, dist, 100);
		struct lx_render_report r;
		run(platforms[p], "plane", &s, &r);
		print_message("%s: paper's bad case: plane-optimal %.4f%% against uniform %.4f%%; side wall: %ld px, "
			      "m_max %.2f (fallback map)\n",
			      platforms[p], plane, uniform, r.light[0].planes[2].s.pixels, r.light[0].planes[2].s.m_max);
		assert_true(r.light[0].planes[2].present && r.light[0].result.maps[r.light[0].result.map_count - 1].rendered);
		lx_render_report_free(&r);
	}
	free(dist);
}

/* A random view (tools/random-views.py) at 1024x768 and `time`: plane-optimal's mismatch
 * within 0.01 points of uniform's (issue 9's bound). Returns the lixels of the first
 * plane's maps. */
static long plane_near_uniform(const struct lx_scene *s, double time, const char *what)
{
	double pct[2];
	long floor_lixels = 0;
	for (int m = 0; m < 2; m++) {
		struct lx_render_report r;
		run_frame(m ? "plane" : "uniform", s, 1024, 768, time, LX_DEPTH_AUTO, true, &r);
		pct[m] = r.mismatch.mismatch_pct;
		for (int k = 0; m && k < r.light[0].result.map_count; k++) {
			const struct lx_shadow_map *map = &r.light[0].result.maps[k];
			floor_lixels += map->rendered && map->plane == 0 ? (long)map->w * map->h : 0;
		}
		lx_render_report_free(&r);
	}
	print_message("%-36s plane %.4f%%, uniform %.4f%%: %+.4f points; the floor's maps %ld lixels\n", what, pct[1],
		      pct[0], pct[1] - pct[0], floor_lixels);
	if (!(pct[1] - pct[0] <= 0.01))
		fail_msg("%s: plane-optimal %.4f%% against uniform's %.4f%%", what, pct[1], pct[0]);
	return floor_lixels;
}

/* A plane without a map this frame hands its idle budget to the fallback
 * (test_plane idle_plane_budget_goes_to_the_fallback). Random views of
 * tools/random-views.py where the wall had no map and a caster near the eye read the
 * 128x128 fallback: view 186 of seed 7 at 640x480 (the box's lit side, 0.0458% against
 * uniform's 0.0112%) and view 156 of seed 11 at 1024x768 (the sphere's and the cone's
 * terminators, 0.0692% against 0.0181%). Each within 0.01 points of uniform now. */
static void idle_budget_serves_the_casters(void **state)
{
	(void)state;
	static const struct {
		vec3 eye, at, light;
		double time;
		int w, h;
	} views[] = {
		{{3.07023, 1.90226, -0.018996}, {-1.49423, 0.998694, -0.893653}, {-3.77015, 3.6115, 5.11981}, 1.09132, 640, 480},
		{{2.92289, 3.75639, 1.79489}, {0.909238, 0.993191, 0.0708277}, {5.8313, 1.60503, 5.50379}, 2.01133, 1024, 768},
	};
	for (size_t i = 0; i < sizeof views / sizeof views[0]; i++) {
		struct lx_scene s;
		lx_scene_default(&s);
		s.camera.eye = views[i].eye, s.camera.at = views[i].at, s.light.position = views[i].light;
		struct lx_render_report u, p;
		run_frame("uniform", &s, views[i].w, views[i].h, views[i].time, LX_DEPTH_AUTO, true, &u);
		run_frame("plane", &s, views[i].w, views[i].h, views[i].time, LX_DEPTH_AUTO, true, &p);
		int side = 0;
		for (int m = 0; m < p.light[0].result.map_count; m++)
			if (p.light[0].result.maps[m].rendered && p.light[0].result.maps[m].plane < 0)
				side = p.light[0].result.maps[m].w;
		print_message("view %zu: plane %.4f%% (the fallback %dx%d), uniform %.4f%%\n", i, p.mismatch.mismatch_pct, side,
			      side, u.mismatch.mismatch_pct);
		assert_true(side > 128);
		assert_true(p.mismatch.mismatch_pct <= u.mismatch.mismatch_pct + 0.01);
		lx_render_report_free(&u);
		lx_render_report_free(&p);
	}
}

/* Views where the plane method once lost shadows without a word (a caster's vertex
 * behind a plane map's light flattened onto its near plane, a plane's image mirrored
 * when the eye sees its unlit side, table legs and a sphere served by a foreshortened
 * floor map): on
 * each its mismatch stays within 0.05 percentage points of uniform's, or it says on
 * which plane it fell back. */
static void plane_keeps_every_shadow(void **state)
{
	(void)state;
	struct {
		const char *what;
		bool table, directional, eye_set;
		vec3 light, eye, at;
		const char *config;
	} cases[] = {
		{"light behind the wall", false, false, false, {0, 3, -7}, {0, 0, 0}, {0, 0, 0}, NULL},
		{"light below the floor", false, false, false, {0, -2, 0}, {0, 0, 0}, {0, 0, 0}, NULL},
		{"directional, towards the camera", false, true, false, {0, -0.2, 1}, {0, 0, 0}, {0, 0, 0}, NULL},
		{"light in front of the wall", false, false, false, {0, 1.5, -3}, {0, 0, 0}, {0, 0, 0}, NULL},
		{"eye at the wall, looking along it", false, false, true, {2.5, 6, 3}, {0, 1, -4.95}, {3, 1, -4.95}, NULL},
		{"table: eye below the top", true, false, true, {0, 0, 0}, {0, 0.5, 3}, {0, 0.5, 0}, NULL},
		{"table: floor-close", true, false, false, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}, "floor-close"},
		{"table: horizon", true, false, false, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}, "horizon"},
	};
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		struct lx_scene s;
		if (cases[i].table)
			lx_scene_table(&s);
		else
			lx_scene_default(&s);
		if (cases[i].config)
			lx_config_apply(lx_config_find(cases[i].config), &s);
		if (!cases[i].table || cases[i].directional) {
			s.light.directional = cases[i].directional;
			if (cases[i].directional)
				assert_true(v3_normalize(cases[i].light, &s.light.direction));
			else if (!cases[i].eye_set || !cases[i].table)
				s.light.position = cases[i].light;
		}
		if (cases[i].eye_set)
			s.camera.eye = cases[i].eye, s.camera.at = cases[i].at;
		struct lx_render_report u, p;
		run("osmesa", "uniform", &s, &u);
		run("osmesa", "plane", &s, &p);
		double diff = p.mismatch.mismatch_pct - u.mismatch.mismatch_pct;
		print_message("%-36s plane %.4f%% (missing %.4f%%), uniform %.4f%%: %+.4f points; colour_error %.3f, %.3f "
			      "levels%s%s\n",
			      cases[i].what, p.mismatch.mismatch_pct, p.mismatch.missing_shadow_pct, u.mismatch.mismatch_pct, diff,
			      p.colour_error, u.colour_error, p.light[0].result.warning_count ? "; " : "",
			      p.light[0].result.warning_count ? p.light[0].result.warnings[0] : "");
		/* The shading too, a plane turned away from the light (the light behind the wall,
		 * below the floor) included: its draws have no face test, their Lambert term
		 * leaves it unlit (main.frag) */
		assert_true(p.colour_error < 0.5 && u.colour_error < 0.5);
		/* Known gap: on the table seen from close to the floor the front legs' edges
		 * read their shadow from the 128x128 fallback or the floor map; measured +0.056
		 * points here (+0.035 at 1024x1024), against 0.74 points before. Held to 0.10
		 * points so that it cannot slide back unnoticed. */
		double allowed = cases[i].table && cases[i].config && !strcmp(cases[i].config, "floor-close") ? 0.10 : 0.05;
		if (!(diff <= allowed) && p.light[0].result.warning_count == 0)
			fail_msg("%s: plane-optimal %.4f%% against uniform's %.4f%%, and no warning", cases[i].what,
				 p.mismatch.mismatch_pct, u.mismatch.mismatch_pct);
		lx_render_report_free(&u);
		lx_render_report_free(&p);
	}
	/* The eye a millimetre above the floor, at the default size (at 320x240 the floor's
	 * band is too thin for a caster to pick its map): the sphere once read the floor map,
	 * three lixels tall there, and lost 10% of the pixels' shadows. It reads the 128x128
	 * fallback while it fills a third of the screen (beside a floor map three lixels
	 * tall): +0.039 points (+0.093 on older builds), +0.021 since the fallback keeps to
	 * what the view holds; within the issue's 0.05 points. */
	struct lx_scene s;
	lx_scene_default(&s);
	s.camera.eye = v3(0, 0.001, 3), s.camera.at = v3(0, 0.001, 0);
	double pct[2] = {mismatch_pct_of("uniform", &s, 1024, 768), mismatch_pct_of("plane", &s, 1024, 768)};
	print_message("%-36s plane %.4f%%, uniform %.4f%%: %+.4f points\n", "eye a millimetre above the floor", pct[1], pct[0],
		      pct[1] - pct[0]);
	if (!(pct[1] - pct[0] <= 0.05))
		fail_msg("eye a millimetre above the floor: plane-optimal %.4f%% against uniform's %.4f%%", pct[1], pct[0]);
	/* Random view 72 of the default scene (tools/random-views.py): no shadow in view falls
	 * on a plane, the fallback serves every one. With fixed budgets it kept its 128x128:
	 * 0.0302% against uniform's 0.0058% at 1024x768. A frame without a plane map now
	 * gives it every budget: within the issue's 0.01 points. */
	s.camera.eye = v3(1.65294, 4.75918, 0.0246814), s.camera.at = v3(-0.31962, 0.255539, 0.896479);
	s.light.position = v3(-4.29707, 1.31104, -3.39865);
	plane_near_uniform(&s, 1.96661, "no plane map in view (view 72)");
	/* Random view 32 (seed 7): the wall out of view, the floor's shadows over 205,000
	 * pixels. With its own 122,500 lixels alone the floor map gave 0.0650% against
	 * uniform's 0.0534%; it takes the wall's budget now (fixed budgets too). */
	s.camera.eye = v3(0.540502, 2.37015, -0.873426), s.camera.at = v3(-0.505506, 0.748712, -0.950951);
	s.light.position = v3(-5.22851, 6.9105, 3.88363);
	assert_true(plane_near_uniform(&s, 4.85848, "the floor alone short (view 32)") > 350L * 350);
	/* Random view 70 (seed 13): the sphere's shadow on the cylinder's top, which reads the
	 * fallback. The sphere, beside the light, once took most of the fallback though no
	 * caster reaches it: 0.0562% against uniform's 0.0353%. */
	s.camera.eye = v3(-0.611149, 2.02308, 0.333994), s.camera.at = v3(-0.646251, 1.00542, 0.85989);
	s.light.position = v3(-1.50432, 2.72382, -0.628421);
	plane_near_uniform(&s, 4.31861, "the cylinder's top (view 70)");
	/* Random view 132 (seed 13): the sphere near the eye hides most of its own shadow on
	 * the floor, whose map once spread 0.53 lixels per pixel over it too: 0.0429% against
	 * uniform's 0.0242%. The hidden floor takes no lixel now. */
	s.camera.eye = v3(-2.78897, 3.07978, 1.92653), s.camera.at = v3(-0.403308, 0.0241855, 0.946119);
	s.light.position = v3(-0.174909, 2.25104, 2.6265);
	plane_near_uniform(&s, 0.455596, "the floor behind the sphere (view 132)");
}

/* Short of a lixel per pixel a plane map stretches its lixels along the shadows' edges
 * (method_plane.c, chart_stretch, and fit_plane's snapping of the finer axis). The
 * default scene near the wall at 1920x1080, where the casters' shadows cover much of
 * the floor: the floor map is stretched, and fewer pixels are wrong than with square
 * lixels (plane/similar): measured 0.0269% against 0.0847% (uniform 0.1394%).
 * Until the floor took the budget of a wall without a map (fixed budgets too), the case
 * was the table under the low light at 1920x1080: 0.0085% against 0.0778%; it now has
 * a lixel per pixel there, 0.0004%, and nothing to stretch. */
static void stretched_maps_follow_long_shadows(void **state)
{
	(void)state;
	struct lx_scene s;
	lx_scene_default(&s);
	lx_config_apply(lx_config_find("near-wall"), &s);
	static const char *const methods[2] = {"plane", "plane/similar"};
	double pct[2], stretch[2];
	for (int k = 0; k < 2; k++) {
		struct lx_render_report r;
		run_sized(methods[k], &s, 1920, 1080, &r);
		pct[k] = r.mismatch.mismatch_pct;
		const struct lx_shadow_map *floor_map = &r.light[0].result.maps[0]; /* the floor */
		assert_true(floor_map->rendered && floor_map->plane == 0);
		stretch[k] = fmax(floor_map->lixel_stretch, 1 / floor_map->lixel_stretch);
		lx_render_report_free(&r);
	}
	print_message("default scene near the wall, plane stretched by %.3f: %.4f%%; square lixels: %.4f%%\n", stretch[0],
		      pct[0], pct[1]);
	assert_true(stretch[0] > 1.1 && stretch[1] == 1); /* finer along one axis, 1.1 times or more */
	assert_true(pct[0] < 0.8 * pct[1]);
}

/* Two rectangles over one plane may overlap (method_plane.c, plane_pieces) where the one
 * around every footprint holds more pixels than the plane's budget has lixels: on the
 * default scene under the light facing the camera, one rectangle gives the floor 0.25
 * lixels a pixel, 0.0902% mismatch; three, two of them overlapping, give it a lixel per
 * pixel, 0.0003%. Where pieces overlap, a pixel is drawn with each map and reads the
 * first that serves it. (The case was the table under the directional light, 0.0003%
 * against 0.0123%, until one rectangle less what the casters hide from the eye gave the
 * floor a lixel per pixel there too, take_hidden.) */
static void overlapping_pieces_give_a_lixel_per_pixel(void **state)
{
	(void)state;
	struct lx_scene s;
	lx_scene_default(&s);
	lx_config_apply(lx_config_find("facing"), &s);
	static const char *const methods[2] = {"plane", "plane/onepiece"};
	double pct[2], lpp[2];
	for (int k = 0; k < 2; k++) {
		struct lx_render_report r;
		run_sized(methods[k], &s, 1024, 1024, &r);
		pct[k] = r.mismatch.mismatch_pct;
		assert_true(r.light[0].planes[0].present);
		lpp[k] = r.light[0].planes[0].s.lpp_median;
		const struct lx_shadow_result *res = &r.light[0].result;
		int floor_maps = 0, overlaps = 0;
		for (int m = 0; m < res->map_count; m++) {
			const struct lx_shadow_map *a = &res->maps[m];
			if (!a->rendered || a->plane != 0)
				continue;
			floor_maps++;
			for (int n = m + 1; n < res->map_count; n++) {
				const struct lx_shadow_map *b = &res->maps[n];
				overlaps += b->rendered && b->plane == 0 && a->screen[0] < b->screen[2] && b->screen[0] < a->screen[2] &&
					    a->screen[1] < b->screen[3] && b->screen[1] < a->screen[3];
			}
		}
		assert_true(k == 1 || (floor_maps >= 2 && overlaps > 0)); /* the floor in pieces, some overlapping */
		lx_render_report_free(&r);
	}
	print_message("default scene, light facing the camera, 1024x1024: pieces %.4f%% (floor lpp %.3f), one %.4f%% (lpp %.3f)\n",
		      pct[0], lpp[0], pct[1], lpp[1]);
	assert_true(lpp[0] >= 1 - 1e-9 && lpp[1] < 1); /* a lixel per pixel but for the density's rounding */
	assert_true(pct[0] < 0.5 * pct[1]);
}

/* The default view at 1024x1024 (issue 9): every pixel of the floor and of the wall that
 * reads a map gets at least a lixel. The sampling counts only pixels that ran a lookup:
 * no shadow can fall on the wall where it is seen, it gets no map, and its pixels read
 * none, though the fallback's rectangle holds some of them (at 0.06 lixels a pixel when
 * they were counted). */
static void default_view_planes_get_a_lixel_per_pixel(void **state)
{
	(void)state;
	struct lx_scene s;
	lx_scene_default(&s);
	struct lx_render_report r;
	run_sized("plane", &s, 1024, 1024, &r);
	const struct lx_light_report *lr = &r.light[0];
	long n = 1024L * 1024, wall_looked = 0, wall_ref_shadowed = 0;
	for (long i = 0; i < n; i++)
		if (r.ref_object[i] == 1)
			wall_looked += r.served[i], wall_ref_shadowed += r.ref_shadow[i];
	const struct lx_plane_sampling *floor = &lr->planes[0].s, *wall = &lr->planes[1].s;
	print_message("default 1024x1024: floor %ld of %ld pixels read a map, lpp %.4g-%.4g; wall %ld pixels, "
		      "%ld looked up, %ld in the reference's shadow\n",
		      floor->pixels, floor->seen, floor->lpp_min, floor->lpp_max, wall->seen, wall_looked, wall_ref_shadowed);
	assert_true(lr->planes[0].present && floor->pixels > 10000);
	assert_true(floor->lpp_min >= 1 - 1e-9 && floor->m_max <= 1 + 1e-9);
	assert_true(wall->seen > 100000);
	/* the wall: any pixel that reads a map reads one with a lixel per pixel */
	assert_true(!lr->planes[1].present || wall->lpp_min >= 1 - 1e-9);
	assert_int_equal(wall->pixels + wall->no_lookup + wall->unserved + wall->degenerate, wall->seen);
	assert_true(wall_ref_shadowed == 0 || wall_looked > 0); /* shadows on it: it is looked up */
	lx_render_report_free(&r);
}

/* Pixels where plane-optimal's decision (or object) differs between the mediump and the
 * highp path, at w x h at the scene's time; *shadowed: highp's shadowed pixels. */
static long mediump_differs(const struct lx_scene *s, int w, int h, double time, long *shadowed)
{
	struct lx_render_report r[2];
	for (int k = 0; k < 2; k++) {
		run_frame("plane", s, w, h, time, k ? LX_DEPTH_MEDIUMP : LX_DEPTH_HIGHP, false, &r[k]);
		assert_non_null(r[k].shadow);
	}
	long differ = 0, n = (long)w * h;
	*shadowed = 0;
	for (long i = 0; i < n; i++) {
		*shadowed += r[0].shadow[i];
		differ += r[0].object[i] != r[1].object[i] || r[0].shadow[i] != r[1].shadow[i];
	}
	for (int k = 0; k < 2; k++)
		lx_render_report_free(&r[k]);
	return differ;
}

/* The mediump path (fp16) reads plane-optimal's maps at the lixels and depths the highp
 * path reads: main.frag's coordinates are taken from each map's centre and its far
 * depth, so the divide works on small numbers and the one rounding of the sum keeps a
 * lixel centre inside its lixel and a far depth within its code. On the table at
 * 1024x1024 the two paths' decisions differed at 113 pixels with the divide of the whole
 * coordinate, and at 7 with the origin; on a random view of the default scene (random
 * views' view 52, rows of lit pixels across a shadow on the floor), at 794 with the
 * centre alone and 48 with the far depth too. */
static void mediump_reads_the_lixels_highp_reads(void **state)
{
	(void)state;
	struct lx_scene s;
	lx_scene_table(&s);
	long shadowed, differ = mediump_differs(&s, 1024, 1024, 0, &shadowed);
	print_message("table, plane, 1024x1024: %ld shadowed pixels; mediump's decision differs at %ld\n", shadowed,
		      differ);
	assert_true(shadowed > 10000);
	assert_true(differ <= 30);
	lx_scene_default(&s);
	s.camera.eye = v3(3.19898, 4.85011, 2.14616), s.camera.at = v3(-0.694028, 0.251805, 0.782349);
	s.light = lx_light_white(v3(-3.47149, 4.48883, -2.58259));
	differ = mediump_differs(&s, 1024, 768, 2.62033, &shadowed);
	print_message("default, a random view, plane, 1024x768: %ld shadowed pixels; mediump's decision differs at %ld\n",
		      shadowed, differ);
	assert_true(shadowed > 10000);
	assert_true(differ <= 150);
}

/* PSM, LiSPSM, XPSM and TSM under the same edge bound on every configuration. */
static void warps_match_reference(void **state)
{
	(void)state;
	static const char *const warps[] = {"psm", "lispsm", "xpsm", "tsm"};
	uint8_t *dist = malloc((size_t)W * H);
	for (size_t p = 0; p < 2; p++)
		for (int c = 0; c < lx_config_count; c++)
			for (size_t m = 0; m < sizeof warps / sizeof warps[0]; m++)
				check_config(platforms[p], warps[m], lx_configs[c].name, false, dist);
	free(dist);
}

/* The 11-bit mediump depth path (boards without fragment highp) under the same bounds.
 * llvmpipe still computes in fp32, so this checks the path's layout and compare, while
 * test_depth_rgba checks its fp16 arithmetic. */
static void mediump_path_matches_reference(void **state)
{
	(void)state;
	static const char *const configs[] = {"default", "low", "directional"};
	uint8_t *dist = malloc((size_t)W * H);
	for (size_t p = 0; p < 2; p++)
		for (size_t c = 0; c < sizeof configs / sizeof configs[0]; c++)
			check_config(platforms[p], "uniform", configs[c], true, dist);
	free(dist);
}

static void none_shadows_nothing(void **state)
{
	(void)state;
	for (size_t p = 0; p < 2; p++) {
		struct lx_scene scene;
		lx_scene_default(&scene);
		struct lx_render_report r;
		run(platforms[p], "none", &scene, &r);
		long shadowed = 0, ref_shadowed = 0;
		for (long i = 0; i < (long)W * H; i++)
			shadowed += r.shadow[i], ref_shadowed += r.ref_shadow[i] == 1;
		assert_int_equal(shadowed, 0);
		assert_int_equal(r.light[0].result.map_count, 0);
		assert_true(ref_shadowed > 0); /* there were shadows to miss */
		assert_true(r.mismatch.missing_shadow_pct > 1.0);
		assert_near(r.mismatch.false_shadow_pct, 0, 0);
		/* the edge-distance check of uniform_matches_reference can fail: shadow
		 * interiors missed by `none` lie far from every edge */
		uint8_t *dist = malloc((size_t)W * H);
		edge_distance(&r, 0, dist, 10);
		long far = 0;
		for (long i = 0; i < (long)W * H; i++)
			far += r.ref_shadow[i] == 1 && !r.shadow[i] && r.ref_object[i] == r.object[i] && dist[i] > 3;
		print_message("%s: none misses %ld shadow pixels more than 3 px from an edge\n", platforms[p], far);
		assert_true(far > 100);
		free(dist);
		lx_render_report_free(&r);
	}
}

/* Pixels where footprint's decision (a, sa) differs from all's (b, sb); *wrong counts
 * those footprint may not change: any but a caster's pixel that all shadows and footprint
 * does not where no other object blocks the light (all read the caster's own texels:
 * footprint draws no lookup where only the receiver itself could shadow it). */
static long lookup_differences(const struct lx_frame *f, const int16_t *a, const uint8_t *sa, const int16_t *b,
			       const uint8_t *sb, long *wrong)
{
	long differ = 0, n = (long)f->view.width * f->view.height;
	struct lx_raycaster *rc = NULL;
	for (long i = 0; i < n; i++) {
		if (a[i] == b[i] && sa[i] == sb[i])
			continue;
		differ++;
		*wrong += !(a[i] == b[i] && own_texels(f, &rc, i, a[i], !sa[i] && sb[i]));
	}
	lx_raycaster_destroy(rc);
	return differ;
}

/* What the tests comparing two runs' decisions over every method share: an OSMesa
 * platform, two decision images of w x h and the RGBA scratch they are read through, and
 * the registry's method names ("|"-separated, for strtok_r). */
struct decisions {
	struct lx_platform *plat;
	struct lx_gl_caps caps;
	uint8_t *rgba, *sh[2];
	int16_t *obj[2];
	char names[128];
};

static struct decisions decisions_alloc(int w, int h)
{
	size_t n = (size_t)w * h;
	struct decisions d = {.rgba = malloc(n * 4), .sh = {malloc(n), malloc(n)},
			      .obj = {malloc(n * sizeof(int16_t)), malloc(n * sizeof(int16_t))}};
	assert_true(d.rgba && d.sh[0] && d.sh[1] && d.obj[0] && d.obj[1]);
	d.plat = platform_with_caps("osmesa", &d.caps);
	snprintf(d.names, sizeof d.names, "%s", lx_shadow_method_names());
	return d;
}

static void decisions_free(struct decisions *d)
{
	free(d->rgba), free(d->sh[0]), free(d->sh[1]), free(d->obj[0]), free(d->obj[1]);
	lx_platform_destroy(d->plat);
}

/* Both runs' shadow passes and decisions of one frame (w x h): the same object at every
 * pixel, asserted; returns how many pixels they decide otherwise, and adds the first run's
 * shadowed pixels to *shadowed. */
static long decide_both(struct decisions *dc, struct lx_method_run run[2], const struct lx_frame *f, int w, int h,
			long *shadowed)
{
	for (int k = 0; k < 2; k++) {
		lx_method_run_shadows(&run[k], f);
		lx_method_run_decision(&run[k], 0, dc->rgba, dc->obj[k], dc->sh[k]);
	}
	long d = 0;
	for (long i = 0; i < (long)w * h; i++) {
		assert_int_equal(dc->obj[0][i], dc->obj[1][i]);
		d += dc->sh[0][i] != dc->sh[1][i], *shadowed += dc->sh[0][i] != 0;
	}
	return d;
}

/* --lookup-region footprint (the default) draws without a lookup wherever no other
 * object's shadow can fall, and casters with only the maps that serve them: against
 * --lookup-region all, no pixel's decision or object may change but where all reads a
 * caster's own texels on its side turned to the light (the map's error at its
 * terminator), and the exact reference has those lit. Every method, every standard
 * configuration of both built-in scenes, on the highp and the mediump path (whose fp16
 * rounding differs). */
static void lookup_region_changes_no_decision(void **state)
{
	(void)state;
	enum { w = 256, h = 192 };
	char err[512];
	struct decisions dc = decisions_alloc(w, h);
	struct lx_gl_caps caps = dc.caps;
	uint8_t *rgba = dc.rgba, **sh = dc.sh;
	int16_t **obj = dc.obj;
	char *names = dc.names;
	long compared = 0, own = 0;
	for (const char *const *sn = (const char *const[]){"default", "table", NULL}; *sn; sn++) {
		struct lx_scene base;
		assert_true(lx_scene_builtin(*sn, &base));
		struct lx_scene_meshes meshes = {0};
		assert_true(lx_meshes_build(&base, &meshes));
		for (int mediump = 0; mediump < 2; mediump++) {
			char list[128];
			memcpy(list, names, sizeof list);
			for (char *save = NULL, *m = strtok_r(list, "|", &save); m; m = strtok_r(NULL, "|", &save)) {
				/* 0: footprint, 1: all (the same run, its maps drawn once), 2: footprint with the
				 * atlas cleared whole (a tiler's way: a run of its own) */
				struct lx_method_run run[2];
				long looked[3] = {0, 0, 0};
				for (int k = 0; k < 2; k++) {
					struct lx_method_options o = LX_METHOD_OPTIONS_DEFAULT;
					o.depth_slots = 1; /* both cleared every frame (slots: their own test) */
					if (k == 1)
						setenv("LIXEL_CLEAR_WHOLE_ATLAS", "1", 1);
					if (lx_method_run_init(&run[k], m, &base, &meshes, &caps, &o, w, h,
							       mediump ? LX_DEPTH_MEDIUMP : LX_DEPTH_AUTO,
							       LX_DEFAULT_BIAS_CODES, false, err, sizeof err))
						fail_msg("%s: %s", m, err);
					unsetenv("LIXEL_CLEAR_WHOLE_ATLAS");
				}
				for (int c = 0; c < lx_config_count; c++) {
					struct lx_scene scene = base;
					lx_config_apply(&lx_configs[c], &scene);
					struct lx_frame frame;
					assert_true(lx_frame_setup(&frame, &scene, &meshes, 0.4, w, h, err, sizeof err));
					for (int k = 0; k < 3; k++) {
						struct lx_method_run *r = &run[k == 2];
						if (k != 1)
							lx_method_run_shadows(r, &frame);
						lx_method_run_set_lookup_everywhere(r, k == 1);
						looked[k] += lx_method_run_decision(r, 0, rgba, obj[k % 2], sh[k % 2]);
						if (k == 0)
							continue;
						long wrong = 0, differ = lookup_differences(&frame, obj[0], sh[0], obj[1], sh[1], &wrong);
						if (wrong)
							fail_msg("%s scene, %s, %s, %s: %ld of %ld pixels that differ between %s are "
								 "not a caster's own texels",
								 *sn, lx_configs[c].name, m, mediump ? "mediump" : "highp", wrong, differ,
								 k == 1 ? "--lookup-region footprint and all"
									: "--lookup-region all and footprint with the atlas cleared whole");
						own += k == 1 ? differ : 0;
					}
					compared++;
				}
				if (looked[1] > 0)
					print_message("%-7s %-7s %-7s: footprint looks up %.1f%% of the pixels all does\n", *sn, m,
						      mediump ? "mediump" : "highp", 100.0 * looked[0] / looked[1]);
				assert_true(looked[0] <= looked[1]);
				for (int k = 0; k < 2; k++)
					lx_method_run_free(&run[k]);
			}
		}
		lx_meshes_free(&meshes);
	}
	print_message("%ld frames compared: identical but for %ld pixels where all read a caster's own texels (no other "
		      "object blocks the light there)\n", compared, own);
	decisions_free(&dc);
}

/* Where two pieces of a plane overlap, a pixel reads one of their maps, not both: each
 * holds every caster over its rectangle (on llvmpipe a read costs the same whether or not
 * its map serves). The default scene's views at 1024x1024 whose floor comes in
 * pieces that meet or overlap: the floor's spans that read two maps or more are the
 * seams where they meet only (each piece's rectangle less a margin is read alone; before,
 * a row of spans through two pieces read both all along), and they decide as reading
 * every map does (--lookup-region all) but on a caster's own texels. How well the
 * pieces decide is overlapping_pieces_give_a_lixel_per_pixel's. */
static void overlapping_pieces_read_one_map(void **state)
{
	(void)state;
	enum { w = 1024, h = 1024 };
	char err[512];
	struct decisions dc = decisions_alloc(w, h);
	uint8_t *rgba = dc.rgba, **sh = dc.sh;
	int16_t **obj = dc.obj;
	struct lx_scene base;
	lx_scene_default(&base);
	struct lx_scene_meshes meshes = {0};
	assert_true(lx_meshes_build(&base, &meshes));
	struct lx_method_options o = LX_METHOD_OPTIONS_DEFAULT;
	struct lx_method_run run;
	if (lx_method_run_init(&run, "plane", &base, &meshes, &dc.caps, &o, w, h, LX_DEPTH_AUTO, LX_DEFAULT_BIAS_CODES, false,
			       err, sizeof err))
		fail_msg("%s", err);
	int views = 0;
	for (int c = 0; c < lx_config_count; c++) {
		struct lx_scene scene = base;
		lx_config_apply(&lx_configs[c], &scene);
		struct lx_frame frame;
		assert_true(lx_frame_setup(&frame, &scene, &meshes, 0.4, w, h, err, sizeof err));
		struct lx_frame_times t;
		lx_method_run_frame(&run, &frame, NULL, &t);
		/* the floor's pieces that touch or overlap, and the seams where they meet: a
		 * band 8 pixels wide on either side of each rectangle's edge inside the other
		 * (sure_rect's margin at a lixel per pixel is 4, and up to 3 more to whole
		 * blocks; the spans' 1) */
		const struct lx_shadow_result *res = &run.lights[0].result;
		double seams = 0, area = 0;
		for (int m = 0; m < res->map_count; m++)
			for (int n = m + 1; n < res->map_count; n++) {
				const struct lx_shadow_map *a = &res->maps[m], *b = &res->maps[n];
				if (!a->rendered || !b->rendered || a->plane != 0 || b->plane != 0)
					continue;
				double g = 8, x0 = fmax(a->screen[0], b->screen[0]) - g, x1 = fmin(a->screen[2], b->screen[2]) + g;
				double y0 = fmax(a->screen[1], b->screen[1]) - g, y1 = fmin(a->screen[3], b->screen[3]) + g;
				if (x1 > x0 && y1 > y0) {
					seams += 2 * g * (x1 - x0 + y1 - y0);
					area += (a->screen[2] - a->screen[0]) * (a->screen[3] - a->screen[1]) +
						(b->screen[2] - b->screen[0]) * (b->screen[3] - b->screen[1]);
				}
			}
		long reads[LX_MAX_MAPS + 1], multi = 0;
		lx_renderer_span_reads(run.renderer, reads);
		for (int k = 2; k <= LX_MAX_MAPS; k++)
			multi += reads[k];
		if (!(seams > 0))
			continue; /* the floor in one piece, or in pieces apart */
		views++;
		print_message("%-12s floor pieces that meet: %.0f pixels, their seams %.0f; spans reading two maps or "
			      "more: %ld pixels\n",
			      lx_configs[c].name, area, seams, multi);
		if (multi > seams)
			fail_msg("%s: %ld pixels of spans read two maps or more; the seams hold %.0f", lx_configs[c].name, multi,
				 seams);
		for (int k = 0; k < 2; k++) {
			lx_method_run_set_lookup_everywhere(&run, k == 1);
			lx_method_run_decision(&run, 0, rgba, obj[k], sh[k]);
		}
		lx_method_run_set_lookup_everywhere(&run, false);
		long wrong = 0, differ = lookup_differences(&frame, obj[0], sh[0], obj[1], sh[1], &wrong);
		print_message("%-12s against every map read: %ld pixels differ, %ld of them not a caster's own texels\n",
			      lx_configs[c].name, differ, wrong);
		assert_int_equal(wrong, 0);
	}
	assert_true(views > 0);
	lx_method_run_free(&run);
	lx_meshes_free(&meshes);
	decisions_free(&dc);
}

/* Two runs of every method over every standard configuration of both built-in scenes, at
 * w x h, time 0.4: `setup` gives run k its options and caps, `frame` sees both runs' frame
 * (after decide_both: dc's images hold their decisions). */
struct pair_sweep {
	int w, h;
	void (*setup)(void *ctx, int k, struct lx_method_options *o, const struct lx_gl_caps **caps);
	void (*frame)(void *ctx, const char *scene, const char *method, const char *config, const struct lx_frame *f,
		      long differ);
	void *ctx;
	bool thick; /* also the table with a thick top (thick_table) */
	enum lx_filter filter; /* both runs' (0: none) */
	enum lx_depth_precision precision; /* both runs' (0: auto) */
};

/* The table with a block for a top, 25 cm thick: no flat box, so its shadow is the maps'
 * (the slab's pair of fronts decides the built-in table's exactly, and it is in no map),
 * and the legs meet the block under it. */
static void thick_table(struct lx_scene *s)
{
	lx_scene_table(s);
	assert_true(s->casters[0].shape == LX_BOX && s->casters[1].shape == LX_BOX);
	double bottom = 0.749 - 0.25;
	s->casters[0].size.y = 0.25, s->casters[0].low = s->casters[0].high = bottom;
	for (int c = 1; c <= 4; c++)
		s->casters[c].size.y = bottom;
}

static void sweep_pairs(struct decisions *dc, const struct pair_sweep *p, long *shadowed)
{
	char err[512];
	for (const char *const *sn = (const char *const[]){"default", "table", p->thick ? "thick" : NULL, NULL}; *sn; sn++) {
		struct lx_scene base;
		if (!strcmp(*sn, "thick"))
			thick_table(&base);
		else
			assert_true(lx_scene_builtin(*sn, &base));
		struct lx_scene_meshes meshes = {0};
		assert_true(lx_meshes_build(&base, &meshes));
		char list[128];
		memcpy(list, dc->names, sizeof list);
		for (char *save = NULL, *m = strtok_r(list, "|", &save); m; m = strtok_r(NULL, "|", &save)) {
			struct lx_method_run run[2];
			for (int k = 0; k < 2; k++) {
				struct lx_method_options o = LX_METHOD_OPTIONS_DEFAULT;
				const struct lx_gl_caps *caps = &dc->caps;
				p->setup(p->ctx, k, &o, &caps);
				if (lx_method_run_init(&run[k], m, &base, &meshes, caps, &o, p->w, p->h, p->precision,
						       LX_DEFAULT_BIAS_CODES, false, err, sizeof err))
					fail_msg("%s: %s", m, err);
				if (p->filter && lx_method_run_set_filter(&run[k], p->filter, err, sizeof err))
					fail_msg("%s: %s", m, err);
			}
			for (int c = 0; c < lx_config_count; c++) {
				struct lx_scene scene = base;
				lx_config_apply(&lx_configs[c], &scene);
				struct lx_frame frame;
				assert_true(lx_frame_setup(&frame, &scene, &meshes, 0.4, p->w, p->h, err, sizeof err));
				long d = decide_both(dc, run, &frame, p->w, p->h, shadowed);
				p->frame(p->ctx, *sn, m, lx_configs[c].name, &frame, d);
			}
			for (int k = 0; k < 2; k++)
				lx_method_run_free(&run[k]);
		}
		lx_meshes_free(&meshes);
	}
}

/* caster_faces_compare_along_their_planes' sweep: run 0 face, run 1 point. */
struct face_sweep {
	struct decisions *dc;
	uint8_t *ref_sh;
	int16_t *ref_obj;
	long lit, wrong[2], on_plane_map[2];
};

static void face_setup(void *ctx, int k, struct lx_method_options *o, const struct lx_gl_caps **caps)
{
	(void)ctx, (void)caps;
	o->caster_face_depth = k == 0;
}

/* Each of the two runs' decisions (dc) against the exact reference of frame f (into ref_obj
 * and ref_sh): the pixels decided otherwise, false or missing shadow, into wrong[k]. */
static void runs_against_reference(const struct lx_frame *f, const struct decisions *dc, int16_t *ref_obj,
				   uint8_t *ref_sh, long wrong[2])
{
	long n = (long)f->view.width * f->view.height;
	assert_true(lx_reference_image(f, ref_obj, ref_sh, 2));
	for (int k = 0; k < 2; k++) {
		struct lx_mismatch mm;
		lx_mismatch_compare(ref_obj, ref_sh, dc->obj[k], dc->sh[k], n, &mm);
		wrong[k] = mm.false_shadow + mm.missing_shadow;
	}
}

static void face_frame(void *ctx, const char *scene, const char *method, const char *config, const struct lx_frame *f,
		       long differ)
{
	struct face_sweep *s = ctx;
	struct decisions *dc = s->dc;
	long n = (long)f->view.width * f->view.height;
	for (long i = 0; differ && i < n; i++) {
		if (dc->sh[0][i] == dc->sh[1][i])
			continue;
		if (dc->obj[0][i] < f->scene->plane_count || dc->sh[0][i] || !dc->sh[1][i])
			fail_msg("%s scene, %s, %s: pixel %ld (object %d) is %s with face, %s with point", scene, config,
				 method, i, dc->obj[0][i], dc->sh[0][i] ? "shadowed" : "lit", dc->sh[1][i] ? "shadowed" : "lit");
		s->lit++;
	}
	long wrong[2];
	runs_against_reference(f, dc, s->ref_obj, s->ref_sh, wrong);
	for (int k = 0; k < 2; k++) {
		s->wrong[k] += wrong[k];
		if (!strcmp(scene, "thick") && !strcmp(method, "plane") && !strcmp(config, "directional"))
			s->on_plane_map[k] = wrong[k];
	}
}

/* --caster-depth face (the default) against point: a caster's face compared along its
 * plane at the centre of the lixel read, moved only towards the light, can only light a
 * pixel the pixel's own depth shadowed, and only on a caster (a plane is compared as
 * before); over every method and standard configuration of both built-in scenes and of
 * the table with a thick top it decides fewer pixels otherwise than the exact reference
 * does, so too on that table under a directional light with plane-optimal maps, where the
 * ball and the cone read the table's map. (On the built-in table, whose slab is in no map
 * since its pair of fronts decides its shadow, the two decide alike: the legs' tops no
 * longer read a map under it.) */
static void caster_faces_compare_along_their_planes(void **state)
{
	(void)state;
	enum { w = 320, h = 240 };
	struct decisions dc = decisions_alloc(w, h);
	struct face_sweep s = {.dc = &dc, .ref_sh = malloc((size_t)w * h),
			       .ref_obj = malloc((size_t)w * h * sizeof(int16_t))};
	assert_true(s.ref_sh && s.ref_obj);
	long shadowed = 0;
	sweep_pairs(&dc, &(struct pair_sweep){w, h, face_setup, face_frame, &s, true, LX_FILTER_NONE, LX_DEPTH_AUTO},
		    &shadowed);
	print_message("face against point: %ld casters' pixels lit that point shadowed; %ld against %ld pixels decided "
		      "otherwise than the exact reference; the thick table under a directional light, plane: %ld against %ld\n",
		      s.lit, s.wrong[0], s.wrong[1], s.on_plane_map[0], s.on_plane_map[1]);
	assert_true(s.lit > 0);
	assert_true(s.wrong[0] < s.wrong[1]);
	assert_true(s.on_plane_map[0] < s.on_plane_map[1]);
	free(s.ref_sh), free(s.ref_obj);
	decisions_free(&dc);
}

/* eight_varyings_decide_alike's sweep: run 1 on a GPU of 8 varying vectors. */
static void eight_setup(void *ctx, int k, struct lx_method_options *o, const struct lx_gl_caps **caps)
{
	(void)o;
	if (k == 1)
		*caps = ctx;
}

static void eight_frame(void *ctx, const char *scene, const char *method, const char *config, const struct lx_frame *f,
			long differ)
{
	(void)ctx, (void)f;
	if (differ)
		fail_msg("%s scene, %s, %s: %ld pixels decided otherwise with 8 varyings", scene, config, method, differ);
}

/* A GPU with 8 varying vectors (a VideoCore IV): the variants that read four maps give up
 * the served test on edge functions for the compare of the divided point (lx_main_defines)
 * and decide as the full set, pixel for pixel: every method, every standard configuration
 * of both built-in scenes. */
static void eight_varyings_decide_alike(void **state)
{
	(void)state;
	enum { w = 256, h = 192 };
	struct decisions dc = decisions_alloc(w, h);
	struct lx_gl_caps small = dc.caps;
	small.max_varying_vectors = 8;
	assert_true(dc.caps.max_varying_vectors > 10); /* llvmpipe's 32: the full set here */
	long shadowed = 0;
	sweep_pairs(&dc, &(struct pair_sweep){w, h, eight_setup, eight_frame, &small, false, LX_FILTER_NONE, LX_DEPTH_AUTO},
		    &shadowed);
	print_message("every method and configuration with 8 varyings: the same decisions (%ld shadowed pixels)\n",
		      shadowed);
	assert_true(shadowed > 10000);
	decisions_free(&dc);
}

/* A sweep with a renderer's test hook (`hook`=1) in run 1 and not in run 0, all else
 * alike: round_casters_fanned_decide_as_faces' (LIXEL_ROUND_CASTERS_AS_FACES: every round
 * caster drawn as its faces turned away; the fan's outline still cuts the sure shadows)
 * and box_polygons_decide_no_worse's (LIXEL_BOXES_AS_FACES: every box so). Counted: the
 * pixels the runs decide otherwise, those shadowed in run 0 alone (more_shadow), and
 * with ref_sh, where they part, each run's pixels otherwise than the exact reference. */
struct hook_sweep {
	const char *hook;
	struct decisions *dc;
	uint8_t *ref_sh;
	int16_t *ref_obj;
	long differ, more_shadow, frames, wrong[2];
};

static void hook_setup(void *ctx, int k, struct lx_method_options *o, const struct lx_gl_caps **caps)
{
	(void)o, (void)caps;
	const struct hook_sweep *s = ctx;
	if (k == 1)
		setenv(s->hook, "1", 1);
	else
		unsetenv(s->hook);
}

static void hook_frame(void *ctx, const char *scene, const char *method, const char *config, const struct lx_frame *f,
		       long differ)
{
	struct hook_sweep *s = ctx;
	long n = (long)f->view.width * f->view.height, more = 0, wrong[2] = {0, 0};
	s->differ += differ, s->frames++;
	if (!differ)
		return;
	for (long i = 0; i < n; i++)
		more += s->dc->sh[0][i] && !s->dc->sh[1][i];
	s->more_shadow += more;
	if (s->ref_sh) {
		runs_against_reference(f, s->dc, s->ref_obj, s->ref_sh, wrong);
		s->wrong[0] += wrong[0], s->wrong[1] += wrong[1];
	}
	print_message("%s scene, %s, %s: %ld pixels decided otherwise, %ld of them shadowed without %s alone; otherwise "
		      "than the reference %ld and %ld\n",
		      scene, config, method, differ, more, s->hook, wrong[0], wrong[1]);
}

/* The two paths the hook sweeps take: highp (auto) unfiltered; the widest reach
 * (pcf3x3) on mediump's wider margin. */
static const struct {
	enum lx_filter filter;
	enum lx_depth_precision precision;
	const char *name;
} hook_paths[2] = {{LX_FILTER_NONE, LX_DEPTH_AUTO, "auto"}, {LX_FILTER_PCF3X3, LX_DEPTH_MEDIUMP, "mediump"}};

/* Sweep s (its hook, its decisions at w x h) on hook_paths[i]; the hook left unset. */
static long sweep_hook(struct hook_sweep *s, int i, int w, int h)
{
	long shadowed = 0;
	sweep_pairs(s->dc,
		    &(struct pair_sweep){w, h, hook_setup, hook_frame, s, true, hook_paths[i].filter, hook_paths[i].precision},
		    &shadowed);
	unsetenv(s->hook);
	return shadowed;
}

/* A round caster drawn as a fan over its faces turned away (or that fan's polygon), with
 * its far side within 30 degrees of edge-on kept where it reads the map itself
 * (FAN_WELL_AWAY: the faces within 11.5 degrees, BAND_FACES, and a strip across the rest;
 * with the strip from the edge-on, one pixel of XPSM's on the thick table's default view
 * turned shadowed), decides every pixel as its faces turned away do (the fan's depths lie
 * inside the caster, nearer than its far side: where the two differ, the fan shadows):
 * every method, every standard configuration of both built-in scenes and of the thick
 * table, with no filter on the highp path and with the widest (pcf3x3) on the mediump
 * path's wider margin. Drawn as the polygon alone (FAN_WELL_AWAY 0), 17 pixels turned
 * shadowed in each (the thick table's default view; on mediump also near-wall on the
 * default scene); with the band at 17 degrees this test passed (results.md, "The speed
 * targets", says what did not). */
static void round_casters_fanned_decide_as_faces(void **state)
{
	(void)state;
	enum { w = 320, h = 240 };
	struct decisions dc = decisions_alloc(w, h);
	for (int i = 0; i < 2; i++) {
		struct hook_sweep s = {.hook = "LIXEL_ROUND_CASTERS_AS_FACES", .dc = &dc};
		long shadowed = sweep_hook(&s, i, w, h);
		print_message("fans against faces, %s, filter %s: %ld frames, %ld pixels decided otherwise, %ld of them "
			      "shadowed with the fans alone (%ld shadowed pixels)\n",
			      hook_paths[i].name, lx_filter_name(hook_paths[i].filter), s.frames, s.differ, s.more_shadow,
			      shadowed);
		assert_true(s.frames > 100 && shadowed > 10000);
		assert_int_equal(s.differ, 0);
	}
	decisions_free(&dc);
}

/* A box drawn into a plane's map it does not read as its silhouette's polygon (four or
 * six corners, cut at its shortest inner edges) in place of its faces turned away covers
 * the same lixels at depths inside it, between its near and far sides, and decides as the
 * faces do but for a pixel here and there, no worse against the exact reference in all:
 * every method, every standard configuration of both built-in scenes and of the thick
 * table, with no filter on the highp path and with the widest (pcf3x3) on the mediump
 * path (first run: none parted on the first, one on the second, right with the polygon).
 * Drawn so into every map, 5 and 9 pixels parted, each right with the polygon here; at
 * 1024x1024 on coarser maps some were not (results.md, "Boxes as their polygons"). */
static void box_polygons_decide_no_worse(void **state)
{
	(void)state;
	enum { w = 320, h = 240 };
	struct decisions dc = decisions_alloc(w, h);
	uint8_t *ref_sh = malloc((size_t)w * h);
	int16_t *ref_obj = malloc((size_t)w * h * sizeof(int16_t));
	assert_true(ref_sh && ref_obj);
	for (int i = 0; i < 2; i++) {
		struct hook_sweep s = {.hook = "LIXEL_BOXES_AS_FACES", .dc = &dc, .ref_sh = ref_sh, .ref_obj = ref_obj};
		long shadowed = sweep_hook(&s, i, w, h);
		print_message("box polygons against faces, %s, filter %s: %ld frames, %ld pixels decided otherwise (%ld "
			      "shadowed pixels); there otherwise than the reference %ld with the polygons, %ld with the faces\n",
			      hook_paths[i].name, lx_filter_name(hook_paths[i].filter), s.frames, s.differ, shadowed, s.wrong[0],
			      s.wrong[1]);
		assert_true(s.frames > 100 && shadowed > 10000);
		assert_true(s.differ * 10000 < shadowed); /* a pixel here and there */
		assert_true(s.wrong[0] <= s.wrong[1]);
	}
	free(ref_sh), free(ref_obj);
	decisions_free(&dc);
}

/* The atlas's alpha byte (the RGBA8 paths): every texel holds the id of the object drawn
 * there, or 255 where none is (the clear colour), and LIXEL_NO_CASTER_IDS=1 leaves it 255
 * throughout; the default scene's three casters each leave theirs. */
static void atlas_ids(struct decisions *dc, bool ids, int *distinct)
{
	enum { w = 320, h = 240 };
	char err[512];
	struct lx_scene base;
	assert_true(lx_scene_builtin("default", &base));
	struct lx_scene_meshes meshes = {0};
	assert_true(lx_meshes_build(&base, &meshes));
	if (!ids)
		setenv("LIXEL_NO_CASTER_IDS", "1", 1);
	struct lx_method_run run;
	struct lx_method_options o = LX_METHOD_OPTIONS_DEFAULT;
	if (lx_method_run_init(&run, "plane", &base, &meshes, &dc->caps, &o, w, h, LX_DEPTH_HIGHP, LX_DEFAULT_BIAS_CODES,
			       false, err, sizeof err))
		fail_msg("plane: %s", err);
	unsetenv("LIXEL_NO_CASTER_IDS");
	struct lx_frame frame;
	assert_true(lx_frame_setup(&frame, &base, &meshes, 0.4, w, h, err, sizeof err));
	lx_method_run_shadows(&run, &frame);
	const struct lx_atlas *a = &run.lights[0].atlas;
	size_t n = (size_t)a->texture_width * a->texture_height;
	uint8_t *tex = malloc(n * 4);
	assert_non_null(tex);
	lx_renderer_read_atlas(run.renderer, tex);
	bool seen[256] = {false};
	for (size_t i = 0; i < n; i++)
		seen[tex[4 * i + 3]] = true;
	*distinct = 0;
	for (int id = 0; id < 255; id++) {
		if (seen[id] && id >= meshes.count)
			fail_msg("an alpha byte of %d in the atlas, past the %d objects", id, meshes.count);
		*distinct += seen[id];
	}
	assert_true(seen[255]);
	free(tex);
	lx_method_run_free(&run);
	lx_meshes_free(&meshes);
}

/* A caster's faces turned towards the light pass over their own texels, known by the id
 * in the atlas's alpha byte (the RGBA8 paths, main.frag's LX_SELF): a convex caster never
 * shadows them. Its maps then need not hold its faces near its silhouette (the band,
 * keep_back_faces), and the pixels where that decides otherwise than the band with the
 * ids off (LIXEL_NO_CASTER_IDS=1, as the depth-texture path draws) are no worse against
 * the exact reference in all: every method, every standard configuration of both built-in
 * scenes and of the thick table, unfiltered on the highp path and with the widest filter
 * (pcf3x3) on the mediump path. */
static void casters_pass_over_their_own_texels(void **state)
{
	(void)state;
	enum { w = 320, h = 240 };
	struct decisions dc = decisions_alloc(w, h);
	int distinct[2];
	atlas_ids(&dc, true, &distinct[0]);
	atlas_ids(&dc, false, &distinct[1]);
	print_message("the default view's atlas: %d objects' ids in its alpha bytes, %d with the ids off\n", distinct[0],
		      distinct[1]);
	assert_true(distinct[0] >= 3);
	assert_int_equal(distinct[1], 0);
	uint8_t *ref_sh = malloc((size_t)w * h);
	int16_t *ref_obj = malloc((size_t)w * h * sizeof(int16_t));
	assert_true(ref_sh && ref_obj);
	static const struct {
		enum lx_filter filter;
		enum lx_depth_precision precision;
		const char *name;
	} paths[2] = {{LX_FILTER_NONE, LX_DEPTH_HIGHP, "highp"}, {LX_FILTER_PCF3X3, LX_DEPTH_MEDIUMP, "mediump"}};
	for (int i = 0; i < 2; i++) {
		struct hook_sweep s = {.hook = "LIXEL_NO_CASTER_IDS", .dc = &dc, .ref_sh = ref_sh, .ref_obj = ref_obj};
		long shadowed = 0;
		sweep_pairs(&dc, &(struct pair_sweep){w, h, hook_setup, hook_frame, &s, true, paths[i].filter,
						      paths[i].precision},
			    &shadowed);
		unsetenv(s.hook);
		print_message("ids against the band, %s, filter %s: %ld frames, %ld pixels decided otherwise (%ld shadowed "
			      "pixels), %ld of them shadowed with the ids alone; there otherwise than the reference %ld "
			      "with the ids, %ld with the band\n",
			      paths[i].name, lx_filter_name(paths[i].filter), s.frames, s.differ, shadowed, s.more_shadow,
			      s.wrong[0], s.wrong[1]);
		assert_true(s.frames > 100 && shadowed > 10000);
		assert_true(s.wrong[0] <= s.wrong[1]);
	}
	free(ref_sh), free(ref_obj);
	decisions_free(&dc);
}

/* A round caster's sure shadow (sure_spans) begins at its whole silhouette in every map:
 * where it reads the map itself, the depth-texture path draws its band as well as its fan
 * (keep_back_faces), and the highp RGBA8 path, whose ids let it draw the fan alone over
 * all its faces turned away, holds the same silhouette. So both paths run as many
 * lookups, frame by frame: uniform and plane-optimal on every standard configuration of
 * both built-in scenes at 640x480, at time 0 (as lixel render). With the inner fan's
 * corners for the outline where the band is drawn, plane-optimal's lookups on the default
 * scene's facing view were 11.77% of the pixels on the depth-texture path, 10.84% on the
 * highp path. */
static void sure_shadows_begin_at_the_silhouette(void **state)
{
	(void)state;
	enum { w = 640, h = 480 };
	char err[512];
	struct decisions dc = decisions_alloc(w, h);
	long frames = 0, looked[2] = {0, 0};
	for (const char *const *sn = (const char *const[]){"default", "table", NULL}; *sn; sn++) {
		struct lx_scene base;
		assert_true(lx_scene_builtin(*sn, &base));
		struct lx_scene_meshes meshes = {0};
		assert_true(lx_meshes_build(&base, &meshes));
		for (const char *const *m = (const char *const[]){"uniform", "plane", NULL}; *m; m++) {
			struct lx_method_run run[2];
			for (int k = 0; k < 2; k++) {
				struct lx_method_options o = LX_METHOD_OPTIONS_DEFAULT;
				if (lx_method_run_init(&run[k], *m, &base, &meshes, &dc.caps, &o, w, h,
						       k ? LX_DEPTH_TEXTURE : LX_DEPTH_HIGHP, LX_DEFAULT_BIAS_CODES, false, err,
						       sizeof err))
					fail_msg("%s: %s", *m, err);
			}
			assert_true(lx_renderer_atlas_is_depth_texture(run[1].renderer));
			for (int c = 0; c < lx_config_count; c++) {
				struct lx_scene scene = base;
				lx_config_apply(&lx_configs[c], &scene);
				struct lx_frame frame;
				assert_true(lx_frame_setup(&frame, &scene, &meshes, 0, w, h, err, sizeof err)); /* as render */
				long n[2];
				for (int k = 0; k < 2; k++) {
					lx_method_run_shadows(&run[k], &frame);
					n[k] = lx_method_run_decision(&run[k], 0, dc.rgba, dc.obj[k], dc.sh[k]);
					looked[k] += n[k];
				}
				if (n[0] != n[1])
					fail_msg("%s scene, %s, %s: %ld lookups on the highp path, %ld on the depth-texture path",
						 *sn, lx_configs[c].name, *m, n[0], n[1]);
				frames++;
			}
			for (int k = 0; k < 2; k++)
				lx_method_run_free(&run[k]);
		}
		lx_meshes_free(&meshes);
	}
	print_message("sure shadows at the silhouette: %ld frames, %ld and %ld lookups on the highp and depth-texture paths\n",
		      frames, looked[0], looked[1]);
	assert_true(frames >= 40 && looked[0] > 0);
	decisions_free(&dc);
}

/* Texels of the default scene's facing view in which the shadow passes with and without
 * LIXEL_WHOLE_BANDS=1 differ (plane-optimal at 640x480, the depth-texture path). */
static long band_texels_moved(struct decisions *dc)
{
	enum { w = 640, h = 480 }; /* at 320x240 the band's rectangle is most of the ball's image */
	char err[512];
	struct lx_scene base;
	assert_true(lx_scene_builtin("default", &base));
	struct lx_scene_meshes meshes = {0};
	assert_true(lx_meshes_build(&base, &meshes));
	struct lx_scene scene = base;
	const struct lx_config *facing = lx_config_find("facing");
	assert_non_null(facing);
	lx_config_apply(facing, &scene);
	struct lx_frame frame;
	assert_true(lx_frame_setup(&frame, &scene, &meshes, 0, w, h, err, sizeof err));
	uint8_t *tex[2] = {NULL, NULL};
	size_t n = 0;
	for (int k = 0; k < 2; k++) {
		if (k)
			setenv("LIXEL_WHOLE_BANDS", "1", 1);
		struct lx_method_run run;
		struct lx_method_options o = LX_METHOD_OPTIONS_DEFAULT;
		o.depth_slots = 1; /* each frame's codes as written */
		if (lx_method_run_init(&run, "plane", &base, &meshes, &dc->caps, &o, w, h, LX_DEPTH_TEXTURE,
				       LX_DEFAULT_BIAS_CODES, false, err, sizeof err))
			fail_msg("plane: %s", err);
		unsetenv("LIXEL_WHOLE_BANDS");
		lx_method_run_shadows(&run, &frame);
		const struct lx_atlas *a = &run.lights[0].atlas;
		n = (size_t)a->texture_width * a->texture_height;
		tex[k] = malloc(n * 4);
		assert_non_null(tex[k]);
		lx_renderer_read_atlas(run.renderer, tex[k]);
		lx_method_run_free(&run);
	}
	long moved = 0;
	for (size_t i = 0; i < n; i++)
		moved += memcmp(tex[0] + 4 * i, tex[1] + 4 * i, 4) != 0;
	free(tex[0]), free(tex[1]);
	lx_meshes_free(&meshes);
	return moved;
}

/* A round caster reading a map itself keeps its band (its far side near its silhouette,
 * drawn as faces and a strip) only around the image of its own faces that read the map
 * (band_rect), and its polygon elsewhere, in scissored draws: the same decisions as the
 * whole band (LIXEL_WHOLE_BANDS=1) on every method and standard configuration of both
 * built-in scenes and the thick table, on the depth-texture path with no filter and with
 * the widest (pcf3x3, whose reach the rectangle's margin holds); and on the default
 * scene's facing view the atlas does change (the ball's faces read the floor's map in 4
 * triangles). */
static void bands_kept_where_their_caster_reads(void **state)
{
	(void)state;
	enum { w = 640, h = 480 };
	struct decisions dc = decisions_alloc(w, h);
	long moved = band_texels_moved(&dc);
	print_message("the facing view's atlas: %ld texels differ from the whole band's\n", moved);
	assert_true(moved > 0);
	for (int i = 0; i < 2; i++) {
		enum lx_filter filter = i ? LX_FILTER_PCF3X3 : LX_FILTER_NONE;
		struct hook_sweep s = {.hook = "LIXEL_WHOLE_BANDS", .dc = &dc};
		long shadowed = 0;
		sweep_pairs(&dc, &(struct pair_sweep){w, h, hook_setup, hook_frame, &s, true, filter, LX_DEPTH_TEXTURE},
			    &shadowed);
		unsetenv(s.hook);
		print_message("bands where read against whole, filter %s: %ld frames, %ld pixels decided otherwise (%ld "
			      "shadowed pixels)\n",
			      lx_filter_name(filter), s.frames, s.differ, shadowed);
		assert_true(s.frames > 100 && shadowed > 10000);
		assert_int_equal(s.differ, 0);
	}
	decisions_free(&dc);
}

/* The two runs' atlases (run[0] RGBA8, run[1] a depth texture) read back as codes: the
 * largest difference is returned (the RGBA8 path's shader interpolates z and w in single
 * precision, the rasterizer its own depth, so they part by tens of codes on triangles
 * seen edge-on from the light; the decisions are compared by the caller); and the depth
 * texture written with what was read reads back within two codes (its depth reaches the
 * shader as a float, whose steps near 1 are as fine as 24-bit codes). */
static double atlas_codes_agree(struct lx_method_run run[2])
{
	struct lx_renderer *rt = run[1].renderer;
	const struct lx_atlas *a = &run[1].lights[0].atlas;
	size_t n = (size_t)a->texture_width * a->texture_height;
	uint8_t *tex[3] = {malloc(n * 4), malloc(n * 4), malloc(n * 4)};
	assert_true(tex[0] && tex[1] && tex[2]);
	lx_renderer_read_atlas(run[0].renderer, tex[0]);
	lx_renderer_read_atlas(rt, tex[1]);
	lx_renderer_write_atlas(rt, tex[1]);
	lx_renderer_read_atlas(rt, tex[2]);
	double worst = 0, back = 0;
	for (size_t i = 0; i < n; i++) {
		double depth = lx_depth_decode_code(tex[1] + 4 * i);
		worst = fmax(worst, fabs(lx_depth_decode_code(tex[0] + 4 * i) - depth));
		back = fmax(back, fabs(lx_depth_decode_code(tex[2] + 4 * i) - depth));
	}
	if (back > 2)
		fail_msg("the depth-texture atlas written back reads %.0f codes from what was written", back);
	for (int k = 0; k < 3; k++)
		free(tex[k]);
	return worst;
}

/* The depth-texture path (auto's first choice, --depth-precision texture) keeps 24-bit
 * codes in a depth texture: the rasterizer's depth, where the RGBA8 path's shader computes
 * its own from interpolated z and w. Every method on every standard configuration of both
 * built-in scenes decides as the highp RGBA8 path, pixel for pixel. */
static void depth_texture_path_decides_as_highp(void **state)
{
	(void)state;
	enum { w = 256, h = 192 };
	char err[512];
	struct decisions dc = decisions_alloc(w, h);
	long frames = 0, differ = 0, shadowed = 0;
	double worst_code = 0;
	for (const char *const *sn = (const char *const[]){"default", "table", NULL}; *sn; sn++) {
		struct lx_scene base;
		assert_true(lx_scene_builtin(*sn, &base));
		struct lx_scene_meshes meshes = {0};
		assert_true(lx_meshes_build(&base, &meshes));
		for (char *save = NULL, *m = strtok_r(dc.names, "|", &save); m; m = strtok_r(NULL, "|", &save)) {
			struct lx_method_run run[2];
			for (int k = 0; k < 2; k++) {
				struct lx_method_options o = LX_METHOD_OPTIONS_DEFAULT;
				o.depth_slots = 1; /* the codes as the highp path has them (slots: the next test) */
				if (lx_method_run_init(&run[k], m, &base, &meshes, &dc.caps, &o, w, h,
						       k ? LX_DEPTH_TEXTURE : LX_DEPTH_HIGHP, LX_DEFAULT_BIAS_CODES, false, err,
						       sizeof err))
					fail_msg("%s: %s", m, err);
			}
			assert_string_equal(run[1].depth.path, "highp24-texture");
			assert_string_equal(run[1].depth.warning, "");
			assert_false(lx_renderer_atlas_is_depth_texture(run[0].renderer));
			assert_true(lx_renderer_atlas_is_depth_texture(run[1].renderer));
			for (int c = 0; c < lx_config_count; c++) {
				struct lx_scene scene = base;
				lx_config_apply(&lx_configs[c], &scene);
				struct lx_frame frame;
				assert_true(lx_frame_setup(&frame, &scene, &meshes, 0.4, w, h, err, sizeof err));
				long d = decide_both(&dc, run, &frame, w, h, &shadowed);
				if (c == 0)
					worst_code = fmax(worst_code, atlas_codes_agree(run));
				if (d > 0)
					fail_msg("%s scene, %s, %s: %ld pixels decided otherwise on the depth-texture path", *sn,
						 lx_configs[c].name, m, d);
				differ += d, frames++;
			}
			for (int k = 0; k < 2; k++)
				lx_method_run_free(&run[k]);
		}
		snprintf(dc.names, sizeof dc.names, "%s", lx_shadow_method_names()); /* strtok_r cut it */
		lx_meshes_free(&meshes);
	}
	print_message("%ld frames: %ld pixels of %ld shadowed ones decided otherwise on the depth-texture path; its "
		      "atlas's codes at most %.0f from the RGBA8 one's\n",
		      frames, differ, shadowed, worst_code);
	assert_true(frames > 100 && shadowed > 10000);
	decisions_free(&dc);
}

/* Depth slots (renderer.c): the atlas cleared once every 8 frames, each frame's depths in
 * a slot below the earlier frames', decides as clearing it every frame, but for the
 * coarser steps of a slot (21 bits): every method, both built-in scenes, 12 frames of the
 * casters bouncing (a cycle of slots and half another, the maps moving over the atlas as
 * the casters do, onto texels earlier frames wrote), then every standard configuration
 * one after another (the layouts jumping). An earlier frame's depth read as near would
 * show as a shadow where none falls, on many pixels (675 on the frame after a wrap whose
 * clear was left out). */
static void depth_slots_decide_as_clearing_every_frame(void **state)
{
	(void)state;
	enum { w = 160, h = 120, frames = 12, most_per_frame = 3 };
	char err[512];
	struct decisions dc = decisions_alloc(w, h);
	long views = 0, differ = 0, shadowed = 0, worst = 0;
	for (const char *const *sn = (const char *const[]){"default", "table", NULL}; *sn; sn++) {
		struct lx_scene base;
		assert_true(lx_scene_builtin(*sn, &base));
		struct lx_scene_meshes meshes = {0};
		assert_true(lx_meshes_build(&base, &meshes));
		for (int i = 0; i < lx_shadow_method_count(); i++) {
			const char *m = lx_shadow_method_at(i)->name;
			struct lx_method_run run[2];
			for (int k = 0; k < 2; k++) {
				struct lx_method_options o = LX_METHOD_OPTIONS_DEFAULT;
				o.depth_slots = k ? 8 : 1;
				if (lx_method_run_init(&run[k], m, &base, &meshes, &dc.caps, &o, w, h, LX_DEPTH_TEXTURE,
						       LX_DEFAULT_BIAS_CODES, false, err, sizeof err))
					fail_msg("%s: %s", m, err);
			}
			assert_int_equal(lx_renderer_depth_slots(run[0].renderer), 1);
			assert_int_equal(lx_renderer_depth_slots(run[1].renderer), 8);
			for (int n = 0; n < frames + lx_config_count; n++) {
				struct lx_scene scene = base;
				if (n >= frames)
					lx_config_apply(&lx_configs[n - frames], &scene);
				struct lx_frame frame;
				assert_true(lx_frame_setup(&frame, &scene, &meshes, n < frames ? 0.17 * n : 0.4, w, h, err,
							   sizeof err));
				long d = decide_both(&dc, run, &frame, w, h, &shadowed);
				if (d > most_per_frame)
					fail_msg("%s scene, %s, frame %d: %ld pixels decided otherwise with depth slots", *sn, m, n, d);
				differ += d, views++, worst = d > worst ? d : worst;
			}
			for (int k = 0; k < 2; k++)
				lx_method_run_free(&run[k]);
		}
		lx_meshes_free(&meshes);
	}
	print_message("%ld frames: %ld pixels of %ld shadowed ones decided otherwise with depth slots (at most %ld in "
		      "a frame of %d)\n",
		      views, differ, shadowed, worst, w * h);
	assert_true(views > 250 && shadowed > 100000);
	decisions_free(&dc);
}

/* The depth path is found by trying it (depth_selftest.c): on llvmpipe the 24-bit path
 * passes; under LIXEL_SIMULATE_LIMA=1 (highp compiled as mediump, which llvmpipe computes
 * in fp16, while highp is still reported, as Mesa's lima does) it fails, auto falls back
 * to the 11-bit path, and a forced highp warns. */
/* The lima simulation stands for lima only where the driver computes mediump in fp16:
 * llvmpipe does; softpipe (the tests' control, and the armhf cross run) computes it in
 * fp32, where the simulated shaders keep 24 bits. */
static bool mediump_is_fp16(const struct lx_gl_caps *caps) { return strstr(caps->renderer, "llvmpipe") != NULL; }

static void depth_selftest_picks_the_path(void **state)
{
	(void)state;
	char err[512];
	for (size_t p = 0; p < 2; p++) {
		struct lx_platform *plat = lx_platform_create(platforms[p], err, sizeof err);
		if (!plat)
			fail_msg("%s", err);
		struct lx_depth_choice c;
		unsetenv("LIXEL_SIMULATE_LIMA");
		assert_true(lx_depth_choose(LX_DEPTH_AUTO, &c, err, sizeof err));
		assert_string_equal(c.path, "highp24-texture"), assert_string_equal(c.selftest, "passed");
		setenv("LIXEL_SIMULATE_NO_DEPTH_TEXTURE", "1", 1); /* without depth textures: the RGBA8 one */
		assert_true(lx_depth_choose(LX_DEPTH_AUTO, &c, err, sizeof err));
		assert_string_equal(c.path, "highp24"), assert_string_equal(c.selftest, "passed");
		assert_true(lx_depth_choose(LX_DEPTH_TEXTURE, &c, err, sizeof err));
		assert_string_equal(c.path, "highp24");
		assert_true(strstr(c.warning, "cannot be taken") != NULL);
		unsetenv("LIXEL_SIMULATE_NO_DEPTH_TEXTURE");
		assert_true(lx_depth_choose(LX_DEPTH_MEDIUMP, &c, err, sizeof err));
		assert_string_equal(c.path, "mediump11"), assert_string_equal(c.selftest, "forced");
		assert_string_equal(c.warning, "");
		assert_true(lx_depth_choose(LX_DEPTH_TEXTURE, &c, err, sizeof err));
		assert_string_equal(c.path, "highp24-texture"), assert_string_equal(c.selftest, "forced");
		assert_int_equal(c.taken, LX_DEPTH_TEXTURE);
		assert_string_equal(c.warning, "");
		struct lx_gl_caps caps;
		lx_gl_caps_probe(&caps);
		if (!mediump_is_fp16(&caps)) {
			print_message("%s on %s: mediump is not fp16 here, the lima simulation cannot fail the 24-bit "
				      "path (skipped)\n", platforms[p], caps.renderer);
			lx_platform_destroy(plat);
			continue;
		}
		setenv("LIXEL_SIMULATE_LIMA", "1", 1);
		lx_gl_caps_probe(&caps);
		assert_true(caps.fragment_highp); /* the query still says highp */
		assert_true(lx_depth_choose(LX_DEPTH_AUTO, &c, err, sizeof err));
		assert_string_equal(c.path, "mediump11"), assert_string_equal(c.selftest, "fell-back");
		assert_true(lx_depth_choose(LX_DEPTH_HIGHP, &c, err, sizeof err));
		assert_string_equal(c.path, "highp24"), assert_string_equal(c.selftest, "forced");
		assert_true(strstr(c.warning, "fails its self-test") != NULL);
		print_message("%s, simulated lima: %s\n", platforms[p], c.warning);
		assert_true(lx_depth_choose(LX_DEPTH_TEXTURE, &c, err, sizeof err));
		assert_true(strstr(c.warning, "depth-texture depth path fails its self-test") != NULL);
		print_message("%s, simulated lima: %s\n", platforms[p], c.warning);
		unsetenv("LIXEL_SIMULATE_LIMA");
		lx_platform_destroy(plat);
	}
}

/* Under the lima simulation the default (auto) render keeps its shadows: within 0.05
 * percentage points of the render without it, on every standard configuration of both
 * built-in scenes. */
static void simulated_lima_keeps_the_shadows(void **state)
{
	(void)state;
	enum { w = 256, h = 192 };
	char err[512];
	struct lx_gl_caps caps;
	struct lx_platform *plat = platform_with_caps("osmesa", &caps);
	if (!mediump_is_fp16(&caps)) {
		print_message("%s: mediump is not fp16 here, nothing to simulate (skipped)\n", caps.renderer);
		lx_platform_destroy(plat);
		return;
	}
	uint8_t *rgba = malloc((size_t)w * h * 4), *sh = malloc((size_t)w * h), *ref_sh = malloc((size_t)w * h);
	int16_t *obj = malloc((size_t)w * h * sizeof(int16_t)), *ref_obj = malloc((size_t)w * h * sizeof(int16_t));
	assert_true(rgba && sh && ref_sh && obj && ref_obj);
	double worst = 0;
	for (const char *const *sn = (const char *const[]){"default", "table", NULL}; *sn; sn++) {
		struct lx_scene base;
		assert_true(lx_scene_builtin(*sn, &base));
		struct lx_scene_meshes meshes = {0};
		assert_true(lx_meshes_build(&base, &meshes));
		struct lx_method_run run[2];
		struct lx_method_options o = LX_METHOD_OPTIONS_DEFAULT;
		for (int k = 0; k < 2; k++) {
			if (k)
				setenv("LIXEL_SIMULATE_LIMA", "1", 1);
			if (lx_method_run_init(&run[k], "plane", &base, &meshes, &caps, &o, w, h, LX_DEPTH_AUTO,
					       LX_DEFAULT_BIAS_CODES, false, err, sizeof err))
				fail_msg("%s", err);
			unsetenv("LIXEL_SIMULATE_LIMA");
		}
		assert_string_equal(run[0].depth.path, "highp24-texture");
		assert_string_equal(run[1].depth.path, "mediump11");
		for (int c = 0; c < lx_config_count; c++) {
			struct lx_scene scene = base;
			lx_config_apply(&lx_configs[c], &scene);
			struct lx_frame frame;
			assert_true(lx_frame_setup(&frame, &scene, &meshes, 0.4, w, h, err, sizeof err));
			assert_true(lx_reference_image(&frame, ref_obj, ref_sh, 2));
			double pct[2];
			for (int k = 0; k < 2; k++) {
				lx_method_run_shadows(&run[k], &frame);
				lx_method_run_decision(&run[k], 0, rgba, obj, sh);
				struct lx_mismatch mm;
				lx_mismatch_compare(ref_obj, ref_sh, obj, sh, (long)w * h, &mm);
				pct[k] = mm.mismatch_pct;
			}
			print_message("%-7s %-12s plane mismatch %.4f%%, simulated lima %.4f%%\n", *sn, lx_configs[c].name, pct[0],
				      pct[1]);
			worst = fmax(worst, pct[1] - pct[0]);
			if (pct[1] - pct[0] > 0.05)
				fail_msg("%s scene, %s: %.4f%% under the lima simulation against %.4f%%", *sn, lx_configs[c].name,
					 pct[1], pct[0]);
		}
		lx_method_run_free(&run[0]);
		lx_method_run_free(&run[1]);
		lx_meshes_free(&meshes);
	}
	print_message("worst: %.4f points more under the simulation\n", worst);
	free(rgba), free(sh), free(ref_sh), free(obj), free(ref_obj);
	lx_platform_destroy(plat);
}

/* Both platforms see the same objects at the same pixels. */
static void platforms_agree(void **state)
{
	(void)state;
	struct lx_scene scene;
	lx_scene_default(&scene);
	struct lx_render_report a, b;
	run("osmesa", "uniform", &scene, &a);
	run("egl", "uniform", &scene, &b);
	long differ = 0;
	for (long i = 0; i < (long)W * H; i++)
		differ += a.object[i] != b.object[i] || a.shadow[i] != b.shadow[i];
	print_message("osmesa and egl differ on %ld of %d pixels\n", differ, W * H);
	assert_true(differ <= W * H / 1000);
	lx_render_report_free(&a);
	lx_render_report_free(&b);
}

/* The GPU writes the same depth codes the CPU mirror computes, and never touches the
 * atlas's guard bands. A horizontal quad at y = 2, lit from above on its back face,
 * fills the map with one known depth per texel. */
static void gpu_depth_encoding_and_guards(void **state)
{
	(void)state;
	for (size_t p = 0; p < 2; p++) {
		char err[512];
		struct lx_scene s;
		/* the floor is there to be shadowed: the pass draws only what a lookup can read
		 * (lx_lookup_caster_maps), and the floor, turned to the light, is not drawn */
		const char *text = "light directional 0.3 -1 0.2\n"
				   "camera eye 0 0.3 4 at 0 2 0 fov 60\n"
				   "plane ceiling corner -3 2 -3 edge1 6 0 0 edge2 0 0 6\n"
				   "plane floor corner -3 0 3 edge1 6 0 0 edge2 0 0 -6\n";
		if (!lx_scene_parse(text, "ceiling.scene", &s, err, sizeof err))
			fail_msg("%s", err);
		struct lx_scene_meshes m;
		assert_true(lx_meshes_build(&s, &m));
		struct lx_frame f;
		assert_true(lx_frame_setup(&f, &s, &m, 0, 64, 64, err, sizeof err));
		struct lx_gl_caps caps;
		struct lx_platform *plat = platform_with_caps(platforms[p], &caps);
		const struct lx_shadow_method *me = lx_shadow_method_find("uniform");
		struct lx_region_request req[LX_MAX_MAPS];
		struct lx_atlas atlas;
		assert_true(lx_atlas_layout(&atlas, req, lx_shadow_method_regions(me, &s, &(struct lx_method_options)LX_METHOD_OPTIONS_DEFAULT, req), 2, caps.max_texture_size, err, sizeof err));
		struct lx_shadow_result res = {0};
		lx_shadow_method_frame(me, &f, &atlas, &(struct lx_method_options)LX_METHOD_OPTIONS_DEFAULT, &res);
		assert_true(res.maps[0].rendered);
		struct lx_renderer_desc d = {.scene = &s, .meshes = &m, .caps = &caps, .map_count = 1, .light_count = 1,
					     .lights = {{.atlas = &atlas}}, .width = 64, .height = 64,
					     .bias_codes = LX_DEFAULT_BIAS_CODES};
		struct lx_renderer *r = lx_renderer_create(&d, err, sizeof err);
		if (!r)
			fail_msg("%s", err);
		const struct lx_frame *fp = &f;
		const struct lx_shadow_result *rp = &res;
		lx_renderer_shadow_passes(r, &fp, &rp, 1);
		uint8_t *tex = malloc((size_t)atlas.width * atlas.height * 4);
		lx_renderer_read_atlas(r, tex);
		const struct lx_region *g = &atlas.regions[0];
		mat4 inv;
		assert_true(m4_invert(&res.maps[0].light_clip, &inv));
		long written = 0, worst = 0;
		for (int y = 0; y < atlas.height; y++)
			for (int x = 0; x < atlas.width; x++) {
				const uint8_t *t = tex + ((size_t)y * atlas.width + x) * 4;
				bool inside = x >= g->x && x < g->x + g->w && y >= g->y && y < g->y + g->h;
				if (!inside) {
					if (t[0] != 255 || t[1] != 255 || t[2] != 255 || t[3] != 255)
						fail_msg("%s: guard texel (%d, %d) was written", platforms[p], x, y);
					continue;
				}
				if (lx_depth_decode_code(t) == LX_DEPTH_MAX_CODE)
					continue; /* the quad does not cover this texel */
				/* the texel centre's light ray meets the plane y = 2 at a depth we compute in double */
				double cx = (x - g->x + 0.5) / g->w * 2 - 1, cy = (y - g->y + 0.5) / g->h * 2 - 1;
				vec4 a = m4_mul_v4(&inv, (vec4){cx, cy, -1, 1}), b = m4_mul_v4(&inv, (vec4){cx, cy, 1, 1});
				vec3 pa = v3(a.x / a.w, a.y / a.w, a.z / a.w), pb = v3(b.x / b.w, b.y / b.w, b.z / b.w);
				double k = (2 - pa.y) / (pb.y - pa.y); /* the light is not horizontal */
				vec4 q = m4_mul_point(&res.maps[0].light_clip, v3_add(pa, v3_scale(v3_sub(pb, pa), k)));
				long expect = (long)lx_depth_code(q.z / q.w * 0.5 + 0.5);
				long diff = labs((long)lx_depth_decode_code(t) - expect);
				worst = diff > worst ? diff : worst;
				written++;
			}
		print_message("%s: %ld texels written, worst depth code difference %ld (of 2^24)\n", platforms[p], written,
			      worst);
		assert_true(written > g->w * g->h / 2);
		/* float interpolation of z/w across the quad: a few codes, far below the bias */
		assert_true(worst <= 16);
		free(tex);
		lx_renderer_destroy(r);
		lx_platform_destroy(plat);
		lx_meshes_free(&m);
	}
}

static void unknown_platform_and_method_are_bad_input(void **state)
{
	(void)state;
	struct lx_render_job job = {.method = "teapot", .platform = "osmesa", .width = 8, .height = 8, .timed_frames = 1};
	lx_scene_default(&job.scene);
	struct lx_render_report r;
	char err[256];
	assert_int_equal(lx_render_run(&job, &r, err, sizeof err), 2);
	assert_non_null(strstr(err, "unknown method 'teapot'"));
	job.method = "uniform";
	job.platform = "vulkan";
	assert_int_equal(lx_render_run(&job, &r, err, sizeof err), 2);
	assert_non_null(strstr(err, "vulkan"));
}

/* A reference given to a job (render_run_cached's) is the one measured against: the same
 * figures as the cast one, other figures when its decisions are flipped, and one of
 * another size is refused with a message. */
static void given_reference_is_used_and_must_fit(void **state)
{
	(void)state;
	enum { w = 64, h = 48 };
	struct lx_render_job job = {.method = "uniform", .platform = "osmesa", .platform_in_use = shared_platform("osmesa"),
				    .width = w, .height = h, .time = 0.4, .timed_frames = 1, .measure = true,
				    .keep_pixels = true, .bias_codes = LX_DEFAULT_BIAS_CODES, .reference_threads = 1};
	lx_scene_default(&job.scene);
	struct lx_render_report cast, given;
	char err[256];
	assert_int_equal(lx_render_run(&job, &cast, err, sizeof err), 0);
	uint8_t *flipped = malloc((size_t)w * h);
	assert_non_null(flipped);
	for (long i = 0; i < (long)w * h; i++)
		flipped[i] = cast.ref_shadow[i] == 0 ? 1 : cast.ref_shadow[i] == 1 ? 0 : cast.ref_shadow[i];
	struct lx_reference_images ref = {w, h, 1, cast.ref_object, cast.ref_shadow, cast.ref_rgba};
	job.reference = &ref;
	assert_int_equal(lx_render_run(&job, &given, err, sizeof err), 0);
	assert_int_equal(given.mismatch.false_shadow, cast.mismatch.false_shadow);
	assert_int_equal(given.mismatch.missing_shadow, cast.mismatch.missing_shadow);
	assert_true(given.colour_error == cast.colour_error);
	lx_render_report_free(&given);
	ref.shadow = flipped;
	assert_int_equal(lx_render_run(&job, &given, err, sizeof err), 0);
	assert_true(given.mismatch.false_shadow + given.mismatch.missing_shadow >
		    cast.mismatch.false_shadow + cast.mismatch.missing_shadow + 100);
	lx_render_report_free(&given);
	ref.width = w / 2;
	assert_int_equal(lx_render_run(&job, &given, err, sizeof err), 1);
	assert_non_null(strstr(err, "the reference given is 32x48 (lights: 1), the frame 64x48 (lights: 1)"));
	free(flipped);
	lx_render_report_free(&cast);
}

/* A shader that fails names its file and carries the driver's log; the embedded
 * shaders build on both platforms. */
static void shader_failures_show_the_log(void **state)
{
	(void)state;
	for (size_t p = 0; p < 2; p++) {
		char err[2048];
		struct lx_platform *plat = lx_platform_create(platforms[p], err, sizeof err);
		if (!plat)
			fail_msg("%s", err);
		const char *vert = lx_embedded_text(lx_shader_files, "shadow_depth.vert");
		const char *broken = "#version 100\nprecision mediump float;\nvoid main() { gl_FragColor = undeclared; }\n";
		assert_int_equal(lx_program_build_text("shadow_depth.vert", vert, "broken.frag", broken, NULL, err, sizeof err), 0);
		print_message("%s: %s\n", platforms[p], err);
		assert_non_null(strstr(err, "broken.frag: compile error: "));
		assert_non_null(strstr(err, "undeclared"));
		const char *no_main = "#version 100\nprecision mediump float;\nvoid helper() {}\n";
		assert_int_equal(lx_program_build_text("shadow_depth.vert", vert, "nomain.frag", no_main, NULL, err, sizeof err), 0);
		assert_true(strstr(err, "nomain.frag") != NULL);
		GLuint prog = lx_program_build("main.vert", "main.frag", "#define LX_SHADOWED 1\n#define LX_READS 3\n", err, sizeof err);
		if (!prog)
			fail_msg("%s", err);
		lx_platform_destroy(plat);
	}
}

/* A context keeps the programs built in it by their texts: the same texts give the same
 * program (and its compiled variants), other defines another, a failed build none; a new
 * context starts with none of the old one's, and renders the same as without them. */
/* Frames over an animated show in a fresh context: the programs built, with the renderer
 * warmed first (lx_renderer_warm, as the kiosk does) and without. Returns how many the
 * frames built after the set-up. */
static int programs_built_by_frames(const char *scene_name, double step, bool warm, int *at_start)
{
	char err[512];
	struct lx_platform *plat = lx_platform_create("osmesa", err, sizeof err);
	if (!plat)
		fail_msg("%s", err);
	struct lx_gl_caps caps;
	lx_gl_caps_probe(&caps);
	struct lx_scene s;
	assert_true(lx_scene_builtin(scene_name, &s));
	struct lx_scene_meshes m = {0};
	assert_true(lx_meshes_build(&s, &m));
	struct lx_method_options o = LX_METHOD_OPTIONS_DEFAULT;
	struct lx_method_run run;
	if (lx_method_run_init(&run, "plane", &s, &m, &caps, &o, 160, 120, LX_DEPTH_AUTO, LX_DEFAULT_BIAS_CODES, false, err,
			       sizeof err) ||
	    lx_method_run_set_filter(&run, LX_FILTER_PCF2X2, err, sizeof err) ||
	    lx_method_run_set_filter(&run, LX_FILTER_NONE, err, sizeof err))
		fail_msg("%s", err);
	if (warm)
		lx_method_run_warm(&run);
	int kept;
	long reused;
	lx_programs_counts(at_start, &reused);
	for (int f = 0; f < 2; f++) {
		assert_int_equal(lx_method_run_set_filter(&run, f ? LX_FILTER_PCF2X2 : LX_FILTER_NONE, err, sizeof err), 0);
		for (int c = 0; c < lx_config_count; c++)
			for (double t = 0; t < 30; t += step) {
				struct lx_scene scene = s;
				lx_config_apply(&lx_configs[c], &scene);
				struct lx_frame frame;
				struct lx_frame_times times;
				assert_true(lx_frame_setup(&frame, &scene, &m, t, 160, 120, err, sizeof err));
				lx_method_run_frame(&run, &frame, NULL, &times);
			}
	}
	lx_programs_counts(&kept, &reused);
	lx_method_run_free(&run);
	lx_meshes_free(&m);
	lx_platform_destroy(plat);
	return kept - *at_start;
}

/* A warmed renderer builds no program while it shows every configuration of the default
 * scene over 30 s of its animation with both filters, nor of the table's (whose slab and
 * legs under its top draw with the top's cover test); unwarmed, the same frames build
 * some (so the frames do need more than the set-up builds). */
static void warmed_renderer_builds_nothing_later(void **state)
{
	(void)state;
	for (int sc = 0; sc < 2; sc++) {
		const char *name = sc ? "table" : "default";
		double step = sc ? 3.0 : 0.75;
		int warm_start, cold_start;
		int warm_later = programs_built_by_frames(name, step, true, &warm_start),
		    cold_later = programs_built_by_frames(name, step, false, &cold_start);
		print_message("%s scene: programs at the start: %d warmed, %d not; built by the frames after: %d, %d\n", name,
			      warm_start, cold_start, warm_later, cold_later);
		assert_int_equal(warm_later, 0);
		assert_true(cold_later > 0);
		assert_true(warm_start >= cold_start + cold_later); /* all the show needed, perhaps more */
	}
}

static void programs_are_kept_per_context(void **state)
{
	(void)state;
	char err[2048];
	for (int round = 0; round < 2; round++) {
		struct lx_platform *plat = lx_platform_create("osmesa", err, sizeof err);
		if (!plat)
			fail_msg("%s", err);
		int kept;
		long reused;
		lx_programs_counts(&kept, &reused);
		assert_int_equal(kept, 0); /* none of the context before */
		GLuint a = lx_program_build("main.vert", "main.frag", "#define LX_SHADOWED 1\n#define LX_READS 3\n", err, sizeof err);
		GLuint b = lx_program_build("main.vert", "main.frag", "#define LX_SHADOWED 1\n#define LX_READS 3\n", err, sizeof err);
		GLuint c = lx_program_build("main.vert", "main.frag", "#define LX_SHADOWED 1\n#define LX_READS 2\n", err, sizeof err);
		const char *vert = lx_embedded_text(lx_shader_files, "shadow_depth.vert");
		assert_int_equal(lx_program_build_text("shadow_depth.vert", vert, "broken.frag", "void main() { x; }\n", NULL, err,
						       sizeof err), 0);
		assert_true(a && a == b && c && c != a);
		lx_programs_counts(&kept, &reused);
		assert_int_equal(kept, 2);
		assert_int_equal(reused, 1);
		lx_platform_destroy(plat);
	}
	/* a run after another in one context reuses its programs, the decisions the same */
	struct lx_scene s;
	lx_scene_default(&s);
	struct lx_render_report first, again;
	run_path("osmesa", "plane", &s, false, &first);
	int kept;
	long reused;
	lx_programs_counts(&kept, &reused);
	long before = reused;
	run_path("osmesa", "plane", &s, false, &again);
	lx_programs_counts(&kept, &reused);
	print_message("programs kept %d, builds answered with a kept one %ld (the second run: %ld)\n", kept, reused,
		      reused - before);
	assert_true(reused - before >= 3);
	assert_memory_equal(first.shadow, again.shadow, (size_t)W * H);
	assert_memory_equal(first.object, again.object, (size_t)W * H * sizeof(int16_t));
	assert_true(first.mismatch.mismatch_pct == again.mismatch.mismatch_pct);
	lx_render_report_free(&first);
	lx_render_report_free(&again);
}

/* A frame's light matrices made ahead, while the GL drew the frame before
 * (lx_method_run_frame's `next`), are the ones it would make itself: the same result,
 * atlas layout and decisions, frame after frame of the table's animation (its maps laid
 * out anew each frame) for plane-optimal, which lays its maps out per frame, uniform
 * and none (no shadow pass: made while the main pass draws). A frame other than the one
 * foretold makes its own. */
static void a_set_up_made_ahead_is_the_frames_own(void **state)
{
	(void)state;
	struct lx_gl_caps caps;
	struct lx_platform *plat = platform_with_caps("osmesa", &caps);
	struct lx_scene s;
	assert_true(lx_scene_builtin("table", &s));
	struct lx_scene_meshes m;
	assert_true(lx_meshes_build(&s, &m));
	enum { N = 4 };
	static struct lx_frame f[N + 1];
	char err[512];
	for (int i = 0; i <= N; i++) /* frames 0..N-1 in turn; N: one not foretold */
		assert_true(lx_frame_setup(&f[i], &s, &m, i < N ? 2.0 + 0.7 * i : 9.5, W, H, err, sizeof err));
	size_t n = (size_t)W * H;
	uint8_t *rgba = malloc(n * 4), *sh[2] = {malloc(n), malloc(n)};
	int16_t *obj[2] = {malloc(n * sizeof(int16_t)), malloc(n * sizeof(int16_t))};
	assert_true(rgba && sh[0] && sh[1] && obj[0] && obj[1]);
	const char *names[] = {"plane", "uniform", "none"}; /* none: made while the main pass draws */
	static struct lx_method_run run[2]; /* [0] ahead, [1] frame by frame */
	for (int k = 0; k < 3; k++) {
		struct lx_method_options o = LX_METHOD_OPTIONS_DEFAULT;
		for (int r = 0; r < 2; r++)
			assert_int_equal(lx_method_run_init(&run[r], names[k], &s, &m, &caps, &o, W, H, LX_DEPTH_AUTO,
							    LX_DEFAULT_BIAS_CODES, false, err, sizeof err),
					 0);
		long shadowed = 0;
		for (int i = 0; i <= N; i++) {
			struct lx_frame_times t[2];
			/* frame N-1 foretells frame 0 again; frame N (another) comes instead */
			lx_method_run_frame(&run[0], &f[i], i < N - 1 ? &f[i + 1] : i == N - 1 ? &f[0] : NULL, &t[0]);
			lx_method_run_frame(&run[1], &f[i], NULL, &t[1]);
			assert_true(t[0].setup_ahead == (i > 0 && i < N));
			assert_false(t[1].setup_ahead);
			const struct lx_light_maps *a = &run[0].lights[0], *b = &run[1].lights[0];
			assert_memory_equal(&a->result, &b->result, sizeof a->result);
			assert_int_equal(a->atlas.count, b->atlas.count);
			for (int g = 0; g < a->atlas.count; g++) {
				const struct lx_region *ga = &a->atlas.regions[g], *gb = &b->atlas.regions[g];
				assert_true(ga->x == gb->x && ga->y == gb->y && ga->w == gb->w && ga->h == gb->h);
			}
			for (int r = 0; r < 2; r++)
				lx_method_run_decision(&run[r], 0, rgba, obj[r], sh[r]);
			assert_memory_equal(obj[0], obj[1], n * sizeof(int16_t));
			assert_memory_equal(sh[0], sh[1], n);
			for (size_t p = 0; p < n; p++)
				shadowed += sh[0][p];
		}
		assert_true(shadowed > 0 || k == 2); /* frames with shadows to get wrong */
		for (int r = 0; r < 2; r++)
			lx_method_run_free(&run[r]);
	}
	free(rgba), free(sh[0]), free(sh[1]), free(obj[0]), free(obj[1]);
	lx_meshes_free(&m);
	lx_platform_destroy(plat);
}

/* The kiosk's overlay draws its text over a frame: a dark box at the top left with
 * bright glyph pixels in it, the rest of the frame untouched. */
static void overlay_draws_text(void **state)
{
	(void)state;
	for (size_t p = 0; p < 2; p++) {
		char err[512];
		struct lx_platform *plat = lx_platform_create(platforms[p], err, sizeof err);
		if (!plat)
			fail_msg("%s", err);
		struct lx_scene s;
		lx_scene_default(&s);
		struct lx_scene_meshes m;
		assert_true(lx_meshes_build(&s, &m));
		struct lx_frame f;
		assert_true(lx_frame_setup(&f, &s, &m, 0, W, H, err, sizeof err));
		struct lx_gl_caps caps;
		lx_gl_caps_probe(&caps);
		struct lx_method_run mr;
		struct lx_method_options o = LX_METHOD_OPTIONS_DEFAULT;
		assert_int_equal(lx_method_run_init(&mr, "plane", &s, &m, &caps, &o, W, H, LX_DEPTH_AUTO, LX_DEFAULT_BIAS_CODES, false,
						    err, sizeof err),
				 0);
		struct lx_frame_times t;
		lx_method_run_frame(&mr, &f, NULL, &t);
		uint8_t *before = malloc((size_t)W * H * 4), *after = malloc((size_t)W * H * 4);
		lx_renderer_read(mr.renderer, before);
		struct lx_overlay *ov = lx_overlay_create(err, sizeof err);
		if (!ov)
			fail_msg("%s", err);
		const char *lines[] = {"lixel  plane", "60.0 fps", "floor  lpp 1.00  m 1.00  aniso 1.00"};
		lx_overlay_set_text(ov, lines, 3, 2);
		lx_overlay_draw(ov, W, H);
		lx_renderer_read(mr.renderer, after);
		if (p == 0 && getenv("LX_TEST_OVERLAY_PNG")) /* to look at it: LX_TEST_OVERLAY_PNG=file.png */
			lx_png_write(getenv("LX_TEST_OVERLAY_PNG"), after, W, H, err, sizeof err);
		/* the box, scale 2: 2 * 8 + 36 * 12 = 448 px wide (clipped to W), 2 * 8 + 3 * 18 = 70 px tall, at the top */
		long bright = 0, darker = 0, changed_outside = 0;
		for (int y = 0; y < H; y++)
			for (int x = 0; x < W; x++) {
				const uint8_t *a = before + ((size_t)y * W + x) * 4, *b = after + ((size_t)y * W + x) * 4;
				bool in_box = y >= H - 70 && x < 448;
				if (in_box) {
					bright += b[0] > 200 && b[1] > 200;
					darker += b[0] + b[1] + b[2] < a[0] + a[1] + a[2];
				} else
					changed_outside += memcmp(a, b, 4) != 0;
			}
		print_message("%s: overlay: %ld bright text pixels, %ld darkened, %ld changed outside the box\n",
			      platforms[p], bright, darker, changed_outside);
		assert_true(bright > 300);
		assert_true(darker > 5000);
		assert_int_equal(changed_outside, 0);
		free(before);
		free(after);
		lx_overlay_destroy(ov);
		lx_method_run_free(&mr);
		lx_meshes_free(&m);
		lx_platform_destroy(plat);
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_teardown(uniform_matches_reference, close_shared_platform),
		cmocka_unit_test_teardown(mediump_path_matches_reference, close_shared_platform),
		cmocka_unit_test_teardown(plane_matches_reference_and_wins, close_shared_platform),
		cmocka_unit_test_teardown(warps_match_reference, close_shared_platform),
		cmocka_unit_test_teardown(projective_lights_match_reference, close_shared_platform),
		cmocka_unit_test_teardown(two_lights_add_up, close_shared_platform),
		cmocka_unit_test_teardown(paper_bad_case_is_measured, close_shared_platform),
		cmocka_unit_test_teardown(plane_keeps_every_shadow, close_shared_platform),
		cmocka_unit_test_teardown(idle_budget_serves_the_casters, close_shared_platform),
		cmocka_unit_test_teardown(stretched_maps_follow_long_shadows, close_shared_platform),
		cmocka_unit_test_teardown(overlapping_pieces_give_a_lixel_per_pixel, close_shared_platform),
		cmocka_unit_test(overlapping_pieces_read_one_map),
		cmocka_unit_test_teardown(default_view_planes_get_a_lixel_per_pixel, close_shared_platform),
		cmocka_unit_test_teardown(mediump_reads_the_lixels_highp_reads, close_shared_platform),
		cmocka_unit_test_teardown(none_shadows_nothing, close_shared_platform),
		cmocka_unit_test_teardown(lookup_region_changes_no_decision, close_shared_platform),
		cmocka_unit_test_teardown(caster_faces_compare_along_their_planes, close_shared_platform),
		cmocka_unit_test_teardown(eight_varyings_decide_alike, close_shared_platform),
		cmocka_unit_test_teardown(round_casters_fanned_decide_as_faces, close_shared_platform),
		cmocka_unit_test_teardown(box_polygons_decide_no_worse, close_shared_platform),
		cmocka_unit_test_teardown(casters_pass_over_their_own_texels, close_shared_platform),
		cmocka_unit_test_teardown(sure_shadows_begin_at_the_silhouette, close_shared_platform),
		cmocka_unit_test_teardown(bands_kept_where_their_caster_reads, close_shared_platform),
		cmocka_unit_test_teardown(depth_selftest_picks_the_path, close_shared_platform),
		cmocka_unit_test_teardown(depth_texture_path_decides_as_highp, close_shared_platform),
		cmocka_unit_test_teardown(depth_slots_decide_as_clearing_every_frame, close_shared_platform),
		cmocka_unit_test_teardown(simulated_lima_keeps_the_shadows, close_shared_platform),
		cmocka_unit_test_teardown(platforms_agree, close_shared_platform),
		cmocka_unit_test_teardown(gpu_depth_encoding_and_guards, close_shared_platform),
		cmocka_unit_test_teardown(unknown_platform_and_method_are_bad_input, close_shared_platform),
		cmocka_unit_test_teardown(given_reference_is_used_and_must_fit, close_shared_platform),
		cmocka_unit_test_teardown(shader_failures_show_the_log, close_shared_platform),
		cmocka_unit_test_teardown(programs_are_kept_per_context, close_shared_platform),
		cmocka_unit_test_teardown(warmed_renderer_builds_nothing_later, close_shared_platform),
		cmocka_unit_test(a_lit_plane_front_shadows_what_lies_under_it),
		cmocka_unit_test(a_shelf_shadows_the_floor_without_a_caster),
		cmocka_unit_test(a_flat_box_pair_decides_its_shadow),
		cmocka_unit_test(a_slab_alone_needs_no_map),
		cmocka_unit_test(sure_shadows_skip_lookups),
		cmocka_unit_test(two_shelves_shadow_the_floor_both),
		cmocka_unit_test(a_set_up_made_ahead_is_the_frames_own),
		cmocka_unit_test_teardown(overlay_draws_text, close_shared_platform),
	};
	if (getenv("LIXEL_TEST_ONLY")) /* one test by name (a developer's rerun) */
		cmocka_set_test_filter(getenv("LIXEL_TEST_ONLY"));
	return cmocka_run_group_tests_name("render", tests, NULL, reference_cache_clear);
}
