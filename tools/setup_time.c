/* The light matrices' set-up timed without a GL (`make setup-time`): for each standard
 * configuration of the default and table scenes, each method's set-up of one frame,
 * repeated, its median in us in three states of the CPU:
 *   warm       the same set-up back to back, its code, data and branches all learnt;
 *   caches     after 8 MB of memory is written, which evicts its data from the caches;
 *   branches   after a million branches whose outcomes follow no pattern (two branch
 *              sites), which wear out the branch predictor's history;
 *   sort       after qsort of 200,000 numbers: many branch sites, a call through a
 *              pointer per comparison and 1.6 MB of memory, nearer what a GL driver's
 *              work does between two frames (the bench's `setup us` is a frame's first
 *              set-up, made after the driver has taken the main pass; its `again us` the
 *              same work repeated once the frame's shadow passes are planned);
 *   sleep      after 3 ms asleep (nanosleep), the thread off the CPU as a frame loop's
 *              wait for the GL or the display leaves it: what the set-up pays for state
 *              it did not wear out itself.
 * What it prints are figures, not a verdict: they move with the machine.
 * Usage: setup-time [-n REPEATS] [-s WxH] [METHOD...]   (default: 101 repeats, 1024x1024,
 * the methods plane and uniform) */
#include "atlas.h"
#include "configs.h"
#include "frame.h"
#include "mesh.h"
#include "metrics.h"
#include "shadow_method.h"
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double now_us(void)
{
	struct timespec t;
	clock_gettime(CLOCK_MONOTONIC, &t);
	return t.tv_sec * 1e6 + t.tv_nsec * 1e-3;
}

enum { WARM, CACHES, BRANCHES, SORT, SLEEP, STATES };
static const char *const state_names[STATES] = {"warm", "caches", "branches", "sort", "sleep"};

static unsigned char *junk; /* 8 MB, written a byte a cache line */
static unsigned *numbers;   /* SORT_COUNT, sorted by `wear` */
enum { SORT_COUNT = 200000 };
static volatile unsigned long sink;

static int compare_numbers(const void *a, const void *b)
{
	unsigned x = *(const unsigned *)a, y = *(const unsigned *)b;
	return (x > y) - (x < y);
}

/* The CPU put in state s before a timed set-up. */
static void wear(int s)
{
	if (s == CACHES) {
		for (size_t i = 0; i < (8u << 20); i += 64)
			junk[i]++;
	} else if (s == BRANCHES) {
		unsigned x = 12345, acc = 0;
		for (int i = 0; i < 1000000; i++) {
			x = x * 1103515245u + 12345u; /* a linear congruential step: bit 16 follows no pattern a predictor learns */
			if (x >> 16 & 1) {
				acc += x;
				__asm__ volatile("" ::: "memory"); /* a branch, not a conditional move */
			} else {
				acc ^= x >> 3;
				__asm__ volatile("" ::: "memory");
			}
		}
		sink += acc;
	} else if (s == SLEEP) {
		struct timespec d = {0, 3000000};
		while (nanosleep(&d, &d) != 0 && errno == EINTR) /* a signal: the rest of it */
			;
	} else if (s == SORT) {
		unsigned x = 12345;
		for (int i = 0; i < SORT_COUNT; i++)
			numbers[i] = x = x * 1103515245u + 12345u;
		qsort(numbers, SORT_COUNT, sizeof *numbers, compare_numbers);
		sink += numbers[SORT_COUNT / 2];
	}
}

/* The median of the set-up's time over `repeats`, the CPU in state s before each. */
static double time_setup(const struct lx_shadow_method *m, const struct lx_method_options *o,
			 const struct lx_frame *f, const struct lx_atlas *a0, int s, int repeats, double *t)
{
	static struct lx_shadow_result res;
	for (int r = 0; r < repeats; r++) {
		struct lx_atlas a = *a0;
		wear(s);
		double t0 = now_us();
		lx_shadow_method_frame(m, f, &a, o, &res);
		t[r] = now_us() - t0;
	}
	return lx_median(t, repeats);
}

/* One configuration of one scene, every method: a line each. */
static bool time_config(const char *scene, int c, int w, int h, char **methods, int nm, int repeats, double *t)
{
	struct lx_scene s;
	struct lx_scene_meshes me;
	if (!lx_scene_builtin(scene, &s) || (lx_config_apply(&lx_configs[c], &s), !lx_meshes_build(&s, &me))) {
		fprintf(stderr, "setup-time: scene %s cannot be built\n", scene);
		return false;
	}
	struct lx_frame f;
	char err[256];
	bool ok = lx_frame_setup(&f, &s, &me, 0, w, h, err, sizeof err);
	for (int k = 0; ok && k < nm; k++) {
		struct lx_method_options o = LX_METHOD_OPTIONS_DEFAULT;
		const struct lx_shadow_method *m = lx_shadow_method_spec(methods[k], &o, err, sizeof err);
		struct lx_region_request req[LX_MAX_MAPS];
		struct lx_atlas a;
		ok = m && lx_atlas_layout(&a, req, lx_shadow_method_regions(m, f.scene, &o, req), 1, 2048, err, sizeof err);
		if (!ok)
			break;
		printf("%-8s %-12s %-14s", scene, lx_configs[c].name, methods[k]);
		for (int st = 0; st < STATES; st++)
			printf(" %9.1f", time_setup(m, &o, &f, &a, st, repeats, t));
		printf("\n");
	}
	if (!ok)
		fprintf(stderr, "setup-time: %s %s: %s\n", scene, lx_configs[c].name, err);
	lx_meshes_free(&me);
	return ok;
}

int main(int argc, char **argv)
{
	int repeats = 101, w = 1024, h = 1024, nm = 0;
	char *methods[16];
	for (int i = 1; i < argc; i++) {
		if (!strcmp(argv[i], "-n") && i + 1 < argc) {
			repeats = atoi(argv[++i]);
		} else if (!strcmp(argv[i], "-s") && i + 1 < argc) {
			if (sscanf(argv[++i], "%dx%d", &w, &h) != 2)
				w = 0;
		} else if (argv[i][0] != '-' && nm < 16) {
			methods[nm++] = argv[i];
		} else {
			repeats = 0;
		}
	}
	if (repeats < 1 || repeats > 100000 || w < 1 || h < 1 || w > 16384 || h > 16384) {
		fprintf(stderr, "usage: setup-time [-n REPEATS 1..100000] [-s WxH] [METHOD...]\n");
		return 2;
	}
	if (nm == 0)
		methods[nm++] = "plane", methods[nm++] = "uniform";
	for (int k = 0; k < nm; k++) { /* every method known before anything is printed */
		char err[256];
		struct lx_method_options o = LX_METHOD_OPTIONS_DEFAULT;
		if (!lx_shadow_method_spec(methods[k], &o, err, sizeof err)) {
			fprintf(stderr, "setup-time: %s\n", err);
			return 2;
		}
	}
	double *t = malloc((size_t)repeats * sizeof *t);
	junk = calloc(8u << 20, 1);
	numbers = malloc(SORT_COUNT * sizeof *numbers);
	bool ok = t && junk && numbers;
	printf("set-up, us, the median of %d at %dx%d, the CPU before each:\n%-8s %-12s %-14s", repeats, w, h, "scene",
	       "config", "method");
	for (int st = 0; st < STATES; st++)
		printf(" %9s", state_names[st]);
	printf("\n");
	static const char *const scenes[] = {"default", "table"};
	for (int sc = 0; ok && sc < 2; sc++)
		for (int c = 0; ok && c < lx_config_count; c++)
			ok = time_config(scenes[sc], c, w, h, methods, nm, repeats, t);
	free(t);
	free(junk);
	free(numbers);
	return ok ? 0 : 1;
}
