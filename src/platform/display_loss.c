#include "display_loss.h"
#include <errno.h>
#include <stdio.h>
#include <string.h>

enum lx_display_state lx_egl_swap_state(int egl_error)
{
	switch (egl_error) {
	case LX_EGL_BAD_SURFACE:
	case LX_EGL_BAD_NATIVE_WINDOW:
	case LX_EGL_BAD_CURRENT_SURFACE:
		return LX_DISPLAY_CLOSED;
	case LX_EGL_BAD_DISPLAY:
	case LX_EGL_NOT_INITIALIZED:
	case LX_EGL_CONTEXT_LOST:
		return LX_DISPLAY_LOST;
	default:
		return LX_DISPLAY_OK;
	}
}

enum lx_display_state lx_kms_watch_frame(struct lx_kms_watch *w, const char *call, int err, int is_master, char *why,
					 size_t whylen)
{
	if (!err) {
		w->failed = w->missed = 0;
		return LX_DISPLAY_OK;
	}
	if (err == EACCES || err == EPERM) {
		snprintf(why, whylen, "another process took the display (%s: %s)", call, strerror(err));
		return LX_DISPLAY_CLOSED;
	}
	if (err == ENODEV || err == ENXIO || err == EIO) {
		snprintf(why, whylen, "the display device went away (%s: %s)", call, strerror(err));
		return LX_DISPLAY_LOST;
	}
	if (is_master == 0) {
		if (err == LX_KMS_NO_FLIP_EVENT)
			snprintf(why, whylen, "another process took the display (no page flip event, no longer DRM master)");
		else
			snprintf(why, whylen, "another process took the display (%s: %s, no longer DRM master)", call,
				 strerror(err));
		return LX_DISPLAY_CLOSED;
	}
	/* every frame not shown counts, a missed flip event also on its own: a display that
	 * answers neither way (a flip missed, the next one refused as busy, ...) is seen */
	w->failed++;
	if (err == LX_KMS_NO_FLIP_EVENT && ++w->missed >= LX_KMS_MAX_MISSED_FLIPS) {
		snprintf(why, whylen, "the display stopped answering (%d page flip events missed in %d frames)", w->missed,
			 w->failed);
		return LX_DISPLAY_LOST;
	}
	if (w->failed >= LX_KMS_MAX_FAILED_FRAMES) {
		if (err == LX_KMS_NO_FLIP_EVENT)
			snprintf(why, whylen, "the display refused %d frames in a row", w->failed);
		else
			snprintf(why, whylen, "the display refused %d frames in a row (%s: %s)", w->failed, call,
				 strerror(err));
		return LX_DISPLAY_LOST;
	}
	return LX_DISPLAY_OK;
}
