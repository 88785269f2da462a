#include "overlay.h"
#include "font5x7.h"
#include "gl_api.h"
#include "gl_program.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FIRST 32
#define GLYPHS 95 /* printable ASCII */
#define MAX_CHARS 512

struct lx_overlay {
	GLuint prog, tex, vbo;
	GLint window, font;
	GLsizei count; /* vertices uploaded */
	float verts[(MAX_CHARS + 1) * 6 * 4];
};

struct lx_overlay *lx_overlay_create(char *err, size_t errlen)
{
	struct lx_overlay *o = calloc(1, sizeof(*o));
	if (!o) {
		snprintf(err, errlen, "overlay: out of memory");
		return NULL;
	}
	o->prog = lx_program_build("overlay.vert", "overlay.frag", NULL, err, errlen);
	if (!o->prog) {
		free(o);
		return NULL;
	}
	o->window = lx_gl.GetUniformLocation(o->prog, "u_window");
	o->font = lx_gl.GetUniformLocation(o->prog, "u_font");
	/* the font: a 6x8 cell per glyph, coverage 255 where the glyph has a pixel */
	unsigned char texels[8][GLYPHS * 6];
	memset(texels, 0, sizeof texels);
	for (int g = 0; g < GLYPHS; g++) {
		const uint8_t *rows = lx_font5x7((char)(FIRST + g));
		for (int r = 0; rows && r < 7; r++)
			for (int b = 0; b < 5; b++)
				if (rows[r] & (16 >> b))
					texels[r][g * 6 + b] = 255;
	}
	lx_gl.GenTextures(1, &o->tex);
	lx_gl.BindTexture(GL_TEXTURE_2D, o->tex);
	lx_gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
	lx_gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
	lx_gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
	lx_gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
	lx_gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
	lx_gl.TexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, GLYPHS * 6, 8, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, texels);
	lx_gl.GenBuffers(1, &o->vbo);
	return o;
}

void lx_overlay_destroy(struct lx_overlay *o)
{
	if (!o)
		return;
	lx_gl.DeleteTextures(1, &o->tex); /* the program is the context's (lx_program_build) */
	lx_gl.DeleteBuffers(1, &o->vbo);
	free(o);
}

static float *quad(float *v, float x0, float y0, float x1, float y1, float u0, float v0, float u1, float v1)
{
	const float q[6][4] = {{x0, y0, u0, v0}, {x1, y0, u1, v0}, {x1, y1, u1, v1},
			       {x0, y0, u0, v0}, {x1, y1, u1, v1}, {x0, y1, u0, v1}};
	memcpy(v, q, sizeof q);
	return v + 24;
}

void lx_overlay_set_text(struct lx_overlay *o, const char *const *lines, int n, int scale)
{
	float *v = o->verts;
	int longest = 0, chars = 0;
	for (int i = 0; i < n; i++)
		longest = (int)strlen(lines[i]) > longest ? (int)strlen(lines[i]) : longest;
	float pad = 4.0f * scale, cw = 6.0f * scale, ch = 9.0f * scale;
	v = quad(v, 0, 0, 2 * pad + longest * cw, 2 * pad + n * ch, -1, -1, -1, -1); /* the box */
	for (int i = 0; i < n; i++)
		for (const char *c = lines[i]; *c && chars < MAX_CHARS; c++, chars++) {
			int g = *c - FIRST;
			if (g < 0 || g >= GLYPHS)
				g = 0;
			float x = pad + (float)(c - lines[i]) * cw, y = pad + i * ch;
			v = quad(v, x, y, x + cw, y + 8.0f * scale, (float)(g * 6) / (GLYPHS * 6), 0,
				 (float)(g * 6 + 6) / (GLYPHS * 6), 1);
		}
	o->count = (GLsizei)((v - o->verts) / 4);
	lx_gl.BindBuffer(GL_ARRAY_BUFFER, o->vbo);
	lx_gl.BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(o->count * 4 * sizeof(float)), o->verts, GL_DYNAMIC_DRAW);
}

void lx_overlay_draw(struct lx_overlay *o, int width, int height)
{
	if (!o->count)
		return;
	lx_gl.Viewport(0, 0, width, height);
	lx_gl.Disable(GL_DEPTH_TEST);
	lx_gl.Disable(GL_CULL_FACE);
	lx_gl.Enable(GL_BLEND);
	lx_gl.BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
	lx_gl.UseProgram(o->prog);
	lx_gl.Uniform2f(o->window, (float)width, (float)height);
	lx_gl.Uniform1i(o->font, 0);
	lx_gl.ActiveTexture(GL_TEXTURE0);
	lx_gl.BindTexture(GL_TEXTURE_2D, o->tex);
	lx_gl.BindBuffer(GL_ARRAY_BUFFER, o->vbo);
	lx_gl.EnableVertexAttribArray(LX_ATTR_POSITION);
	lx_gl.DisableVertexAttribArray(LX_ATTR_NORMAL);
	lx_gl.DisableVertexAttribArray(LX_ATTR_FACE_NORMAL);
	lx_gl.VertexAttribPointer(LX_ATTR_POSITION, 4, GL_FLOAT, GL_FALSE, 4 * sizeof(float), (const void *)0);
	lx_gl.DrawArrays(GL_TRIANGLES, 0, o->count);
	lx_gl.Disable(GL_BLEND);
}
