#include "gl_program.h"
#include "embedded.h"
#include "shader_text.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Driver logs end in newlines; messages are one line each where the log allows. */
static void trim(char *log)
{
	size_t n = strlen(log);
	while (n && (log[n - 1] == '\n' || log[n - 1] == '\r' || log[n - 1] == ' '))
		log[--n] = 0;
}

/* The driver's log of a shader or a program, trimmed: what a failure shows. */
static const char *driver_log(GLuint obj, bool program, char *log, size_t n)
{
	log[0] = 0;
	if (program)
		lx_gl.GetProgramInfoLog(obj, (GLsizei)n, NULL, log);
	else
		lx_gl.GetShaderInfoLog(obj, (GLsizei)n, NULL, log);
	trim(log);
	return log;
}

static GLuint compile(GLenum type, const char *name, const char *src, char *err, size_t errlen)
{
	GLuint sh = lx_gl.CreateShader(type);
	const char *srcs[1] = {src};
	lx_gl.ShaderSource(sh, 1, srcs, NULL);
	lx_gl.CompileShader(sh);
	GLint ok = 0;
	lx_gl.GetShaderiv(sh, GL_COMPILE_STATUS, &ok);
	if (!ok) {
		char log[2048];
		snprintf(err, errlen, "%s: compile error: %s", name, driver_log(sh, false, log, sizeof log));
		lx_gl.DeleteShader(sh);
		return 0;
	}
	return sh;
}

static GLuint link(const char *vert, const char *vs_src, const char *frag, const char *fs_src, char *err, size_t errlen)
{
	GLuint vs = compile(GL_VERTEX_SHADER, vert, vs_src, err, errlen);
	if (!vs)
		return 0;
	GLuint fs = compile(GL_FRAGMENT_SHADER, frag, fs_src, err, errlen);
	if (!fs) {
		lx_gl.DeleteShader(vs);
		return 0;
	}
	GLuint prog = lx_gl.CreateProgram();
	lx_gl.AttachShader(prog, vs);
	lx_gl.AttachShader(prog, fs);
	lx_gl.BindAttribLocation(prog, LX_ATTR_POSITION, "a_position");
	lx_gl.BindAttribLocation(prog, LX_ATTR_NORMAL, "a_normal");
	lx_gl.BindAttribLocation(prog, LX_ATTR_FACE_NORMAL, "a_face_normal");
	lx_gl.LinkProgram(prog);
	lx_gl.DeleteShader(vs); /* flagged for deletion; freed with the program */
	lx_gl.DeleteShader(fs);
	GLint ok = 0;
	lx_gl.GetProgramiv(prog, GL_LINK_STATUS, &ok);
	if (!ok) {
		char log[2048];
		snprintf(err, errlen, "%s + %s: link error: %s", vert, frag, driver_log(prog, true, log, sizeof log));
		lx_gl.DeleteProgram(prog);
		return 0;
	}
	return prog;
}

/* The programs the current context keeps, by their two texts. A program object owns
 * what the driver compiled for it (llvmpipe compiles each program's variants with LLVM,
 * or loads them from Mesa's shader cache, when first drawn), so building the same texts
 * twice in a context is waste: test_render, some 200 renderers in one context, took a
 * tenth more CPU time without this. */
struct kept {
	char *texts; /* the vertex shader's text, a NUL, the fragment shader's */
	size_t len;
	GLuint prog;
};
static struct {
	unsigned context; /* lx_gl_context_serial of the context they belong to */
	int count, room;
	long reused;
	struct kept *at;
} kept;

/* The kept list, emptied first when it belongs to another context than the current one
 * (its names mean nothing here): one gone before, or one that still lives while a second
 * platform is made (a render job given no platform makes its own), whose programs then
 * stay with it and go with it. */
static void kept_for_this_context(void)
{
	if (kept.context == lx_gl_context_serial())
		return;
	for (int i = 0; i < kept.count; i++)
		free(kept.at[i].texts);
	kept.count = 0, kept.reused = 0;
	kept.context = lx_gl_context_serial();
}

static GLuint kept_find(const char *texts, size_t len)
{
	kept_for_this_context();
	for (int i = 0; i < kept.count; i++)
		if (kept.at[i].len == len && !memcmp(kept.at[i].texts, texts, len)) {
			kept.reused++;
			return kept.at[i].prog;
		}
	return 0;
}

/* Keeps prog under texts (taken over); a program not kept (out of memory) is only built
 * again next time. */
static void kept_add(char *texts, size_t len, GLuint prog)
{
	if (kept.count == kept.room) {
		int room = kept.room ? 2 * kept.room : 16;
		struct kept *at = realloc(kept.at, (size_t)room * sizeof *at);
		if (!at) {
			free(texts);
			return;
		}
		kept.at = at, kept.room = room;
	}
	kept.at[kept.count++] = (struct kept){texts, len, prog};
}

void lx_programs_forget(void)
{
	bool current = kept.context == lx_gl_context_serial();
	for (int i = 0; i < kept.count; i++) {
		if (current)
			lx_gl.DeleteProgram(kept.at[i].prog);
		free(kept.at[i].texts);
	}
	free(kept.at);
	kept.at = NULL, kept.count = kept.room = 0, kept.reused = 0;
}

void lx_programs_counts(int *kept_count, long *reused)
{
	kept_for_this_context();
	*kept_count = kept.count, *reused = kept.reused;
}

static GLuint nearest_texture(GLenum format, GLenum type, int w, int h)
{
	GLuint tex;
	lx_gl.GenTextures(1, &tex);
	lx_gl.BindTexture(GL_TEXTURE_2D, tex);
	lx_gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
	lx_gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
	lx_gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
	lx_gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
	lx_gl.TexImage2D(GL_TEXTURE_2D, 0, (GLint)format, w, h, 0, format, type, NULL);
	return tex;
}

GLuint lx_texture_rgba8(int w, int h) { return nearest_texture(GL_RGBA, GL_UNSIGNED_BYTE, w, h); }

GLuint lx_texture_depth(int w, int h) { return nearest_texture(GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, w, h); }

GLuint lx_program_build(const char *vert, const char *frag, const char *defines, char *err, size_t errlen)
{
	const char *vs_text = lx_embedded_text(lx_shader_files, vert), *fs_text = lx_embedded_text(lx_shader_files, frag);
	if (!vs_text || !fs_text) {
		snprintf(err, errlen, "%s: no such shader file is built in", vs_text ? frag : vert);
		return 0;
	}
	return lx_program_build_text(vert, vs_text, frag, fs_text, defines, err, errlen);
}

GLuint lx_program_build_text(const char *vert, const char *vert_text, const char *frag, const char *frag_text,
			     const char *defines, char *err, size_t errlen)
{
	char *vs = lx_shader_text(vert, vert_text, defines, false, err, errlen);
	char *fs = vs ? lx_shader_text(frag, frag_text, defines, lx_simulating_lima(), err, errlen) : NULL;
	size_t nv = vs ? strlen(vs) : 0, len = fs ? nv + 1 + strlen(fs) + 1 : 0;
	char *texts = fs ? malloc(len) : NULL;
	GLuint prog = 0;
	if (texts) {
		memcpy(texts, vs, nv + 1);
		memcpy(texts + nv + 1, fs, len - nv - 1);
		if (!(prog = kept_find(texts, len)) && (prog = link(vert, vs, frag, fs, err, errlen))) {
			kept_add(texts, len, prog);
			texts = NULL;
		}
	} else if (fs)
		snprintf(err, errlen, "out of memory for the shaders' text");
	free(texts);
	free(vs);
	free(fs);
	return prog;
}
