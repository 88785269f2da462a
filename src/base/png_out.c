#include "png_out.h"
#include "out_file.h"
#include <errno.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static bool write_file(FILE *f, const uint8_t *rgba, int width, int height)
{
	png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
	if (!png)
		return false;
	png_infop info = png_create_info_struct(png);
	if (!info || setjmp(png_jmpbuf(png))) {
		png_destroy_write_struct(&png, &info);
		return false;
	}
	png_init_io(png, f);
	png_set_IHDR(png, info, (png_uint_32)width, (png_uint_32)height, 8, PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE,
		     PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
	png_write_info(png, info);
	for (int y = height - 1; y >= 0; y--)
		png_write_row(png, (png_const_bytep)(rgba + (size_t)y * width * 4));
	png_write_end(png, NULL);
	png_destroy_write_struct(&png, &info);
	return true;
}

struct image {
	const uint8_t *rgba;
	int width, height;
};

static bool write_image(FILE *f, void *ctx)
{
	const struct image *im = ctx;
	return write_file(f, im->rgba, im->width, im->height);
}

bool lx_png_write(const char *path, const uint8_t *rgba, int width, int height, char *err, size_t errlen)
{
	struct image im = {rgba, width, height};
	return lx_out_write(path, write_image, &im, err, errlen);
}
