/* Filtered shadows (--filter): with none (the default) the images are the ones lixel drew
 * before filters existed, byte for byte; pcf2x2 and pcf3x3 keep the hard reference's
 * decisions within the render tests' bounds, come closer than none to an area light's
 * soft shadows, never read outside their map's atlas region, and read their maps
 * wherever a shadow can fall (--lookup-region footprint changes nothing). */
#include "configs.h"
#include "light_space.h"
#include "method_run.h"
#include "platform.h"
#include "soft_reference.h"
#include "test_util.h"
#include "gl_fixture.h"
#include "lookup_check.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef LX_TEST_DATA
#define LX_TEST_DATA "tests/data"
#endif
#define GOLDEN LX_TEST_DATA "/filter-none.golden"

enum { GW = 256, GH = 192 };

/* One golden line: the scene, the depth path, the method, the configuration, and the
 * hashes of the shaded image and of the decision image (every byte of both). */
static void golden_line(struct lx_method_run *run, const struct lx_frame *frame, uint8_t *rgba, int16_t *obj, uint8_t *sh,
			const char *what, char *line, size_t len)
{
	struct lx_frame_times t;
	lx_method_run_frame(run, frame, NULL, &t);
	lx_renderer_read(run->renderer, rgba);
	uint64_t shaded = test_fnv1a(TEST_FNV_BASIS, rgba, (size_t)GW * GH * 4);
	lx_method_run_decision(run, 0, rgba, obj, sh);
	/* the decision, the object and the visibility, not whether a lookup was drawn (B):
	 * where the main pass looks is the lookup regions' to change (test_render) */
	for (size_t i = 0; i < (size_t)GW * GH; i++)
		rgba[4 * i + 2] = 0;
	uint64_t decision = test_fnv1a(TEST_FNV_BASIS, rgba, (size_t)GW * GH * 4);
	snprintf(line, len, "%s %016llx %016llx\n", what, (unsigned long long)shaded, (unsigned long long)decision);
}

/* Every golden line of one scene and depth path (its key word: highp, mediump, texture),
 * appended to out. */
static void golden_scene(const char *scene_name, enum lx_depth_precision path, const struct lx_gl_caps *caps, char *out,
			 size_t room)
{
	static const char *const key[] = {"", "highp", "mediump", "texture"};
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
		o.depth_slots = 1; /* the depth paths' codes, byte for byte; slots: test_render */
		if (lx_method_run_init(&run, name, &base, &meshes, caps, &o, GW, GH, path, LX_DEFAULT_BIAS_CODES, false, err,
				       sizeof err))
			fail_msg("%s: %s", name, err);
		for (int c = 0; c < lx_config_count; c++) {
			struct lx_scene scene = base;
			lx_config_apply(&lx_configs[c], &scene);
			struct lx_frame frame;
			assert_true(lx_frame_setup(&frame, &scene, &meshes, 0.4, GW, GH, err, sizeof err));
			char what[96], line[160];
			snprintf(what, sizeof what, "%s %s %s %s", scene_name, key[path], name, lx_configs[c].name);
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

/* The length of a golden line's key: its first four words (scene, depth path, method,
 * configuration) and the space after them. */
static size_t key_length(const char *line)
{
	size_t k = 0, len = strcspn(line, "\n");
	for (int words = 0; words < 4 && k < len; k++)
		words += line[k] == ' ';
	return k;
}

/* The line of text whose key is the first n bytes of key, or NULL. */
static const char *find_line(const char *text, const char *key, size_t n)
{
	for (const char *l = text; *l; l += strcspn(l, "\n") + (l[strcspn(l, "\n")] != 0))
		if (key_length(l) == n && !strncmp(l, key, n))
			return l;
	return NULL;
}

/* Every golden line's images drawn again with the same hashes; lines of methods or
 * configurations added since (another method in the registry) are new, counted apart. */
static void compare_golden(const char *golden, const char *now)
{
	long lines = 0, differ = 0, fresh = 0;
	for (const char *g = golden; *g; g += strcspn(g, "\n") + (g[strcspn(g, "\n")] != 0), lines++) {
		size_t len = strcspn(g, "\n");
		const char *l = find_line(now, g, key_length(g));
		if (!l || strcspn(l, "\n") != len || memcmp(l, g, len)) {
			print_message("differs: %.*s (now %.*s)\n", (int)len, g, l ? (int)strcspn(l, "\n") : 4, l ? l : "none");
			differ++;
		}
	}
	for (const char *l = now; *l; l += strcspn(l, "\n") + (l[strcspn(l, "\n")] != 0))
		fresh += !find_line(golden, l, key_length(l));
	print_message("%ld image pairs compared with the golden hashes, %ld differ; %ld new (not in the file)\n", lines,
		      differ, fresh);
	assert_int_equal(differ, 0);
	assert_true(lines > 0);
}

/* The depth-texture path draws every image the RGBA8 highp path draws, byte for byte:
 * each of its lines (key word texture) has the hashes of the highp line of its key. */
static void same_as_highp(const char *texture, const char *now)
{
	long lines = 0;
	for (const char *t = texture; *t; t += strcspn(t, "\n") + (t[strcspn(t, "\n")] != 0), lines++) {
		char key[128];
		size_t n = key_length(t), len = strcspn(t, "\n");
		const char *word = strstr(t, " texture ");
		assert_true(word && (size_t)(word - t) < n && n < sizeof key - 8);
		snprintf(key, sizeof key, "%.*s highp %.*s", (int)(word - t), t, (int)(n - (word - t) - 9), word + 9);
		const char *h = find_line(now, key, strlen(key));
		if (!h || strcspn(h, "\n") != len - 2 || memcmp(h + strlen(key), t + n, len - n))
			fail_msg("the depth-texture path draws otherwise: %.*s (highp: %.*s)", (int)len, t,
				 h ? (int)strcspn(h, "\n") : 4, h ? h : "none");
	}
	print_message("%ld image pairs of the depth-texture path: the same hashes as the highp path's\n", lines);
	assert_true(lines > 0);
}

/* --filter none draws what lixel drew before filters: the hashes of every method's shaded
 * and decision images, on every standard configuration of both built-in scenes and both
 * depth paths, against tests/data/filter-none.golden, written by the code before the
 * filters came (LIXEL_GOLDEN_WRITE=FILE writes them again; the decision hashes, since
 * they leave out where a lookup was drawn, by the code before the sure shadows, d6fed27;
 * the shaded hashes by the code that first drew a plane's lit spans as fewer, taller
 * rectangles (span_merge.h), whose lighting, interpolated over other triangles, moved
 * one or two pixels of 12 of the 280 images by one level; plane-optimal's two of the
 * table's low light by the code that tests a flat box's two fronts over the hull of
 * their shadows, where one floor pixel the exact reference shadows was lit before; 26 by
 * the code that ends spans on whole 4x4 blocks (LX_SPAN_ALIGN), which moved one pixel of
 * 22 shaded images by one level and, in 4, which surface 1 to 3 pixels where two planes
 * or a plane and the background meet show, shadow decisions unchanged; XPSM's on the
 * table's floor-close at mediump by the code that bounds a box caster's volume by the
 * faces the shadow pass draws, whose lookup spans cut the table top into other pieces:
 * one pixel on the top's edge now shows the background, as the exact reference does; 10
 * by the code that bounds a round caster's lookup volume in sixteen directions, whose
 * spans cut the floor into other pieces: one pixel of 7 images one level of lighting,
 * and where the floor meets the background seen from close to it, one pixel of 5 (TSM,
 * LiSPSM, XPSM) another surface: the table's two the floor, as the exact reference
 * does, where they showed the background; the default scene's TSM the background where
 * it showed the floor, and its LiSPSM and XPSM at mediump another surface where they
 * showed the background (the reference: the floor); no shadow decision changed; 7 by the
 * code that ends a box caster's lookup volume at its lit faces, whose spans cut the
 * table's floor seen from close to it into other pieces: one pixel on the floor's far
 * edge (uniform, PSM and TSM at both precisions, plane-optimal at highp) now shows the
 * background, as the exact reference does; 4 of plane-optimal's by the code that puts
 * the cuts at its maps' screen rectangles on whole blocks too, whose spans cut the floor
 * into other pieces: one pixel of the default view (highp) and of the table's low light
 * (mediump) one level of lighting, and on the default scene's floor-close view at both
 * precisions one pixel on the floor's edge the floor, as the exact reference has it,
 * where it showed the background). A method or configuration
 * the file does not hold is new and not compared; one it holds must draw the same. llvmpipe's images depend on
 * its version and the CPU's vector width: on another renderer the test says so and skips. */
static void filter_none_draws_as_before(void **state)
{
	(void)state;
	struct lx_gl_caps caps;
	struct lx_platform *plat = platform_with_caps("osmesa", &caps);
	char renderer[512];
	snprintf(renderer, sizeof renderer, "%s | %s", caps.renderer, caps.version);
	size_t room = 1 << 20;
	char *now = calloc(room, 1);
	assert_non_null(now);
	char *texture = calloc(room, 1);
	assert_non_null(texture);
	for (const char *const *sn = (const char *const[]){"default", "table", NULL}; *sn; sn++) {
		golden_scene(*sn, LX_DEPTH_HIGHP, &caps, now, room);
		golden_scene(*sn, LX_DEPTH_MEDIUMP, &caps, now, room);
		golden_scene(*sn, LX_DEPTH_TEXTURE, &caps, texture, room);
	}
	same_as_highp(texture, now);
	free(texture);
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
		} else
			compare_golden(golden, now);
	}
	free(now);
	lx_platform_destroy(plat);
}

enum { W = 320, H = 240 };
/* The area light the soft-edge error is measured against here: at 320x240 a pixel on the
 * default view's floor is about 3 cm, so a 2-degree light gives penumbrae of one to a few
 * pixels, as the default half degree does at 1024x1024 (lixel bench). */
#define TEST_LIGHT_DEG 2.0

/* One frame's pixels: the references', and a run's decision and visibility. */
struct pixels {
	uint8_t *rgba, *sh, *ref_sh, *vis, *dist;
	int16_t *obj, *ref_obj;
	float *ref_vis;
};

static void pixels_alloc(struct pixels *px, long n)
{
	*px = (struct pixels){malloc((size_t)n * 4), malloc((size_t)n), malloc((size_t)n), malloc((size_t)n), malloc((size_t)n),
			      malloc((size_t)n * sizeof(int16_t)), malloc((size_t)n * sizeof(int16_t)),
			      malloc((size_t)n * sizeof(float))};
	assert_true(px->rgba && px->sh && px->ref_sh && px->vis && px->dist && px->obj && px->ref_obj && px->ref_vis);
}

static void pixels_free(struct pixels *px)
{
	free(px->rgba), free(px->sh), free(px->ref_sh), free(px->vis), free(px->dist), free(px->obj), free(px->ref_obj),
		free(px->ref_vis);
}

/* Chessboard distance from each pixel to the nearest edge of the hard reference (a pixel
 * whose 4-neighbour differs in object or shadow), capped at cap; as test_render's. */
static void edge_distance(const struct pixels *px, int w, int h, int cap)
{
	for (int y = 0; y < h; y++)
		for (int x = 0; x < w; x++) {
			long i = (long)y * w + x;
			bool edge = false;
			for (int k = 0; k < 4; k++) {
				int nx = x + (k == 0) - (k == 1), ny = y + (k == 2) - (k == 3);
				long j = (long)ny * w + nx;
				if (nx >= 0 && ny >= 0 && nx < w && ny < h)
					edge |= px->ref_obj[j] != px->ref_obj[i] || px->ref_sh[j] != px->ref_sh[i];
			}
			px->dist[i] = edge ? 0 : (uint8_t)cap;
		}
	for (int pass = 0; pass < cap; pass++)
		for (int y = 0; y < h; y++)
			for (int x = 0; x < w; x++)
				for (int oy = -1; oy <= 1 && px->dist[(long)y * w + x] == pass; oy++)
					for (int ox = -1; ox <= 1; ox++) {
						int nx = x + ox, ny = y + oy;
						if (nx >= 0 && ny >= 0 && nx < w && ny < h && px->dist[(long)ny * w + nx] > pass + 1)
							px->dist[(long)ny * w + nx] = (uint8_t)(pass + 1);
					}
}

/* The worst lixel span in pixels over the planes (each pixel with the map that serves it). */
static double worst_m(const struct lx_frame *f, const struct lx_method_run *run, const struct pixels *px)
{
	double worst = 1;
	for (int p = 0; p < f->scene->plane_count; p++) {
		struct lx_plane_sampling ps;
		if (lx_plane_sampling(f, &run->lights[0].atlas, &run->lights[0].result, p, px->ref_obj, NULL, NULL, &ps))
			worst = fmax(worst, ps.m_max);
	}
	return worst;
}

/* The run's maps of frame f, and the edge bound every filter of them is held to: the
 * reach in pixels (ceil(m_max) + 2), with px->dist filled up to it. */
static int run_edges(struct lx_method_run *run, const struct lx_frame *f, struct pixels *px)
{
	lx_method_run_shadows(run, f);
	int reach = (int)fmin(ceil(worst_m(f, run, px)) + 2, 250);
	edge_distance(px, f->view.width, f->view.height, reach + 1);
	return reach;
}

/* A run's frame against both references: the mismatch within ceil(m_max) + 2 pixels of a
 * true edge and under 0.5% in all (test_render's bounds for NEAREST); returns
 * soft_error_pct, *mismatch the mismatch. The run's maps are drawn (lx_method_run_shadows)
 * and px->dist holds the distances to the edges up to reach + 1 (run_edges). */
static double check_run(struct lx_method_run *run, const struct lx_frame *f, struct pixels *px, int reach,
			const char *what, double *mismatch)
{
	long n = (long)f->view.width * f->view.height;
	lx_method_run_decision(run, 0, px->rgba, px->obj, px->sh);
	lx_decision_visibility(px->rgba, n, run->filter, px->vis);
	long far = 0;
	for (long i = 0; i < n; i++)
		far += px->ref_obj[i] >= 0 && px->ref_obj[i] == px->obj[i] && px->ref_sh[i] != LX_REF_EDGE_ON &&
		       px->ref_sh[i] != px->sh[i] && px->dist[i] > reach;
	struct lx_mismatch mm;
	lx_mismatch_compare(px->ref_obj, px->ref_sh, px->obj, px->sh, n, &mm);
	double soft = lx_soft_error(px->ref_obj, px->ref_sh, px->ref_vis, px->obj, px->vis, n);
	if (far || !(mm.mismatch_pct < 0.5))
		fail_msg("%s: mismatch %.4f%%, %ld pixels more than %d from an edge", what, mm.mismatch_pct, far, reach);
	*mismatch = mm.mismatch_pct;
	return soft;
}

/* The default scene's references per configuration, cast once for the three calls of
 * filters_against_references (the frame depends on neither the platform nor the depth path). */
enum { REF_ROOM = 16 };
static struct {
	const char *config;
	int16_t *obj;
	uint8_t *sh;
	float *vis;
} refs[REF_ROOM];

static void references(const char *config, const struct lx_frame *f, struct pixels *px)
{
	size_t n = (size_t)W * H;
	int i = 0;
	while (i < REF_ROOM && refs[i].config && strcmp(refs[i].config, config))
		i++;
	assert_true(i < REF_ROOM);
	if (!refs[i].config) {
		assert_true(lx_reference_image(f, px->ref_obj, px->ref_sh, 2));
		assert_true(lx_soft_reference_image(f, TEST_LIGHT_DEG, px->ref_vis, 2));
		refs[i].obj = malloc(n * sizeof(int16_t)), refs[i].sh = malloc(n), refs[i].vis = malloc(n * sizeof(float));
		assert_true(refs[i].obj && refs[i].sh && refs[i].vis);
		memcpy(refs[i].obj, px->ref_obj, n * sizeof(int16_t));
		memcpy(refs[i].sh, px->ref_sh, n);
		memcpy(refs[i].vis, px->ref_vis, n * sizeof(float));
		refs[i].config = config;
		return;
	}
	memcpy(px->ref_obj, refs[i].obj, n * sizeof(int16_t));
	memcpy(px->ref_sh, refs[i].sh, n);
	memcpy(px->ref_vis, refs[i].vis, n * sizeof(float));
}

static int references_free(void **state)
{
	(void)state;
	for (int i = 0; i < REF_ROOM; i++)
		free(refs[i].obj), free(refs[i].sh), free(refs[i].vis);
	return 0;
}

/* Methods and filters over configurations of the default scene on one platform and depth
 * path: the decisions within the bounds; the soft-edge error below none's for uniform
 * (both filters) and plane (pcf3x3). The plane maps put a lixel centre on each pixel
 * centre where they have a lixel for every pixel, so there a bilinear weight is 0 or 1
 * and pcf2x2 reads what NEAREST reads: it is held within 0.01 points of none instead.
 * With the light at the eye no map is drawn: every filter gives none's image, exactly. */
static void filters_against_references(const char *platform, bool mediump, const char *const *configs, int nc)
{
	char err[512];
	struct lx_gl_caps caps;
	struct lx_platform *plat = platform_with_caps(platform, &caps);
	struct lx_scene base;
	lx_scene_default(&base);
	struct lx_scene_meshes meshes = {0};
	assert_true(lx_meshes_build(&base, &meshes));
	static const char *const methods[] = {"uniform", "plane"};
	struct lx_method_run run[2];
	for (int m = 0; m < 2; m++) {
		struct lx_method_options o = LX_METHOD_OPTIONS_DEFAULT;
		if (lx_method_run_init(&run[m], methods[m], &base, &meshes, &caps, &o, W, H,
				       mediump ? LX_DEPTH_MEDIUMP : LX_DEPTH_AUTO, LX_DEFAULT_BIAS_CODES, false, err, sizeof err))
			fail_msg("%s", err);
	}
	struct pixels px;
	pixels_alloc(&px, (long)W * H);
	for (int c = 0; c < nc; c++) {
		struct lx_scene scene = base;
		lx_config_apply(lx_config_find(configs[c]), &scene);
		struct lx_frame f;
		assert_true(lx_frame_setup(&f, &scene, &meshes, 0.4, W, H, err, sizeof err));
		references(configs[c], &f, &px);
		for (int m = 0; m < 2; m++) {
			double soft[LX_FILTER_COUNT], mis[LX_FILTER_COUNT];
			int reach = run_edges(&run[m], &f, &px); /* a filter changes only how the main pass reads the maps */
			for (int k = 0; k < LX_FILTER_COUNT; k++) {
				char what[96];
				snprintf(what, sizeof what, "%s %s %s %s+%s", platform, mediump ? "mediump" : "highp", configs[c],
					 methods[m], lx_filter_name((enum lx_filter)k));
				assert_int_equal(lx_method_run_set_filter(&run[m], (enum lx_filter)k, err, sizeof err), 0);
				soft[k] = check_run(&run[m], &f, &px, reach, what, &mis[k]);
			}
			print_message("%-6s %-7s %-12s %-8s mismatch %.4f%% %.4f%% %.4f%%, soft-edge error %.4f%% %.4f%% %.4f%% "
				      "(none, pcf2x2, pcf3x3)\n", platform, mediump ? "mediump" : "highp", configs[c], methods[m],
				      mis[0], mis[1], mis[2], soft[0], soft[1], soft[2]);
			bool plane = m == 1;
			if (lx_shadows_hidden(&f)) { /* the miner's lamp: no map to filter, and nothing wrong */
				if (!(mis[0] == 0 && mis[1] == 0 && mis[2] == 0 && soft[1] == soft[0] && soft[2] == soft[0]))
					fail_msg("%s %s: the light at the eye draws no map, yet the filters differ or err", configs[c],
						 methods[m]);
				continue;
			}
			if (!(soft[2] < soft[0]) || (plane ? !(soft[1] <= soft[0] + 0.01) : !(soft[1] < soft[0])))
				fail_msg("%s %s: the filters' soft-edge errors %.4f%% and %.4f%% against none's %.4f%%", configs[c],
					 methods[m], soft[1], soft[2], soft[0]);
		}
	}
	pixels_free(&px);
	for (int m = 0; m < 2; m++)
		lx_method_run_free(&run[m]);
	lx_meshes_free(&meshes);
	lx_platform_destroy(plat);
}

static void filters_match_the_references(void **state)
{
	(void)state;
	const char *configs[16];
	for (int c = 0; c < lx_config_count; c++)
		configs[c] = lx_configs[c].name;
	filters_against_references("osmesa", false, configs, lx_config_count);
	filters_against_references("egl", false, (const char *const[]){"default", "low"}, 2);
}

/* On the 11-bit mediump path (fp16 on llvmpipe: texture coordinates keep few bits of a
 * texel's fraction) under the same bounds. */
static void filters_on_the_mediump_path(void **state)
{
	(void)state;
	filters_against_references("osmesa", true, (const char *const[]){"default", "low", "directional"}, 3);
}

/* Every texel of the atlas outside the frame's rendered regions (guard bands, and the
 * other regions' neighbours), or with ring, only the regions' own outermost texels, set to
 * depth code 0: nearer the light than anything. Returns how many were set. */
static long paint_near(const struct lx_method_run *run, uint8_t *tex, bool ring)
{
	const struct lx_atlas *a = &run->lights[0].atlas;
	long painted = 0;
	for (int y = 0; y < a->texture_height; y++)
		for (int x = 0; x < a->texture_width; x++) {
			bool inside = false, edge = false;
			for (int m = 0; m < run->lights[0].result.map_count; m++) {
				const struct lx_region *g = &a->regions[run->lights[0].result.maps[m].region];
				if (!run->lights[0].result.maps[m].rendered || x < g->x || y < g->y || x >= g->x + g->w || y >= g->y + g->h)
					continue;
				inside = true;
				edge |= x == g->x || y == g->y || x == g->x + g->w - 1 || y == g->y + g->h - 1;
			}
			if (ring ? edge : !inside) {
				uint8_t *t = tex + ((size_t)y * a->texture_width + x) * 4;
				t[0] = t[1] = t[2] = 0, t[3] = 255;
				painted++;
			}
		}
	return painted;
}

/* Pixels whose decision or visibility differ between two decision images. */
static long differ(const uint8_t *a, const uint8_t *b, long n)
{
	long d = 0;
	for (long i = 0; i < n; i++)
		d += a[i * 4] != b[i * 4] || a[i * 4 + 1] != b[i * 4 + 1] || a[i * 4 + 3] != b[i * 4 + 3];
	return d;
}

/* Pixels where footprint's decision image a (R the decision, G the object, A the
 * visibility) differs from all's b; *wrong counts those footprint may not change: any but
 * a caster's own texels (lookup_check.h), where footprint is the lighter. */
static long lookup_differ(const struct lx_frame *f, const uint8_t *a, const uint8_t *b, long *wrong)
{
	long d = 0, n = (long)f->view.width * f->view.height;
	struct lx_raycaster *rc = NULL;
	for (long i = 0; i < n; i++) {
		const uint8_t *p = a + i * 4, *q = b + i * 4;
		if (p[0] == q[0] && p[1] == q[1] && p[3] == q[3])
			continue;
		d++;
		*wrong += !(p[1] == q[1] && own_texels(f, &rc, i, p[1] - 1, p[0] <= q[0] && p[3] >= q[3]));
	}
	lx_raycaster_destroy(rc);
	return d;
}

/* A filter's samples stay in the map's own atlas region (clamped to its edge texels'
 * centres): with every texel outside the frame's regions made "near", every method and
 * configuration decides and shades every pixel (--lookup-region all: each one reads) as
 * before, the atlas read back and written alike. That the lookups do reach their regions' edges shows in the control: the
 * regions' own outermost texels made near change some pixels. */
static void filters_stay_in_their_region(void **state)
{
	(void)state;
	enum { w = 256, h = 192 };
	char err[512];
	struct lx_gl_caps caps;
	struct lx_platform *plat = platform_with_caps("osmesa", &caps);
	struct lx_scene base;
	lx_scene_default(&base);
	struct lx_scene_meshes meshes = {0};
	assert_true(lx_meshes_build(&base, &meshes));
	uint8_t *before = malloc((size_t)w * h * 4), *after = malloc((size_t)w * h * 4), *sh = malloc((size_t)w * h);
	int16_t *obj = malloc((size_t)w * h * sizeof(int16_t));
	for (int i = 0; i < lx_shadow_method_count(); i++) {
		const char *name = lx_shadow_method_at(i)->name;
		struct lx_method_run run;
		struct lx_method_options o = LX_METHOD_OPTIONS_DEFAULT;
		o.lookup_everywhere = true;
		o.depth_slots = 1; /* the atlas read, painted and written back: the codes over the whole range */
		if (lx_method_run_init(&run, name, &base, &meshes, &caps, &o, w, h, LX_DEPTH_AUTO, LX_DEFAULT_BIAS_CODES, false,
				       err, sizeof err))
			fail_msg("%s", err);
		uint8_t *tex = malloc((size_t)run.lights[0].atlas.texture_width * run.lights[0].atlas.texture_height * 4);
		long outside = 0, control = 0;
		for (int k = 1; k < LX_FILTER_COUNT; k++)
			for (int c = 0; c < lx_config_count; c++) {
				struct lx_scene scene = base;
				lx_config_apply(&lx_configs[c], &scene);
				struct lx_frame f;
				assert_true(lx_frame_setup(&f, &scene, &meshes, 0.4, w, h, err, sizeof err));
				assert_int_equal(lx_method_run_set_filter(&run, (enum lx_filter)k, err, sizeof err), 0);
				lx_method_run_shadows(&run, &f);
				/* before: the atlas through the read-back and write once, unpainted (the
				 * depth-texture path reads back whole codes, and a texel written as its
				 * code may sit a step from where the rasterizer put it: a compare at the
				 * bias's edge, one pixel of tsm+pcf2x2 floor-close, moved with it; a
				 * second round trip moves nothing) */
				lx_renderer_read_atlas(run.renderer, tex);
				lx_renderer_write_atlas(run.renderer, tex);
				lx_method_run_decision(&run, 0, before, obj, sh);
				for (int ring = 0; ring < 2; ring++) {
					lx_renderer_read_atlas(run.renderer, tex);
					long painted = paint_near(&run, tex, ring);
					lx_renderer_write_atlas(run.renderer, tex);
					lx_method_run_decision(&run, 0, after, obj, sh);
					long d = differ(before, after, (long)w * h);
					if (ring)
						control += d;
					else if (d)
						fail_msg("%s+%s %s: %ld pixels changed with the %ld texels outside the regions near", name,
							 lx_filter_name((enum lx_filter)k), lx_configs[c].name, d, painted);
					outside += ring ? 0 : painted;
					lx_method_run_shadows(&run, &f); /* the atlas drawn again */
				}
			}
		print_message("%-7s: %ld texels outside the regions made near changed nothing; the regions' edge texels "
			      "made near changed %ld pixels\n", name, outside, control);
		if (strcmp(name, "none"))
			assert_true(control > 0);
		free(tex);
		lx_method_run_free(&run);
	}
	free(before), free(after), free(sh), free(obj);
	lx_meshes_free(&meshes);
	lx_platform_destroy(plat);
}

/* A filter reads up to a lixel farther than NEAREST: the main pass's lookup region grows
 * by that (lx_filter_reach), so --lookup-region footprint still gives every pixel the
 * decision and the visibility --lookup-region all gives. Every method, every standard
 * configuration of both built-in scenes, both filters, the highp and the mediump path. */
static void filters_lookup_where_shadows_fall(void **state)
{
	(void)state;
	enum { w = 256, h = 192 };
	char err[512];
	struct lx_gl_caps caps;
	struct lx_platform *plat = platform_with_caps("osmesa", &caps);
	uint8_t *rgba[2] = {malloc((size_t)w * h * 4), malloc((size_t)w * h * 4)}, *sh = malloc((size_t)w * h);
	int16_t *obj = malloc((size_t)w * h * sizeof(int16_t));
	long frames = 0, own = 0, looked[2] = {0, 0};
	for (const char *const *sn = (const char *const[]){"default", "table", NULL}; *sn; sn++) {
		struct lx_scene base;
		assert_true(lx_scene_builtin(*sn, &base));
		struct lx_scene_meshes meshes = {0};
		assert_true(lx_meshes_build(&base, &meshes));
		for (int i = 0; i < lx_shadow_method_count(); i++)
			for (int mediump = 0; mediump < 2; mediump++) {
				/* one run: footprint then all read the same maps, drawn once a frame (a filter and
				 * the lookup region change only how the main pass reads them) */
				struct lx_method_run run;
				struct lx_method_options o = LX_METHOD_OPTIONS_DEFAULT;
				if (lx_method_run_init(&run, lx_shadow_method_at(i)->name, &base, &meshes, &caps, &o, w, h,
						       mediump ? LX_DEPTH_MEDIUMP : LX_DEPTH_AUTO, LX_DEFAULT_BIAS_CODES, false, err,
						       sizeof err))
					fail_msg("%s", err);
				for (int c = 0; c < lx_config_count; c++) {
					struct lx_scene scene = base;
					lx_config_apply(&lx_configs[c], &scene);
					struct lx_frame f;
					assert_true(lx_frame_setup(&f, &scene, &meshes, 0.4, w, h, err, sizeof err));
					lx_method_run_shadows(&run, &f);
					for (int fl = 1; fl < LX_FILTER_COUNT; fl++) {
						assert_int_equal(lx_method_run_set_filter(&run, (enum lx_filter)fl, err, sizeof err), 0);
						for (int k = 0; k < 2; k++) {
							lx_method_run_set_lookup_everywhere(&run, k == 1);
							looked[k] += lx_method_run_decision(&run, 0, rgba[k], obj, sh);
						}
						long wrong = 0, d = lookup_differ(&f, rgba[0], rgba[1], &wrong);
						if (wrong)
							fail_msg("%s scene, %s, %s+%s, %s: %ld of %ld pixels that differ between --lookup-region "
								 "footprint and all are not a caster's own texels",
								 *sn, lx_configs[c].name, lx_shadow_method_at(i)->name,
								 lx_filter_name((enum lx_filter)fl), mediump ? "mediump" : "highp", wrong, d);
						own += d;
						frames++;
					}
				}
				lx_method_run_free(&run);
			}
		lx_meshes_free(&meshes);
	}
	print_message("%ld filtered frames identical with footprint and all but for %ld pixels where all read a caster's "
		      "own texels; footprint looked up %.1f%% of the pixels all did\n",
		      frames, own, looked[1] ? 100.0 * looked[0] / looked[1] : 0);
	free(rgba[0]), free(rgba[1]), free(sh), free(obj);
	lx_platform_destroy(plat);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(filter_none_draws_as_before),
		cmocka_unit_test(filters_match_the_references),
		cmocka_unit_test(filters_on_the_mediump_path),
		cmocka_unit_test(filters_stay_in_their_region),
		cmocka_unit_test(filters_lookup_where_shadows_fall),
	};
	return cmocka_run_group_tests_name("filter", tests, NULL, references_free);
}
