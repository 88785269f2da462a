/* The kiosk's overlay: a few lines of text (the method, the frame rate, the planes'
 * sampling figures) on a dark box at the top left, drawn over the frame with the
 * built-in 5x7 font. */
#ifndef LX_OVERLAY_H
#define LX_OVERLAY_H
#include <stddef.h>

struct lx_overlay;

struct lx_overlay *lx_overlay_create(char *err, size_t errlen);
void lx_overlay_destroy(struct lx_overlay *o);
/* Lays out and uploads the text (each font pixel `scale` pixels). Every call uploads:
 * the kiosk calls it once a second, not per frame. */
void lx_overlay_set_text(struct lx_overlay *o, const char *const *lines, int n, int scale);
/* Draws the text last set into the bound framebuffer of width x height. */
void lx_overlay_draw(struct lx_overlay *o, int width, int height);

#endif
