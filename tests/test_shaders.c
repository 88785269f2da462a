/* Every shader variant the loader builds, checked as GLSL ES 1.00 by glslangValidator
 * (Debian's glslang-tools): a driver accepts what it likes, a strict one does not. The
 * texts come from the same code the loader uses (shader_text.c). */
#include "embedded.h"
#include "shader_text.h"
#include "plane_cover.h"
#include "shadow_filter.h"
#include "test_util.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

enum { SEEN_SLOTS = 1 << 15 }; /* more than twice the variants: the open-addressed set stays sparse */

struct batch {
	char dir[64];
	int files, variants; /* texts written (each different), variants built */
	char list[1048576];
	uint64_t seen[SEEN_SLOTS]; /* the texts written, by test_fnv1a of the stage and the text (0: empty) */
};

/* Whether a text of this stage (its file extension) was written before; else it is noted.
 * Many variants differ only in what one stage reads (a vertex shader is the same under
 * every filter): glslangValidator checks each text once. A 64-bit hash: two different
 * texts of the ten thousand share one with a chance of about 3e-12. */
static bool seen_before(struct batch *b, const char *ext, const char *text)
{
	uint64_t h = test_fnv1a(test_fnv1a(TEST_FNV_BASIS, ext, strlen(ext)), text, strlen(text)) | 1; /* never 0, the empty slot */
	for (size_t i = h % SEEN_SLOTS;; i = (i + 1) % SEEN_SLOTS) {
		if (b->seen[i] == h)
			return true;
		if (!b->seen[i]) {
			b->seen[i] = h;
			return false;
		}
	}
}

static void write_variant(struct batch *b, const char *file, const char *defines, bool lima, const char *tag)
{
	char err[256], path[256];
	const char *text = lx_embedded_text(lx_shader_files, file);
	assert_non_null(text);
	char *src = lx_shader_text(file, text, defines, lima, err, sizeof err);
	if (!src)
		fail_msg("%s", err);
	const char *ext = strrchr(file, '.');
	b->variants++;
	assert_true(b->variants < SEEN_SLOTS / 2); /* the set has room */
	if (seen_before(b, ext, src)) {
		free(src);
		return;
	}
	snprintf(path, sizeof path, "%s/%d-%s%s", b->dir, b->files++, tag, ext);
	FILE *f = fopen(path, "w");
	assert_non_null(f);
	fputs(src, f);
	assert_int_equal(fclose(f), 0);
	free(src);
	size_t n = strlen(b->list);
	assert_true(n + strlen(path) + 2 < sizeof b->list);
	snprintf(b->list + n, sizeof b->list - n, " %s", path);
}

static const enum lx_depth_precision paths[3] = {LX_DEPTH_HIGHP, LX_DEPTH_MEDIUMP, LX_DEPTH_TEXTURE};

/* One main-pass variant's texts (its defines, `extra` and the filter's, as the renderer
 * puts them): the vertex shader, the fragment shader, and that under the lima simulation. */
static void write_main_variant(struct batch *b, const struct lx_main_variant *v, const char *extra, int filter,
			       const char *tag)
{
	char defines[360];
	lx_main_defines(v, defines, sizeof defines);
	strncat(defines, extra, sizeof defines - strlen(defines) - 1);
	strncat(defines, lx_filter_define((enum lx_filter)filter), sizeof defines - strlen(defines) - 1);
	write_variant(b, "main.vert", defines, false, tag); /* a filter leaves the face plane out */
	write_variant(b, "main.frag", defines, false, tag);
	write_variant(b, "main.frag", defines, true, tag);
}

/* The main pass under a limit of varyings (0: none): every count of maps, every count of
 * them read, shaded or decision, each rule for their faces (toward the light, tested,
 * away, a caster's along its plane), each depth path (0 highp, 1 mediump, 2 highp with
 * the maps in a depth texture), every shadow filter; with one plane's cover test where a
 * draw reads none of the maps or all of them, and with two so, unfiltered. */
static void main_variants(struct batch *b, int max_varyings)
{
	char tag[64];
	for (int maps = 0; maps <= 4; maps++)
		for (int reads = 0; reads <= maps; reads++)
			for (int decision = 0; decision < 2; decision++)
				for (int face = 0; face < LX_FACES_COUNT; face++)
					for (int path = 0; path < 3; path++)
						for (int filter = 0; filter < LX_FILTER_COUNT; filter++)
							for (int cover = 0; cover <= LX_MAX_COVERS; cover++) {
								if (face == LX_FACES_AWAY && reads > 0)
									continue; /* faces turned away read nothing: the reads 0 text */
								if (cover && (face == LX_FACES_AWAY || (reads > 0 && reads < maps)))
									continue;
								if (cover > 1 && filter > 0)
									continue; /* its text is the same with any filter */
								struct lx_main_variant v = {
									.maps = maps, .reads = reads, .decision = decision,
									.faces = (enum lx_faces)face, .path = paths[path],
									.filtered = filter > 0, .covers = cover, .max_varyings = max_varyings};
								snprintf(tag, sizeof tag, "main-%d-%d-%d-%d-%d-%d-%d-%d", max_varyings, maps,
									 reads, decision, face, path, filter, cover);
								write_main_variant(b, &v, "", filter, tag);
								v.self_id = true; /* a caster's own texels passed over (LX_SELF) */
								if (lx_main_self(&v)) {
									strncat(tag, "-self", sizeof tag - strlen(tag) - 1);
									write_main_variant(b, &v, "", filter, tag);
								}
							}
}

static void every_variant_is_glsl_es_100(void **state)
{
	(void)state;
	if (system("glslangValidator --version > /dev/null 2>&1") != 0)
		fail_msg("glslangValidator is not installed (Debian: glslang-tools; make check installs it)");
	static struct batch b;
	snprintf(b.dir, sizeof b.dir, "/tmp/lixel-glsl-XXXXXX");
	assert_non_null(mkdtemp(b.dir));
	b.files = 0, b.variants = 0, b.list[0] = 0;
	memset(b.seen, 0, sizeof b.seen);
	char tag[64];
	/* the main pass with no limit on varyings and with a VideoCore IV's 8 */
	main_variants(&b, 0);
	main_variants(&b, 8);
	/* a projective light's shaded variants (the decision reads no light image), with each
	 * filter, every map read */
	for (int maps = 0; maps <= 4; maps++)
		for (int path = 0; path < 3; path++)
			for (int filter = 0; filter < LX_FILTER_COUNT; filter++) {
				struct lx_main_variant v = {.maps = maps, .reads = maps, .faces = LX_FACES_TESTED,
							    .path = paths[path], .filtered = filter > 0, .projective = true};
				snprintf(tag, sizeof tag, "projective-%d-%d-%d", maps, path, filter);
				write_main_variant(&b, &v, "#define LX_PROJECTIVE 1\n", filter, tag);
			}
	for (int path = 0; path < 3; path++)
		for (int lima = 0; lima < 2; lima++) {
			const char *d = lx_shadow_defines(paths[path]);
			write_variant(&b, "shadow_depth.vert", d, false, "shadow");
			write_variant(&b, "shadow_depth.frag", d, lima, "shadow");
		}
	for (const char *const *f = (const char *const[]){"atlas_clear.vert", "atlas_clear.frag", "atlas_readback.frag",
							    "overlay.vert", "overlay.frag", NULL};
	     *f; f++)
		write_variant(&b, *f, NULL, false, "plain");
	/* the files through xargs: one sh -c argument holds at most 128 KiB */
	char cmd[700], out[300], list[300];
	snprintf(out, sizeof out, "%s/log", b.dir);
	snprintf(list, sizeof list, "%s/list", b.dir);
	FILE *lf = fopen(list, "w");
	assert_non_null(lf);
	fputs(b.list, lf);
	assert_int_equal(fclose(lf), 0);
	snprintf(cmd, sizeof cmd, "xargs glslangValidator < %s > %s 2>&1", list, out);
	int st = system(cmd);
	if (st != 0) {
		FILE *f = fopen(out, "r");
		char line[512];
		while (f && fgets(line, sizeof line, f))
			if (strstr(line, "ERROR") || strstr(line, "error"))
				print_message("%s", line);
		if (f)
			fclose(f);
	}
	print_message("%d shader variants, %d different texts given to glslangValidator: %s\n", b.variants, b.files,
		      st == 0 ? "all accepted" : "rejected");
	snprintf(cmd, sizeof cmd, "rm -rf %s", b.dir);
	assert_int_equal(system(cmd), 0);
	assert_int_equal(st, 0);
}

/* main.vert's text for a variant into dir/vK.vert, appended to the list of files. */
static void write_vertex(const char *dir, const char *defines, int k, char *list, size_t size)
{
	char err[256], path[128];
	char *src = lx_shader_text("main.vert", lx_embedded_text(lx_shader_files, "main.vert"), defines, false, err,
				   sizeof err);
	if (!src)
		fail_msg("%s", err);
	snprintf(path, sizeof path, "%s/v%d.vert", dir, k);
	FILE *f = fopen(path, "w");
	assert_non_null(f);
	fputs(src, f);
	assert_int_equal(fclose(f), 0);
	free(src);
	assert_true(strlen(list) + strlen(path) + 2 < size);
	strcat(list, " "), strcat(list, path);
}

/* The varying vectors of each of the n texts in list, as one glslangValidator -E
 * preprocesses them (one process: each was a twentieth of a second), in their order:
 * each text's output begins at its #version line, the only one a text may have. Every
 * varying counts but a float, which the packing rules put beside a vec3. */
static void vertex_varyings(const char *dir, const char *list, int n, int *count)
{
	static char cmd[16640];
	char path[128], line[256];
	snprintf(path, sizeof path, "%s/pre", dir);
	assert_true(snprintf(cmd, sizeof cmd, "glslangValidator -E%s > %s 2>&1", list, path) < (int)sizeof cmd);
	assert_int_equal(system(cmd), 0);
	FILE *f = fopen(path, "r");
	assert_non_null(f);
	int k = -1;
	while (fgets(line, sizeof line, f)) {
		const char *t = line + strspn(line, " \t");
		if (!strncmp(t, "#version", 8)) {
			assert_true(++k < n);
			count[k] = 0;
			continue;
		}
		assert_true(k >= 0);
		count[k] += !strncmp(t, "varying ", 8) && !strstr(t, " float ");
	}
	fclose(f);
	assert_int_equal(k + 1, n);
}

/* What a variant's varyings must be: the count lx_main_varyings gives, within the limit. */
struct varyings_case {
	int want, limit;
};

/* lx_main_varyings counts what main.vert writes, for every count of maps read, with and
 * without a face plane and a projective light, with no, one or two covers; under a
 * VideoCore IV's 8 no variant writes more (edges give way first, then the face plane,
 * then a second cover), and without a limit every variant keeps all. */
static void variants_fit_the_varyings(void **state)
{
	(void)state;
	if (system("glslangValidator --version > /dev/null 2>&1") != 0)
		fail_msg("glslangValidator is not installed (Debian: glslang-tools; make check installs it)");
	char dir[64] = "/tmp/lixel-varyings-XXXXXX", defines[400];
	static char list[16384];
	list[0] = 0;
	assert_non_null(mkdtemp(dir));
	enum { CASES = 5 * 2 * 2 * 2 * (LX_MAX_COVERS + 1) };
	struct varyings_case c[CASES];
	int k = 0, dropped = 0, given_up = 0, count[CASES];
	for (int reads = 0; reads <= 4; reads++)
		for (int caster = 0; caster < 2; caster++)
			for (int projective = 0; projective < 2; projective++)
				for (int limit = 0; limit <= 8; limit += 8)
					for (int cover = 0; cover <= LX_MAX_COVERS; cover++) {
						struct lx_main_variant v = {.maps = 4, .reads = reads,
									    .faces = caster ? LX_FACES_CASTER : LX_FACES_TOWARD,
									    .path = LX_DEPTH_HIGHP, .projective = projective,
									    .covers = cover, .max_varyings = limit};
						lx_main_defines(&v, defines, sizeof defines);
						if (projective)
							strncat(defines, "#define LX_PROJECTIVE 1\n", sizeof defines - strlen(defines) - 1);
						bool edges = strstr(defines, "LX_EDGES") != NULL,
						     plane = strstr(defines, "LX_FACE_PLANE") != NULL;
						/* the first cover is never given up: it decides shadows, not their
						 * cost; the second only where nothing else is left to give */
						int covers = lx_main_covers(&v);
						assert_true((strstr(defines, "LX_COVER 1") != NULL) == (cover > 0));
						assert_true((strstr(defines, "LX_COVER2") != NULL) == (covers > 1));
						if (covers < cover)
							assert_true(limit && !edges && !plane &&
								    lx_main_varyings(reads, false, false, projective, cover) > limit);
						else
							assert_int_equal(covers, cover);
						given_up += covers < cover;
						if (!limit)
							assert_true(edges == (reads > 0) && plane == (caster && reads > 0));
						dropped += limit && reads > 0 && (!edges || plane != (bool)caster);
						assert_true(k < CASES);
						c[k] = (struct varyings_case){lx_main_varyings(reads, edges, plane, projective, covers), limit};
						write_vertex(dir, defines, k++, list, sizeof list);
					}
	vertex_varyings(dir, list, k, count);
	for (int i = 0; i < k; i++) {
		assert_int_equal(count[i], c[i].want);
		if (c[i].limit)
			assert_true(count[i] <= c[i].limit);
	}
	print_message("%d variants' varyings counted; under 8, %d gave up edges or the face plane, %d a second cover\n", k,
		      dropped, given_up);
	assert_true(dropped > 0);
	assert_int_equal(given_up, 2); /* 4 maps read, a projective light, two covers: 9, caster or not */
	char cmd[128];
	snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
	assert_int_equal(system(cmd), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(every_variant_is_glsl_es_100),
		cmocka_unit_test(variants_fit_the_varyings),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
