/* Full screen on a board: DRM/KMS for the display, GBM for the buffers, EGL with an
 * OpenGL ES 2.0 context on the GBM surface. The device is the first that can mode-set
 * (or the one asked for), the mode the connector's preferred one (or the one asked for);
 * frames are shown by page flips in step with vblank; the CRTC that was there before is
 * put back when the platform is destroyed (the kiosk does so on SIGINT and SIGTERM).
 *
 * Another process may take the display (the kiosk's DRM master dropped, e.g. by a session
 * manager handing the display to a display server): the next drmModePageFlip or
 * drmModeSetCrtc fails with EACCES, or the flip event stops coming. What each failure means is decided by lx_kms_watch_frame
 * (display_loss.c, unit-tested); a verdict other than OK sets the platform's state and
 * the kiosk stops, trying to put the CRTC back on the way out. */
#include "kms_select.h"
#include "egl_setup.h"
#include "platform.h"
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <errno.h>
#include <fcntl.h>
#include <gbm.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <xf86drm.h>
#include <xf86drmMode.h>

struct kms {
	struct lx_platform base;
	int fd;
	uint32_t connector_id, crtc_id;
	drmModeModeInfo mode;
	drmModeCrtc *saved; /* to restore at exit */
	struct gbm_device *gbm;
	struct gbm_surface *surface;
	EGLDisplay edpy;
	EGLSurface esurf;
	EGLContext ctx;
	struct gbm_bo *bo; /* on screen */
	uint32_t fb;
	bool flip_pending;
	struct lx_kms_watch watch;
};

static void *kms_get_proc(const char *name) { return (void *)eglGetProcAddress(name); }

static void destroy_fb(struct gbm_bo *bo, void *data)
{
	int fd = gbm_device_get_fd(gbm_bo_get_device(bo));
	uint32_t fb = (uint32_t)(uintptr_t)data;
	if (fb)
		drmModeRmFB(fd, fb);
}

/* The framebuffer of a GBM buffer, made once and kept with it. */
static uint32_t fb_of(struct kms *k, struct gbm_bo *bo)
{
	uint32_t fb = (uint32_t)(uintptr_t)gbm_bo_get_user_data(bo);
	if (fb)
		return fb;
	uint32_t handle = gbm_bo_get_handle(bo).u32, stride = gbm_bo_get_stride(bo);
	if (drmModeAddFB(k->fd, gbm_bo_get_width(bo), gbm_bo_get_height(bo), 24, 32, stride, handle, &fb))
		return 0;
	gbm_bo_set_user_data(bo, (void *)(uintptr_t)fb, destroy_fb);
	return fb;
}

static void flip_done(int fd, unsigned int frame, unsigned int sec, unsigned int usec, void *data)
{
	(void)fd, (void)frame, (void)sec, (void)usec;
	((struct kms *)data)->flip_pending = false;
}

/* Waits for the pending flip's event; false when it did not come within a second (the
 * kiosk must not hang on a display that stopped answering). */
static bool wait_flip(struct kms *k)
{
	drmEventContext ev = {.version = 2, .page_flip_handler = flip_done};
	bool done = true;
	while (k->flip_pending) {
		struct pollfd p = {.fd = k->fd, .events = POLLIN};
		int n = poll(&p, 1, 1000);
		if (n < 0 && errno == EINTR)
			continue; /* a signal: the kiosk's stop flag is read after the frame */
		if (n <= 0) {
			done = false;
			break;
		}
		if (drmHandleEvent(k->fd, &ev) != 0) {
			done = false;
			break;
		}
	}
	k->flip_pending = false;
	return done;
}

/* One frame's outcome to the watch; a verdict other than OK stops the kiosk. */
static void watch(struct kms *k, const char *call, int err)
{
	int master = err ? drmIsMaster(k->fd) : -1;
	char why[sizeof k->base.why];
	enum lx_display_state s = lx_kms_watch_frame(&k->watch, call, err, master, why, sizeof why);
	if (s != LX_DISPLAY_OK && k->base.state == LX_DISPLAY_OK) {
		k->base.state = s;
		snprintf(k->base.why, sizeof k->base.why, "%s", why);
	}
}

static void kms_swap(struct lx_platform *p)
{
	struct kms *k = (struct kms *)p;
	if (p->state != LX_DISPLAY_OK)
		return;
	if (!eglSwapBuffers(k->edpy, k->esurf)) {
		EGLint e = eglGetError();
		enum lx_display_state s = lx_egl_swap_state(e);
		if (s != LX_DISPLAY_OK) {
			p->state = s;
			snprintf(p->why, sizeof p->why, "lost the display (eglSwapBuffers: EGL error 0x%04x)", (unsigned)e);
		}
		return;
	}
	errno = 0;
	struct gbm_bo *next = gbm_surface_lock_front_buffer(k->surface);
	if (!next) {
		watch(k, "gbm_surface_lock_front_buffer", errno ? errno : EBUSY);
		return;
	}
	errno = 0;
	uint32_t fb = fb_of(k, next);
	if (!fb) {
		gbm_surface_release_buffer(k->surface, next); /* never shown: back to the surface */
		watch(k, "drmModeAddFB", errno ? errno : EINVAL);
		return;
	}
	/* libdrm returns -errno */
	const char *call = k->bo ? "drmModePageFlip" : "drmModeSetCrtc";
	int ret = k->bo ? drmModePageFlip(k->fd, k->crtc_id, fb, DRM_MODE_PAGE_FLIP_EVENT, k)
			: drmModeSetCrtc(k->fd, k->crtc_id, fb, 0, 0, &k->connector_id, 1, &k->mode); /* the first frame sets the mode */
	if (ret) {
		gbm_surface_release_buffer(k->surface, next);
		watch(k, call, -ret);
		return;
	}
	int err = 0;
	if (k->bo) {
		k->flip_pending = true;
		if (!wait_flip(k))
			err = LX_KMS_NO_FLIP_EVENT;
		gbm_surface_release_buffer(k->surface, k->bo);
	}
	k->bo = next;
	watch(k, call, err);
}

static int kms_poll_key(struct lx_platform *p)
{
	(void)p;
	return 0; /* no keyboard on a kiosk: the GPIO button */
}

static void kms_destroy(struct lx_platform *p)
{
	struct kms *k = (struct kms *)p;
	wait_flip(k);
	if (k->saved) {
		/* tried even when another process took the display: it fails then (EACCES),
		 * and the display stays as the new master set it */
		int ret = drmModeSetCrtc(k->fd, k->saved->crtc_id, k->saved->buffer_id, k->saved->x, k->saved->y,
					 &k->connector_id, 1, &k->saved->mode);
		if (ret && k->bo)
			fprintf(stderr, "lixel kiosk: could not put back the display mode it found (drmModeSetCrtc: %s)\n",
				strerror(-ret));
		drmModeFreeCrtc(k->saved);
	}
	lx_egl_release(k->edpy, k->ctx, k->esurf);
	if (k->bo)
		gbm_surface_release_buffer(k->surface, k->bo);
	if (k->surface)
		gbm_surface_destroy(k->surface);
	if (k->gbm)
		gbm_device_destroy(k->gbm);
	if (k->fd >= 0)
		close(k->fd);
	free(k);
}

/* What the selection needs to know of one device. */
static void describe(int fd, const char *path, struct lx_kms_device *d)
{
	memset(d, 0, sizeof(*d));
	snprintf(d->path, sizeof d->path, "%s", path);
	d->opened = fd >= 0;
	drmModeRes *res = fd >= 0 ? drmModeGetResources(fd) : NULL;
	if (!res)
		return;
	d->crtc_count = res->count_crtcs;
	for (int c = 0; c < res->count_connectors && d->connector_count < LX_KMS_MAX; c++) {
		drmModeConnector *con = drmModeGetConnector(fd, res->connectors[c]);
		if (!con)
			continue;
		struct lx_kms_connector *o = &d->connectors[d->connector_count++];
		o->id = con->connector_id;
		o->connected = con->connection == DRM_MODE_CONNECTED;
		for (int m = 0; m < con->count_modes && o->mode_count < LX_KMS_MAX; m++)
			o->modes[o->mode_count++] = (struct lx_kms_mode){con->modes[m].hdisplay, con->modes[m].vdisplay,
									  (int)con->modes[m].vrefresh,
									  (con->modes[m].type & DRM_MODE_TYPE_PREFERRED) != 0};
		for (int e = 0; e < con->count_encoders; e++) {
			drmModeEncoder *enc = drmModeGetEncoder(fd, con->encoders[e]);
			if (enc) {
				o->possible_crtcs |= enc->possible_crtcs;
				drmModeFreeEncoder(enc);
			}
		}
		drmModeFreeConnector(con);
	}
	drmModeFreeResources(res);
}

/* The DRM nodes to choose from: the one named, else card0 to card7 (missing ones
 * skipped), each opened and described. Returns the count, or -1 after err when the
 * named one cannot be opened. */
static int open_devices(const char *device, struct lx_kms_device *devs, int *fds, char *err, size_t errlen)
{
	int n = 0;
	for (int i = 0; i < 8; i++) {
		char path[64];
		if (device && i > 0)
			break;
		snprintf(path, sizeof path, "%s", device ? device : "");
		if (!device)
			snprintf(path, sizeof path, "/dev/dri/card%d", i);
		int fd = open(path, O_RDWR | O_CLOEXEC);
		if (fd < 0 && !device && errno == ENOENT)
			continue; /* no such node: not worth mentioning */
		if (fd < 0 && device) {
			snprintf(err, errlen, "kms: %s: cannot open: %s", path, strerror(errno));
			return -1;
		}
		describe(fd, path, &devs[n]);
		fds[n++] = fd;
	}
	return n;
}

/* The chosen connector, CRTC and mode read back (and the CRTC as it was, to restore). */
static bool take_mode(struct kms *k, const struct lx_kms_device *dev, const struct lx_kms_choice *ch, char *err,
		      size_t errlen)
{
	drmModeRes *res = drmModeGetResources(k->fd);
	drmModeConnector *con = res ? drmModeGetConnector(k->fd, dev->connectors[ch->connector].id) : NULL;
	bool ok = res && con && ch->mode < con->count_modes && ch->crtc < res->count_crtcs;
	if (ok) {
		k->connector_id = con->connector_id;
		k->crtc_id = res->crtcs[ch->crtc];
		k->mode = con->modes[ch->mode];
		k->saved = drmModeGetCrtc(k->fd, k->crtc_id);
	} else
		snprintf(err, errlen, "kms: %s changed while it was being read", dev->path);
	if (con)
		drmModeFreeConnector(con);
	if (res)
		drmModeFreeResources(res);
	return ok;
}

/* A GBM surface of the mode's size and an OpenGL ES 2.0 context on it, through EGL's
 * GBM platform, with the config whose visual is the surface's format (XRGB8888). */
static bool gbm_egl(struct kms *k, const char *path, int w, int h, char *err, size_t errlen)
{
	k->gbm = gbm_create_device(k->fd);
	k->surface = k->gbm ? gbm_surface_create(k->gbm, (uint32_t)w, (uint32_t)h, GBM_FORMAT_XRGB8888,
						 GBM_BO_USE_SCANOUT | GBM_BO_USE_RENDERING)
			    : NULL;
	k->edpy = k->surface ? lx_egl_display(EGL_PLATFORM_GBM_KHR, k->gbm) : EGL_NO_DISPLAY;
	EGLint count = 0;
	EGLConfig configs[64], cfg = NULL;
	const EGLint attrs[] = LX_EGL_CONFIG(EGL_WINDOW_BIT, 1);
	if (k->edpy == EGL_NO_DISPLAY || !eglChooseConfig(k->edpy, attrs, configs, 64, &count)) {
		snprintf(err, errlen, "kms: %s: no GBM or EGL on this device", path);
		return false;
	}
	for (int i = 0; i < count && !cfg; i++) {
		EGLint id;
		if (eglGetConfigAttrib(k->edpy, configs[i], EGL_NATIVE_VISUAL_ID, &id) && id == GBM_FORMAT_XRGB8888)
			cfg = configs[i];
	}
	if (cfg) {
		k->ctx = lx_egl_context(k->edpy, cfg);
		k->esurf = eglCreateWindowSurface(k->edpy, cfg, (EGLNativeWindowType)k->surface, NULL);
	}
	if (!cfg || k->ctx == EGL_NO_CONTEXT || k->esurf == EGL_NO_SURFACE ||
	    !eglMakeCurrent(k->edpy, k->esurf, k->esurf, k->ctx)) {
		snprintf(err, errlen, "kms: %s: cannot create an OpenGL ES 2.0 context on an XRGB8888 GBM surface", path);
		return false;
	}
	return true;
}

struct lx_platform *lx_platform_kms_create(const char *device, int want_w, int want_h, int want_hz, char *err,
					   size_t errlen)
{
	struct lx_kms_device devs[8];
	int fds[8], n = open_devices(device, devs, fds, err, errlen);
	if (n < 0)
		return NULL;
	struct lx_kms_choice ch;
	bool chosen = lx_kms_choose(devs, n, want_w, want_h, want_hz, &ch, err, errlen);
	for (int i = 0; i < n; i++)
		if (fds[i] >= 0 && (!chosen || i != ch.device))
			close(fds[i]);
	if (!chosen)
		return NULL;
	struct kms *k = lx_platform_alloc(sizeof(*k), "kms", err, errlen);
	if (!k) {
		close(fds[ch.device]);
		return NULL;
	}
	k->fd = fds[ch.device];
	k->edpy = EGL_NO_DISPLAY;
	k->esurf = EGL_NO_SURFACE;
	k->ctx = EGL_NO_CONTEXT;
	if (!take_mode(k, &devs[ch.device], &ch, err, errlen) ||
	    !gbm_egl(k, devs[ch.device].path, k->mode.hdisplay, k->mode.vdisplay, err, errlen)) {
		kms_destroy(&k->base);
		return NULL;
	}
	k->base = (struct lx_platform){.name = "kms", .get_proc = kms_get_proc, .destroy = kms_destroy,
				       .width = k->mode.hdisplay, .height = k->mode.vdisplay, .swap = kms_swap,
				       .poll_key = kms_poll_key};
	return &k->base;
}
