/* OSMesa: Mesa's off-screen software GL, the desktop test build. It gives a desktop
 * GL compatibility context that compiles #version 100 shaders with ES rules; lixel
 * uses it strictly as ES 2.0 (no VAOs, no desktop-only calls). A core profile would
 * require a VAO, so the default (compatibility) profile is requested.
 *
 * libOSMesa is opened when this platform is first asked for, not linked: it carries
 * llvmpipe and LLVM, whose loading made every start of lixel (a --help, a bad option, the
 * kiosk on EGL) pay about 0.1 s, and Mesa dropped OSMesa in 25.1, so a board's Mesa may
 * not have it at all; then only this platform is missing. */
#include "platform.h"
#include <GL/osmesa.h>
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>

#define OSMESA_LIBRARY "libOSMesa.so.8"

/* The four entry points lixel uses, from the library opened once. */
static struct {
	void *lib;
	OSMesaContext (*create)(GLenum, GLint, GLint, GLint, OSMesaContext);
	GLboolean (*make_current)(OSMesaContext, void *, GLenum, GLsizei, GLsizei);
	void (*destroy)(OSMesaContext);
	OSMESAproc (*get_proc)(const char *);
} osm;

static bool osmesa_open(char *err, size_t errlen)
{
	if (osm.lib)
		return true;
	void *lib = dlopen(OSMESA_LIBRARY, RTLD_NOW | RTLD_LOCAL);
	if (!lib) {
		snprintf(err, errlen, "osmesa: cannot open %s (%s); the egl platform may work", OSMESA_LIBRARY, dlerror());
		return false;
	}
	/* POSIX's way from an object pointer to a function pointer */
	*(void **)&osm.create = dlsym(lib, "OSMesaCreateContextExt");
	*(void **)&osm.make_current = dlsym(lib, "OSMesaMakeCurrent");
	*(void **)&osm.destroy = dlsym(lib, "OSMesaDestroyContext");
	*(void **)&osm.get_proc = dlsym(lib, "OSMesaGetProcAddress");
	if (!osm.create || !osm.make_current || !osm.destroy || !osm.get_proc) {
		snprintf(err, errlen, "osmesa: %s lacks the OSMesa entry points", OSMESA_LIBRARY);
		dlclose(lib);
		osm.create = NULL, osm.make_current = NULL, osm.destroy = NULL, osm.get_proc = NULL;
		return false;
	}
	osm.lib = lib; /* kept open: unloading Mesa's drivers before exit is not safe */
	return true;
}

struct osmesa {
	struct lx_platform base;
	OSMesaContext ctx;
	unsigned char pixel[4]; /* the 1x1 window buffer; lixel draws into its own FBOs */
};

static void *osmesa_get_proc(const char *name) { return (void *)osm.get_proc(name); }

static void osmesa_destroy(struct lx_platform *p)
{
	struct osmesa *o = (struct osmesa *)p;
	osm.make_current(NULL, NULL, 0, 0, 0);
	osm.destroy(o->ctx);
	free(o);
}

struct lx_platform *lx_platform_osmesa_create(char *err, size_t errlen)
{
	if (!osmesa_open(err, errlen))
		return NULL;
	struct osmesa *o = lx_platform_alloc(sizeof(*o), "osmesa", err, errlen);
	if (!o)
		return NULL;
	o->ctx = osm.create(OSMESA_RGBA, 0, 0, 0, NULL);
	if (!o->ctx) {
		snprintf(err, errlen, "osmesa: OSMesaCreateContextExt failed");
		free(o);
		return NULL;
	}
	if (!osm.make_current(o->ctx, o->pixel, GL_UNSIGNED_BYTE, 1, 1)) {
		snprintf(err, errlen, "osmesa: OSMesaMakeCurrent failed");
		osm.destroy(o->ctx);
		free(o);
		return NULL;
	}
	o->base = (struct lx_platform){.name = "osmesa", .get_proc = osmesa_get_proc, .destroy = osmesa_destroy};
	return &o->base;
}
