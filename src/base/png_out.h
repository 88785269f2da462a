/* Writing RGBA images as PNG through libpng. */
#ifndef LX_PNG_OUT_H
#define LX_PNG_OUT_H
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* Writes rows given bottom to top (as GL reads them) as a top-down PNG, as out_file.h
 * writes files: a fresh temporary beside it, renamed into place, nothing left behind on
 * a failure, never over anything but a regular file. */
bool lx_png_write(const char *path, const uint8_t *rgba, int width, int height, char *err, size_t errlen);

#endif
