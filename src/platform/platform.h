/* A GL platform: something that makes an OpenGL ES 2.0 context current and resolves
 * its entry points. The renderer never learns which one it runs on. Headless
 * platforms render into the renderer's own framebuffer objects. */
#ifndef LX_PLATFORM_H
#define LX_PLATFORM_H
#include "display_loss.h"
#include <stdbool.h>
#include <stddef.h>

struct lx_platform {
	const char *name;
	void *(*get_proc)(const char *name);
	void (*destroy)(struct lx_platform *p);
	void *priv;
	/* Windowed platforms (x11): the window's size, presenting a frame drawn into the
	 * default framebuffer, and the next key pressed (0 when none; ' ', 'l', 'q', 27 for
	 * Escape). NULL on headless platforms. */
	int width, height;
	void (*swap)(struct lx_platform *p);
	int (*poll_key)(struct lx_platform *p);
	/* Set by swap and poll_key when the window or the display went away (see
	 * display_loss.h), with one line in why saying what happened; then the caller stops
	 * drawing and destroys the platform, which frees all it holds without touching what is
	 * gone. */
	enum lx_display_state state;
	char why[256];
};

/* Creates and makes current a context on the named platform ("osmesa" or "egl");
 * NULL with a one-line reason in err. On success the GL entry points are loaded. */
struct lx_platform *lx_platform_create(const char *name, char *err, size_t errlen);
void lx_platform_destroy(struct lx_platform *p);
const char *lx_platform_names(void);
/* Whether lx_platform_create knows the name (the commands check it before any GL). */
bool lx_platform_known(const char *name);

/* A display platform: "x11" (EGL on an X11 window of width x height, DISPLAY from the
 * environment) or "kms" (full screen on device, NULL for the first that can mode-set, in
 * mode_w x mode_h @ mode_hz, 0 for the preferred mode). GL entry points loaded. */
struct lx_platform *lx_platform_create_display(const char *name, int width, int height, const char *device,
					       int mode_w, int mode_h, int mode_hz, char *err, size_t errlen);

struct lx_platform *lx_platform_osmesa_create(char *err, size_t errlen);
/* The platforms' own struct of size bytes, zeroed; NULL with "name: out of memory". */
void *lx_platform_alloc(size_t size, const char *name, char *err, size_t errlen);
struct lx_platform *lx_platform_x11_create(int width, int height, char *err, size_t errlen);
/* Full screen through DRM/KMS and GBM: device NULL for the first that can mode-set,
 * want_w = 0 for the preferred mode. */
struct lx_platform *lx_platform_kms_create(const char *device, int want_w, int want_h, int want_hz, char *err,
					   size_t errlen);
struct lx_platform *lx_platform_egl_surfaceless_create(char *err, size_t errlen);

#endif
