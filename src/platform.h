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
};

/* Creates and makes current a context on the named platform ("osmesa" or "egl");
 * NULL with a one-line reason in err. On success the GL entry points are loaded. */
struct lx_platform *lx_platform_create(const char *name, char *err, size_t errlen);
void lx_platform_destroy(struct lx_platform *p);
const char *lx_platform_names(void);

struct lx_platform *lx_platform_osmesa_create(char *err, size_t errlen);
struct lx_platform *lx_platform_egl_surfaceless_create(char *err, size_t errlen);

#endif
