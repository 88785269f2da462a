/* EGL with an OpenGL ES 2.0 context on an X11 window: the kiosk's desktop emulation
 * (`lixel kiosk --platform x11`), and the way the tests drive it under Xvfb. */
#include "platform.h"
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <X11/keysym.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct x11 {
	struct lx_platform base;
	Display *dpy;
	Window win;
	Atom wm_delete;
	EGLDisplay edpy;
	EGLSurface surface;
	EGLContext ctx;
};

static void *x11_get_proc(const char *name) { return (void *)eglGetProcAddress(name); }

static void x11_destroy(struct lx_platform *p)
{
	struct x11 *x = (struct x11 *)p;
	if (x->edpy != EGL_NO_DISPLAY) {
		eglMakeCurrent(x->edpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
		if (x->ctx != EGL_NO_CONTEXT)
			eglDestroyContext(x->edpy, x->ctx);
		if (x->surface != EGL_NO_SURFACE)
			eglDestroySurface(x->edpy, x->surface);
		eglTerminate(x->edpy);
	}
	if (x->win)
		XDestroyWindow(x->dpy, x->win);
	if (x->dpy)
		XCloseDisplay(x->dpy);
	free(x);
}

static void x11_swap(struct lx_platform *p)
{
	struct x11 *x = (struct x11 *)p;
	eglSwapBuffers(x->edpy, x->surface);
}

static int x11_poll_key(struct lx_platform *p)
{
	struct x11 *x = (struct x11 *)p;
	while (XPending(x->dpy)) {
		XEvent ev;
		XNextEvent(x->dpy, &ev);
		if (ev.type == ClientMessage && (Atom)ev.xclient.data.l[0] == x->wm_delete)
			return -1;
		if (ev.type != KeyPress)
			continue;
		KeySym sym = XLookupKeysym(&ev.xkey, 0);
		switch (sym) {
		case XK_space: return ' ';
		case XK_l: return 'l';
		case XK_q: return 'q';
		case XK_Escape: return 27;
		default: break;
		}
	}
	return 0;
}

struct lx_platform *lx_platform_x11_create(int width, int height, char *err, size_t errlen)
{
	struct x11 *x = calloc(1, sizeof(*x));
	if (!x) {
		snprintf(err, errlen, "x11: out of memory");
		return NULL;
	}
	x->edpy = EGL_NO_DISPLAY;
	x->surface = EGL_NO_SURFACE;
	x->ctx = EGL_NO_CONTEXT;
	x->dpy = XOpenDisplay(NULL);
	if (!x->dpy) {
		const char *d = getenv("DISPLAY");
		snprintf(err, errlen, "x11: cannot open display '%s'", d ? d : "(DISPLAY is not set)");
		free(x);
		return NULL;
	}
	PFNEGLGETPLATFORMDISPLAYEXTPROC get_display =
		(PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
	x->edpy = get_display ? get_display(EGL_PLATFORM_X11_KHR, x->dpy, NULL) : EGL_NO_DISPLAY;
	EGLint major, minor, n = 0;
	EGLConfig cfg;
	const EGLint attrs[] = {EGL_SURFACE_TYPE, EGL_WINDOW_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_ES2_BIT, EGL_RED_SIZE, 8,
				EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_DEPTH_SIZE, 16, EGL_NONE};
	if (x->edpy == EGL_NO_DISPLAY || !eglInitialize(x->edpy, &major, &minor) ||
	    !eglChooseConfig(x->edpy, attrs, &cfg, 1, &n) || n < 1) {
		snprintf(err, errlen, "x11: no EGL config with OpenGL ES 2.0 and a window on this display");
		x11_destroy(&x->base);
		return NULL;
	}
	EGLint visual_id;
	eglGetConfigAttrib(x->edpy, cfg, EGL_NATIVE_VISUAL_ID, &visual_id);
	XVisualInfo tmpl = {.visualid = (VisualID)visual_id}, *vi;
	int nv = 0;
	vi = XGetVisualInfo(x->dpy, VisualIDMask, &tmpl, &nv);
	Window root = DefaultRootWindow(x->dpy);
	XSetWindowAttributes wa = {.event_mask = KeyPressMask | StructureNotifyMask,
				   .colormap = XCreateColormap(x->dpy, root, vi ? vi->visual : DefaultVisual(x->dpy, 0), AllocNone)};
	x->win = XCreateWindow(x->dpy, root, 0, 0, (unsigned)width, (unsigned)height, 0,
			       vi ? vi->depth : CopyFromParent, InputOutput, vi ? vi->visual : CopyFromParent,
			       CWEventMask | CWColormap, &wa);
	if (vi)
		XFree(vi);
	XStoreName(x->dpy, x->win, "lixel");
	x->wm_delete = XInternAtom(x->dpy, "WM_DELETE_WINDOW", False);
	XSetWMProtocols(x->dpy, x->win, &x->wm_delete, 1);
	XMapWindow(x->dpy, x->win);
	XFlush(x->dpy);
	const EGLint ctx_attrs[] = {EGL_CONTEXT_CLIENT_VERSION, 2, EGL_NONE};
	eglBindAPI(EGL_OPENGL_ES_API);
	x->surface = eglCreateWindowSurface(x->edpy, cfg, (EGLNativeWindowType)x->win, NULL);
	x->ctx = eglCreateContext(x->edpy, cfg, EGL_NO_CONTEXT, ctx_attrs);
	if (x->surface == EGL_NO_SURFACE || x->ctx == EGL_NO_CONTEXT ||
	    !eglMakeCurrent(x->edpy, x->surface, x->surface, x->ctx)) {
		snprintf(err, errlen, "x11: cannot create an OpenGL ES 2.0 context on the window");
		x11_destroy(&x->base);
		return NULL;
	}
	x->base = (struct lx_platform){.name = "x11", .get_proc = x11_get_proc, .destroy = x11_destroy,
				       .width = width, .height = height, .swap = x11_swap, .poll_key = x11_poll_key};
	return &x->base;
}
