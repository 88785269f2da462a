#include "method_run.h"
#include "light_image.h"
#include "reference.h"
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

static double now_ms(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return ts.tv_sec * 1e3 + ts.tv_nsec / 1e6;
}

/* Each light's budgets, atlas part and image; then the parts stacked in one texture.
 * Returns 0, or 2 for input the GL cannot hold. */
static int light_maps(struct lx_method_run *mr, const struct lx_scene *scene, int max_texture, char *err, size_t errlen)
{
	struct lx_atlas *parts[LX_MAX_LIGHTS];
	for (int i = 0; i < mr->light_count; i++) {
		struct lx_light_maps *lm = &mr->lights[i];
		lm->options = lx_method_options_for_light(&mr->options, i);
		struct lx_region_request req[LX_MAX_MAPS];
		int nreq = lx_shadow_method_regions(mr->method, scene, &lm->options, req);
		if (!lx_atlas_layout(&lm->atlas, req, nreq, 1, max_texture, err, errlen))
			return 2; /* budgets this GL cannot hold: the input asks too much */
		const struct lx_light *l = &scene->lights[i];
		if (!lx_light_image_load(l, &lm->image, err, errlen))
			return 2; /* the scene names a file that is not a usable PNG */
		parts[i] = &lm->atlas;
	}
	if (lx_atlas_stack(parts, mr->light_count, max_texture, err, errlen))
		return 0;
	size_t len = strlen(err); /* the lights' budgets are the user's to lower */
	snprintf(err + len, errlen - len, "; give the lights less with --light-budget (e.g. 1,0.5)");
	return 2;
}

int lx_method_run_init(struct lx_method_run *mr, const char *name, const struct lx_scene *scene,
		       const struct lx_scene_meshes *meshes, const struct lx_gl_caps *caps,
		       const struct lx_method_options *budgets, int width, int height, enum lx_depth_precision precision,
		       double bias_codes, bool to_window, char *err, size_t errlen)
{
	memset(mr, 0, sizeof(*mr));
	mr->options = *budgets;
	mr->method = lx_shadow_method_spec(name, &mr->options, err, errlen);
	if (!mr->method)
		return 2;
	mr->width = width;
	mr->height = height;
	mr->light_count = lx_method_lights(&mr->options, scene);
	int status = light_maps(mr, scene, caps->max_texture_size, err, errlen);
	if (status)
		return status;
	if (!lx_depth_choose(precision, &mr->depth, err, errlen))
		return 1;
	struct lx_renderer_desc rd = {.scene = scene, .meshes = meshes, .caps = caps,
				      .map_count = mr->lights[0].atlas.count, .width = width, .height = height,
				      .depth = mr->depth.taken, .bias_codes = bias_codes, .to_window = to_window,
				      .lookup_everywhere = mr->options.lookup_everywhere,
				      .caster_face_depth = mr->options.caster_face_depth, .light_count = mr->light_count,
				      .depth_slots = mr->options.depth_slots};
	for (int i = 0; i < mr->light_count; i++) {
		rd.lights[i].atlas = &mr->lights[i].atlas;
		rd.lights[i].image = mr->lights[i].image.rgba ? &mr->lights[i].image : NULL;
	}
	mr->renderer = lx_renderer_create(&rd, err, errlen);
	if (!mr->renderer)
		return 1;
	for (int i = 0; i < mr->light_count; i++) /* what the main pass can test decides what the maps keep */
		mr->lights[i].options.keep_flat_boxes = lx_renderer_covers_short(mr->renderer);
	return 0;
}

void lx_method_run_warm(struct lx_method_run *mr) { lx_renderer_warm(mr->renderer); }

int lx_method_run_set_filter(struct lx_method_run *mr, enum lx_filter filter, char *err, size_t errlen)
{
	if (!lx_renderer_set_filter(mr->renderer, filter, err, errlen))
		return 1;
	mr->filter = filter;
	/* a filter reads lixels around the one a pixel falls in: the plane maps' density
	 * shapes their own pixels' edges too (method_plane.c, readers_scale) */
	mr->options.filtered = filter != LX_FILTER_NONE;
	for (int i = 0; i < mr->light_count; i++)
		mr->lights[i].options.filtered = mr->options.filtered;
	mr->ahead_ready = false; /* made with the filter before */
	return 0;
}

void lx_method_run_set_lookup_everywhere(struct lx_method_run *mr, bool everywhere)
{
	lx_renderer_set_lookup_everywhere(mr->renderer, everywhere);
	mr->options.lookup_everywhere = everywhere;
}

void lx_decision_visibility(const uint8_t *rgba, long pixels, enum lx_filter filter, uint8_t *visibility)
{
	for (long i = 0; i < pixels; i++)
		visibility[i] = filter == LX_FILTER_NONE ? (rgba[i * 4] > 127 ? 0 : 255) : rgba[i * 4 + 3];
}

void lx_decision_served(const uint8_t *rgba, long pixels, uint8_t *served)
{
	for (long i = 0; i < pixels; i++)
		served[i] = rgba[i * 4 + 2] > 63; /* 255: a lookup ran; 128: a sure shadow */
}

void lx_method_run_free(struct lx_method_run *mr)
{
	lx_renderer_destroy(mr->renderer);
	mr->renderer = NULL;
	for (int i = 0; i < LX_MAX_LIGHTS; i++)
		lx_image_free(&mr->lights[i].image);
}

/* Light i's frame of f and its light matrices into frame and res, its maps placed in
 * *atlas (which starts as the light's layout of the frame before). */
static void set_up_light(const struct lx_method_run *mr, int i, const struct lx_frame *f, struct lx_frame *frame,
			 struct lx_atlas *atlas, struct lx_shadow_result *res)
{
	lx_frame_for_light(f, i, frame);
	lx_shadow_method_frame(mr->method, frame, atlas, &mr->lights[i].options, res);
}

/* Every light's frame and light matrices, its maps placed in its part of the atlas. */
static void build_maps(struct lx_method_run *mr, const struct lx_frame *f)
{
	mr->ahead_ready = false; /* made from the atlas as it was before this */
	lx_renderer_drop_plan(mr->renderer);
	for (int i = 0; i < mr->light_count; i++) {
		struct lx_light_maps *lm = &mr->lights[i];
		set_up_light(mr, i, f, &lm->frame, &lm->atlas, &lm->result);
	}
}

/* The set-up of frame `next` into mr->ahead, each light's atlas as this frame left it
 * (what build_maps would start from); returns its time in us. */
static double build_ahead(struct lx_method_run *mr, const struct lx_frame *next)
{
	double t0 = now_ms();
	for (int i = 0; i < mr->light_count; i++) {
		struct lx_light_ahead *a = &mr->ahead[i];
		a->atlas = mr->lights[i].atlas;
		set_up_light(mr, i, next, &a->frame, &a->atlas, &a->result);
	}
	memcpy(&mr->ahead_of, next, sizeof *next); /* compared byte by byte: no padding left out */
	mr->ahead_ready = true;
	return (now_ms() - t0) * 1e3;
}

/* The next frame's shadow-pass CPU work from the set-up made ahead (the renderer's plan),
 * which take_ahead hands over byte for byte. */
static void plan_ahead(struct lx_method_run *mr)
{
	const struct lx_frame *frames[LX_MAX_LIGHTS];
	const struct lx_shadow_result *results[LX_MAX_LIGHTS];
	const struct lx_atlas *atlases[LX_MAX_LIGHTS];
	for (int i = 0; i < mr->light_count; i++)
		frames[i] = &mr->ahead[i].frame, results[i] = &mr->ahead[i].result, atlases[i] = &mr->ahead[i].atlas;
	lx_renderer_plan_shadows(mr->renderer, frames, results, atlases, mr->light_count);
}

/* Whether the set-up made ahead is frame f's, taken into the lights if so (dropped
 * either way). */
static bool take_ahead(struct lx_method_run *mr, const struct lx_frame *f)
{
	bool ours = mr->ahead_ready && !memcmp(&mr->ahead_of, f, sizeof *f);
	mr->ahead_ready = false;
	for (int i = 0; ours && i < mr->light_count; i++) {
		struct lx_light_maps *lm = &mr->lights[i];
		lm->frame = mr->ahead[i].frame, lm->atlas = mr->ahead[i].atlas, lm->result = mr->ahead[i].result;
	}
	return ours;
}

/* The lights' set-up of frame f: taken from the one made ahead, or made now. */
static bool set_up(struct lx_method_run *mr, const struct lx_frame *f)
{
	if (take_ahead(mr, f))
		return true;
	build_maps(mr, f);
	return false;
}

/* The lights' frames and maps as the renderer takes them. */
struct light_lists {
	const struct lx_frame *frames[LX_MAX_LIGHTS];
	const struct lx_shadow_result *results[LX_MAX_LIGHTS];
};

static struct light_lists light_lists(const struct lx_method_run *mr)
{
	struct light_lists l;
	for (int i = 0; i < mr->light_count; i++)
		l.frames[i] = &mr->lights[i].frame, l.results[i] = &mr->lights[i].result;
	return l;
}

static void shadow_passes(struct lx_method_run *mr)
{
	struct light_lists l = light_lists(mr);
	lx_renderer_shadow_passes(mr->renderer, l.frames, l.results, mr->light_count);
}

static void main_passes(struct lx_method_run *mr)
{
	struct light_lists l = light_lists(mr);
	lx_renderer_main_pass(mr->renderer, l.frames, l.results, mr->light_count);
}

/* The shadow passes sent and flushed, the main pass's CPU work done while the GL draws
 * them (on one llvmpipe thread 40-140 us a frame that the frame no longer waits for; on a
 * board the GPU's work beside the CPU's). A method without maps has nothing to overlap. */
static void shadows_then_main_prepared(struct lx_method_run *mr)
{
	shadow_passes(mr);
	if (mr->lights[0].atlas.count == 0)
		return;
	struct light_lists l = light_lists(mr);
	lx_renderer_flush();
	lx_renderer_main_prepare(mr->renderer, l.frames, l.results, mr->light_count);
}

/* The set-up once more, right after the frame's own, into copies that nothing reads:
 * after the previous frame's glFinish llvmpipe's rasterizer has run through the CPU's
 * caches, and the frame's set-up takes 1.5 to 1.9 times as long as the same work done
 * again at once (results.md's runs). Returns the repeat's time in us. */
static double setup_again_us(const struct lx_method_run *mr, const struct lx_frame *f)
{
	double t0 = now_ms();
	for (int i = 0; i < mr->light_count; i++) {
		struct lx_frame frame;
		struct lx_atlas atlas = mr->lights[i].atlas;
		struct lx_shadow_result res;
		set_up_light(mr, i, f, &frame, &atlas, &res);
	}
	return (now_ms() - t0) * 1e3;
}

/* The main pass handed to the GL, then, while it draws, the next frame's set-up (and its
 * repeat, timed); returns when the GL is done. */
static void main_then_ahead(struct lx_method_run *mr, const struct lx_frame *next)
{
	main_passes(mr);
	if (next) {
		lx_renderer_flush();
		mr->ahead_us = build_ahead(mr, next);
		plan_ahead(mr);
		mr->ahead_again_us = mr->setup_again ? setup_again_us(mr, next) : NAN;
	}
}

void lx_method_run_frame(struct lx_method_run *mr, const struct lx_frame *f, const struct lx_frame *next,
			 struct lx_frame_times *t)
{
	double t0 = now_ms();
	bool ahead = set_up(mr, f);
	double t1 = now_ms(), setup = ahead ? mr->ahead_us : (t1 - t0) * 1e3;
	double again = ahead ? mr->ahead_again_us : mr->setup_again ? setup_again_us(mr, f) : NAN;
	double t1b = now_ms();
	shadows_then_main_prepared(mr);
	lx_renderer_finish();
	double t2 = now_ms();
	main_then_ahead(mr, next);
	lx_renderer_finish();
	double t3 = now_ms();
	*t = (struct lx_frame_times){.setup_us = setup, .setup_ahead = ahead, .setup_again_us = again,
				     .shadow_ms = t2 - t1b, .main_ms = t3 - t2, .frame_ms = (t1 - t0) + (t3 - t1b)};
}

void lx_method_run_shadows(struct lx_method_run *mr, const struct lx_frame *f)
{
	build_maps(mr, f);
	shadow_passes(mr);
}

void lx_method_run_draw(struct lx_method_run *mr, const struct lx_frame *f, const struct lx_frame *next)
{
	set_up(mr, f);
	shadows_then_main_prepared(mr);
	main_then_ahead(mr, next);
}

long lx_method_run_decision(struct lx_method_run *mr, int light, uint8_t *rgba, int16_t *object, uint8_t *shadow)
{
	const struct lx_light_maps *lm = &mr->lights[light >= 0 && light < mr->light_count ? light : 0];
	long lookups = 0;
	lx_renderer_decision_pass(mr->renderer, &lm->frame, &lm->result);
	lx_renderer_read(mr->renderer, rgba);
	long n = (long)mr->width * mr->height;
	for (long i = 0; i < n; i++) {
		shadow[i] = rgba[i * 4] > 127;
		object[i] = (int16_t)(rgba[i * 4 + 1] - 1); /* (id + 1.25) / 255 stores id + 1 */
		lookups += rgba[i * 4 + 2] > 191; /* 255: a lookup ran; 128: a map decided without one */
	}
	return lookups;
}

bool lx_method_run_reference(const struct lx_method_run *mr, int16_t *object, uint8_t *shadowed, uint8_t *rgba,
			     int threads)
{
	const struct lx_frame *frames[LX_MAX_LIGHTS];
	const struct lx_image *images[LX_MAX_LIGHTS];
	uint8_t *out[LX_MAX_LIGHTS];
	for (int l = 0; l < mr->light_count; l++) {
		frames[l] = &mr->lights[l].frame;
		images[l] = mr->lights[l].image.rgba ? &mr->lights[l].image : NULL;
		out[l] = shadowed + (size_t)l * mr->width * mr->height;
	}
	return lx_reference_lights(frames, images, mr->light_count, object, out, rgba, threads);
}

void lx_measure(const struct lx_frame *f, const struct lx_atlas *atlas, const struct lx_shadow_result *res,
		const int16_t *ref_object, const uint8_t *ref_shadow, const int16_t *object, const uint8_t *shadow,
		const uint8_t *looked, const struct lx_plane_points *pts, struct lx_mismatch *mismatch,
		struct lx_plane_report *planes)
{
	lx_mismatch_compare(ref_object, ref_shadow, object, shadow, (long)f->view.width * f->view.height, mismatch);
	for (int p = 0; p < f->scene->plane_count; p++) {
		snprintf(planes[p].name, sizeof planes[p].name, "%s", f->scene->planes[p].name);
		planes[p].present = lx_plane_sampling(f, atlas, res, p, ref_object, pts, looked, &planes[p].s);
	}
}

void lx_sampling_warnings(const struct lx_plane_report *planes, int n, long map_lixels, struct lx_shadow_result *res)
{
	double used = 0;
	bool coarse = false; /* some plane's pixels read less than a lixel each (median) */
	for (int p = 0; p < n; p++) {
		if (!planes[p].present)
			continue;
		coarse |= planes[p].s.lpp_median < 1;
		used += planes[p].s.lixels_used;
		if (planes[p].s.m_median > LX_COARSE_PIXELS_PER_LIXEL)
			lx_shadow_warn(res, "plane %s: one lixel spans %.0f pixels (median): its shadows are that coarse there",
				       planes[p].name, planes[p].s.m_median);
	}
	/* few pixels reading the maps at a lixel or more each is a small shadow, not a coarse one */
	if (coarse && map_lixels > 0 && used < LX_LOW_BUDGET_USE * map_lixels)
		lx_shadow_warn(res, "only %.2f%% of the maps' %ld lixels fall on the visible planes: their shadows are coarse",
			       100 * used / map_lixels, map_lixels);
}
