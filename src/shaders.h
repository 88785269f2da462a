/* Shader files of shaders_es/, built into the binary, and the program builder.
 * The loader inserts "#define" lines after the file's "#version 100" line and
 * replaces each "//!include NAME" line with that file's text. */
#ifndef LX_SHADERS_H
#define LX_SHADERS_H
#include <stdbool.h>
#include <stddef.h>

struct lx_shader_file {
	const char *name;
	const char *text;
};

extern const struct lx_shader_file lx_shader_files[]; /* ends with {0, 0} */

const char *lx_shader_text(const char *name);

#endif
