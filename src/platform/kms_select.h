/* Choosing what the kiosk drives on a board, GL-free and libdrm-free so that the tests
 * can feed it fake DRM data: the first device that can mode-set (a Raspberry Pi 4's
 * card0 is render-only), its first connected connector, the preferred mode or the one
 * asked for, and a CRTC the connector's encoders can use. */
#ifndef LX_KMS_SELECT_H
#define LX_KMS_SELECT_H
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#define LX_KMS_MAX 16

struct lx_kms_mode {
	int w, h, hz;
	bool preferred;
};

struct lx_kms_connector {
	uint32_t id;
	bool connected;
	int mode_count;
	struct lx_kms_mode modes[LX_KMS_MAX];
	uint32_t possible_crtcs; /* bit i: the device's CRTC i (union over the connector's encoders) */
};

struct lx_kms_device {
	char path[64];
	bool opened;   /* false: the node could not be opened */
	int crtc_count; /* 0: no mode setting (a render-only node) */
	int connector_count;
	struct lx_kms_connector connectors[LX_KMS_MAX];
};

struct lx_kms_choice {
	int device, connector, mode, crtc; /* indices */
};

/* want_w = 0: the connector's preferred mode (else its first); want_hz = 0: any refresh,
 * the highest. Returns false with one line in err (what was tried, what was missing). */
bool lx_kms_choose(const struct lx_kms_device *devs, int ndevs, int want_w, int want_h, int want_hz,
		   struct lx_kms_choice *out, char *err, size_t errlen);

#endif
