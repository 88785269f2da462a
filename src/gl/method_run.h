/* A shadow method set up to draw: its atlas and renderer for one scene and view size,
 * one frame at a time with the times of each step, its decision image, and the
 * measurements against the exact reference. Used by `lixel render` and `lixel bench`.
 * A scene of several lights gets the method once per light: each light its own maps,
 * in its own part of the one atlas texture, and its own additive main pass [Segal]. */
#ifndef LX_METHOD_RUN_H
#define LX_METHOD_RUN_H
#include "gl_caps.h"
#include "metrics.h"
#include "depth_selftest.h"
#include "renderer.h"

/* The default bias: a few 24-bit codes, enough for the rounding of interpolated depth. */
#define LX_DEFAULT_BIAS_CODES 64.0

/* One light's share of a method run. */
struct lx_light_maps {
	struct lx_atlas atlas;            /* its part of the atlas texture; its maps laid out again
					   * each frame where their shapes vary */
	struct lx_method_options options; /* the run's budgets scaled by the light's share */
	struct lx_shadow_result result;   /* of the last frame */
	struct lx_frame frame;            /* the last frame, as this light sees it */
	struct lx_image image;            /* a projective light's beam or slide (empty for others) */
};

struct lx_method_run {
	const struct lx_shadow_method *method;
	struct lx_method_options options;
	int light_count; /* the lights drawn: the scene's, or the first options.max_lights */
	struct lx_light_maps lights[LX_MAX_LIGHTS];
	struct lx_renderer *renderer;
	struct lx_depth_choice depth;   /* the depth path taken, and how */
	int width, height;
	enum lx_filter filter; /* the main pass's shadow filter (none unless set) */
	bool setup_again;      /* lx_method_run_frame times the set-up a second time (the bench) */
	/* The next frame's set-up, made while the GL drew the last frame's main pass (the
	 * calls' `next`): for frame ahead_of, each light's in ahead[], in ahead_us (and
	 * ahead_again_us); taken by the call that draws that frame, dropped by any other.
	 * The frame is all it depends on: the lights' options are fixed at init (the
	 * setters change the renderer's main pass, not the set-up, but for the filter,
	 * which drops it). */
	bool ahead_ready;
	double ahead_us, ahead_again_us;
	struct lx_frame ahead_of;
	struct lx_light_ahead {
		struct lx_frame frame;
		struct lx_atlas atlas;
		struct lx_shadow_result result;
	} ahead[LX_MAX_LIGHTS];
};

struct lx_frame_times {
	double setup_us;  /* CPU time building the light matrices (every light's), wherever it
			   * ran: in the frame, or ahead, while the GL drew the frame before */
	bool setup_ahead; /* the set-up ran ahead: the frame did not wait for it */
	double setup_again_us; /* with setup_again: the same work done again at once, on copies,
				* the CPU awake; the frame does not pay it. NAN otherwise. */
	double shadow_ms; /* shadow passes, glFinish'ed (and the main pass's CPU work, done while
			   * the GL draws them) */
	double main_ms;   /* main pass (every light's), glFinish'ed (and the next frame's set-up,
			   * done while the GL draws it) */
	double frame_ms;  /* all three; the set-up only where it ran in the frame */
};

struct lx_plane_report {
	char name[LX_NAME_MAX];
	bool present; /* the plane covers pixels and a map serves it */
	struct lx_plane_sampling s;
};

/* Returns 0, or 2 for bad input (unknown method, budgets the GL cannot hold), 1 for a GL
 * failure; err says what. A current GL context is needed. */
int lx_method_run_init(struct lx_method_run *mr, const char *method, const struct lx_scene *scene,
		       const struct lx_scene_meshes *meshes, const struct lx_gl_caps *caps,
		       const struct lx_method_options *budgets, int width, int height, enum lx_depth_precision precision,
		       double bias_codes, bool to_window, char *err, size_t errlen);
void lx_method_run_free(struct lx_method_run *mr);
/* The main pass's shadow filter from the next frame on (--filter); 1 with err set when
 * its programs do not build (the filter then stays as it was), else 0. */
int lx_method_run_set_filter(struct lx_method_run *mr, enum lx_filter filter, char *err, size_t errlen);
/* lx_renderer_warm on the run's renderer (the kiosk, at start). */
void lx_method_run_warm(struct lx_method_run *mr);
/* Where the main pass looks its maps up from the next main or decision pass on, the
 * maps drawn kept (--lookup-region: all when everywhere, else footprint). */
void lx_method_run_set_lookup_everywhere(struct lx_method_run *mr, bool everywhere);
/* Light matrices, shadow passes and the shaded main pass, each step timed (glFinish
 * after each pass: for the bench and render, not for a display). f is the frame set up
 * for the scene (any light: each light's is made from it). next, when not NULL, is the
 * frame the next call will draw: its light matrices are made once this frame's main
 * pass is handed to the GL, while the GL draws it (the CPU waits for the GL there
 * anyway), and that call takes them if its frame is the same bytes, else makes its own. */
void lx_method_run_frame(struct lx_method_run *mr, const struct lx_frame *f, const struct lx_frame *next,
			 struct lx_frame_times *t);
/* The same, untimed and unsynchronised: on a tiler a glFinish between the passes costs a
 * flush of every tile; the kiosk's swap is the only sync it needs. */
void lx_method_run_draw(struct lx_method_run *mr, const struct lx_frame *f, const struct lx_frame *next);
/* The light matrices and the shadow passes only: all that lx_method_run_decision needs
 * (the tests that judge decisions skip the shaded main pass). */
void lx_method_run_shadows(struct lx_method_run *mr, const struct lx_frame *f);
/* The main pass's shadow decision for the last frame's matrices of light `light` (0 to
 * light_count - 1): per pixel the visible object (or LX_NO_OBJECT) and 1 where shadowed.
 * rgba is scratch of width*height*4. Returns how many pixels ran a shadow lookup. */
long lx_method_run_decision(struct lx_method_run *mr, int light, uint8_t *rgba, int16_t *object, uint8_t *shadow);
/* The exact reference of the last frame for every light the run draws, with their frames
 * and images (lx_reference_lights): shadowed holds light after light, width*height each;
 * rgba (or NULL) the lights' shading summed. False as lx_reference_lights. */
bool lx_method_run_reference(const struct lx_method_run *mr, int16_t *object, uint8_t *shadowed, uint8_t *rgba,
			     int threads);
/* The visibility the shading used per pixel, 0 (in shadow) to 255 (lit), from the
 * decision image rgba that lx_method_run_decision left with filter `filter`: the
 * filtered variants write it in alpha, NEAREST's is 0 or 255 by the decision. */
void lx_decision_visibility(const uint8_t *rgba, long pixels, enum lx_filter filter, uint8_t *visibility);
/* 1 where a map decided the pixel, from the same decision image: it ran a lookup, or lies
 * in a caster's sure shadow, drawn without one (sure_shadow.h); lx_method_run_decision
 * counts the lookups alone. */
void lx_decision_served(const uint8_t *rgba, long pixels, uint8_t *served);
/* The mismatch against the reference, and each plane's sampling figures over the pixels
 * that a map decided (looked, lx_decision_served; NULL: every pixel a map's bounds hold);
 * pts, when not NULL, the frame's plane points (lx_plane_points_make) shared by the
 * methods measured. */
void lx_measure(const struct lx_frame *f, const struct lx_atlas *atlas, const struct lx_shadow_result *res,
		const int16_t *ref_object, const uint8_t *ref_shadow, const int16_t *object, const uint8_t *shadow,
		const uint8_t *looked, const struct lx_plane_points *pts, struct lx_mismatch *mismatch,
		struct lx_plane_report *planes);

/* A plane whose median lixel spans more than this many pixels has shadows too coarse to
 * pass unremarked: a good map gives it 1 to 3; PSM with a random point light over the table
 * gave 9, its shadows 1.7% wrong, which 16 let pass unwarned. */
#define LX_COARSE_PIXELS_PER_LIXEL 8.0
/* Budget use below this share of the maps' lixels (the visible planes' lixels used over
 * all the maps hold), where a plane's pixels read less than a lixel each, is a map spent
 * almost wholly off the screen. */
#define LX_LOW_BUDGET_USE 0.01
/* The measured figures' warnings, added to the result's: planes sampled that coarsely,
 * and budget use that low. */
void lx_sampling_warnings(const struct lx_plane_report *planes, int n, long map_lixels, struct lx_shadow_result *res);
#endif
