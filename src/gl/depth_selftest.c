#include "depth_selftest.h"
#include "depth_rgba.h"
#include "gl_program.h"
#include "mesh.h"
#include "shader_text.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { N = 64 };                       /* texels in the ramp */
static const double RAMP_A = 0.02, RAMP_B = 0.96; /* depth at window x: a + b x, x in [0, 1] */

struct target {
	GLuint tex, fbo;
};

/* A w x h texture as a framebuffer's only attachment: RGBA8 colour, or (depth) a depth
 * texture, as the texture path's atlas is; false when this GL cannot make it (a depth
 * texture without GL_OES_depth_texture raises an error, which is taken here). */
static bool make_target(struct target *t, int w, int h, bool depth)
{
	t->tex = depth ? lx_texture_depth(w, h) : lx_texture_rgba8(w, h);
	lx_gl.GenFramebuffers(1, &t->fbo);
	lx_gl.BindFramebuffer(GL_FRAMEBUFFER, t->fbo);
	lx_gl.FramebufferTexture2D(GL_FRAMEBUFFER, depth ? GL_DEPTH_ATTACHMENT : GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D,
				   t->tex, 0);
	lx_gl.Viewport(0, 0, w, h);
	bool ok = (!depth || lx_gl.GetError() == GL_NO_ERROR) &&
		  lx_gl.CheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
	while (depth && lx_gl.GetError() != GL_NO_ERROR) {
	}
	return ok;
}

static void free_target(struct target *t)
{
	lx_gl.DeleteFramebuffers(1, &t->fbo);
	lx_gl.DeleteTextures(1, &t->tex);
}

/* The unit square [0, 1]^2 at z = 0, two triangles, with normals and face normals +z. */
static void bind_square(GLuint vbo)
{
	float v[6 * LX_VERTEX_FLOATS];
	static const float xy[6][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}};
	for (int i = 0; i < 6; i++) {
		float *o = v + i * LX_VERTEX_FLOATS;
		const float p[LX_VERTEX_FLOATS] = {xy[i][0], xy[i][1], 0, 0, 0, 1, 0, 0, 1};
		memcpy(o, p, sizeof p);
	}
	lx_gl.BindBuffer(GL_ARRAY_BUFFER, vbo);
	lx_gl.BufferData(GL_ARRAY_BUFFER, sizeof v, v, GL_STATIC_DRAW);
	const GLsizei stride = LX_VERTEX_FLOATS * sizeof(float);
	for (int a = 0; a < 3; a++) {
		lx_gl.EnableVertexAttribArray((GLuint)a);
		lx_gl.VertexAttribPointer((GLuint)a, 3, GL_FLOAT, GL_FALSE, stride, (const void *)(a * 3 * sizeof(float)));
	}
}

/* Column-major 4x4 with the given rows. */
static void rows_to_matrix(const float r[4][4], float m[16])
{
	for (int row = 0; row < 4; row++)
		for (int col = 0; col < 4; col++)
			m[col * 4 + row] = r[row][col];
}

/* The ramp drawn by the depth-write shader: window x -> depth a + b x. */
static void draw_ramp(GLuint write)
{
	float m[16];
	const float r[4][4] = {{2, 0, 0, -1}, {0, 2, 0, -1}, {(float)(2 * RAMP_B), 0, 0, (float)(2 * RAMP_A - 1)}, {0, 0, 0, 1}};
	rows_to_matrix(r, m);
	lx_gl.UseProgram(write);
	lx_gl.UniformMatrix4fv(lx_gl.GetUniformLocation(write, "u_light_clip"), 1, GL_FALSE, m);
	lx_gl.DrawArrays(GL_TRIANGLES, 0, 6);
}

/* 1. The ramp written by the depth-write shader and read back: a 24-bit code within a
 * few steps (single-precision interpolation), an 11-bit one within one. A shader
 * computing in fp16 misses by thousands of 24-bit steps. (A depth texture cannot be read
 * back under ES 2.0: the texture path is checked by step 2 alone.) */
static bool write_ramp(GLuint write, bool mediump, uint8_t *px, char *detail, size_t len)
{
	draw_ramp(write);
	lx_gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
	lx_gl.ReadPixels(0, 0, N, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
	for (int i = 0; i < N; i++) {
		double d = RAMP_A + RAMP_B * (i + 0.5) / N;
		long want = mediump ? (long)floor(d * 2047) : (long)floor(d * LX_DEPTH_MAX_CODE);
		long got = mediump ? (long)lx_depth_decode_code_fp16(px + 4 * i) : (long)lx_depth_decode_code(px + 4 * i);
		if (labs(got - want) > (mediump ? 1 : 16)) {
			snprintf(detail, len, "depth %.6f written as code %ld, expected %ld (%s codes)", d, got, want,
				 mediump ? "11-bit" : "24-bit");
			return false;
		}
	}
	return true;
}

/* 2. The ramp read by the main pass's compare, a little behind it (row 0: shadowed)
 * and a little in front (row 1: lit), by twice the bias. */
static bool compare_ramp(GLuint compare, GLuint stored, bool mediump, uint8_t *px, char *detail, size_t len)
{
	double bias = mediump ? 1.0 : 64.0, step = mediump ? 1.0 / 2047 : 1.0 / LX_DEPTH_MAX_CODE;
	double off = (2 * bias + (mediump ? 2 : 16)) * step;
	float vp[16], tex[16];
	const float v[4][4] = {{2, 0, 0, -1}, {0, 2, 0, -1}, {0, 0, 0, 0}, {0, 0, 0, 1}};
	/* s = x, t = the row's centre, depth = a + b x + off (2 - 4 y): +off at y = 1/4, -off at 3/4 */
	const float t[4][4] = {{1, 0, 0, 0}, {0, 0, 0, 0.5f}, {(float)RAMP_B, (float)(-4 * off), 0, (float)(RAMP_A + 2 * off)}, {0, 0, 0, 1}};
	rows_to_matrix(v, vp);
	rows_to_matrix(t, tex);
	lx_gl.UseProgram(compare);
	lx_gl.ActiveTexture(GL_TEXTURE0);
	lx_gl.BindTexture(GL_TEXTURE_2D, stored);
	lx_gl.UniformMatrix4fv(lx_gl.GetUniformLocation(compare, "u_view_proj"), 1, GL_FALSE, vp);
	lx_gl.UniformMatrix4fv(lx_gl.GetUniformLocation(compare, "u_shadow_tex"), 1, GL_FALSE, tex);
	lx_gl.Uniform3f(lx_gl.GetUniformLocation(compare, "u_offset"), 0, 0, 0);
	lx_gl.Uniform4f(lx_gl.GetUniformLocation(compare, "u_light"), 0.5f, 0.5f, 10, 1); /* in front of +z */
	lx_gl.Uniform4f(lx_gl.GetUniformLocation(compare, "u_region"), 0, 0, 1, 1);
	lx_gl.Uniform1f(lx_gl.GetUniformLocation(compare, "u_bias"), (float)bias);
	lx_gl.Uniform1i(lx_gl.GetUniformLocation(compare, "u_atlas"), 0);
	lx_gl.Uniform1f(lx_gl.GetUniformLocation(compare, "u_object_id"), 0);
	lx_gl.DrawArrays(GL_TRIANGLES, 0, 6);
	lx_gl.ReadPixels(0, 0, N, 2, GL_RGBA, GL_UNSIGNED_BYTE, px);
	for (int row = 0; row < 2; row++)
		for (int i = 0; i < N; i++)
			if ((px[(row * N + i) * 4] > 127) != (row == 0)) {
				snprintf(detail, len, "depth %.6f compared %s its stored code by %.0f codes reads %s",
					 RAMP_A + RAMP_B * (i + 0.5) / N, row == 0 ? "behind" : "in front of", off / step,
					 row == 0 ? "lit" : "shadowed");
				return false;
			}
	return true;
}

/* The texture path's ramp: written into a depth texture by the rasterizer (the shadow
 * pass's depth test), then step 2. */
static bool texture_ramp(GLuint write, struct target *stored, bool *unsupported, char *detail, size_t len)
{
	if (!make_target(stored, N, 1, true)) {
		*unsupported = true;
		snprintf(detail, len, "this GL makes no depth-texture framebuffer (GL_OES_depth_texture)");
		return false;
	}
	lx_gl.Enable(GL_DEPTH_TEST);
	lx_gl.DepthFunc(GL_ALWAYS); /* the ramp covers the target: every texel written */
	draw_ramp(write);
	lx_gl.DepthFunc(GL_LESS);
	lx_gl.Disable(GL_DEPTH_TEST);
	return true;
}

static bool run(enum lx_depth_precision path, bool *unsupported, char *detail, size_t len)
{
	bool mediump = path == LX_DEPTH_MEDIUMP, texture = path == LX_DEPTH_TEXTURE;
	char err[1024];
	GLuint write = lx_program_build("shadow_depth.vert", "shadow_depth.frag", lx_shadow_defines(path), err, sizeof err);
	char cdef[320];
	lx_main_defines(&(struct lx_main_variant){.maps = 1, .reads = 1, .decision = true, .faces = LX_FACES_TESTED,
						  .path = path},
			cdef, sizeof cdef);
	GLuint compare = write ? lx_program_build("main.vert", "main.frag", cdef, err, sizeof err) : 0;
	if (!write || !compare) {
		snprintf(detail, len, "%.200s", err);
		return false;
	}
	GLuint vbo;
	lx_gl.GenBuffers(1, &vbo);
	bind_square(vbo);
	lx_gl.Disable(GL_DEPTH_TEST);
	lx_gl.Disable(GL_CULL_FACE);
	lx_gl.Disable(GL_SCISSOR_TEST);
	struct target stored = {0, 0}, decided = {0, 0};
	uint8_t px[N * 2 * 4];
	bool ok = (texture ? texture_ramp(write, &stored, unsupported, detail, len)
			   : make_target(&stored, N, 1, false) && write_ramp(write, mediump, px, detail, len)) &&
		  make_target(&decided, N, 2, false) && compare_ramp(compare, stored.tex, mediump, px, detail, len);
	if (stored.fbo)
		free_target(&stored);
	if (decided.fbo)
		free_target(&decided);
	lx_gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
	lx_gl.DeleteBuffers(1, &vbo); /* the programs stay the context's: the renderer's are the same texts */
	return ok;
}

/* One driver per process: each path is tried once (and once more under the lima
 * simulation, which the tests switch on and off). */
static struct selftest {
	bool done, ok, unsupported;
	char detail[240];
} cache[2][4];

static const struct selftest *selftest(enum lx_depth_precision path)
{
	/* LIXEL_SIMULATE_NO_DEPTH_TEXTURE=1: a GL without GL_OES_depth_texture, for the tests */
	static const struct selftest none = {true, false, true, "no GL_OES_depth_texture (simulated)"};
	const char *no = getenv("LIXEL_SIMULATE_NO_DEPTH_TEXTURE");
	if (path == LX_DEPTH_TEXTURE && no && !strcmp(no, "1"))
		return &none;
	struct selftest *c = &cache[lx_simulating_lima()][path];
	if (!c->done) {
		c->detail[0] = 0;
		c->ok = run(path, &c->unsupported, c->detail, sizeof c->detail);
		c->done = true;
	}
	return c;
}

bool lx_depth_selftest(enum lx_depth_precision path, char *detail, size_t len)
{
	const struct selftest *c = selftest(path == LX_DEPTH_AUTO ? LX_DEPTH_HIGHP : path);
	snprintf(detail, len, "%s", c->detail);
	return c->ok;
}

bool lx_depth_choose(enum lx_depth_precision want, struct lx_depth_choice *out, char *err, size_t errlen)
{
	char why[240] = "", why11[240] = "";
	memset(out, 0, sizeof *out);
	if (want == LX_DEPTH_TEXTURE && selftest(want)->unsupported) {
		/* a GL without depth textures (a board profile may ask for them): the path auto
		 * takes, said in a warning */
		bool ok = lx_depth_choose(LX_DEPTH_AUTO, out, err, errlen);
		snprintf(out->warning, sizeof out->warning, "the depth-texture path cannot be taken (%.120s): %s instead",
			 selftest(want)->detail, ok ? out->path : "none");
		return ok;
	}
	if (want != LX_DEPTH_AUTO) {
		static const char *const name[] = {"", "24-bit highp", "11-bit mediump", "24-bit depth-texture"};
		out->taken = want;
		out->selftest = "forced";
		if (!lx_depth_selftest(want, why, sizeof why))
			snprintf(out->warning, sizeof out->warning, "the forced %s depth path fails its self-test (%.100s)",
				 name[want], why);
	} else if (lx_depth_selftest(LX_DEPTH_TEXTURE, why, sizeof why)) {
		out->taken = LX_DEPTH_TEXTURE;
		out->selftest = "passed";
	} else if (lx_depth_selftest(LX_DEPTH_HIGHP, why, sizeof why)) {
		out->taken = LX_DEPTH_HIGHP;
		out->selftest = "passed";
	} else if (lx_depth_selftest(LX_DEPTH_MEDIUMP, why11, sizeof why11)) {
		out->taken = LX_DEPTH_MEDIUMP;
		out->selftest = "fell-back";
	} else {
		snprintf(err, errlen, "this GL keeps no shadow depth: the 24-bit path fails (%s) and the 11-bit one too (%s)",
			 why, why11);
		return false;
	}
	static const char *const path[] = {"", "highp24", "mediump11", "highp24-texture"};
	out->path = path[out->taken];
	return true;
}
