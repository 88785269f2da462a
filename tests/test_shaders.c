/* Every shader variant the loader builds, checked as GLSL ES 1.00 by glslangValidator
 * (Debian's glslang-tools): a driver accepts what it likes, a strict one does not. The
 * texts come from the same code the loader uses (shader_text.c). */
#include "embedded.h"
#include "shader_text.h"
#include "shadow_filter.h"
#include "test_util.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

struct batch {
	char dir[64];
	int files;
	char list[262144];
};

static void write_variant(struct batch *b, const char *file, const char *defines, bool lima, const char *tag)
{
	char err[256], path[256];
	const char *text = lx_embedded_text(lx_shader_files, file);
	assert_non_null(text);
	char *src = lx_shader_text(file, text, defines, lima, err, sizeof err);
	if (!src)
		fail_msg("%s", err);
	const char *ext = strrchr(file, '.');
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

static void every_variant_is_glsl_es_100(void **state)
{
	(void)state;
	if (system("glslangValidator --version > /dev/null 2>&1") != 0)
		fail_msg("glslangValidator is not installed (Debian: glslang-tools; make check installs it)");
	static struct batch b;
	snprintf(b.dir, sizeof b.dir, "/tmp/lixel-glsl-XXXXXX");
	assert_non_null(mkdtemp(b.dir));
	b.files = 0, b.list[0] = 0;
	char defines[360], tag[64];
	static const enum lx_depth_precision paths[3] = {LX_DEPTH_HIGHP, LX_DEPTH_MEDIUMP, LX_DEPTH_TEXTURE};
	/* the main pass: every count of maps, every count of them read, shaded or decision,
	 * each rule for their faces (toward the light, tested, away), each depth path (0 highp, 1 mediump, 2 highp with
	 * the maps in a depth texture), every shadow filter, and the fragment shader under the
	 * lima simulation */
	for (int maps = 0; maps <= 4; maps++)
		for (int reads = 0; reads <= maps; reads++)
			for (int decision = 0; decision < 2; decision++)
				for (int face = 0; face < LX_FACES_COUNT; face++)
					for (int path = 0; path < 3; path++)
						for (int filter = 0; filter < LX_FILTER_COUNT; filter++) {
							if (face == LX_FACES_AWAY && reads > 0)
								continue; /* faces turned away read nothing: the reads 0 text */
							lx_main_defines(maps, reads, decision, (enum lx_faces)face, paths[path], defines,
									sizeof defines);
							strncat(defines, lx_filter_define((enum lx_filter)filter), sizeof defines - strlen(defines) - 1);
							snprintf(tag, sizeof tag, "main-%d-%d-%d-%d-%d-%d", maps, reads, decision, face, path, filter);
							if (filter == 0) /* the vertex shader reads no filter */
								write_variant(&b, "main.vert", defines, false, tag);
							write_variant(&b, "main.frag", defines, false, tag);
							write_variant(&b, "main.frag", defines, true, tag);
						}
	/* a projective light's shaded variants (the decision reads no light image), with each
	 * filter, every map read */
	for (int maps = 0; maps <= 4; maps++)
		for (int path = 0; path < 3; path++)
			for (int filter = 0; filter < LX_FILTER_COUNT; filter++) {
				lx_main_defines(maps, maps, false, LX_FACES_TESTED, paths[path], defines, sizeof defines);
				strncat(defines, "#define LX_PROJECTIVE 1\n", sizeof defines - strlen(defines) - 1);
				strncat(defines, lx_filter_define((enum lx_filter)filter), sizeof defines - strlen(defines) - 1);
				snprintf(tag, sizeof tag, "projective-%d-%d-%d", maps, path, filter);
				if (filter == 0)
					write_variant(&b, "main.vert", defines, false, tag);
				write_variant(&b, "main.frag", defines, false, tag);
				write_variant(&b, "main.frag", defines, true, tag);
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
	char cmd[sizeof b.list + 400], out[300];
	snprintf(out, sizeof out, "%s/log", b.dir);
	snprintf(cmd, sizeof cmd, "glslangValidator%s > %s 2>&1", b.list, out);
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
	print_message("%d shader variants given to glslangValidator: %s\n", b.files, st == 0 ? "all accepted" : "rejected");
	snprintf(cmd, sizeof cmd, "rm -rf %s", b.dir);
	assert_int_equal(system(cmd), 0);
	assert_int_equal(st, 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(every_variant_is_glsl_es_100),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
