/* OSMesa: Mesa's off-screen software GL, the desktop test build. It gives a desktop
 * GL compatibility context that compiles #version 100 shaders with ES rules; lixel
 * uses it strictly as ES 2.0 (no VAOs, no desktop-only calls). A core profile would
 * require a VAO, so the default (compatibility) profile is requested. */
#include "platform.h"
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>

struct osmesa {
	struct lx_platform base;
	OSMesaContext ctx;
	unsigned char pixel[4]; /* the 1x1 window buffer; lixel draws into its own FBOs */
};

static void *osmesa_get_proc(const char *name) { return (void *)OSMesaGetProcAddress(name); }

static void osmesa_destroy(struct lx_platform *p)
{
	struct osmesa *o = (struct osmesa *)p;
	OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
	OSMesaDestroyContext(o->ctx);
	free(o);
}

struct lx_platform *lx_platform_osmesa_create(char *err, size_t errlen)
{
	struct osmesa *o = calloc(1, sizeof(*o));
	if (!o) {
		snprintf(err, errlen, "osmesa: out of memory");
		return NULL;
	}
	o->ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
	if (!o->ctx) {
		snprintf(err, errlen, "osmesa: OSMesaCreateContextExt failed");
		free(o);
		return NULL;
	}
	if (!OSMesaMakeCurrent(o->ctx, o->pixel, GL_UNSIGNED_BYTE, 1, 1)) {
		snprintf(err, errlen, "osmesa: OSMesaMakeCurrent failed");
		OSMesaDestroyContext(o->ctx);
		free(o);
		return NULL;
	}
	o->base = (struct lx_platform){.name = "osmesa", .get_proc = osmesa_get_proc, .destroy = osmesa_destroy};
	return &o->base;
}
