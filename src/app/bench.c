#include "commands.h"
#include "board.h"
#include "cli_args.h"
#include "configs.h"
#include "json.h"
#include "metrics.h"
#include "method_run.h"
#include "platform.h"
#include "plot.h"
#include "png_out.h"
#include "out_file.h"
#include "reference.h"
#include "run_order.h"
#include "renderer.h"
#include "soft_reference.h"
#include <sys/stat.h>
#include <unistd.h>
#include <errno.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_METHODS 16
/* a run: a method with a filter (none reads no map: once, unfiltered) */
#define MAX_RUNS (MAX_METHODS * LX_FILTER_COUNT)
_Static_assert(MAX_RUNS <= LX_RUN_ORDER_MAX, "lx_run_order orders every run");
#define LX_STR_(x) #x
#define LX_STR(x) LX_STR_(x) /* a limit in a message */
#define MAX_CONFIGS 16
#define ANIMATION_SAMPLES 5 /* times at which the animation's accuracy is measured */

/* the timed figures of a frame, kept per method over every configuration */
enum { T_FRAME, T_SETUP, T_SHADOW, T_MAIN, T_SETUP_AGAIN, T_KINDS };

/* Rounds in which every method is timed alone, each round with GL objects made anew: on
 * llvmpipe under a virtual machine one allocation of an atlas can read 20% slower than
 * another for the same method, so a median over rounds outvotes an unlucky one. */
#define TIME_ROUNDS 5

/* The rounds a run of `frames` timed frames takes, and how many frames round r takes
 * when `done` went to the rounds before it: shared out as evenly as they go. */
static int rounds_for(int frames) { return frames < TIME_ROUNDS ? frames : TIME_ROUNDS; }
static int round_length(int frames, int rounds, int r, int done) { return (frames - done) / (rounds - r); }

struct row {
	double round_ms[TIME_ROUNDS]; /* the median frame of each round (rounds_for), in turn */
	double frame_ms_median, frame_ms_min, frame_ms_max, setup_us, setup_again_us, shadow_ms, main_ms;
	double mismatch_pct, false_pct, missing_pct; /* the animation: the median of its samples */
	double soft_pct; /* soft_error_pct, the same */
	double lookup_pct; /* share of the image's pixels that ran a shadow lookup (the first sample) */
	double mismatch_worst;
	double m_max[LX_MAX_PLANES]; /* NAN where the plane is not measured */
	double lpp[LX_MAX_PLANES], used[LX_MAX_PLANES]; /* median lpp and lixels used (budget use), same */
};

/* A row's figures as the CSV and the JSON name them, in their order, with the CSV's
 * decimals: one list for both outputs. */
static const struct column {
	const char *name;
	size_t at; /* offsetof(struct row, ...), a double */
	int csv_decimals;
} row_columns[] = {
#define COLUMN(name, field, decimals) {name, offsetof(struct row, field), decimals}
	/* the frame: its median and range, its passes apart, the light matrices' set-up */
	COLUMN("frame_ms_median", frame_ms_median, 4), COLUMN("frame_ms_min", frame_ms_min, 4),
	COLUMN("frame_ms_max", frame_ms_max, 4), COLUMN("shadow_ms_median", shadow_ms, 4),
	COLUMN("main_ms_median", main_ms, 4), COLUMN("setup_us", setup_us, 2),
	COLUMN("setup_again_us", setup_again_us, 2), /* the same set-up again at once (lx_frame_times) */
	/* where the main pass looked a map up; the decisions against the references */
	COLUMN("lookup_pct", lookup_pct, 3), COLUMN("mismatch_pct", mismatch_pct, 5),
	COLUMN("false_shadow_pct", false_pct, 5), COLUMN("missing_shadow_pct", missing_pct, 5),
	COLUMN("mismatch_worst", mismatch_worst, 5), COLUMN("soft_error_pct", soft_pct, 5),
#undef COLUMN
};
#define ROW_COLUMNS (int)(sizeof row_columns / sizeof row_columns[0])

static double column_of(const struct row *r, int k)
{
	double v;
	memcpy(&v, (const char *)r + row_columns[k].at, sizeof v);
	return v;
}

struct bench {
	int width, height, frames, warmup;
	const char *platform, *csv, *plot, *strips;
	bool json;
	int nm, nc; /* runs, configurations */
	const char *methods[MAX_RUNS];     /* each run's method spec */
	enum lx_filter filters[MAX_RUNS];  /* and its shadow filter */
	char labels[MAX_RUNS][80];         /* "uniform", "uniform+pcf2x2": the text, plot and strips */
	int slots[MAX_RUNS];               /* each run's depth slots (lx_renderer_depth_slots) */
	int nf;
	enum lx_filter filter_list[LX_FILTER_COUNT]; /* --filters */
	double light_size_deg;                      /* the soft reference's area light */
	struct lx_method_options options; /* the plane maps' options (each method may add its own: plane/square) */
	enum lx_depth_precision depth_precision;
	struct lx_depth_choice depth; /* the path every method's run took (one driver, one choice) */
	struct lx_gl_caps caps;
	const char *configs[MAX_CONFIGS];
	struct lx_scene scene;
	struct row rows[MAX_RUNS][MAX_CONFIGS];
	double *all[MAX_RUNS][T_KINDS]; /* every timed frame of a run over all configurations */
	int nframes[MAX_RUNS];
};

static void usage(FILE *f)
{
	fprintf(f, "usage: lixel bench [--size WxH] [--frames N] [--warmup N] [--methods LIST] [--configs LIST]\n"
		   "                   [--platform osmesa|egl] [--scene NAME|FILE] [--csv FILE] [--plot FILE.png]\n"
		   "                   [--strips DIR] [--json] [--region-shape S] [--budget-split S]\n"
		   "                   [--plane-max-lpp X] [--lookup-region R] [--depth-slots N]\n"
		   "                   [--depth-precision P] [--filters LIST] [--light-size DEG]\n"
		   "\n"
		   "Renders every method over every configuration: N timed frames each (glFinish after\n"
		   "the shadow passes and after the main pass; each frame's light matrices made while\n"
		   "the GL draws the frame before, so that the frame time leaves them out but for a\n"
		   "round's first frame, and 'setup us' is their CPU time), in 5 rounds: in each the\n"
		   "methods take turns in a fresh order (drawn over the runs sorted by name: the same\n"
		   "for any order of --methods), each alone on GL objects made for the round, its\n"
		   "warm-up frames first, so that they share the machine's noise and no method keeps an\n"
		   "unlucky allocation; then the accuracy against the exact reference: the mismatch of\n"
		   "the shadow decision, and the soft-edge error of the visibility against a small area\n"
		   "light. Prints a line per method, filter and configuration, then a summary per run:\n"
		   "medians of the frame, its shadow passes and its main pass, with ratios to no shadows\n"
		   "and to uniform; then each run's frame over uniform's view by view (per configuration,\n"
		   "the median of those ratios, their range, how many are at most 1, where the most\n"
		   "is, and on how many views the method was slower, and faster, than uniform in every\n"
		   "round: the differences the rounds resolve). Run with LP_NUM_THREADS=1 to stand in\n"
		   "for a fill-limited board GPU.\n"
		   "\n"
		   "  --size WxH       view size (default 1024x1024)\n"
		   "  --frames N       timed frames per method and configuration (default 30)\n"
		   "  --warmup N       warm-up frames per method and configuration, shared out over\n"
		   "                   the rounds, at least one a round (default 5)\n"
		   "  --methods LIST   comma-separated, from %s (default: all of them);\n"
		   "                   plane takes options after slashes to compare settings in one run:\n"
		   "                   plane/square (the paper's square maps), plane/shared (shared\n"
		   "                   budgets), plane/lpp1 (at most 1 lixel per pixel), plane/twist (the\n"
		   "                   paper's twist, not screen-aligned), plane/onepiece (one rectangle\n"
		   "                   per plane), plane/similar (square lixels even short of a lixel\n"
		   "                   per pixel, not stretched along the shadows' edges),\n"
		   "                   plane/unslabbed (no footprint cut in slabs where a plane is\n"
		   "                   short of its budget),\n"
		   "                   plane/casterfallback (casters read the fallback alone, not\n"
		   "                   first the plane maps denser on them, --caster-maps fallback),\n"
		   "                   plane/budget (as dense as the budget allows past a lixel per\n"
		   "                   pixel, not only as the casters reading a map need),\n"
		   "                   plane/uncapped; combined freely (plane/shared/lpp1);\n"
		   "                   every method takes /all or /footprint (--lookup-region),\n"
		   "                   /pointdepth or /facedepth (--caster-depth),\n"
		   "                   /slotsN (--depth-slots N: plane,plane/slots1 measures what clearing\n"
		   "                   the atlas every frame costs) and /lightsN (only the scene's first\n"
		   "                   N lights: uniform,uniform/lights1 on a scene of two lights\n"
		   "                   measures what the second costs)\n"
		   "  --region-shape, --budget-split, --plane-density, --caster-maps, --plane-max-lpp,\n"
		   "                   --lookup-region, --caster-depth, --depth-slots, --light-budget: as\n"
		   "                   in lixel render --help, for every method of the run\n"
		   "  --filters LIST   shadow filters each method runs with, comma-separated, from none,\n"
		   "                   pcf2x2 and pcf3x3 (default none; see lixel render --help); a run\n"
		   "                   is named METHOD+FILTER, or METHOD for none\n"
		   "  --light-size DEG the soft-edge error's area light, as in lixel render --help\n"
		   "  --configs LIST   comma-separated configurations of lixel render --help, and\n"
		   "                   'animation' (the default scene's casters bouncing); default all\n"
		   "  --scene NAME|FILE  as in lixel render --help (default, table, spotlight, projector,\n"
		   "                   twolights, or a scene file)\n"
		   "  --csv FILE       every row as CSV\n"
		   "  --plot FILE.png  median mismatch against median frame time, one mark per method\n"
		   "  --strips DIR     per configuration a PNG of the methods side by side, in --methods\n"
		   "                   order, each panel scaled down to at most 512 pixels wide\n"
		   "  --json           one JSON object on stdout instead of the text\n"
		   "  --depth-precision, --mediump: as in lixel render --help\n"
		   "\n"
		   "Progress goes to stderr. Exit status: 0 done; 1 GL failure; 2 bad input.\n",
		lx_shadow_method_names());
}

#define bad(opt, expected, got) lx_arg_bad("bench", opt, expected, got)

/* Splits a comma list in place into out[]; false on an empty item (",,", a comma at
 * either end) or too many. */
static bool split(char *list, const char **out, int max, int *n)
{
	*n = 0;
	for (char *t = list;;) {
		char *comma = strchr(t, ',');
		if (comma)
			*comma = 0;
		if (*n == max || !*t)
			return false;
		out[(*n)++] = t;
		if (!comma)
			return true;
		t = comma + 1;
	}
}

/* A name given twice in a list: its rows and its ratios would be two runs under one name
 * (the view-by-view table took one for the other). 0, or 2 after the one line. */
static int named_twice(const char *opt, const char *what, const char *const *names, int n)
{
	for (int i = 1; i < n; i++)
		for (int j = 0; j < i; j++)
			if (!strcmp(names[i], names[j])) {
				fprintf(stderr, "lixel bench: %s: expected each %s once, got '%s' twice\n", opt, what, names[i]);
				return 2;
			}
	return 0;
}

static bool is_animation(const char *c) { return !strcmp(c, "animation"); }

static double median_of(const double *v, int n)
{
	double *t = malloc((size_t)n * sizeof(double));
	if (!t)
		return NAN;
	memcpy(t, v, (size_t)n * sizeof(double));
	double m = lx_median(t, n);
	free(t);
	return m;
}

/* The mean: with depth slots, one frame in that many also clears the atlas, which a
 * median passes over. */
static double mean_of(const double *v, int n)
{
	double sum = 0;
	for (int k = 0; k < n; k++)
		sum += v[k];
	return n > 0 ? sum / n : NAN;
}

static void config_scene(const struct bench *b, const char *config, struct lx_scene *s)
{
	*s = b->scene;
	if (!is_animation(config))
		lx_config_apply(lx_config_find(config), s);
}

/* The scratch images of a configuration's accuracy and strips. */
struct pixels {
	uint8_t *rgba, *sh, *ref_sh, *vis, *served;
	int16_t *obj, *ref_obj;
	float *ref_vis; /* the soft reference */
	/* ref_sh and ref_vis: every light's, light after light (light k's from k * width * height) */
};

/* Run m of the bench (its method and filter) on the depth path `path`: the measuring
 * runs with the one asked, each timing run with the one the first measuring run took.
 * 0, or 1 or 2 after err, nothing left to free. */
static int make_run(const struct bench *b, int m, enum lx_depth_precision path, const struct lx_scene_meshes *meshes,
		    struct lx_method_run *run, char *err, size_t errlen)
{
	int st = lx_method_run_init(run, b->methods[m], &b->scene, meshes, &b->caps, &b->options, b->width, b->height,
				    path, LX_DEFAULT_BIAS_CODES, false, err, errlen);
	if (!st)
		st = lx_method_run_set_filter(run, b->filters[m], err, errlen);
	if (st)
		lx_method_run_free(run);
	else
		run->setup_again = true;
	return st;
}

/* Frame i of a configuration into *frame: false after err (a degenerate view). */
static bool frame_at(const struct bench *b, const struct lx_scene *scene, bool anim, const struct lx_scene_meshes *meshes,
		     int i, struct lx_frame *frame, char *err, size_t errlen)
{
	return lx_frame_setup(frame, scene, meshes, anim ? i / 30.0 : 0.0, b->width, b->height, err, errlen);
}

/* Every method's timed frames, times[(kind * nm + method) * frames + frame]: in rounds
 * (TIME_ROUNDS, fewer when there are fewer frames), each method alone in a fresh order
 * each round, on a run of its own made for the round and freed after it, its share of
 * the warm-up frames first (at least one when there are any: the first frame on new
 * objects also pays for their memory). Each method renders the same frames. The last
 * frame stays in *frame. 0; 1 or 2 after err. */
static int time_frames(struct bench *b, const struct lx_scene *scene, bool anim, const struct lx_scene_meshes *meshes,
		       double *times, struct lx_frame *frame, char *err, size_t errlen)
{
	unsigned long long seq = LX_RUN_ORDER_SEED;
	const char *names[MAX_RUNS];
	for (int m = 0; m < b->nm; m++)
		names[m] = b->labels[m];
	int rounds = rounds_for(b->frames), warm = (b->warmup + rounds - 1) / rounds;
	enum lx_depth_precision path = b->depth.taken;
	/* a still configuration's one frame, set up once; the animation's, frame by frame,
	 * each one's next set up ahead (lx_method_run_frame's `next`) */
	if (!anim && !frame_at(b, scene, false, meshes, 0, frame, err, errlen))
		return 2;
	struct lx_frame next;
	struct lx_frame *after = anim ? &next : frame;
	int st = 0;
	for (int r = 0, done = 0; r < rounds; r++) {
		int n = round_length(b->frames, rounds, r, done), order[MAX_RUNS];
		lx_run_order(names, b->nm, &seq, order); /* the same schedule for any order of --methods */
		for (int k = 0; k < b->nm && !st; k++) {
			int m = order[k];
			struct lx_method_run run;
			if ((st = make_run(b, m, path, meshes, &run, err, errlen)))
				break;
			if (anim && !frame_at(b, scene, true, meshes, done, frame, err, errlen))
				st = 2;
			for (int i = -warm; i < n && !st; i++) {
				struct lx_frame_times ft;
				bool more = i + 1 < n; /* frame done + i + 1 (warm-up frames are frame done) */
				if (anim && more && !frame_at(b, scene, true, meshes, done + (i + 1 > 0 ? i + 1 : 0), after, err,
							      errlen)) {
					st = 2;
					break;
				}
				lx_method_run_frame(&run, frame, more ? after : NULL, &ft);
				double v[T_KINDS] = {ft.frame_ms, ft.setup_us, ft.shadow_ms, ft.main_ms, ft.setup_again_us};
				for (int q = 0; q < T_KINDS && i >= 0; q++)
					times[((size_t)q * b->nm + m) * b->frames + done + i] = v[q];
				if (anim && more)
					memcpy(frame, after, sizeof *frame); /* the bytes the run set up ahead */
			}
			lx_method_run_free(&run);
		}
		done += n;
	}
	if (st)
		return st;
	return !anim || frame_at(b, scene, true, meshes, b->frames - 1, frame, err, errlen) ? 0 : 2;
}

/* --strips: each method's last shaded frame side by side in DIR/CONFIG.png, panels at
 * most 512 pixels wide (box-filtered down by a whole factor). False after err. */
static bool write_strip(const struct bench *b, const char *config, struct lx_method_run *runs,
			const struct lx_frame *frame, uint8_t *rgba, char *err, size_t errlen)
{
	int k = (b->width + 511) / 512, pw = b->width / k, ph = b->height / k, gap = 8;
	int sw = b->nm * pw + (b->nm - 1) * gap;
	uint8_t *strip = malloc((size_t)sw * ph * 4);
	if (!strip)
		return true; /* no strip, no harm to the figures */
	memset(strip, 255, (size_t)sw * ph * 4);
	for (int m = 0; m < b->nm; m++) {
		lx_method_run_frame(&runs[m], frame, NULL, &(struct lx_frame_times){0});
		lx_renderer_read(runs[m].renderer, rgba);
		for (int y = 0; y < ph; y++)
			for (int x = 0; x < pw; x++)
				for (int c = 0; c < 4; c++) {
					unsigned sum = 0;
					for (int dy = 0; dy < k; dy++)
						for (int dx = 0; dx < k; dx++)
							sum += rgba[(((size_t)(y * k + dy)) * b->width + x * k + dx) * 4 + c];
					strip[((size_t)y * sw + m * (pw + gap) + x) * 4 + c] = (uint8_t)(sum / (unsigned)(k * k));
				}
	}
	char path[4096];
	snprintf(path, sizeof path, "%s/%s.png", b->strips, config);
	bool ok = lx_png_write(path, strip, sw, ph, err, errlen);
	free(strip);
	return ok;
}

/* A configuration's timed figures per method: medians and extremes, and every frame
 * kept for the method's overall median. */
static void time_rows(struct bench *b, int ci, const double *times)
{
	for (int m = 0; m < b->nm; m++) {
		struct row *r = &b->rows[m][ci];
		const double *own[T_KINDS];
		for (int q = 0; q < T_KINDS; q++) {
			own[q] = times + ((size_t)q * b->nm + m) * b->frames;
			memcpy(b->all[m][q] + b->nframes[m], own[q], sizeof(double) * (size_t)b->frames);
		}
		b->nframes[m] += b->frames;
		r->frame_ms_median = median_of(own[T_FRAME], b->frames);
		for (int k = 0, rounds = rounds_for(b->frames), done = 0; k < rounds; k++) {
			int n = round_length(b->frames, rounds, k, done);
			r->round_ms[k] = median_of(own[T_FRAME] + done, n);
			done += n;
		}
		r->frame_ms_min = INFINITY, r->frame_ms_max = 0;
		for (int k = 0; k < b->frames; k++) {
			r->frame_ms_min = fmin(r->frame_ms_min, own[T_FRAME][k]);
			r->frame_ms_max = fmax(r->frame_ms_max, own[T_FRAME][k]);
		}
		r->setup_us = median_of(own[T_SETUP], b->frames);
		r->setup_again_us = median_of(own[T_SETUP_AGAIN], b->frames);
		r->shadow_ms = median_of(own[T_SHADOW], b->frames);
		r->main_ms = median_of(own[T_MAIN], b->frames);
		for (int p = 0; p < LX_MAX_PLANES; p++)
			r->m_max[p] = r->lpp[p] = r->used[p] = NAN;
	}
}

/* One method's accuracy at one sampled time, against the reference in px: its lights'
 * decisions together (lx_mismatch_add), the soft error weighted by each light's compared
 * pixels, the planes' figures of its first light. */
static void measure_method(struct bench *b, int ci, int m, int sidx, struct lx_method_run *run, const struct pixels *px,
			   const struct lx_plane_points *pts, double mis[4])
{
	long n = (long)b->width * b->height, looked = 0;
	struct lx_mismatch all = {0};
	double soft = 0;
	struct row *rw = &b->rows[m][ci];
	for (int l = 0; l < run->light_count; l++) {
		const struct lx_light_maps *lm = &run->lights[l];
		size_t o = (size_t)l * n;
		looked += lx_method_run_decision(run, l, px->rgba, px->obj, px->sh);
		lx_decision_visibility(px->rgba, n, run->filter, px->vis);
		lx_decision_served(px->rgba, n, px->served);
		struct lx_mismatch mm;
		struct lx_plane_report planes[LX_MAX_PLANES];
		lx_measure(&lm->frame, &lm->atlas, &lm->result, px->ref_obj, px->ref_sh + o, px->obj, px->sh, px->served, pts, &mm,
			   planes);
		soft += mm.compared * lx_soft_error(px->ref_obj, px->ref_sh + o, px->ref_vis + o, px->obj, px->vis, n);
		lx_mismatch_add(&all, &mm);
		for (int p = 0; l == 0 && p < lm->frame.scene->plane_count && p < LX_MAX_PLANES; p++)
			if (planes[p].present) {
				rw->m_max[p] = isnan(rw->m_max[p]) ? planes[p].s.m_max : fmax(rw->m_max[p], planes[p].s.m_max);
				if (isnan(rw->lpp[p])) /* the first sampled time (the animation's first) */
					rw->lpp[p] = planes[p].s.lpp_median, rw->used[p] = planes[p].s.lixels_used;
			}
	}
	if (sidx == 0)
		rw->lookup_pct = 100.0 * looked / ((double)n * run->light_count);
	mis[0] = all.mismatch_pct, mis[1] = all.false_shadow_pct, mis[2] = all.missing_shadow_pct;
	mis[3] = all.compared > 0 ? soft / all.compared : 0;
}

/* The exact and the soft reference of every light of the scene at one time, into px. */
static bool references(const struct bench *b, const struct lx_frame *frame, const struct pixels *px)
{
	int lights = lx_scene_light_count(frame->scene);
	long n = (long)b->width * b->height;
	struct lx_frame fl[LX_MAX_LIGHTS];
	const struct lx_frame *frames[LX_MAX_LIGHTS];
	const struct lx_image *images[LX_MAX_LIGHTS] = {0};
	uint8_t *ref_sh[LX_MAX_LIGHTS];
	for (int l = 0; l < lights; l++) {
		lx_frame_for_light(frame, l, &fl[l]);
		frames[l] = &fl[l], ref_sh[l] = px->ref_sh + (size_t)l * n;
		if (!lx_soft_reference_image(&fl[l], b->light_size_deg, px->ref_vis + (size_t)l * n, 2))
			return false;
	}
	return lx_reference_lights(frames, images, lights, px->ref_obj, ref_sh, NULL, 2);
}

/* Accuracy: one reference per sampled time, shared by the methods; each row gets the
 * median over the samples and the worst. 0, 1 or 2 after err. */
static int measure_config(struct bench *b, int ci, const struct lx_scene *scene, bool anim, struct lx_method_run *runs,
			  const struct lx_scene_meshes *meshes, const struct pixels *px, char *err, size_t errlen)
{
	int samples = anim ? ANIMATION_SAMPLES : 1;
	double mis[MAX_RUNS][4][ANIMATION_SAMPLES];
	struct lx_frame frame;
	for (int sidx = 0; sidx < samples; sidx++) {
		if (!lx_frame_setup(&frame, scene, meshes, anim ? sidx * 0.6 : 0.0, b->width, b->height, err, errlen))
			return 2;
		struct lx_plane_points pts; /* the methods' (and lights') shared view of the planes */
		if (!references(b, &frame, px) || !lx_plane_points_make(&frame, px->ref_obj, &pts)) {
			snprintf(err, errlen, "out of memory for the reference image");
			return 1;
		}
		for (int m = 0; m < b->nm; m++) {
			double v[4];
			lx_method_run_frame(&runs[m], &frame, NULL, &(struct lx_frame_times){0});
			measure_method(b, ci, m, sidx, &runs[m], px, &pts, v);
			for (int q = 0; q < 4; q++)
				mis[m][q][sidx] = v[q];
		}
		lx_plane_points_free(&pts);
	}
	for (int m = 0; m < b->nm; m++) {
		struct row *r = &b->rows[m][ci];
		r->mismatch_pct = median_of(mis[m][0], samples);
		r->false_pct = median_of(mis[m][1], samples);
		r->missing_pct = median_of(mis[m][2], samples);
		r->soft_pct = median_of(mis[m][3], samples);
		r->mismatch_worst = 0;
		for (int k = 0; k < samples; k++)
			r->mismatch_worst = fmax(r->mismatch_worst, mis[m][0][k]);
	}
	return 0;
}

/* One configuration: timed frames for every method (interleaved), then accuracy. */
static int run_config(struct bench *b, int ci, struct lx_method_run *runs, const struct lx_scene_meshes *meshes,
		      const struct pixels *px, char *err, size_t errlen)
{
	const char *config = b->configs[ci];
	bool anim = is_animation(config);
	struct lx_scene scene;
	config_scene(b, config, &scene);
	double *times = malloc(sizeof(double) * (size_t)b->frames * T_KINDS * b->nm);
	if (!times) {
		snprintf(err, errlen, "out of memory");
		return 1;
	}
	struct lx_frame frame;
	int st = time_frames(b, &scene, anim, meshes, times, &frame, err, errlen);
	if (!st && b->strips && !write_strip(b, config, runs, &frame, px->rgba, err, errlen))
		st = 1;
	if (!st)
		time_rows(b, ci, times);
	free(times);
	return st ? st : measure_config(b, ci, &scene, anim, runs, meshes, px, err, errlen);
}

/* The run labelled name ("uniform": uniform unfiltered), or -1. */
static int method_index(const struct bench *b, const char *name)
{
	for (int m = 0; m < b->nm; m++)
		if (!strcmp(b->labels[m], name))
			return m;
	return -1;
}

/* One line per run and configuration, glmark2's way. */
static void print_rows(const struct bench *b)
{
	for (int c = 0; c < b->nc; c++)
		for (int m = 0; m < b->nm; m++) {
			const struct row *r = &b->rows[m][c];
			printf("[%s] config=%s: FrameTime: %.3f ms (%.3f-%.3f) shadow: %.3f ms main: %.3f ms setup: %.1f us "
			       "(again at once %.1f) lookups: %.2f%% mismatch: %.4f%% (false %.4f%%, missing %.4f%%) soft: %.4f%%",
			       b->labels[m], b->configs[c], r->frame_ms_median, r->frame_ms_min, r->frame_ms_max, r->shadow_ms,
			       r->main_ms, r->setup_us, r->setup_again_us, r->lookup_pct, r->mismatch_pct, r->false_pct, r->missing_pct, r->soft_pct);
			for (int p = 0; p < b->scene.plane_count; p++)
				if (!isnan(r->m_max[p]))
					printf(" %s: m_max %.3g lpp %.3g used %.0f", b->scene.planes[p].name, r->m_max[p], r->lpp[p],
					       r->used[p]);
			printf("\n");
		}
}

/* A run's figures over every configuration: medians of its configurations' rows (the
 * frame times over every frame), the worst mismatch and m_max per plane. */
struct summary {
	double frame_ms, lo, hi, mismatch, worst, lookups, soft, beyond, m_max[2];
	struct lx_paired_ratios by_view; /* its configurations' median frames over uniform's */
	int over_every_round, under_every_round; /* views slower, faster than uniform in each round */
	char over_views[160];                    /* the first, comma-separated */
};

static void summarize(const struct bench *b, int m, int uni, struct summary *s)
{
	double mis[MAX_CONFIGS], looked[MAX_CONFIGS], soft[MAX_CONFIGS], own[MAX_CONFIGS], uni_own[MAX_CONFIGS];
	*s = (struct summary){.frame_ms = median_of(b->all[m][T_FRAME], b->nframes[m]), .lo = INFINITY,
			      .beyond = uni >= 0 ? -INFINITY : NAN, .m_max = {NAN, NAN}};
	for (int k = 0; k < b->nframes[m]; k++)
		s->lo = fmin(s->lo, b->all[m][T_FRAME][k]), s->hi = fmax(s->hi, b->all[m][T_FRAME][k]);
	for (int c = 0; c < b->nc; c++) {
		const struct row *r = &b->rows[m][c];
		mis[c] = r->mismatch_pct, s->worst = fmax(s->worst, r->mismatch_worst);
		looked[c] = r->lookup_pct, soft[c] = r->soft_pct;
		own[c] = r->frame_ms_median, uni_own[c] = uni >= 0 ? b->rows[uni][c].frame_ms_median : NAN;
		int sign = uni >= 0 && m != uni ? lx_rounds_sign(r->round_ms, b->rows[uni][c].round_ms, rounds_for(b->frames)) : 0;
		s->under_every_round += sign < 0;
		if (sign > 0 && s->over_every_round++ < 4) /* four names fit */
			snprintf(s->over_views + strlen(s->over_views), sizeof s->over_views - strlen(s->over_views), "%s%s",
				 s->over_views[0] ? "," : "", b->configs[c]);
		/* the most this run's mismatch exceeds uniform's on one configuration */
		if (uni >= 0)
			s->beyond = fmax(s->beyond, r->mismatch_pct - b->rows[uni][c].mismatch_pct);
		for (int p = 0; p < b->scene.plane_count && p < 2; p++)
			if (!isnan(r->m_max[p]))
				s->m_max[p] = isnan(s->m_max[p]) ? r->m_max[p] : fmax(s->m_max[p], r->m_max[p]);
	}
	s->mismatch = median_of(mis, b->nc), s->lookups = median_of(looked, b->nc), s->soft = median_of(soft, b->nc);
	lx_paired_ratios(own, uni_own, m == uni ? 0 : b->nc, &s->by_view); /* none for uniform itself */
}

/* Each run's frame against uniform's, configuration by configuration (lx_paired_ratios),
 * from the runs' summaries. */
static void print_by_view(const struct bench *b, int uni, const struct summary *sum)
{
	if (uni < 0)
		return;
	int rounds = rounds_for(b->frames);
	printf("\nframe / uniform's, view by view (each configuration's median frame over uniform's, the same run;\n"
	       "slower, faster: the views where the method's median frame was over, under uniform's in each of the\n"
	       "%d rounds, a difference the rounds resolve; two methods that cost the same are slower by chance on\n"
	       "one view in %d):\n"
	       "%-14s %8s %15s %8s  %-12s %6s %6s  %s\n",
	       rounds, 1 << rounds, "method", "median", "(min-max)", "<= 1", "the most on", "slower", "faster",
	       "slower on");
	for (int m = 0; m < b->nm; m++) {
		const struct summary *s = &sum[m];
		const struct lx_paired_ratios *p = &s->by_view;
		if (p->count == 0)
			continue;
		char range[40], under[24], over[24], faster[24];
		snprintf(range, sizeof range, "(%.3f-%.3f)", p->least, p->most);
		snprintf(under, sizeof under, "%d/%d", p->at_most_one, p->count);
		snprintf(over, sizeof over, "%d/%d", s->over_every_round, p->count);
		snprintf(faster, sizeof faster, "%d/%d", s->under_every_round, p->count);
		printf("%-14s %8.3f %15s %8s  %-12s %6s %6s  %s%s\n", b->labels[m], p->median, range, under,
		       b->configs[p->most_at], over, faster, s->over_every_round ? s->over_views : "-",
		       s->over_every_round > 4 ? ",..." : "");
	}
}

static void print_text(const struct bench *b, const struct lx_gl_caps *caps)
{
	printf("lixel bench: %dx%d, %d timed frames after %d warm-up, %s on %s, depth %s (self-test %s), "
	       "the atlas cleared once every %d frames\n",
	       b->width, b->height, b->frames, b->warmup, b->platform, caps->renderer, b->depth.path, b->depth.selftest,
	       b->slots[0]);
	print_rows(b);
	int none = method_index(b, "none"), uni = method_index(b, "uniform");
	double none_ms = none >= 0 ? median_of(b->all[none][T_FRAME], b->nframes[none]) : NAN;
	double uni_ms = uni >= 0 ? median_of(b->all[uni][T_FRAME], b->nframes[uni]) : NAN;
	struct summary sum[MAX_RUNS]; /* the summary table's and the view-by-view one's */
	for (int m = 0; m < b->nm; m++)
		summarize(b, m, uni, &sum[m]);
	printf("\n%-14s %9s %15s %7s %8s %9s %8s %8s %8s %8s %10s %9s %9s %8s", "method", "frame ms", "(min-max)",
	       "/none", "/uniform", "shadow ms", "main ms", "lookups%", "setup us", "again us", "mismatch%", "worst%",
	       "-uniform", "soft%");
	for (int p = 0; p < b->scene.plane_count && p < 2; p++)
		printf(" %8s", b->scene.planes[p].name);
	printf("\n");
	for (int m = 0; m < b->nm; m++) {
		struct summary s = sum[m];
		char range[40];
		snprintf(range, sizeof range, "(%.2f-%.2f)", s.lo, s.hi);
		printf("%-14s %9.3f %15s %7.3f %8.3f %9.3f %8.3f %8.2f %8.1f %8.1f %10.4f %9.4f %9.4f %8.4f", b->labels[m],
		       s.frame_ms, range, s.frame_ms / none_ms, s.frame_ms / uni_ms,
		       median_of(b->all[m][T_SHADOW], b->nframes[m]), median_of(b->all[m][T_MAIN], b->nframes[m]), s.lookups,
		       median_of(b->all[m][T_SETUP], b->nframes[m]), median_of(b->all[m][T_SETUP_AGAIN], b->nframes[m]),
		       s.mismatch, s.worst, s.beyond, s.soft);
		for (int p = 0; p < b->scene.plane_count && p < 2; p++)
			if (isnan(s.m_max[p]))
				printf(" %8s", "-");
			else
				printf(" %8.3g", s.m_max[p]);
		printf("\n");
	}
	printf("(-uniform: the most a method's mismatch exceeds uniform's on one configuration, in percentage\n"
	       " points; the two plane columns: worst m_max over the configurations, lixel spans in pixels;\n"
	       " shadow ms and main ms: medians of the shadow passes and of the main pass, apart, the main\n"
	       " pass's CPU work done while the maps are drawn, in shadow ms; lookups%%: the median share\n"
	       " of the pixels that ran a shadow lookup; soft%%: the median soft-edge error,\n"
	       " the mean |visibility - a %.3g-degree area light's| in percent)\n",
	       b->light_size_deg);
	print_by_view(b, uni, sum);
}

/* One result object: a run on a configuration. */
static void json_row(struct lx_json *j, const struct bench *b, int m, int c)
{
	const struct row *r = &b->rows[m][c];
	lx_json_object(j);
	lx_json_key(j, "method"), lx_json_string(j, b->methods[m]);
	lx_json_key(j, "filter"), lx_json_string(j, lx_filter_name(b->filters[m]));
	lx_json_key(j, "config"), lx_json_string(j, b->configs[c]);
	for (int k = 0; k < ROW_COLUMNS; k++)
		lx_json_key(j, row_columns[k].name), lx_json_number(j, column_of(r, k));
	lx_json_key(j, "m_max"), lx_json_object(j);
	for (int p = 0; p < b->scene.plane_count; p++)
		if (!isnan(r->m_max[p]))
			lx_json_key(j, b->scene.planes[p].name), lx_json_number(j, r->m_max[p]);
	lx_json_end(j);
	lx_json_end(j);
}

static void print_json(const struct bench *b)
{
	struct lx_json j;
	lx_json_begin(&j, stdout);
	lx_json_object(&j);
	lx_json_key(&j, "size"), lx_json_array(&j), lx_json_int(&j, b->width), lx_json_int(&j, b->height), lx_json_end(&j);
	lx_json_key(&j, "depth_path"), lx_json_string(&j, b->depth.path);
	lx_json_key(&j, "depth_selftest"), lx_json_string(&j, b->depth.selftest);
	lx_json_key(&j, "light_size_deg"), lx_json_number(&j, b->light_size_deg);
	lx_json_key(&j, "configs"), lx_json_array(&j);
	for (int c = 0; c < b->nc; c++)
		lx_json_string(&j, b->configs[c]);
	lx_json_end(&j);
	lx_json_key(&j, "results"), lx_json_array(&j);
	for (int c = 0; c < b->nc; c++)
		for (int m = 0; m < b->nm; m++)
			json_row(&j, b, m, c);
	lx_json_end(&j);
	int none = method_index(b, "none"), uni = method_index(b, "uniform");
	double none_ms = none >= 0 ? median_of(b->all[none][T_FRAME], b->nframes[none]) : NAN;
	double uni_ms = uni >= 0 ? median_of(b->all[uni][T_FRAME], b->nframes[uni]) : NAN;
	lx_json_key(&j, "summary"), lx_json_array(&j);
	for (int m = 0; m < b->nm; m++) {
		struct summary s;
		summarize(b, m, uni, &s);
		lx_json_object(&j);
		lx_json_key(&j, "method"), lx_json_string(&j, b->methods[m]);
		lx_json_key(&j, "filter"), lx_json_string(&j, lx_filter_name(b->filters[m]));
		lx_json_key(&j, "frame_ms_median"), lx_json_number(&j, s.frame_ms);
		lx_json_key(&j, "frame_ms_mean"), lx_json_number(&j, mean_of(b->all[m][T_FRAME], b->nframes[m]));
		lx_json_key(&j, "depth_slots"), lx_json_int(&j, b->slots[m]);
		lx_json_key(&j, "ratio_none"), lx_json_number(&j, s.frame_ms / none_ms);
		lx_json_key(&j, "ratio_uniform"), lx_json_number(&j, s.frame_ms / uni_ms);
		/* the same view by view: the median of the configurations' ratios, the most and where */
		lx_json_key(&j, "ratio_uniform_by_view_median"), lx_json_number(&j, s.by_view.median);
		lx_json_key(&j, "ratio_uniform_by_view_most"), lx_json_number(&j, s.by_view.most);
		lx_json_key(&j, "ratio_uniform_most_on");
		if (s.by_view.count > 0)
			lx_json_string(&j, b->configs[s.by_view.most_at]);
		else
			lx_json_number(&j, NAN); /* null: uniform itself, or no uniform run */
		lx_json_key(&j, "views_at_most_uniform");
		lx_json_number(&j, s.by_view.count > 0 ? s.by_view.at_most_one : NAN);
		/* the views its rounds resolve: slower, faster than uniform in every round */
		lx_json_key(&j, "views_slower_every_round");
		lx_json_number(&j, s.by_view.count > 0 ? s.over_every_round : NAN);
		lx_json_key(&j, "views_faster_every_round");
		lx_json_number(&j, s.by_view.count > 0 ? s.under_every_round : NAN);
		lx_json_key(&j, "shadow_ms_median"), lx_json_number(&j, median_of(b->all[m][T_SHADOW], b->nframes[m]));
		lx_json_key(&j, "main_ms_median"), lx_json_number(&j, median_of(b->all[m][T_MAIN], b->nframes[m]));
		lx_json_key(&j, "lookup_pct_median"), lx_json_number(&j, s.lookups);
		lx_json_key(&j, "setup_us"), lx_json_number(&j, median_of(b->all[m][T_SETUP], b->nframes[m]));
		lx_json_key(&j, "setup_again_us"), lx_json_number(&j, median_of(b->all[m][T_SETUP_AGAIN], b->nframes[m]));
		lx_json_key(&j, "mismatch_median"), lx_json_number(&j, s.mismatch);
		lx_json_key(&j, "mismatch_worst"), lx_json_number(&j, s.worst);
		lx_json_key(&j, "soft_error_median"), lx_json_number(&j, s.soft);
		lx_json_end(&j);
	}
	lx_json_end(&j);
	lx_json_end(&j);
}

static bool csv_rows(FILE *f, void *ctx)
{
	const struct bench *b = ctx;
	fprintf(f, "method,filter,config");
	for (int k = 0; k < ROW_COLUMNS; k++)
		fprintf(f, ",%s", row_columns[k].name);
	for (int p = 0; p < b->scene.plane_count; p++)
		fprintf(f, ",m_max_%s,lpp_%s,lixels_used_%s", b->scene.planes[p].name, b->scene.planes[p].name,
			b->scene.planes[p].name);
	fprintf(f, "\n");
	for (int c = 0; c < b->nc; c++)
		for (int m = 0; m < b->nm; m++) {
			const struct row *r = &b->rows[m][c];
			fprintf(f, "%s,%s,%s", b->methods[m], lx_filter_name(b->filters[m]), b->configs[c]);
			for (int k = 0; k < ROW_COLUMNS; k++)
				fprintf(f, ",%.*f", row_columns[k].csv_decimals, column_of(r, k));
			for (int p = 0; p < b->scene.plane_count; p++)
				if (isnan(r->m_max[p]))
					fprintf(f, ",,,");
				else
					fprintf(f, ",%.4f,%.4f,%.0f", r->m_max[p], r->lpp[p], r->used[p]);
			fprintf(f, "\n");
		}
	return !ferror(f);
}

static bool write_csv(const struct bench *b, char *err, size_t errlen)
{
	return lx_out_write(b->csv, csv_rows, (void *)b, err, errlen);
}

static bool write_plot(const struct bench *b, char *err, size_t errlen)
{
	struct lx_plot_point pts[MAX_RUNS];
	for (int m = 0; m < b->nm; m++) {
		double mis[MAX_CONFIGS];
		for (int c = 0; c < b->nc; c++)
			mis[c] = b->rows[m][c].mismatch_pct;
		pts[m] = (struct lx_plot_point){.x = median_of(b->all[m][T_FRAME], b->nframes[m]), .y = median_of(mis, b->nc),
						.label = b->labels[m]};
		lx_plot_color(m, pts[m].rgb);
	}
	char title[96];
	snprintf(title, sizeof title, "lixel bench %dx%d: median over %d configurations", b->width, b->height, b->nc);
	return lx_plot_scatter(b->plot, title, "frame time ms (median)", "mismatch % (median, log)", pts, b->nm, err, errlen);
}

/* What --methods, --configs and --scene said, kept until the lists are checked. */
struct bench_args {
	char methods[256], configs[512], filters[64];
	const char *scene;
};

/* One option and its value: 0, 2 after the one line. */
static int bench_option(struct bench *b, struct bench_args *ba, const char *a, const char *v)
{
	int st, hz;
	enum lx_filter unused;
	const struct lx_arg_text texts[] = {{"--scene", &ba->scene}, {"--csv", &b->csv}, {"--plot", &b->plot},
					    {"--strips", &b->strips}};
	if (lx_arg_text(a, v, texts, sizeof texts / sizeof texts[0]))
		return 0;
	if ((st = lx_arg_depth_precision("bench", a, v, &b->depth_precision)) >= 0 ||
	    (st = lx_arg_plane_option("bench", a, v, &b->options)) >= 0 ||
	    (!strcmp(a, "--light-size") && (st = lx_arg_filter("bench", a, v, &unused, &b->light_size_deg)) >= 0))
		return st;
	if (!strcmp(a, "--size")) {
		if (!lx_parse_mode(v, &b->width, &b->height, &hz) || hz)
			return bad(a, "WxH with W and H from 1 to 16384", v);
	} else if (!strcmp(a, "--frames") || !strcmp(a, "--warmup")) {
		bool frames = !strcmp(a, "--frames");
		enum lx_number_error e = lx_number_int(v, frames ? 1 : 0, 10000, frames ? &b->frames : &b->warmup);
		if (e)
			return lx_arg_bad_number("bench", a, frames ? "a whole number from 1 to 10000" : "a whole number from 0 to 10000",
						 v, e);
	} else if (!strcmp(a, "--methods") || !strcmp(a, "--configs") || !strcmp(a, "--filters") || !strcmp(a, "--filter")) {
		char *to = a[2] == 'm' ? ba->methods : a[2] == 'c' ? ba->configs : ba->filters;
		size_t room = a[2] == 'm' ? sizeof ba->methods : a[2] == 'c' ? sizeof ba->configs : sizeof ba->filters;
		if (strlen(v) >= room)
			return bad(a, "a shorter list", v);
		strcpy(to, v);
	} else if (!strcmp(a, "--platform")) {
		if (!lx_platform_known(v))
			return bad(a, lx_platform_names(), v);
		b->platform = v;
	}
	return 0;
}


/* --filters: the names split and checked into b->filter_list. 0 or 2. */
static int filter_list(struct bench *b, struct bench_args *ba)
{
	char copy[sizeof ba->filters];
	const char *names[LX_FILTER_COUNT];
	strcpy(copy, ba->filters);
	if (!split(ba->filters, names, LX_FILTER_COUNT, &b->nf))
		return bad("--filters", "a comma-separated list of filters from none, pcf2x2 and pcf3x3", copy);
	for (int k = 0; k < b->nf; k++)
		if (!lx_filter_parse(names[k], &b->filter_list[k]))
			return bad("--filters", lx_filter_names(), names[k]);
	return named_twice("--filters", "filter", names, b->nf);
}

/* The runs: each method with each filter (none reads no map: it runs once, unfiltered),
 * named METHOD or METHOD+FILTER; at most MAX_METHODS times LX_FILTER_COUNT (split caps
 * both lists). */
static void expand_runs(struct bench *b, const char *const *specs, int ns)
{
	b->nm = 0;
	for (int m = 0; m < ns; m++) {
		char why[200];
		struct lx_method_options probe = b->options;
		bool mapless = !strcmp(lx_shadow_method_spec(specs[m], &probe, why, sizeof why)->name, "none");
		for (int k = 0; k < (mapless ? 1 : b->nf); k++) {
			enum lx_filter f = mapless ? LX_FILTER_NONE : b->filter_list[k];
			b->methods[b->nm] = specs[m], b->filters[b->nm] = f;
			snprintf(b->labels[b->nm], sizeof b->labels[0], "%s%s%s", specs[m], f ? "+" : "", f ? lx_filter_name(f) : "");
			b->nm++;
		}
	}
}

/* The lists of methods, filters and configurations split and each name checked. 0 or 2. */
static int bench_lists(struct bench *b, struct bench_args *ba)
{
	char copy[512];
	const char *specs[MAX_METHODS];
	int ns, st;
	if ((st = filter_list(b, ba)))
		return st;
	strcpy(copy, ba->methods);
	if (!split(ba->methods, specs, MAX_METHODS, &ns))
		return bad("--methods", "a comma-separated list of at most " LX_STR(MAX_METHODS) " methods, none empty", copy);
	char expected[320];
	snprintf(expected, sizeof expected, "methods from %s, each with options after slashes (lixel bench --help)",
		 lx_shadow_method_names());
	for (int m = 0; m < ns; m++)
		if ((st = lx_arg_method_spec("bench", "--methods", specs[m], &b->options, expected)))
			return st;
	if ((st = named_twice("--methods", "method", specs, ns)))
		return st;
	expand_runs(b, specs, ns);
	if (!ba->configs[0]) {
		for (int c = 0; c < lx_config_count; c++)
			b->configs[b->nc++] = lx_configs[c].name;
		b->configs[b->nc++] = "animation";
		return 0;
	}
	strcpy(copy, ba->configs);
	if (!split(ba->configs, b->configs, MAX_CONFIGS, &b->nc))
		return bad("--configs", "a comma-separated list of at most " LX_STR(MAX_CONFIGS) " configurations, none empty", copy);
	for (int c = 0; c < b->nc; c++)
		if (!is_animation(b->configs[c]) && !lx_config_find(b->configs[c]))
			return bad("--configs", "configurations named in lixel render --help, or animation", b->configs[c]);
	return named_twice("--configs", "configuration", b->configs, b->nc);
}

/* The command line into *b (ba keeps the lists' text, which b points into), the scene
 * loaded and every output checked before any work. 0, 2, or -1 after --help. */
static int bench_parse(int argc, char **argv, struct bench *b, struct bench_args *ba)
{
	*b = (struct bench){.width = 1024, .height = 1024, .frames = 30, .warmup = 5, .platform = "osmesa",
			    .options = LX_METHOD_OPTIONS_DEFAULT, .light_size_deg = LX_DEFAULT_LIGHT_SIZE_DEG};
	*ba = (struct bench_args){0};
	snprintf(ba->methods, sizeof ba->methods, "%s", lx_shadow_method_list());
	snprintf(ba->filters, sizeof ba->filters, "none");
	lx_scene_default(&b->scene);
	static const char *const with_value[] = {"--size", "--frames", "--warmup", "--methods", "--configs", "--platform",
						 "--scene", "--csv", "--plot", "--strips", "--depth-precision", LX_PLANE_OPTION_NAMES,
						 "--filters", "--filter", "--light-size"};
	for (int i = 0; i < argc; i++) {
		const char *a = argv[i], *v;
		if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
			usage(stdout);
			return -1;
		}
		if (!strcmp(a, "--json") || !strcmp(a, "--mediump")) {
			if (a[2] == 'j')
				b->json = true;
			else
				b->depth_precision = LX_DEPTH_MEDIUMP;
			continue;
		}
		int st = lx_arg_value("bench", argc, argv, &i, with_value, sizeof with_value / sizeof with_value[0], &v);
		if (st || (st = bench_option(b, ba, a, v)))
			return st;
	}
	int st = bench_lists(b, ba);
	if (st)
		return st;
	if (ba->scene && !lx_arg_scene(ba->scene, &b->scene))
		return 2;
	struct stat info;
	if (b->strips && (!*b->strips || stat(b->strips, &info) != 0 || !S_ISDIR(info.st_mode) ||
			  access(b->strips, W_OK | X_OK) != 0))
		return bad("--strips", "a writable folder", b->strips);
	/* every output checked before any work: a bad path is found now, not after the run */
	const char *outputs[2] = {b->csv, b->plot};
	char err[512];
	for (int k = 0; k < 2; k++)
		if (outputs[k] && !lx_out_check(outputs[k], err, sizeof err)) {
			fprintf(stderr, "lixel bench: %s\n", err);
			return 2;
		}
	return 0;
}

/* The images and the per-method frame lists; false when memory runs out. */
static bool bench_alloc(struct bench *b, struct pixels *px)
{
	long n = (long)b->width * b->height;
	px->rgba = malloc((size_t)n * 4), px->sh = malloc((size_t)n), px->ref_sh = malloc((size_t)n * LX_MAX_LIGHTS);
	px->obj = malloc((size_t)n * sizeof(int16_t)), px->ref_obj = malloc((size_t)n * sizeof(int16_t));
	px->vis = malloc((size_t)n), px->served = malloc((size_t)n), px->ref_vis = malloc((size_t)n * LX_MAX_LIGHTS * sizeof(float));
	bool ok = px->rgba && px->sh && px->ref_sh && px->obj && px->ref_obj && px->vis && px->served && px->ref_vis;
	for (int m = 0; m < b->nm; m++)
		for (int q = 0; q < T_KINDS; q++)
			ok &= (b->all[m][q] = malloc(sizeof(double) * (size_t)b->frames * b->nc)) != NULL;
	return ok;
}

/* Every method set up, every configuration run, the report and its files. */
static int bench_run(struct bench *b, const struct lx_scene_meshes *meshes, struct lx_method_run *runs, int *ready,
		     const struct pixels *px, char *err, size_t errlen)
{
	lx_gl_caps_probe(&b->caps);
	while (*ready < b->nm) {
		struct lx_method_run *run = &runs[*ready];
		int status = make_run(b, *ready, b->depth_precision, meshes, run, err, errlen);
		if (status)
			return status;
		if (++*ready == 1 && run->depth.warning[0])
			fprintf(stderr, "lixel bench: warning: %s\n", run->depth.warning);
		b->depth = run->depth;
		b->slots[*ready - 1] = lx_renderer_depth_slots(run->renderer);
	}
	for (int c = 0; c < b->nc; c++) {
		fprintf(stderr, "lixel bench: configuration %d/%d: %s\n", c + 1, b->nc, b->configs[c]);
		int status = run_config(b, c, runs, meshes, px, err, errlen);
		if (status)
			return status;
	}
	if (b->json)
		print_json(b);
	else
		print_text(b, &b->caps);
	return (b->csv && !write_csv(b, err, errlen)) || (b->plot && !write_plot(b, err, errlen));
}

int lx_bench_main(int argc, char **argv)
{
	static struct bench b; /* the rows of every method and configuration: large */
	struct bench_args ba;
	int status = bench_parse(argc, argv, &b, &ba);
	if (status)
		return status < 0 ? 0 : status;
	char err[512];
	struct lx_scene_meshes meshes = {0};
	if (!lx_meshes_build(&b.scene, &meshes)) {
		fprintf(stderr, "lixel: out of memory building the meshes\n");
		return 1;
	}
	struct lx_platform *plat = lx_platform_create(b.platform, err, sizeof err);
	if (!plat) {
		fprintf(stderr, "lixel: %s\n", err);
		lx_meshes_free(&meshes);
		return 1;
	}
	static struct lx_method_run runs[MAX_RUNS]; /* large too */
	struct pixels px = {0};
	int ready = 0;
	if (!bench_alloc(&b, &px)) {
		snprintf(err, sizeof err, "out of memory for %dx%d images", b.width, b.height);
		status = 1;
	} else
		status = bench_run(&b, &meshes, runs, &ready, &px, err, sizeof err);
	if (status)
		fprintf(stderr, "lixel: %s\n", err);
	for (int m = 0; m < ready; m++)
		lx_method_run_free(&runs[m]);
	for (int m = 0; m < b.nm; m++)
		for (int q = 0; q < T_KINDS; q++)
			free(b.all[m][q]);
	free(px.rgba), free(px.sh), free(px.ref_sh), free(px.obj), free(px.ref_obj), free(px.vis), free(px.served), free(px.ref_vis);
	lx_platform_destroy(plat);
	lx_meshes_free(&meshes);
	return status;
}
