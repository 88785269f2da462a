/* Reading PNG images (a projector's slide, a spotlight's beam) through libpng. */
#ifndef LX_PNG_IN_H
#define LX_PNG_IN_H
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* The largest side taken: a slide is a texture, and ES 2.0 boards stop at 2048. */
#define LX_PNG_IN_MAX_SIDE 2048

/* An RGBA8 image, rows top to bottom as the PNG stores them. */
struct lx_image {
	int width, height;
	uint8_t *rgba; /* malloc'd; free with lx_image_free */
};

/* Whether the file at path starts like a PNG (signature, then the IHDR chunk), and its
 * size from that header: a cheap check for the scene parser. False with errno set when
 * the file cannot be read. */
bool lx_png_header(const char *path, bool *is_png, int *width, int *height);
/* Any PNG (grey, palette, RGB, with or without alpha, 8 or 16 bits) as RGBA8; from a
 * file or from memory. False with one line in err ("not a PNG", "sides over 2048", ...). */
bool lx_png_read(const char *path, struct lx_image *out, char *err, size_t errlen);
bool lx_png_read_memory(const void *data, size_t size, struct lx_image *out, char *err, size_t errlen);
void lx_image_free(struct lx_image *im);

#endif
