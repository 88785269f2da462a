#include "plot.h"
#include "font5x7.h"
#include "png_out.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct canvas {
	int w, h;
	uint8_t *px; /* rows bottom to top, as lx_png_write wants */
};

static void dot(struct canvas *c, int x, int y, const uint8_t rgb[3])
{
	if (x < 0 || y < 0 || x >= c->w || y >= c->h)
		return;
	uint8_t *p = c->px + ((size_t)y * c->w + x) * 4;
	p[0] = rgb[0], p[1] = rgb[1], p[2] = rgb[2], p[3] = 255;
}

static void rect(struct canvas *c, int x0, int y0, int x1, int y1, const uint8_t rgb[3])
{
	for (int y = y0; y <= y1; y++)
		for (int x = x0; x <= x1; x++)
			dot(c, x, y, rgb);
}

/* Text with its lower-left corner at (x, y), each font pixel `scale` pixels. */
static int text(struct canvas *c, int x, int y, const char *s, int scale, const uint8_t rgb[3])
{
	for (; *s; s++, x += 6 * scale) {
		const uint8_t *rows = lx_font5x7(*s);
		for (int r = 0; rows && r < 7; r++)
			for (int b = 0; b < 5; b++)
				if (rows[r] & (16 >> b))
					rect(c, x + b * scale, y + (6 - r) * scale, x + b * scale + scale - 1,
					     y + (6 - r) * scale + scale - 1, rgb);
	}
	return x;
}

void lx_plot_color(int i, uint8_t rgb[3])
{
	/* as many colours as the bench takes methods (12) */
	static const uint8_t pal[12][3] = {{90, 90, 90},    {31, 119, 180}, {214, 39, 40},  {44, 160, 44},
					   {255, 127, 14},  {148, 103, 189}, {23, 190, 207}, {140, 86, 75},
					   {227, 119, 194}, {188, 189, 34},  {0, 0, 0},      {174, 199, 232}};
	memcpy(rgb, pal[((i % 12) + 12) % 12], 3);
}

/* A "nice" tick step for a range. */
static double tick_step(double range)
{
	double raw = range / 5, mag = pow(10, floor(log10(raw))), f = raw / mag;
	return (f < 1.5 ? 1 : f < 3.5 ? 2 : f < 7.5 ? 5 : 10) * mag;
}

bool lx_plot_scatter(const char *path, const char *title, const char *xlabel, const char *ylabel,
		     const struct lx_plot_point *pts, int n, char *err, size_t errlen)
{
	struct canvas c = {.w = 900, .h = 560};
	c.px = malloc((size_t)c.w * c.h * 4);
	if (!c.px) {
		snprintf(err, errlen, "%s: out of memory", path);
		return false;
	}
	memset(c.px, 255, (size_t)c.w * c.h * 4);
	const uint8_t black[3] = {0, 0, 0}, grey[3] = {215, 215, 215};
	int x0 = 90, y0 = 70, x1 = 640, y1 = 500; /* the plot area */
	/* x linear from 0; y logarithmic (errors span decades), values below the floor drawn on it */
	double xmax = 0, ymax = 0, ymin = INFINITY;
	for (int i = 0; i < n; i++) {
		if (isfinite(pts[i].x))
			xmax = fmax(xmax, pts[i].x);
		if (isfinite(pts[i].y) && pts[i].y > 0)
			ymax = fmax(ymax, pts[i].y), ymin = fmin(ymin, pts[i].y);
	}
	xmax = xmax > 0 ? xmax * 1.1 : 1;
	double d0 = isfinite(ymin) ? floor(log10(ymin)) : -3, d1 = ymax > 0 ? ceil(log10(ymax)) : 0;
	if (d1 <= d0)
		d1 = d0 + 1;
	double xs = tick_step(xmax);
	char buf[64];
	for (double v = 0; v <= xmax + 1e-12; v += xs) {
		int px = x0 + (int)((x1 - x0) * v / xmax);
		rect(&c, px, y0, px, y1, grey);
		snprintf(buf, sizeof buf, "%g", v);
		text(&c, px - 3 * (int)strlen(buf) * 2, y0 - 22, buf, 2, black);
	}
	for (double d = d0; d <= d1 + 1e-9; d += 1) {
		int py = y0 + (int)((y1 - y0) * (d - d0) / (d1 - d0));
		rect(&c, x0, py, x1, py, grey);
		snprintf(buf, sizeof buf, "%g", pow(10, d));
		text(&c, x0 - 12 - 12 * (int)strlen(buf), py - 7, buf, 2, black);
	}
	rect(&c, x0, y0, x1, y0 + 1, black);
	rect(&c, x0, y0, x0 + 1, y1, black);
	text(&c, x0, 20, xlabel, 2, black);
	text(&c, 10, y1 + 10, ylabel, 2, black);
	text(&c, x0, c.h - 22, title, 2, black);
	for (int i = 0; i < n; i++) {
		if (!isfinite(pts[i].x) || !isfinite(pts[i].y))
			continue; /* left out of the plot, still in the legend below */
		double ly = pts[i].y > 0 ? fmax(log10(pts[i].y), d0) : d0;
		int px = x0 + (int)((x1 - x0) * pts[i].x / xmax), py = y0 + (int)((y1 - y0) * (ly - d0) / (d1 - d0));
		rect(&c, px - 6, py - 6, px + 6, py + 6, pts[i].rgb);
		rect(&c, 670, y1 - 30 * i - 8, 684, y1 - 30 * i + 6, pts[i].rgb);
		text(&c, 694, y1 - 30 * i - 7, pts[i].label, 2, black);
	}
	bool ok = lx_png_write(path, c.px, c.w, c.h, err, errlen);
	free(c.px);
	return ok;
}
