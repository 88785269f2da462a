/* EGL with an OpenGL ES 2.0 context on an X11 window: the kiosk's desktop emulation
 * (`lixel kiosk --platform x11`), and the way the tests drive it under Xvfb.
 *
 * The window may go away under the kiosk: the window manager asks to close it
 * (WM_DELETE_WINDOW), another client destroys it (DestroyNotify, or a BadWindow or
 * BadDrawable error naming it), or the X server goes (Xlib's I/O error). Each sets the
 * platform's state instead of letting Xlib end the process, and the kiosk stops. */
#include "egl_setup.h"
#include "platform.h"
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <X11/keysym.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

_Static_assert(LX_EGL_BAD_SURFACE == EGL_BAD_SURFACE && LX_EGL_BAD_NATIVE_WINDOW == EGL_BAD_NATIVE_WINDOW &&
		       LX_EGL_BAD_CURRENT_SURFACE == EGL_BAD_CURRENT_SURFACE && LX_EGL_BAD_DISPLAY == EGL_BAD_DISPLAY &&
		       LX_EGL_NOT_INITIALIZED == EGL_NOT_INITIALIZED && LX_EGL_CONTEXT_LOST == EGL_CONTEXT_LOST &&
		       LX_EGL_BAD_ALLOC == EGL_BAD_ALLOC && LX_EGL_SUCCESS == EGL_SUCCESS,
	       "display_loss.h mirrors EGL's error codes");

struct x11 {
	struct lx_platform base;
	Display *dpy;
	Window win;
	Atom wm_delete;
	EGLDisplay edpy;
	EGLSurface surface;
	EGLContext ctx;
	bool win_gone;       /* destroyed by another client: not ours to destroy again */
	bool conn_gone;      /* the X server went away: no request may be sent */
	bool error_reported; /* one warning for X errors that are not about the window */
};

static void *x11_get_proc(const char *name) { return (void *)eglGetProcAddress(name); }

/* Xlib's handlers are the process's, not one display's: they report to the one window
 * there is while it exists, and the ones found before are put back after. */
static struct x11 *handled;
static XErrorHandler old_error_handler;
static XIOErrorHandler old_io_handler;

static void set_state(struct x11 *x, enum lx_display_state s, const char *why)
{
	if (x->base.state != LX_DISPLAY_OK)
		return; /* the first cause is the one to tell */
	x->base.state = s;
	snprintf(x->base.why, sizeof x->base.why, "%s", why);
}

static int on_x_error(Display *dpy, XErrorEvent *e)
{
	struct x11 *x = handled;
	if (!x || dpy != x->dpy)
		return 0;
	if ((e->error_code == BadWindow || e->error_code == BadDrawable) && e->resourceid == x->win) {
		x->win_gone = true;
		set_state(x, LX_DISPLAY_CLOSED, "the window was closed (destroyed by another client)");
	} else if (!x->error_reported) {
		/* Xlib's default handler ends the process here; one line, and the kiosk goes on */
		char text[128];
		XGetErrorText(dpy, e->error_code, text, sizeof text);
		fprintf(stderr, "lixel kiosk: warning: X error %s (request %d.%d) ignored\n", text, e->request_code,
			e->minor_code);
		x->error_reported = true;
	}
	return 0;
}

/* Called first when the connection breaks; Xlib's own prints a line, this is quiet. */
static int on_x_io_error(Display *dpy)
{
	(void)dpy;
	return 0;
}

/* Called instead of exit(1) once the connection broke: Xlib then refuses requests on
 * this display, and the kiosk stops at the end of the frame. */
static void on_x_io_exit(Display *dpy, void *data)
{
	struct x11 *x = data;
	(void)dpy;
	x->conn_gone = true;
	char why[200];
	snprintf(why, sizeof why, "lost the connection to the X server (%s)", DisplayString(dpy));
	set_state(x, LX_DISPLAY_LOST, why);
}

static void x11_destroy(struct lx_platform *p)
{
	struct x11 *x = (struct x11 *)p;
	if (x->dpy && !x->conn_gone)
		XSync(x->dpy, False); /* errors still on their way reach the handler, not exit() */
	lx_egl_release(x->edpy, x->ctx, x->surface);
	if (x->win && !x->win_gone && !x->conn_gone)
		XDestroyWindow(x->dpy, x->win);
	if (x->dpy && !x->conn_gone)
		XSync(x->dpy, False);
	if (x->dpy && x->conn_gone) {
		/* libX11 1.8's XCloseDisplay still queues its requests (free the default GC,
		 * sync) on a broken connection and prints a line for each it cannot; the kiosk
		 * has said what happened: those lines go to /dev/null while it frees */
		fflush(stderr);
		int saved = dup(STDERR_FILENO), null = open("/dev/null", O_WRONLY | O_CLOEXEC);
		if (saved >= 0 && null >= 0)
			dup2(null, STDERR_FILENO);
		XCloseDisplay(x->dpy);
		if (saved >= 0 && null >= 0)
			dup2(saved, STDERR_FILENO);
		if (saved >= 0)
			close(saved);
		if (null >= 0)
			close(null);
	} else if (x->dpy)
		XCloseDisplay(x->dpy);
	if (handled == x) {
		XSetErrorHandler(old_error_handler);
		XSetIOErrorHandler(old_io_handler);
		handled = NULL;
	}
	free(x);
}

static void x11_swap(struct lx_platform *p)
{
	struct x11 *x = (struct x11 *)p;
	/* Mesa's software path (22.3) loops for ever in eglSwapBuffers when its connection
	 * already broke (the largest request it may send is 0 bytes then): XPending reads the
	 * connection first, and a broken one ends the frame here (on_x_io_exit) */
	if (p->state == LX_DISPLAY_OK && !x->conn_gone)
		XPending(x->dpy);
	if (p->state != LX_DISPLAY_OK || x->conn_gone)
		return;
	if (!eglSwapBuffers(x->edpy, x->surface)) {
		EGLint e = eglGetError();
		enum lx_display_state s = lx_egl_swap_state(e);
		char why[200];
		if (s == LX_DISPLAY_CLOSED)
			snprintf(why, sizeof why, "the window was closed (eglSwapBuffers: EGL error 0x%04x)", (unsigned)e);
		else
			snprintf(why, sizeof why, "lost the display (eglSwapBuffers: EGL error 0x%04x)", (unsigned)e);
		if (s != LX_DISPLAY_OK)
			set_state(x, s, why);
	}
}

static int x11_poll_key(struct lx_platform *p)
{
	struct x11 *x = (struct x11 *)p;
	/* XPending reads the connection: a broken one calls on_x_io_exit and returns 0 */
	while (!x->conn_gone && XPending(x->dpy)) {
		XEvent ev;
		XNextEvent(x->dpy, &ev);
		if (ev.type == ClientMessage && (Atom)ev.xclient.data.l[0] == x->wm_delete)
			set_state(x, LX_DISPLAY_CLOSED, "the window was closed (by the window manager)");
		if (ev.type == DestroyNotify && ev.xdestroywindow.window == x->win) {
			x->win_gone = true;
			set_state(x, LX_DISPLAY_CLOSED, "the window was closed (destroyed by another client)");
		}
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
	struct x11 *x = lx_platform_alloc(sizeof(*x), "x11", err, errlen);
	if (!x)
		return NULL;
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
	x->edpy = lx_egl_display(EGL_PLATFORM_X11_KHR, x->dpy);
	EGLint n = 0;
	EGLConfig cfg;
	const EGLint attrs[] = LX_EGL_CONFIG(EGL_WINDOW_BIT, 1);
	if (x->edpy == EGL_NO_DISPLAY || !eglChooseConfig(x->edpy, attrs, &cfg, 1, &n) || n < 1) {
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
	x->surface = eglCreateWindowSurface(x->edpy, cfg, (EGLNativeWindowType)x->win, NULL);
	x->ctx = lx_egl_context(x->edpy, cfg);
	if (x->surface == EGL_NO_SURFACE || x->ctx == EGL_NO_CONTEXT ||
	    !eglMakeCurrent(x->edpy, x->surface, x->surface, x->ctx)) {
		snprintf(err, errlen, "x11: cannot create an OpenGL ES 2.0 context on the window");
		x11_destroy(&x->base);
		return NULL;
	}
	x->base = (struct lx_platform){.name = "x11", .get_proc = x11_get_proc, .destroy = x11_destroy,
				       .width = width, .height = height, .swap = x11_swap, .poll_key = x11_poll_key};
	if (!handled) {
		handled = x;
		old_error_handler = XSetErrorHandler(on_x_error);
		old_io_handler = XSetIOErrorHandler(on_x_io_error);
	}
	XSetIOErrorExitHandler(x->dpy, on_x_io_exit, x);
	return &x->base;
}
