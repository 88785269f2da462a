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

static GLuint compile(GLenum type, const char *name, const char *text, const char *defines, char *err, size_t errlen)
{
	char *src = lx_shader_text(name, text, defines, type == GL_FRAGMENT_SHADER && lx_simulating_lima(), err, errlen);
	if (!src)
		return 0;
	GLuint sh = lx_gl.CreateShader(type);
	const char *srcs[1] = {src};
	lx_gl.ShaderSource(sh, 1, srcs, NULL);
	lx_gl.CompileShader(sh);
	free(src);
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

GLuint lx_texture_rgba8(int w, int h)
{
	GLuint tex;
	lx_gl.GenTextures(1, &tex);
	lx_gl.BindTexture(GL_TEXTURE_2D, tex);
	lx_gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
	lx_gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
	lx_gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
	lx_gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
	lx_gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
	return tex;
}

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
	GLuint vs = compile(GL_VERTEX_SHADER, vert, vert_text, defines, err, errlen);
	if (!vs)
		return 0;
	GLuint fs = compile(GL_FRAGMENT_SHADER, frag, frag_text, defines, err, errlen);
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
