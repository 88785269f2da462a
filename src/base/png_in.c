#include "png_in.h"
#include <errno.h>
#include <limits.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static unsigned long be32(const unsigned char *b) { return (unsigned long)b[0] << 24 | b[1] << 16 | b[2] << 8 | b[3]; }

bool lx_png_header(const char *path, bool *is_png, int *width, int *height)
{
	FILE *f = fopen(path, "rb");
	if (!f)
		return false;
	unsigned char sig[24]; /* signature, IHDR's length and type, width, height */
	size_t n = fread(sig, 1, sizeof sig, f);
	int saved = errno;
	bool read_error = ferror(f);
	fclose(f);
	if (read_error) {
		errno = saved;
		return false;
	}
	*is_png = n == sizeof sig && png_sig_cmp(sig, 0, 8) == 0 && !memcmp(sig + 12, "IHDR", 4);
	unsigned long w = *is_png ? be32(sig + 16) : 0, h = *is_png ? be32(sig + 20) : 0;
	*width = w > INT_MAX ? INT_MAX : (int)w; /* a PNG's sides are below 2^31 */
	*height = h > INT_MAX ? INT_MAX : (int)h;
	return true;
}

/* The rest of a read begun by png_image_begin_read_*: the size checked, then the pixels. */
static bool finish(png_image *im, struct lx_image *out, char *err, size_t errlen)
{
	memset(out, 0, sizeof *out);
	if (im->width < 1 || im->height < 1 || im->width > LX_PNG_IN_MAX_SIDE || im->height > LX_PNG_IN_MAX_SIDE) {
		snprintf(err, errlen, "a %ux%u image, expected sides from 1 to %d", im->width, im->height,
			 LX_PNG_IN_MAX_SIDE);
		png_image_free(im);
		return false;
	}
	im->format = PNG_FORMAT_RGBA;
	size_t bytes = PNG_IMAGE_SIZE(*im); /* at most 2048 * 2048 * 4 */
	out->rgba = malloc(bytes);
	if (!out->rgba) {
		snprintf(err, errlen, "out of memory for a %ux%u image", im->width, im->height);
		png_image_free(im);
		return false;
	}
	if (!png_image_finish_read(im, NULL, out->rgba, 0, NULL)) {
		snprintf(err, errlen, "not a readable PNG (%s)", im->message);
		lx_image_free(out);
		png_image_free(im);
		return false;
	}
	out->width = (int)im->width;
	out->height = (int)im->height;
	return true;
}

bool lx_png_read(const char *path, struct lx_image *out, char *err, size_t errlen)
{
	bool is_png = false;
	int w, h;
	memset(out, 0, sizeof *out);
	if (!lx_png_header(path, &is_png, &w, &h)) {
		snprintf(err, errlen, "cannot read it (%s)", strerror(errno));
		return false;
	}
	if (!is_png) {
		snprintf(err, errlen, "not a PNG file");
		return false;
	}
	png_image im;
	memset(&im, 0, sizeof im);
	im.version = PNG_IMAGE_VERSION;
	if (!png_image_begin_read_from_file(&im, path)) {
		snprintf(err, errlen, "not a readable PNG (%s)", im.message);
		png_image_free(&im);
		return false;
	}
	return finish(&im, out, err, errlen);
}

bool lx_png_read_memory(const void *data, size_t size, struct lx_image *out, char *err, size_t errlen)
{
	png_image im;
	memset(&im, 0, sizeof im);
	memset(out, 0, sizeof *out);
	im.version = PNG_IMAGE_VERSION;
	if (!png_image_begin_read_from_memory(&im, data, size)) {
		snprintf(err, errlen, "not a readable PNG (%s)", im.message);
		png_image_free(&im);
		return false;
	}
	return finish(&im, out, err, errlen);
}

void lx_image_free(struct lx_image *im)
{
	free(im->rgba);
	im->rgba = NULL;
	im->width = im->height = 0;
}
