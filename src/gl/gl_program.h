/* Compiling and linking GLSL ES programs from the embedded shader files. */
#ifndef LX_GL_PROGRAM_H
#define LX_GL_PROGRAM_H
#include "gl_api.h"
#include "shader_text.h"
#include <stdbool.h>
#include <stddef.h>

/* Attribute locations shared by every program. */
enum { LX_ATTR_POSITION = 0, LX_ATTR_NORMAL = 1, LX_ATTR_FACE_NORMAL = 2 };

/* An RGBA8 texture of w x h, NEAREST (depths must not be blended), CLAMP_TO_EDGE (NPOT
 * in ES 2.0), contents undefined; left bound. */
GLuint lx_texture_rgba8(int w, int h);
/* A depth texture of w x h (GL_OES_depth_texture: DEPTH_COMPONENT, UNSIGNED_INT), NEAREST,
 * CLAMP_TO_EDGE, contents undefined; left bound. A GL without the extension raises an
 * error, which the caller checks. */
GLuint lx_texture_depth(int w, int h);

/* Builds a program from two embedded files with the given "#define" lines (may be
 * NULL). On failure returns 0 and writes "FILE: compile|link error: driver log".
 * The context keeps every program built in it, by its two texts: the same texts again
 * (another renderer, method or self-test of the process) give the same program, and the
 * driver's compiled variants with it. Callers set the uniforms they use before drawing,
 * and never delete a program: lx_programs_forget does, before the context goes. */
GLuint lx_program_build(const char *vert, const char *frag, const char *defines, char *err, size_t errlen);
/* The same from given texts (names are for messages); includes still name embedded files. */
GLuint lx_program_build_text(const char *vert, const char *vert_text, const char *frag, const char *frag_text,
			     const char *defines, char *err, size_t errlen);
/* Deletes the programs the current context keeps (call it while the context is current,
 * before destroying it); programs of a context gone before are only forgotten. */
void lx_programs_forget(void);
/* How many programs the current context keeps, and how many builds it answered with one
 * it had. */
void lx_programs_counts(int *kept, long *reused);

#endif
