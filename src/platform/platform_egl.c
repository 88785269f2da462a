/* EGL with a real OpenGL ES 2.0 context and no display: Mesa's surfaceless platform,
 * rendering into framebuffer objects (desktop tests, CI); and the EGL steps the display
 * platforms (platform_kms.c on GBM, platform_x11.c) share with it (egl_setup.h). */
#include "egl_setup.h"
#include "platform.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct egl {
	struct lx_platform base;
	EGLDisplay dpy;
	EGLContext ctx;
};

static void *egl_get_proc(const char *name) { return (void *)eglGetProcAddress(name); }

static void egl_destroy(struct lx_platform *p)
{
	struct egl *e = (struct egl *)p;
	lx_egl_release(e->dpy, e->ctx, EGL_NO_SURFACE);
	free(e);
}


struct lx_platform *lx_platform_egl_surfaceless_create(char *err, size_t errlen)
{
	const char *exts = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
	if (!exts || !strstr(exts, "EGL_MESA_platform_surfaceless")) {
		snprintf(err, errlen, "egl: EGL_MESA_platform_surfaceless is not available (is Mesa's libegl-mesa0 installed?)");
		return NULL;
	}
	struct egl *e = lx_platform_alloc(sizeof(*e), "egl", err, errlen);
	if (!e)
		return NULL;
	e->ctx = EGL_NO_CONTEXT;
	e->dpy = lx_egl_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY);
	if (e->dpy == EGL_NO_DISPLAY) {
		snprintf(err, errlen, "egl: cannot initialise the surfaceless display: %s", lx_egl_error_name(eglGetError()));
		free(e);
		return NULL;
	}
	/* No surface is ever made: draw into FBOs. PBUFFER keeps Mesa from filtering out
	 * every config, as a SURFACE_TYPE of 0 does on some versions. */
	const EGLint attrs[] = LX_EGL_CONFIG(EGL_PBUFFER_BIT, 0);
	EGLConfig cfg;
	EGLint n = 0;
	if (!eglChooseConfig(e->dpy, attrs, &cfg, 1, &n) || n < 1) {
		snprintf(err, errlen, "egl: no config with OpenGL ES 2.0 and RGB8");
		egl_destroy(&e->base);
		return NULL;
	}
	if ((e->ctx = lx_egl_context(e->dpy, cfg)) == EGL_NO_CONTEXT) {
		snprintf(err, errlen, "egl: cannot create an OpenGL ES 2.0 context: %s", lx_egl_error_name(eglGetError()));
		egl_destroy(&e->base);
		return NULL;
	}
	if (!eglMakeCurrent(e->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, e->ctx)) {
		snprintf(err, errlen, "egl: cannot make the context current without a surface: %s",
			 lx_egl_error_name(eglGetError()));
		egl_destroy(&e->base);
		return NULL;
	}
	e->base = (struct lx_platform){.name = "egl", .get_proc = egl_get_proc, .destroy = egl_destroy};
	return &e->base;
}

EGLDisplay lx_egl_display(EGLenum platform, void *native)
{
	PFNEGLGETPLATFORMDISPLAYEXTPROC get_display =
		(PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
	EGLDisplay dpy = get_display ? get_display(platform, native, NULL) : EGL_NO_DISPLAY;
	EGLint major, minor;
	if (dpy != EGL_NO_DISPLAY && !eglInitialize(dpy, &major, &minor))
		dpy = EGL_NO_DISPLAY;
	return dpy;
}

EGLContext lx_egl_context(EGLDisplay dpy, EGLConfig cfg)
{
	static const EGLint ctx_attrs[] = {EGL_CONTEXT_CLIENT_VERSION, 2, EGL_NONE};
	if (!eglBindAPI(EGL_OPENGL_ES_API))
		return EGL_NO_CONTEXT;
	return eglCreateContext(dpy, cfg, EGL_NO_CONTEXT, ctx_attrs);
}

void lx_egl_release(EGLDisplay dpy, EGLContext ctx, EGLSurface surface)
{
	if (dpy == EGL_NO_DISPLAY)
		return;
	eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
	if (ctx != EGL_NO_CONTEXT)
		eglDestroyContext(dpy, ctx);
	if (surface != EGL_NO_SURFACE)
		eglDestroySurface(dpy, surface);
	eglTerminate(dpy);
	eglReleaseThread();
}

const char *lx_egl_error_name(EGLint e)
{
	switch (e) {
	case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
	case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
	case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
	case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
	case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
	case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
	case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
	case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
	case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
	default: return "EGL error";
	}
}
