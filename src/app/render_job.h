/* One render, end to end: scene + view + light -> light matrices -> atlas layout ->
 * GL passes -> image -> measurements. Used by `lixel render` and by the tests. */
#ifndef LX_RENDER_JOB_H
#define LX_RENDER_JOB_H
#include "method_run.h"

/* An exact reference cast before for the same scene, size, time and drawn lights (a test
 * measures many methods on one view and casts its reference once): width * height each,
 * rows bottom to top, as lx_method_run_reference gives them. */
struct lx_reference_images {
	int width, height, lights;
	const int16_t *object;
	const uint8_t *shadow; /* light after light */
	const uint8_t *rgba;   /* the reference's shading of every light */
};

struct lx_render_job {
	const char *method;   /* a name lx_shadow_method_find() knows */
	const char *platform; /* "osmesa" or "egl" */
	struct lx_platform *platform_in_use; /* a platform already made to render with (the tests share one
					  * per kind), left open; NULL: one made for this job */
	struct lx_scene scene;
	int width, height;
	double time;
	int warmup_frames, timed_frames;
	bool measure;        /* compare with the exact reference, compute the plane figures */
	bool keep_pixels;    /* keep the per-pixel arrays in the report (tests) */
	enum lx_depth_precision depth_precision; /* auto: the self-test decides */
	double bias_codes;   /* depth bias in 24-bit codes */
	struct lx_method_options budgets; /* zero: LX_METHOD_OPTIONS_DEFAULT */
	enum lx_filter filter; /* the main pass's shadow filter (none: one NEAREST lookup) */
	bool soft;             /* with measure: the soft reference too, and soft_error_pct */
	double light_size_deg; /* soft: the area light's angular size in degrees (0: a point) */
	int reference_threads;
	const char *out_png; /* shaded image, or NULL */
	const char *decision_png; /* the first light's decision image (shadowed red, lit by object), or NULL */
	const char *mismatch_png; /* with measure: where the first light's decision differs from the reference, or NULL */
	const char *atlas_png;    /* the atlas's depths as grey levels (near dark, far white), or NULL */
	const char *reference_png; /* with measure: the reference's shaded image, or NULL */
	const struct lx_reference_images *reference; /* with measure: this frame's, cast before; NULL: cast here */
};

/* One light's maps and figures. */
struct lx_light_report {
	char kind[16]; /* lx_light_kind_name */
	struct lx_atlas atlas;           /* its part of the atlas texture, as the last frame laid it out */
	struct lx_shadow_result result;  /* its maps and warnings */
	struct lx_mismatch mismatch;     /* with measure: its decisions against the reference's */
	double lookup_pct;               /* as the report's, for this light's pass */
	struct lx_plane_report planes[LX_MAX_PLANES];
};

struct lx_render_report {
	char method[16], platform[16];
	struct lx_gl_caps caps;
	int width, height;
	int light_count; /* the lights drawn */
	struct lx_light_report light[LX_MAX_LIGHTS];
	struct lx_depth_choice depth;
	int depth_slots; /* the renderer's (lx_renderer_depth_slots) */
	double frame_ms, frame_ms_min, frame_ms_max, shadow_ms, main_ms, setup_us;
	bool measured;
	/* with the decision (measure, keep_pixels or decision_png): the share of the image's
	 * pixels that ran a shadow lookup, in percent (the mean over the lights' passes);
	 * negative when not known */
	double lookup_pct;
	struct lx_mismatch mismatch; /* every light's together (lx_mismatch_add) */
	double colour_error; /* with measure: colour_error of the shaded frame (docs/lixel.md) */
	char filter[16];
	bool soft_measured;    /* soft_error_pct holds, against an area light of light_size_deg */
	double soft_error_pct, light_size_deg;
	int plane_count;
	/* with keep_pixels: width * height each, rows bottom to top; the decisions and
	 * visibilities light after light (light k's from k * width * height); free with
	 * lx_render_report_free */
	int16_t *ref_object, *object;
	uint8_t *ref_shadow, *shadow;
	uint8_t *ref_rgba;     /* with measure: the reference's shading, RGBA */
	uint8_t *visibility;   /* the shading's visibility, 0 to 255 (lx_decision_visibility) */
	uint8_t *served;       /* 1 where a map decided the pixel (lx_decision_served), light after light */
	float *ref_visibility; /* with soft: the soft reference's, 0 to 1 */
};

/* Returns 0 on success; 2 for bad input (err says what), 1 for a failure of the
 * platform or GL (err says what). */
int lx_render_run(const struct lx_render_job *job, struct lx_render_report *rep, char *err, size_t errlen);
void lx_render_report_free(struct lx_render_report *rep);

#endif
