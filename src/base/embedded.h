/* Files built into the binary by tools/embed-files.sh (shaders, board profiles), so
 * lixel runs from any directory. Each array ends with {0, 0}. */
#ifndef LX_EMBEDDED_H
#define LX_EMBEDDED_H
#include <stddef.h>

struct lx_embedded_file {
	const char *name; /* the file's base name */
	const char *text;
};

extern const struct lx_embedded_file lx_shader_files[];
extern const struct lx_embedded_file lx_board_files[];

/* lixel's own slide (tests/data/slide.png, made by tools/make-slide.c), as PNG bytes. */
extern const unsigned char lx_builtin_slide_png[];
extern const size_t lx_builtin_slide_png_size;

/* The text of the named file in an array, or NULL. */
const char *lx_embedded_text(const struct lx_embedded_file *files, const char *name);

#endif
