#include "platform.h"
#include "gl_api.h"
#include "gl_program.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char *lx_platform_names(void) { return "osmesa|egl"; }

bool lx_platform_known(const char *name) { return !strcmp(name, "osmesa") || !strcmp(name, "egl"); }

/* Every platform ends the same way: its context current, the GL entry points loaded. */
static struct lx_platform *with_gl(struct lx_platform *p, const char *name, char *err, size_t errlen)
{
	if (!p)
		return NULL;
	const char *missing = NULL;
	if (!lx_gl_load(p->get_proc, &missing)) {
		snprintf(err, errlen, "%s: the GL entry point %s is missing", name, missing);
		p->destroy(p); /* no GL of its own was loaded: no programs to forget */
		return NULL;
	}
	return p;
}

struct lx_platform *lx_platform_create(const char *name, char *err, size_t errlen)
{
	if (!strcmp(name, "osmesa"))
		return with_gl(lx_platform_osmesa_create(err, errlen), name, err, errlen);
	if (!strcmp(name, "egl"))
		return with_gl(lx_platform_egl_surfaceless_create(err, errlen), name, err, errlen);
	snprintf(err, errlen, "unknown platform '%s', expected %s", name, lx_platform_names());
	return NULL;
}

struct lx_platform *lx_platform_create_display(const char *name, int width, int height, const char *device,
					       int mode_w, int mode_h, int mode_hz, char *err, size_t errlen)
{
	if (!strcmp(name, "x11"))
		return with_gl(lx_platform_x11_create(width, height, err, errlen), name, err, errlen);
	if (!strcmp(name, "kms"))
		return with_gl(lx_platform_kms_create(device, mode_w, mode_h, mode_hz, err, errlen), name, err, errlen);
	snprintf(err, errlen, "unknown display platform '%s', expected x11 or kms", name);
	return NULL;
}

void *lx_platform_alloc(size_t size, const char *name, char *err, size_t errlen)
{
	void *p = calloc(1, size);
	if (!p)
		snprintf(err, errlen, "%s: out of memory", name);
	return p;
}

void lx_platform_destroy(struct lx_platform *p)
{
	if (!p)
		return;
	lx_programs_forget(); /* while its context is current */
	p->destroy(p);
}
