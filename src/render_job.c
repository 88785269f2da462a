#include "render_job.h"
#include "platform.h"
#include "png_out.h"
#include "depth_rgba.h"
#include "reference.h"
#include "renderer.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double now_ms(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return ts.tv_sec * 1e3 + ts.tv_nsec / 1e6;
}

void lx_render_report_free(struct lx_render_report *rep)
{
	free(rep->ref_object);
	free(rep->object);
	free(rep->ref_shadow);
	free(rep->shadow);
	rep->ref_object = rep->object = NULL;
	rep->ref_shadow = rep->shadow = NULL;
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

/* The atlas as a picture: depth codes as grey levels (far white), guard bands red. */
static bool write_atlas(struct lx_renderer *r, const struct lx_atlas *atlas, const char *path, char *err, size_t errlen)
{
	size_t n = (size_t)atlas->width * atlas->height;
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
		int x = (int)(i % (size_t)atlas->width), y = (int)(i / (size_t)atlas->width);
		bool inside = false;
		for (int k = 0; k < atlas->count; k++) {
			const struct lx_region *g2 = &atlas->regions[k];
			inside |= x >= g2->x && x < g2->x + g2->w && y >= g2->y && y < g2->y + g2->h;
		}
		if (!inside)
			tex[i * 4] = 200, tex[i * 4 + 1] = 40, tex[i * 4 + 2] = 40;
	}
	bool ok = lx_png_write(path, tex, atlas->width, atlas->height, err, errlen);
	free(tex);
	return ok;
}

int lx_render_run(const struct lx_render_job *job, struct lx_render_report *rep, char *err, size_t errlen)
{
	memset(rep, 0, sizeof(*rep));
	const struct lx_shadow_method *method = lx_shadow_method_find(job->method);
	if (!method) {
		snprintf(err, errlen, "unknown method '%s', expected %s", job->method, lx_shadow_method_names());
		return 2;
	}
	if (job->width < 1 || job->height < 1) {
		snprintf(err, errlen, "size %dx%d, expected at least 1x1", job->width, job->height);
		return 2;
	}
	snprintf(rep->method, sizeof rep->method, "%s", method->name);
	snprintf(rep->platform, sizeof rep->platform, "%s", job->platform);
	rep->width = job->width;
	rep->height = job->height;

	struct lx_scene_meshes meshes = {0};
	if (!lx_meshes_build(&job->scene, &meshes)) {
		snprintf(err, errlen, "out of memory building the meshes");
		return 1;
	}
	struct lx_frame frame;
	if (!lx_frame_setup(&frame, &job->scene, &meshes, job->time, job->width, job->height, err, errlen)) {
		lx_meshes_free(&meshes);
		return 2;
	}
	struct lx_platform *plat = lx_platform_create(job->platform, err, errlen);
	if (!plat) {
		lx_meshes_free(&meshes);
		return strcmp(job->platform, "osmesa") && strcmp(job->platform, "egl") ? 2 : 1;
	}
	int status = 1;
	struct lx_renderer *r = NULL;
	uint8_t *rgba = NULL;
	lx_gl_caps_probe(&rep->caps);

	struct lx_region_request req[LX_MAX_MAPS];
	struct lx_method_options opt = job->budgets.uniform_lixels ? job->budgets : LX_METHOD_OPTIONS_DEFAULT;
	int nreq = method->regions(&job->scene, &opt, req);
	if (!lx_atlas_layout(&rep->atlas, req, nreq, 1, rep->caps.max_texture_size, err, errlen)) {
		status = 2; /* budgets this GL cannot hold: the input asks too much */
		goto out;
	}
	struct lx_renderer_desc rd = {.scene = &job->scene, .meshes = &meshes, .atlas = &rep->atlas, .caps = &rep->caps,
				      .map_count = nreq, .width = job->width, .height = job->height,
				      .force_mediump = job->force_mediump, .bias_codes = job->bias_codes};
	r = lx_renderer_create(&rd, err, errlen);
	if (!r)
		goto out;

	int total = job->warmup_frames + (job->timed_frames > 0 ? job->timed_frames : 1);
	int timed = total - job->warmup_frames;
	double *frame_ms = calloc((size_t)timed * 4, sizeof(double));
	if (!frame_ms) {
		snprintf(err, errlen, "out of memory");
		goto out;
	}
	double *shadow_ms = frame_ms + timed, *main_ms = shadow_ms + timed, *setup_us = main_ms + timed;
	lx_renderer_finish();
	for (int i = 0; i < total; i++) {
		double t0 = now_ms();
		struct lx_shadow_result res = {0};
		method->build(&frame, &rep->atlas, &res);
		double t1 = now_ms();
		lx_renderer_shadow_passes(r, &frame, &res);
		lx_renderer_finish();
		double t2 = now_ms();
		lx_renderer_main_pass(r, &frame, &res, false);
		lx_renderer_finish();
		double t3 = now_ms();
		if (i >= job->warmup_frames) {
			int k = i - job->warmup_frames;
			setup_us[k] = (t1 - t0) * 1e3;
			shadow_ms[k] = t2 - t1;
			main_ms[k] = t3 - t2;
			frame_ms[k] = t3 - t0;
		}
		rep->result = res;
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
	free(frame_ms);

	long n = (long)job->width * job->height;
	rgba = malloc((size_t)n * 4);
	if (!rgba) {
		snprintf(err, errlen, "out of memory for a %dx%d image", job->width, job->height);
		goto out;
	}
	lx_renderer_read(r, rgba);
	if (job->out_png && !lx_png_write(job->out_png, rgba, job->width, job->height, err, errlen))
		goto out;
	if (job->atlas_png && !write_atlas(r, &rep->atlas, job->atlas_png, err, errlen))
		goto out;

	if (job->measure || job->keep_pixels || job->decision_png) {
		lx_renderer_main_pass(r, &frame, &rep->result, true);
		lx_renderer_read(r, rgba);
		rep->object = malloc((size_t)n * sizeof(int16_t));
		rep->shadow = malloc((size_t)n);
		if (!rep->object || !rep->shadow) {
			snprintf(err, errlen, "out of memory");
			goto out;
		}
		for (long i = 0; i < n; i++) {
			rep->shadow[i] = rgba[i * 4] > 127;
			rep->object[i] = (int16_t)rgba[i * 4 + 1] - 1; /* (id + 1.25) / 255 stores id + 1 */
		}
		if (job->decision_png) {
			decision_colors(rep->object, rep->shadow, n, rgba);
			if (!lx_png_write(job->decision_png, rgba, job->width, job->height, err, errlen))
				goto out;
		}
	}
	if (job->measure) {
		rep->ref_object = malloc((size_t)n * sizeof(int16_t));
		rep->ref_shadow = malloc((size_t)n);
		if (!rep->ref_object || !rep->ref_shadow ||
		    !lx_reference_image(&frame, rep->ref_object, rep->ref_shadow, job->reference_threads)) {
			snprintf(err, errlen, "out of memory for the reference image");
			goto out;
		}
		lx_mismatch_compare(rep->ref_object, rep->ref_shadow, rep->object, rep->shadow, n, &rep->mismatch);
		rep->plane_count = job->scene.plane_count;
		for (int p = 0; p < job->scene.plane_count; p++) {
			struct lx_plane_report *pr = &rep->planes[p];
			snprintf(pr->name, sizeof pr->name, "%s", job->scene.planes[p].name);
			pr->present = lx_plane_sampling(&frame, &rep->atlas, &rep->result, p, rep->ref_object, &pr->s);
		}
		rep->measured = true;
	}
	status = 0;
out:
	free(rgba);
	if (status != 0 || !job->keep_pixels)
		lx_render_report_free(rep);
	lx_renderer_destroy(r);
	lx_platform_destroy(plat);
	lx_meshes_free(&meshes);
	return status;
}
