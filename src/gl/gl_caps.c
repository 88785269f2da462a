#include "gl_caps.h"
#include "gl_api.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef GL_DEPTH_COMPONENT24_OES
#define GL_DEPTH_COMPONENT24_OES 0x81A6
#endif

static void copy_string(char *dst, size_t n, GLenum e)
{
	const GLubyte *s = lx_gl.GetString(e);
	snprintf(dst, n, "%s", s ? (const char *)s : "unknown");
}

/* Desktop GL contexts (OSMesa) list extensions too, but not always under OES names:
 * depth24 is core in desktop GL and accepted by glRenderbufferStorage, so try it. */
static bool renderbuffer_format_works(GLenum format)
{
	GLuint rb;
	lx_gl.GenRenderbuffers(1, &rb);
	lx_gl.BindRenderbuffer(GL_RENDERBUFFER, rb);
	while (lx_gl.GetError() != GL_NO_ERROR) {
	}
	lx_gl.RenderbufferStorage(GL_RENDERBUFFER, format, 4, 4);
	bool ok = lx_gl.GetError() == GL_NO_ERROR;
	lx_gl.BindRenderbuffer(GL_RENDERBUFFER, 0);
	lx_gl.DeleteRenderbuffers(1, &rb);
	return ok;
}

void lx_gl_caps_probe(struct lx_gl_caps *c)
{
	memset(c, 0, sizeof(*c));
	copy_string(c->vendor, sizeof c->vendor, GL_VENDOR);
	copy_string(c->renderer, sizeof c->renderer, GL_RENDERER);
	copy_string(c->version, sizeof c->version, GL_VERSION);
	lx_gl.GetIntegerv(GL_MAX_TEXTURE_SIZE, &c->max_texture_size);
	lx_gl.GetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &c->max_renderbuffer_size);
	lx_gl.GetIntegerv(GL_MAX_VIEWPORT_DIMS, c->max_viewport);
	const char *ext = (const char *)lx_gl.GetString(GL_EXTENSIONS);
	c->depth_texture = ext && (strstr(ext, "GL_OES_depth_texture") || strstr(ext, "GL_ARB_depth_texture"));
	c->depth24 = (ext && strstr(ext, "GL_OES_depth24")) || renderbuffer_format_works(GL_DEPTH_COMPONENT24_OES);
	while (lx_gl.GetError() != GL_NO_ERROR) {
	}
	lx_gl.GetIntegerv(GL_MAX_VARYING_VECTORS, &c->max_varying_vectors);
	if (lx_gl.GetError() != GL_NO_ERROR || c->max_varying_vectors <= 0) { /* a desktop context without it */
		GLint floats = 0;
		lx_gl.GetIntegerv(0x8B4B /* GL_MAX_VARYING_FLOATS */, &floats);
		c->max_varying_vectors = floats / 4;
	}
	const char *cap = getenv("LIXEL_MAX_VARYINGS"); /* a test hook: a smaller GPU's limit */
	int fewer = cap ? atoi(cap) : 0;
	if (fewer > 0 && (c->max_varying_vectors <= 0 || fewer < c->max_varying_vectors))
		c->max_varying_vectors = fewer;
	GLint range[2] = {0, 0}, precision = 0;
	lx_gl.GetShaderPrecisionFormat(GL_FRAGMENT_SHADER, GL_HIGH_FLOAT, range, &precision);
	c->fragment_highp = precision > 0;
	c->fragment_highp_bits = precision;
	lx_gl.GetShaderPrecisionFormat(GL_FRAGMENT_SHADER, GL_MEDIUM_FLOAT, range, &precision);
	c->fragment_mediump_bits = precision;
	static const char *const tilers[] = {"Mali", "VideoCore", "V3D", "VC4", "Vivante", "GC2000", "GC3000", "GC7000",
					     "Adreno", "PowerVR", "Immortalis"};
	for (size_t i = 0; i < sizeof tilers / sizeof tilers[0]; i++)
		c->tiler |= strstr(c->renderer, tilers[i]) != NULL;
	while (lx_gl.GetError() != GL_NO_ERROR) {
	}
}
