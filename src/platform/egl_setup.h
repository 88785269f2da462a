/* The EGL steps every platform takes (surfaceless, X11, GBM): the platform display,
 * initialised; an OpenGL ES 2.0 context on a config; EGL's error names. */
#ifndef LX_EGL_SETUP_H
#define LX_EGL_SETUP_H
#include <EGL/egl.h>
#include <EGL/eglext.h>

/* The display of an EGL platform (EGL_PLATFORM_*) on a native display, initialised;
 * EGL_NO_DISPLAY when the platform or the initialisation fails. */
EGLDisplay lx_egl_display(EGLenum platform, void *native);
/* An OpenGL ES 2.0 context on cfg (the ES API bound first), or EGL_NO_CONTEXT. */
EGLContext lx_egl_context(EGLDisplay dpy, EGLConfig cfg);
/* The config attributes of an RGB8 OpenGL ES 2.0 config for a surface type, with a
 * 16-bit depth buffer when depth is set (the window surfaces draw into it directly). */
#define LX_EGL_CONFIG(surface_type, depth)                                                                      \
	{EGL_SURFACE_TYPE, surface_type, EGL_RENDERABLE_TYPE, EGL_OPENGL_ES2_BIT, EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, \
	 EGL_BLUE_SIZE, 8, EGL_DEPTH_SIZE, (depth) ? 16 : 0, EGL_NONE}
const char *lx_egl_error_name(EGLint e);
/* The end of every platform's EGL: nothing current, the context and the surface destroyed
 * where there are, the display terminated, this thread's EGL state released. Nothing on
 * EGL_NO_DISPLAY. */
void lx_egl_release(EGLDisplay dpy, EGLContext ctx, EGLSurface surface);

#endif
