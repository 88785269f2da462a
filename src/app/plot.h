/* A small raster plot for `lixel bench --plot`: marks on a linear x axis and a
 * logarithmic y axis (values <= 0 sit on its floor), tick labels and a legend, drawn with a built-in 5x7 font, written as PNG. GL-free. */
#ifndef LX_PLOT_H
#define LX_PLOT_H
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

struct lx_plot_point {
	double x, y;
	const char *label;
	uint8_t rgb[3];
};

bool lx_plot_scatter(const char *path, const char *title, const char *xlabel, const char *ylabel,
		     const struct lx_plot_point *pts, int n, char *err, size_t errlen);
/* Distinct colours for up to 8 series. */
void lx_plot_color(int i, uint8_t rgb[3]);

#endif
