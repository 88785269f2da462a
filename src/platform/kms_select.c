#include "kms_select.h"
#include <stdio.h>
#include <string.h>

static int pick_mode(const struct lx_kms_connector *c, int w, int h, int hz)
{
	int best = -1;
	for (int m = 0; m < c->mode_count; m++) {
		const struct lx_kms_mode *md = &c->modes[m];
		if (!w) {
			if (md->preferred)
				return m;
			continue;
		}
		if (md->w != w || md->h != h || (hz && md->hz != hz))
			continue;
		if (best < 0 || md->hz > c->modes[best].hz)
			best = m;
	}
	return !w && c->mode_count ? 0 : best; /* no preferred mode: the first, as drivers list the best first */
}

bool lx_kms_choose(const struct lx_kms_device *devs, int ndevs, int want_w, int want_h, int want_hz,
		   struct lx_kms_choice *out, char *err, size_t errlen)
{
	char why[256] = "";
	for (int d = 0; d < ndevs; d++) {
		const struct lx_kms_device *dev = &devs[d];
		size_t l = strlen(why);
		if (!dev->opened) {
			snprintf(why + l, sizeof why - l, "%s%s cannot be opened", l ? "; " : "", dev->path);
			continue;
		}
		if (dev->crtc_count == 0) {
			snprintf(why + l, sizeof why - l, "%s%s cannot mode-set", l ? "; " : "", dev->path);
			continue;
		}
		for (int c = 0; c < dev->connector_count; c++) {
			const struct lx_kms_connector *con = &dev->connectors[c];
			if (!con->connected || con->mode_count == 0)
				continue;
			int m = pick_mode(con, want_w, want_h, want_hz);
			if (m < 0) {
				l = strlen(why);
				snprintf(why + l, sizeof why - l, "%s%s connector %u has no %dx%d%s mode", l ? "; " : "", dev->path,
					 con->id, want_w, want_h, want_hz ? "@given refresh" : "");
				continue;
			}
			for (int k = 0; k < dev->crtc_count && k < 32; k++)
				if (con->possible_crtcs & (1u << k)) {
					*out = (struct lx_kms_choice){d, c, m, k};
					return true;
				}
			l = strlen(why);
			snprintf(why + l, sizeof why - l, "%s%s connector %u has no usable CRTC", l ? "; " : "", dev->path,
				 con->id);
		}
		l = strlen(why);
		if (!strstr(why, dev->path))
			snprintf(why + l, sizeof why - l, "%s%s has no connected display", l ? "; " : "", dev->path);
	}
	snprintf(err, errlen, "kms: no display to drive (%s)", ndevs ? why : "no DRM device found");
	return false;
}
