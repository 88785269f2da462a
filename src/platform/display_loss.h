/* When the kiosk's display goes away: what a platform's failure means, decided here,
 * GL-free and libdrm-free, so that the unit tests reach every decision without a GPU,
 * an X server or a DRM device. */
#ifndef LX_DISPLAY_LOSS_H
#define LX_DISPLAY_LOSS_H
#include <stdbool.h>
#include <stddef.h>

enum lx_display_state {
	LX_DISPLAY_OK,     /* go on */
	LX_DISPLAY_CLOSED, /* the window was closed or destroyed, or another process took the
			      display (DRM master): the kiosk stops, exit status 0 */
	LX_DISPLAY_LOST,   /* the X server or the DRM device went away, or the display refused
			      frames for good: the kiosk stops, exit status 1 */
};

/* EGL's error codes that matter here (the values of EGL/egl.h, checked against it where
 * EGL is included: platform_x11.c). */
#define LX_EGL_SUCCESS 0x3000
#define LX_EGL_NOT_INITIALIZED 0x3001
#define LX_EGL_BAD_ALLOC 0x3003
#define LX_EGL_BAD_CURRENT_SURFACE 0x3007
#define LX_EGL_BAD_DISPLAY 0x3008
#define LX_EGL_BAD_NATIVE_WINDOW 0x300B
#define LX_EGL_BAD_SURFACE 0x300D
#define LX_EGL_CONTEXT_LOST 0x300E

/* A failed eglSwapBuffers (egl_error from eglGetError): the window or surface gone is
 * CLOSED, the display or context gone is LOST, anything else OK (the frame is dropped). */
enum lx_display_state lx_egl_swap_state(int egl_error);

/* KMS: the frames a page flip may fail or go unanswered before the kiosk gives up. */
#define LX_KMS_MAX_FAILED_FRAMES 120 /* refused flips in a row (EBUSY, EINVAL, ...) */
#define LX_KMS_MAX_MISSED_FLIPS 3    /* flips whose event did not come within the wait (1 s each) */
/* err for a flip the kernel accepted but whose event did not come within the wait */
#define LX_KMS_NO_FLIP_EVENT (-1)

struct lx_kms_watch {
	int failed; /* frames not shown since the last one shown */
	int missed; /* flip events missed among them */
};

/* One frame's outcome on KMS: call is what was tried ("drmModeSetCrtc", "drmModePageFlip"),
 * err 0 when the frame was shown, the errno the call failed with, or LX_KMS_NO_FLIP_EVENT;
 * is_master 1 or 0 from drmIsMaster, -1 unknown (asked only after a failure).
 *   EACCES, EPERM (the DRM master is another process's): CLOSED, another process took the
 *   display;
 *   ENODEV, ENXIO, EIO (the device went away): LOST;
 *   any other failure, or a missed flip, while no longer master: CLOSED, as EACCES;
 *   LX_KMS_MAX_MISSED_FLIPS missed flips among the frames not shown since the last one
 *   shown, while still master: LOST (the display or its driver stopped answering; a
 *   restart sets the mode again);
 *   LX_KMS_MAX_FAILED_FRAMES frames not shown in a row: LOST;
 *   else OK (a busy or interrupted call: the frame is dropped, the next one tries again).
 * Not OK: one line in why saying what happened (no trailing full stop). */
enum lx_display_state lx_kms_watch_frame(struct lx_kms_watch *w, const char *call, int err, int is_master, char *why,
					 size_t whylen);

#endif
