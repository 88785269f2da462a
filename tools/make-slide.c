/* Draws lixel's own slide for the projector scene (tests/data/slide.png, built into the
 * binary): colour bars, a grid, a ring and the word "lixel", each easy to recognise when
 * the casters cut it. Run by `make slide`; the PNG is kept in the repository.
 * Usage: make-slide OUT.png */
#include "font5x7.h"
#include "png_out.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

enum { W = 256, H = 192 };

static void put(uint8_t *im, int x, int y, double r, double g, double b)
{
	if (x < 0 || y < 0 || x >= W || y >= H)
		return;
	uint8_t *p = im + ((size_t)(H - 1 - y) * W + x) * 4; /* y from the top; rows stored bottom up */
	p[0] = (uint8_t)lround(255 * r), p[1] = (uint8_t)lround(255 * g), p[2] = (uint8_t)lround(255 * b), p[3] = 255;
}

static void text(uint8_t *im, const char *s, int x0, int y0, int scale)
{
	for (int i = 0; s[i]; i++) {
		const uint8_t *g = lx_font5x7(s[i]);
		for (int row = 0; g && row < 7; row++)
			for (int col = 0; col < 5; col++)
				if (g[row] & (16 >> col))
					for (int dy = 0; dy < scale; dy++)
						for (int dx = 0; dx < scale; dx++)
							put(im, x0 + (i * 6 + col) * scale + dx, y0 + row * scale + dy, 1, 1, 1);
	}
}

int main(int argc, char **argv)
{
	if (argc != 2) {
		fprintf(stderr, "usage: make-slide OUT.png\n");
		return 2;
	}
	static uint8_t im[W * H * 4];
	static const double bars[6][3] = {{1, 0.2, 0.2}, {1, 0.8, 0.1}, {0.2, 0.9, 0.3},
					  {0.1, 0.8, 1}, {0.3, 0.3, 1}, {0.9, 0.3, 0.9}};
	for (int y = 0; y < H; y++)
		for (int x = 0; x < W; x++) {
			const double *c = bars[x * 6 / W];
			double shade = 0.35 + 0.65 * (1 - (double)y / H); /* brighter at the top */
			bool grid = x % 32 == 0 || y % 32 == 0;
			double rr = hypot(x - W / 2.0, y - H / 2.0);
			bool ring = fabs(rr - 70) < 3;
			double k = grid || ring ? 1 : shade;
			put(im, x, y, grid || ring ? 1 : c[0] * k, grid || ring ? 1 : c[1] * k, grid || ring ? 1 : c[2] * k);
		}
	text(im, "lixel", W / 2 - 5 * 6 * 6 / 2, H / 2 - 7 * 6 / 2, 6);
	char err[256];
	if (!lx_png_write(argv[1], im, W, H, err, sizeof err)) {
		fprintf(stderr, "make-slide: %s\n", err);
		return 1;
	}
	return 0;
}
