/* A GL platform: something that makes an OpenGL ES 2.0 context current and resolves
 * its entry points. The renderer never learns which one it runs on. Headless
 * platforms render into the renderer's own framebuffer objects. */
#ifndef LX_PLATFORM_H
#define LX_PLATFORM_H
#include <stdbool.h>
#include <stddef.h>

struct lx_platform {
	const char *name;
	void *(*get_proc)(const char *name);
	void (*destroy)(struct lx_platform *p);
	void *priv;
	/* Windowed platforms (x11): the window's size, presenting a frame drawn into the
	 * default framebuffer, and the next key pressed (0 when none; ' ', 'l', 'q', 27 for
	 * Escape, -1 when the window was closed). NULL on headless platforms. */
	int width, height;
	void (*swap)(struct lx_platform *p);
	int (*poll_key)(struct lx_platform *p);
};

/* Creates and makes current a context on the named platform ("osmesa" or "egl");
 * NULL with a one-line reason in err. On success the GL entry points are loaded. */
struct lx_platform *lx_platform_create(const char *name, char *err, size_t errlen);
void lx_platform_destroy(struct lx_platform *p);
const char *lx_platform_names(void);

/* A window of the given size ("x11": EGL on an X11 window, DISPLAY from the environment). */
struct lx_platform *lx_platform_create_window(const char *name, int width, int height, char *err, size_t errlen);

struct lx_platform *lx_platform_osmesa_create(char *err, size_t errlen);
struct lx_platform *lx_platform_x11_create(int width, int height, char *err, size_t errlen);
struct lx_platform *lx_platform_egl_surfaceless_create(char *err, size_t errlen);

#endif
