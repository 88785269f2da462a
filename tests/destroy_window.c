/* Test helper: closes one X window from another client, as a window manager or another
 * program may, leaving the window's owner connected.
 *   destroy_window ID               XDestroyWindow: the window is gone at once
 *   destroy_window --wm-delete ID   a WM_DELETE_WINDOW message: the window manager's
 *                                   polite request to close it
 * ID decimal or 0x hex; DISPLAY from the environment.
 * Exit status: 0 done; 1 no display or no such window; 2 bad usage. */
#include <X11/Xlib.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int failed;

static int on_error(Display *dpy, XErrorEvent *e)
{
	char text[128];
	XGetErrorText(dpy, e->error_code, text, sizeof text);
	fprintf(stderr, "destroy_window: %s\n", text);
	failed = 1;
	return 0;
}

int main(int argc, char **argv)
{
	int wm_delete = argc == 3 && !strcmp(argv[1], "--wm-delete");
	const char *arg = argc == 2 ? argv[1] : wm_delete ? argv[2] : NULL;
	char *end = NULL;
	unsigned long id = arg ? strtoul(arg, &end, 0) : 0;
	if (!arg || end == arg || *end || !id) {
		fprintf(stderr, "usage: destroy_window [--wm-delete] WINDOW_ID\n");
		return 2;
	}
	Display *dpy = XOpenDisplay(NULL);
	if (!dpy) {
		fprintf(stderr, "destroy_window: cannot open the display\n");
		return 1;
	}
	XSetErrorHandler(on_error);
	if (wm_delete) {
		XEvent ev;
		memset(&ev, 0, sizeof ev);
		ev.xclient.type = ClientMessage;
		ev.xclient.window = (Window)id;
		ev.xclient.message_type = XInternAtom(dpy, "WM_PROTOCOLS", False);
		ev.xclient.format = 32;
		ev.xclient.data.l[0] = (long)XInternAtom(dpy, "WM_DELETE_WINDOW", False);
		ev.xclient.data.l[1] = CurrentTime;
		XSendEvent(dpy, (Window)id, False, NoEventMask, &ev);
	} else
		XDestroyWindow(dpy, (Window)id);
	XSync(dpy, False);
	XCloseDisplay(dpy);
	return failed;
}
