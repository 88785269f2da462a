/* Device, connector, mode and CRTC selection on fake DRM data. */
#include "kms_select.h"
#include "test_util.h"
#include <string.h>

static struct lx_kms_device device(const char *path, int crtcs)
{
	struct lx_kms_device d;
	memset(&d, 0, sizeof d);
	strcpy(d.path, path);
	d.opened = true;
	d.crtc_count = crtcs;
	return d;
}

static void add_connector(struct lx_kms_device *d, uint32_t id, bool connected, uint32_t crtcs)
{
	struct lx_kms_connector *c = &d->connectors[d->connector_count++];
	memset(c, 0, sizeof *c);
	c->id = id;
	c->connected = connected;
	c->possible_crtcs = crtcs;
}

static void add_mode(struct lx_kms_device *d, int w, int h, int hz, bool preferred)
{
	struct lx_kms_connector *c = &d->connectors[d->connector_count - 1];
	c->modes[c->mode_count++] = (struct lx_kms_mode){w, h, hz, preferred};
}

/* A Raspberry Pi 4: card0 is v3d (render only), card1 the display (vc4-kms) with an HDMI
 * monitor whose preferred mode is 1920x1080@60. */
static void raspberry_pi_4(struct lx_kms_device devs[2])
{
	devs[0] = device("/dev/dri/card0", 0);
	devs[1] = device("/dev/dri/card1", 4);
	add_connector(&devs[1], 32, false, 0x1); /* HDMI-A-2, nothing plugged */
	add_connector(&devs[1], 40, true, 0x6);  /* HDMI-A-1 */
	add_mode(&devs[1], 3840, 2160, 30, false);
	add_mode(&devs[1], 1920, 1080, 60, true);
	add_mode(&devs[1], 1920, 1080, 50, false);
	add_mode(&devs[1], 1280, 720, 60, false);
}

static void render_only_node_is_skipped(void **state)
{
	(void)state;
	struct lx_kms_device devs[2];
	raspberry_pi_4(devs);
	struct lx_kms_choice ch;
	char err[512];
	assert_true(lx_kms_choose(devs, 2, 0, 0, 0, &ch, err, sizeof err));
	assert_int_equal(ch.device, 1);
	assert_int_equal(ch.connector, 1); /* the connected one */
	assert_int_equal(devs[1].connectors[1].modes[ch.mode].w, 1920);
	assert_int_equal(devs[1].connectors[1].modes[ch.mode].hz, 60); /* preferred */
	assert_int_equal(ch.crtc, 1);                                   /* the first CRTC its encoders allow */
}

static void asked_mode(void **state)
{
	(void)state;
	struct lx_kms_device devs[2];
	raspberry_pi_4(devs);
	struct lx_kms_choice ch;
	char err[512];
	assert_true(lx_kms_choose(devs, 2, 1920, 1080, 0, &ch, err, sizeof err));
	assert_int_equal(devs[1].connectors[1].modes[ch.mode].hz, 60); /* the highest refresh */
	assert_true(lx_kms_choose(devs, 2, 1920, 1080, 50, &ch, err, sizeof err));
	assert_int_equal(devs[1].connectors[1].modes[ch.mode].hz, 50);
	assert_true(lx_kms_choose(devs, 2, 1280, 720, 0, &ch, err, sizeof err));
	assert_int_equal(devs[1].connectors[1].modes[ch.mode].w, 1280);
	assert_false(lx_kms_choose(devs, 2, 800, 480, 0, &ch, err, sizeof err));
	assert_non_null(strstr(err, "no 800x480 mode"));
	assert_non_null(strstr(err, "/dev/dri/card0 cannot mode-set"));
}

static void nothing_to_drive(void **state)
{
	(void)state;
	struct lx_kms_choice ch;
	char err[512];
	assert_false(lx_kms_choose(NULL, 0, 0, 0, 0, &ch, err, sizeof err));
	assert_non_null(strstr(err, "no DRM device found"));
	struct lx_kms_device d = device("/dev/dri/card0", 2);
	add_connector(&d, 7, false, 0x3);
	add_mode(&d, 1024, 600, 60, true);
	assert_false(lx_kms_choose(&d, 1, 0, 0, 0, &ch, err, sizeof err));
	assert_non_null(strstr(err, "/dev/dri/card0 has no connected display"));
	struct lx_kms_device closed = device("/dev/dri/card9", 0);
	closed.opened = false;
	assert_false(lx_kms_choose(&closed, 1, 0, 0, 0, &ch, err, sizeof err));
	assert_non_null(strstr(err, "/dev/dri/card9 cannot be opened"));
	/* a connected connector whose encoders allow no CRTC of this device */
	struct lx_kms_device e = device("/dev/dri/card0", 2);
	add_connector(&e, 9, true, 0x4);
	add_mode(&e, 800, 480, 60, true);
	assert_false(lx_kms_choose(&e, 1, 0, 0, 0, &ch, err, sizeof err));
	assert_non_null(strstr(err, "no usable CRTC"));
}

static void no_preferred_mode_takes_the_first(void **state)
{
	(void)state;
	struct lx_kms_device d = device("/dev/dri/card0", 1);
	add_connector(&d, 5, true, 0x1);
	add_mode(&d, 800, 480, 60, false);
	add_mode(&d, 640, 480, 60, false);
	struct lx_kms_choice ch;
	char err[512];
	assert_true(lx_kms_choose(&d, 1, 0, 0, 0, &ch, err, sizeof err));
	assert_int_equal(ch.mode, 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(render_only_node_is_skipped),
		cmocka_unit_test(asked_mode),
		cmocka_unit_test(nothing_to_drive),
		cmocka_unit_test(no_preferred_mode_takes_the_first),
	};
	return cmocka_run_group_tests_name("kms_select", tests, NULL, NULL);
}
