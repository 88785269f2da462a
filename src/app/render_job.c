#include "render_job.h"
#include "platform.h"
#include "png_out.h"
#include "depth_rgba.h"
#include "reference.h"
#include "soft_reference.h"
#include "renderer.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

void lx_render_report_free(struct lx_render_report *rep)
{
	free(rep->ref_object);
	free(rep->object);
	free(rep->ref_shadow);
	free(rep->shadow);
	free(rep->visibility);
	free(rep->served);
	free(rep->ref_visibility);
	free(rep->ref_rgba);
	rep->ref_object = rep->object = NULL;
	rep->ref_shadow = rep->shadow = rep->visibility = rep->served = rep->ref_rgba = NULL;
	rep->ref_visibility = NULL;
}

/* The decision image: shadowed pixels red, lit ones tinted by object, background black. */
static void decision_colors(const int16_t *object, const uint8_t *shadow, long n, uint8_t *rgba)
{
	for (long i = 0; i < n; i++) {
		uint8_t *p = rgba + i * 4;
		if (object[i] < 0)
			p[0] = p[1] = p[2] = 0;
		else if (shadow[i])
			p[0] = 200, p[1] = 30, p[2] = 30;
		else
			p[0] = (uint8_t)(90 + 37 * (object[i] % 4)), p[1] = (uint8_t)(110 + 29 * (object[i] % 5)), p[2] = 140;
		p[3] = 255;
	}
}

/* The mismatch as a picture: false shadow blue, missing shadow red, silhouette pixels
 * yellow, agreeing pixels a dim grey (lighter where shadowed). */
static void mismatch_colors(const int16_t *ref_object, const uint8_t *ref_shadow, const int16_t *object,
			    const uint8_t *shadow, long n, uint8_t *rgba)
{
	for (long i = 0; i < n; i++) {
		uint8_t *p = rgba + i * 4, c[3] = {40, 40, 40};
		if (ref_object[i] != object[i])
			c[0] = 230, c[1] = 200, c[2] = 40;
		else if (object[i] >= 0 && (ref_shadow[i] == LX_REF_EDGE_ON || ref_shadow[i] == LX_REF_UNLIT))
			c[0] = c[1] = c[2] = 70; /* grazed by the light, or out of its reach: not compared */
		else if (object[i] >= 0 && shadow[i] && !ref_shadow[i])
			c[0] = 40, c[1] = 90, c[2] = 255;
		else if (object[i] >= 0 && !shadow[i] && ref_shadow[i])
			c[0] = 255, c[1] = 40, c[2] = 40;
		else if (object[i] >= 0)
			c[0] = c[1] = c[2] = shadow[i] ? 110 : 70;
		p[0] = c[0], p[1] = c[1], p[2] = c[2], p[3] = 255;
	}
}

/* The atlas texture as a picture, every light's part (the report's, as the last frame
 * laid them out): depth codes as grey levels (far white), guard bands red. */
static bool write_atlas(struct lx_renderer *r, const struct lx_render_report *rep, const char *path, char *err,
			size_t errlen)
{
	const struct lx_atlas *atlas = &rep->light[0].atlas; /* the parts share its texture */
	size_t n = (size_t)atlas->texture_width * atlas->texture_height;
	uint8_t *tex = malloc(n * 4);
	if (!tex) {
		snprintf(err, errlen, "out of memory for the atlas image");
		return false;
	}
	lx_renderer_read_atlas(r, tex);
	for (size_t i = 0; i < n; i++) {
		uint8_t g = (uint8_t)(lx_depth_decode_code(tex + i * 4) >> 16);
		tex[i * 4] = tex[i * 4 + 1] = tex[i * 4 + 2] = g;
		tex[i * 4 + 3] = 255;
		/* outside every region (the guard bands): red, to show the layout */
		int x = (int)(i % (size_t)atlas->texture_width), y = (int)(i / (size_t)atlas->texture_width);
		bool inside = false;
		for (int l = 0; l < rep->light_count; l++)
			for (int k = 0; k < rep->light[l].atlas.count; k++) {
				const struct lx_region *g2 = &rep->light[l].atlas.regions[k];
				inside |= x >= g2->x && x < g2->x + g2->w && y >= g2->y && y < g2->y + g2->h;
			}
		if (!inside)
			tex[i * 4] = 200, tex[i * 4 + 1] = 40, tex[i * 4 + 2] = 40;
	}
	bool ok = lx_png_write(path, tex, atlas->texture_width, atlas->texture_height, err, errlen);
	free(tex);
	return ok;
}

/* Warm-up and timed frames: their medians and extremes into rep, and the image read
 * back into rgba. False after err. */
static bool time_frames(const struct lx_render_job *job, struct lx_method_run *mr, const struct lx_frame *frame,
			struct lx_render_report *rep, uint8_t *rgba, char *err, size_t errlen)
{
	int timed = job->timed_frames > 0 ? job->timed_frames : 1;
	double *times = calloc((size_t)timed * 4, sizeof(double));
	if (!times) {
		snprintf(err, errlen, "out of memory for %d frames' times", timed);
		return false;
	}
	double *frame_ms = times, *shadow_ms = times + timed, *main_ms = shadow_ms + timed, *setup_us = main_ms + timed;
	lx_renderer_finish();
	for (int i = 0; i < job->warmup_frames + timed; i++) {
		struct lx_frame_times t; /* a still frame: each one's set-up made during the last */
		lx_method_run_frame(mr, frame, i + 1 < job->warmup_frames + timed ? frame : NULL, &t);
		int k = i - job->warmup_frames;
		if (k >= 0)
			frame_ms[k] = t.frame_ms, shadow_ms[k] = t.shadow_ms, main_ms[k] = t.main_ms, setup_us[k] = t.setup_us;
	}
	for (int l = 0; l < mr->light_count; l++) {
		rep->light[l].result = mr->lights[l].result;
		rep->light[l].atlas = mr->lights[l].atlas; /* as the last frame laid it out */
	}
	rep->frame_ms_min = INFINITY;
	for (int k = 0; k < timed; k++) {
		rep->frame_ms_min = fmin(rep->frame_ms_min, frame_ms[k]);
		rep->frame_ms_max = fmax(rep->frame_ms_max, frame_ms[k]);
	}
	rep->frame_ms = lx_median(frame_ms, timed);
	rep->shadow_ms = lx_median(shadow_ms, timed);
	rep->main_ms = lx_median(main_ms, timed);
	rep->setup_us = lx_median(setup_us, timed);
	free(times);
	lx_renderer_read(mr->renderer, rgba);
	return true;
}

/* The main pass's decision per pixel for every light (with --measure, --decision-out or
 * for tests), and the first light's image. False after err. */
static bool decide(const struct lx_render_job *job, struct lx_method_run *mr, struct lx_render_report *rep,
		   uint8_t *rgba, char *err, size_t errlen)
{
	long n = (long)job->width * job->height;
	int lights = mr->light_count;
	rep->object = malloc((size_t)n * sizeof(int16_t));
	rep->shadow = malloc((size_t)n * lights);
	rep->visibility = malloc((size_t)n * lights);
	rep->served = malloc((size_t)n * lights);
	if (!rep->object || !rep->shadow || !rep->visibility || !rep->served) {
		snprintf(err, errlen, "out of memory");
		return false;
	}
	rep->lookup_pct = 0;
	for (int l = lights - 1; l >= 0; l--) { /* the first light last: its image stays in rgba */
		uint8_t *shadow = rep->shadow + (size_t)l * n, *vis = rep->visibility + (size_t)l * n;
		rep->light[l].lookup_pct = 100.0 * lx_method_run_decision(mr, l, rgba, rep->object, shadow) / n;
		rep->lookup_pct += rep->light[l].lookup_pct / lights;
		lx_decision_visibility(rgba, n, mr->filter, vis);
		lx_decision_served(rgba, n, rep->served + (size_t)l * n);
	}
	if (!job->decision_png)
		return true;
	decision_colors(rep->object, rep->shadow, n, rgba);
	return lx_png_write(job->decision_png, rgba, job->width, job->height, err, errlen);
}

/* The soft reference of each light and soft_error_pct over them all (each light's
 * weighted by the pixels it compares). False after err. */
static bool measure_soft(const struct lx_render_job *job, const struct lx_method_run *mr, struct lx_render_report *rep,
			 char *err, size_t errlen)
{
	long n = (long)job->width * job->height;
	rep->ref_visibility = malloc((size_t)n * mr->light_count * sizeof(float));
	if (!rep->ref_visibility) {
		snprintf(err, errlen, "out of memory for the soft reference image");
		return false;
	}
	double sum = 0, weight = 0;
	for (int l = 0; l < mr->light_count; l++) {
		size_t o = (size_t)l * n;
		if (!lx_soft_reference_image(&mr->lights[l].frame, job->light_size_deg, rep->ref_visibility + o,
					     job->reference_threads)) {
			snprintf(err, errlen, "out of memory for the soft reference image");
			return false;
		}
		double e = lx_soft_error(rep->ref_object, rep->ref_shadow + o, rep->ref_visibility + o, rep->object,
					 rep->visibility + o, n);
		double w = rep->light[l].mismatch.compared;
		sum += e * w, weight += w;
	}
	rep->soft_error_pct = weight > 0 ? sum / weight : 0;
	rep->light_size_deg = job->light_size_deg;
	rep->soft_measured = true;
	return true;
}

/* The exact reference into the report: the job's, cast before, or cast here. False after err. */
static bool reference(const struct lx_render_job *job, struct lx_render_report *rep, const struct lx_method_run *mr,
		      char *err, size_t errlen)
{
	long n = (long)job->width * job->height;
	int lights = mr->light_count;
	rep->ref_object = malloc((size_t)n * sizeof(int16_t));
	rep->ref_shadow = malloc((size_t)n * lights);
	rep->ref_rgba = malloc((size_t)n * 4);
	if (!rep->ref_object || !rep->ref_shadow || !rep->ref_rgba) {
		snprintf(err, errlen, "out of memory for the reference image");
		return false;
	}
	const struct lx_reference_images *given = job->reference;
	if (!given) {
		if (lx_method_run_reference(mr, rep->ref_object, rep->ref_shadow, rep->ref_rgba, job->reference_threads))
			return true;
		snprintf(err, errlen, "out of memory for the reference image");
		return false;
	}
	if (given->width != job->width || given->height != job->height || given->lights != lights) {
		snprintf(err, errlen, "the reference given is %dx%d (lights: %d), the frame %dx%d (lights: %d)", given->width,
			 given->height, given->lights, job->width, job->height, lights);
		return false;
	}
	memcpy(rep->ref_object, given->object, (size_t)n * sizeof(int16_t));
	memcpy(rep->ref_shadow, given->shadow, (size_t)n * lights);
	memcpy(rep->ref_rgba, given->rgba, (size_t)n * 4);
	return true;
}

/* The exact reference, each light's mismatch and planes' figures (and their warnings),
 * the mismatch of them all, and the first light's mismatch image. False after err. */
static bool measure(const struct lx_render_job *job, struct lx_render_report *rep, const struct lx_method_run *mr,
		    const uint8_t *shaded, uint8_t *rgba, char *err, size_t errlen)
{
	long n = (long)job->width * job->height;
	int lights = mr->light_count;
	if (!reference(job, rep, mr, err, errlen))
		return false;
	/* colour_error: the shaded frame against the reference's shading of the same view */
	rep->colour_error = lx_colour_error(shaded, rep->ref_rgba, n);
	if (job->reference_png && !lx_png_write(job->reference_png, rep->ref_rgba, job->width, job->height, err, errlen))
		return false;
	rep->plane_count = job->scene.plane_count;
	rep->mismatch = (struct lx_mismatch){0};
	/* the lights share the view, so their planes' pixels: worked out once for them all */
	struct lx_plane_points pts;
	if (!lx_plane_points_make(&mr->lights[0].frame, rep->ref_object, &pts)) {
		snprintf(err, errlen, "out of memory for the planes' points");
		return false;
	}
	for (int l = 0; l < lights; l++) {
		struct lx_light_report *lr = &rep->light[l];
		lx_measure(&mr->lights[l].frame, &lr->atlas, &lr->result, rep->ref_object, rep->ref_shadow + (size_t)l * n,
			   rep->object, rep->shadow + (size_t)l * n, rep->served + (size_t)l * n, &pts, &lr->mismatch,
			   lr->planes);
		lx_sampling_warnings(lr->planes, rep->plane_count, lx_atlas_lixels(&lr->atlas), &lr->result);
		lx_mismatch_add(&rep->mismatch, &lr->mismatch);
	}
	lx_plane_points_free(&pts);
	rep->measured = true;
	if (job->soft && !measure_soft(job, mr, rep, err, errlen))
		return false;
	if (!job->mismatch_png)
		return true;
	mismatch_colors(rep->ref_object, rep->ref_shadow, rep->object, rep->shadow, n, rgba);
	return lx_png_write(job->mismatch_png, rgba, job->width, job->height, err, errlen);
}

/* The method set up, the frames timed, the outputs written, the measurements. */
static int render_frames(const struct lx_render_job *job, const struct lx_scene_meshes *meshes,
			 const struct lx_frame *frame, struct lx_render_report *rep, char *err, size_t errlen)
{
	lx_gl_caps_probe(&rep->caps);
	struct lx_method_options opt = job->budgets.uniform_lixels ? job->budgets : LX_METHOD_OPTIONS_DEFAULT;
	struct lx_method_run mr;
	int status = lx_method_run_init(&mr, job->method, &job->scene, meshes, &rep->caps, &opt, job->width,
					job->height, job->depth_precision, job->bias_codes, false, err, errlen);
	if (!status)
		status = lx_method_run_set_filter(&mr, job->filter, err, errlen);
	if (status) {
		lx_method_run_free(&mr);
		return status;
	}
	rep->depth = mr.depth;
	rep->depth_slots = lx_renderer_depth_slots(mr.renderer);
	rep->light_count = mr.light_count;
	for (int l = 0; l < mr.light_count; l++)
		snprintf(rep->light[l].kind, sizeof rep->light[l].kind, "%s", lx_light_kind_name(&job->scene.lights[l]));
	uint8_t *rgba = malloc((size_t)job->width * job->height * 4);
	bool ok = rgba != NULL;
	if (!ok)
		snprintf(err, errlen, "out of memory for a %dx%d image", job->width, job->height);
	ok = ok && time_frames(job, &mr, frame, rep, rgba, err, errlen);
	ok = ok && (!job->out_png || lx_png_write(job->out_png, rgba, job->width, job->height, err, errlen));
	ok = ok && (!job->atlas_png || write_atlas(mr.renderer, rep, job->atlas_png, err, errlen));
	/* the shaded frame, kept for the colour error (the decision pass reuses rgba) */
	uint8_t *shaded = ok && job->measure ? malloc((size_t)job->width * job->height * 4) : NULL;
	if (ok && job->measure && !shaded) {
		snprintf(err, errlen, "out of memory for a %dx%d image", job->width, job->height);
		ok = false;
	}
	if (shaded)
		memcpy(shaded, rgba, (size_t)job->width * job->height * 4);
	if (ok && (job->measure || job->keep_pixels || job->decision_png))
		ok = decide(job, &mr, rep, rgba, err, errlen);
	if (ok && job->measure)
		ok = measure(job, rep, &mr, shaded, rgba, err, errlen);
	free(shaded);
	free(rgba);
	lx_method_run_free(&mr);
	return ok ? 0 : 1;
}

int lx_render_run(const struct lx_render_job *job, struct lx_render_report *rep, char *err, size_t errlen)
{
	memset(rep, 0, sizeof(*rep));
	rep->lookup_pct = -1;
	struct lx_method_options probe = job->budgets;
	if (!lx_shadow_method_spec(job->method, &probe, err, errlen))
		return 2;
	if (job->width < 1 || job->height < 1) {
		snprintf(err, errlen, "size %dx%d, expected at least 1x1", job->width, job->height);
		return 2;
	}
	snprintf(rep->method, sizeof rep->method, "%s", job->method);
	snprintf(rep->platform, sizeof rep->platform, "%s", job->platform);
	snprintf(rep->filter, sizeof rep->filter, "%s", lx_filter_name(job->filter));
	rep->width = job->width;
	rep->height = job->height;
	struct lx_scene_meshes meshes = {0};
	if (!lx_meshes_build(&job->scene, &meshes)) {
		snprintf(err, errlen, "out of memory building the meshes");
		return 1;
	}
	struct lx_frame frame;
	int status = 2;
	if (lx_frame_setup(&frame, &job->scene, &meshes, job->time, job->width, job->height, err, errlen)) {
		struct lx_platform *plat = job->platform_in_use ? job->platform_in_use
								 : lx_platform_create(job->platform, err, errlen);
		if (plat)
			status = render_frames(job, &meshes, &frame, rep, err, errlen);
		else
			status = lx_platform_known(job->platform) ? 1 : 2;
		if (plat != job->platform_in_use)
			lx_platform_destroy(plat);
	}
	if (status != 0 || !job->keep_pixels)
		lx_render_report_free(rep);
	lx_meshes_free(&meshes);
	return status;
}
