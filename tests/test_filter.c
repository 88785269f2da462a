/* Filtered shadows (--filter). First of all: with --filter none (the default) the images
 * are the ones lixel drew before filters existed, byte for byte. */
#include "configs.h"
#include "method_run.h"
#include "platform.h"
#include "test_util.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef LX_TEST_DATA
#define LX_TEST_DATA "tests/data"
#endif
#define GOLDEN LX_TEST_DATA "/filter-none.golden"

enum { GW = 256, GH = 192 };

/* 64-bit FNV-1a over n bytes, continued from h */
static uint64_t fnv1a(uint64_t h, const uint8_t *p, size_t n)
{
	for (size_t i = 0; i < n; i++)
		h = (h ^ p[i]) * 0x100000001b3ull;
	return h;
}

/* One golden line: the scene, the depth path, the method, the configuration, and the
 * hashes of the shaded image and of the decision image (every byte of both). */
static void golden_line(struct lx_method_run *run, const struct lx_frame *frame, uint8_t *rgba, int16_t *obj, uint8_t *sh,
			const char *what, char *line, size_t len)
{
	struct lx_frame_times t;
	lx_method_run_frame(run, frame, &t);
	lx_renderer_read(run->renderer, rgba);
	uint64_t shaded = fnv1a(0xcbf29ce484222325ull, rgba, (size_t)GW * GH * 4);
	lx_method_run_decision(run, frame, rgba, obj, sh);
	uint64_t decision = fnv1a(0xcbf29ce484222325ull, rgba, (size_t)GW * GH * 4);
	snprintf(line, len, "%s %016llx %016llx\n", what, (unsigned long long)shaded, (unsigned long long)decision);
}

/* Every golden line of one scene and depth path, appended to out. */
static void golden_scene(const char *scene_name, bool mediump, const struct lx_gl_caps *caps, char *out, size_t room)
{
	char err[512];
	struct lx_scene base;
	assert_true(lx_scene_builtin(scene_name, &base));
	struct lx_scene_meshes meshes = {0};
	assert_true(lx_meshes_build(&base, &meshes));
	uint8_t *rgba = malloc((size_t)GW * GH * 4), *sh = malloc((size_t)GW * GH);
	int16_t *obj = malloc((size_t)GW * GH * sizeof(int16_t));
	assert_true(rgba && sh && obj);
	for (int m = 0; m < lx_shadow_method_count(); m++) {
		const char *name = lx_shadow_method_at(m)->name;
		struct lx_method_run run;
		struct lx_method_options o = LX_METHOD_OPTIONS_DEFAULT;
		if (lx_method_run_init(&run, name, &base, &meshes, caps, &o, GW, GH, mediump ? LX_DEPTH_MEDIUMP : LX_DEPTH_AUTO,
				       LX_DEFAULT_BIAS_CODES, false, err, sizeof err))
			fail_msg("%s: %s", name, err);
		for (int c = 0; c < lx_config_count; c++) {
			struct lx_scene scene = base;
			lx_config_apply(&lx_configs[c], &scene);
			struct lx_frame frame;
			assert_true(lx_frame_setup(&frame, &scene, &meshes, 0.4, GW, GH, err, sizeof err));
			char what[96], line[160];
			snprintf(what, sizeof what, "%s %s %s %s", scene_name, mediump ? "mediump" : "highp", name,
				 lx_configs[c].name);
			golden_line(&run, &frame, rgba, obj, sh, what, line, sizeof line);
			size_t used = strlen(out);
			snprintf(out + used, room - used, "%s", line);
		}
		lx_method_run_free(&run);
	}
	free(rgba), free(sh), free(obj);
	lx_meshes_free(&meshes);
}

/* The golden file: its renderer line (the hashes hold for that driver only) and the rest. */
static char *read_golden(char *renderer, size_t len)
{
	FILE *f = fopen(GOLDEN, "rb");
	if (!f)
		fail_msg("cannot open %s", GOLDEN);
	static char text[1 << 20];
	size_t n = fread(text, 1, sizeof text - 1, f);
	fclose(f);
	text[n] = 0;
	char *eol = strchr(text, '\n');
	assert_non_null(eol);
	assert_true(!strncmp(text, "renderer ", 9));
	snprintf(renderer, len, "%.*s", (int)(eol - text - 9), text + 9);
	return eol + 1;
}

/* --filter none draws what lixel drew before filters: the hashes of every method's shaded
 * and decision images, on every standard configuration of both built-in scenes and both
 * depth paths, against tests/data/filter-none.golden, written by the code before the
 * filters came (LIXEL_GOLDEN_WRITE=FILE writes them again). llvmpipe's images depend on
 * its version and the CPU's vector width: on another renderer the test says so and skips. */
static void filter_none_draws_as_before(void **state)
{
	(void)state;
	char err[512];
	struct lx_platform *plat = lx_platform_create("osmesa", err, sizeof err);
	if (!plat)
		fail_msg("%s", err);
	struct lx_gl_caps caps;
	lx_gl_caps_probe(&caps);
	char renderer[512];
	snprintf(renderer, sizeof renderer, "%s | %s", caps.renderer, caps.version);
	size_t room = 1 << 20;
	char *now = calloc(room, 1);
	assert_non_null(now);
	for (const char *const *sn = (const char *const[]){"default", "table", NULL}; *sn; sn++)
		for (int mediump = 0; mediump < 2; mediump++)
			golden_scene(*sn, mediump, &caps, now, room);
	const char *write = getenv("LIXEL_GOLDEN_WRITE");
	if (write) {
		FILE *f = fopen(write, "wb");
		assert_non_null(f);
		fprintf(f, "renderer %s\n%s", renderer, now);
		fclose(f);
		print_message("wrote %s\n", write);
	} else {
		char was[512];
		const char *golden = read_golden(was, sizeof was);
		if (strcmp(was, renderer)) {
			print_message("the golden hashes are of '%s', this is '%s' (skipped)\n", was, renderer);
		} else {
			const char *a = golden, *b = now;
			long lines = 0, differ = 0;
			while (*a && *b) {
				size_t la = strcspn(a, "\n"), lb = strcspn(b, "\n");
				if (la != lb || memcmp(a, b, la)) {
					print_message("differs: %.*s (golden %.*s)\n", (int)lb, b, (int)la, a);
					differ++;
				}
				lines++;
				a += la + (a[la] != 0), b += lb + (b[lb] != 0);
			}
			print_message("%ld image pairs compared with the golden hashes, %ld differ\n", lines, differ);
			assert_int_equal(differ, 0);
			assert_true(!*a && !*b);
		}
	}
	free(now);
	lx_platform_destroy(plat);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(filter_none_draws_as_before),
	};
	return cmocka_run_group_tests_name("filter", tests, NULL, NULL);
}
