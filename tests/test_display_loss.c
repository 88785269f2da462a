/* What a failure of the display means to the kiosk (display_loss.c): the decisions the
 * KMS and X11 platforms hand over, fed the errors a board would give, since there is no
 * DRM device here to take the display away from the kiosk. */
#include "display_loss.h"
#include "test_util.h"
#include <errno.h>
#include <string.h>

static enum lx_display_state frame(struct lx_kms_watch *w, const char *call, int err, int master, char *why)
{
	strcpy(why, "(untouched)");
	return lx_kms_watch_frame(w, call, err, master, why, 256);
}

static void permission_denied_means_taken(void **state)
{
	(void)state;
	char why[256];
	/* EACCES is what the kernel gives a DRM_MASTER ioctl from a process that is not master */
	struct lx_kms_watch w = {0};
	assert_int_equal(frame(&w, "drmModePageFlip", 0, -1, why), LX_DISPLAY_OK);
	assert_int_equal(frame(&w, "drmModePageFlip", EACCES, 0, why), LX_DISPLAY_CLOSED);
	assert_string_equal(why, "another process took the display (drmModePageFlip: Permission denied)");
	/* the same whatever drmIsMaster said (it may not have been asked) */
	struct lx_kms_watch w2 = {0};
	assert_int_equal(frame(&w2, "drmModeSetCrtc", EPERM, -1, why), LX_DISPLAY_CLOSED);
	assert_non_null(strstr(why, "another process took the display (drmModeSetCrtc: "));
	struct lx_kms_watch w3 = {0};
	assert_int_equal(frame(&w3, "drmModeSetCrtc", EACCES, 1, why), LX_DISPLAY_CLOSED);
}

static void device_gone_is_lost(void **state)
{
	(void)state;
	char why[256];
	const int errs[] = {ENODEV, ENXIO, EIO};
	for (size_t i = 0; i < sizeof errs / sizeof errs[0]; i++) {
		struct lx_kms_watch w = {0};
		assert_int_equal(frame(&w, "drmModePageFlip", errs[i], -1, why), LX_DISPLAY_LOST);
		assert_non_null(strstr(why, "the display device went away (drmModePageFlip: "));
	}
}

static void transient_failures_are_dropped_frames(void **state)
{
	(void)state;
	char why[256];
	struct lx_kms_watch w = {0};
	/* a busy or odd refusal while still master: the frame is dropped, the kiosk goes on */
	for (int i = 1; i < LX_KMS_MAX_FAILED_FRAMES; i++) {
		assert_int_equal(frame(&w, "drmModePageFlip", i % 2 ? EBUSY : EINVAL, 1, why), LX_DISPLAY_OK);
		assert_string_equal(why, "(untouched)");
	}
	/* a frame shown starts the count again; a missed flip event counts as a frame not shown */
	assert_int_equal(frame(&w, "drmModePageFlip", 0, -1, why), LX_DISPLAY_OK);
	assert_int_equal(frame(&w, "drmModePageFlip", LX_KMS_NO_FLIP_EVENT, 1, why), LX_DISPLAY_OK);
	assert_int_equal(frame(&w, "drmModePageFlip", 0, -1, why), LX_DISPLAY_OK);
	for (int i = 1; i < LX_KMS_MAX_FAILED_FRAMES; i++)
		assert_int_equal(frame(&w, "drmModePageFlip", EBUSY, 1, why), LX_DISPLAY_OK);
	/* refused for good: the kiosk gives up with status 1, systemd starts it again */
	assert_int_equal(frame(&w, "drmModePageFlip", EBUSY, 1, why), LX_DISPLAY_LOST);
	assert_non_null(strstr(why, "the display refused 120 frames in a row (drmModePageFlip: "));
}

static void any_failure_without_master_means_taken(void **state)
{
	(void)state;
	char why[256];
	struct lx_kms_watch w = {0};
	assert_int_equal(frame(&w, "drmModePageFlip", EINVAL, 0, why), LX_DISPLAY_CLOSED);
	assert_non_null(strstr(why, "another process took the display (drmModePageFlip: "));
	assert_non_null(strstr(why, "no longer DRM master"));
	/* but a device that went away is said so, master or not */
	struct lx_kms_watch w2 = {0};
	assert_int_equal(frame(&w2, "drmModePageFlip", ENODEV, 0, why), LX_DISPLAY_LOST);
}

static void missed_flip_events(void **state)
{
	(void)state;
	char why[256];
	/* no event within the wait, and no longer master: taken at once */
	struct lx_kms_watch w = {0};
	assert_int_equal(frame(&w, "drmModePageFlip", LX_KMS_NO_FLIP_EVENT, 0, why), LX_DISPLAY_CLOSED);
	assert_string_equal(why, "another process took the display (no page flip event, no longer DRM master)");
	/* still master (or not known): a slow vblank now and then is no reason to stop */
	struct lx_kms_watch w2 = {0};
	for (int round = 0; round < 3; round++) {
		for (int i = 1; i < LX_KMS_MAX_MISSED_FLIPS; i++)
			assert_int_equal(frame(&w2, "drmModePageFlip", LX_KMS_NO_FLIP_EVENT, round == 1 ? -1 : 1, why),
					 LX_DISPLAY_OK);
		assert_int_equal(frame(&w2, "drmModePageFlip", 0, -1, why), LX_DISPLAY_OK);
	}
	/* missed and refused flips in turn (a flip missed, the next refused as busy): the
	 * missed ones still add up */
	assert_int_equal(frame(&w2, "drmModePageFlip", LX_KMS_NO_FLIP_EVENT, 1, why), LX_DISPLAY_OK);
	assert_int_equal(frame(&w2, "drmModePageFlip", EBUSY, 1, why), LX_DISPLAY_OK);
	assert_int_equal(frame(&w2, "drmModePageFlip", LX_KMS_NO_FLIP_EVENT, 1, why), LX_DISPLAY_OK);
	assert_int_equal(frame(&w2, "drmModePageFlip", EBUSY, 1, why), LX_DISPLAY_OK);
	/* while still master: the display or its driver is stuck, status 1 (a restart sets the
	 * mode again) */
	assert_int_equal(frame(&w2, "drmModePageFlip", LX_KMS_NO_FLIP_EVENT, 1, why), LX_DISPLAY_LOST);
	assert_string_equal(why, "the display stopped answering (3 page flip events missed in 5 frames)");
}

static void egl_swap_errors(void **state)
{
	(void)state;
	assert_int_equal(lx_egl_swap_state(LX_EGL_BAD_SURFACE), LX_DISPLAY_CLOSED);
	assert_int_equal(lx_egl_swap_state(LX_EGL_BAD_NATIVE_WINDOW), LX_DISPLAY_CLOSED);
	assert_int_equal(lx_egl_swap_state(LX_EGL_BAD_CURRENT_SURFACE), LX_DISPLAY_CLOSED);
	assert_int_equal(lx_egl_swap_state(LX_EGL_CONTEXT_LOST), LX_DISPLAY_LOST);
	assert_int_equal(lx_egl_swap_state(LX_EGL_BAD_DISPLAY), LX_DISPLAY_LOST);
	assert_int_equal(lx_egl_swap_state(LX_EGL_NOT_INITIALIZED), LX_DISPLAY_LOST);
	/* out of memory for one frame, or no error at all: the frame is dropped, no more */
	assert_int_equal(lx_egl_swap_state(LX_EGL_BAD_ALLOC), LX_DISPLAY_OK);
	assert_int_equal(lx_egl_swap_state(LX_EGL_SUCCESS), LX_DISPLAY_OK);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(permission_denied_means_taken),
		cmocka_unit_test(device_gone_is_lost),
		cmocka_unit_test(transient_failures_are_dropped_frames),
		cmocka_unit_test(any_failure_without_master_means_taken),
		cmocka_unit_test(missed_flip_events),
		cmocka_unit_test(egl_swap_errors),
	};
	return cmocka_run_group_tests_name("display_loss", tests, NULL, NULL);
}
