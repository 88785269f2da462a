/* Board profiles: the built-in ones, overrides of the defaults, malformed files. */
#include "board.h"
#include "test_util.h"
#include <stdio.h>
#include <string.h>

static void built_in_profiles(void **state)
{
	(void)state;
	static const char *const names[] = {"raspberry-pi-3", "raspberry-pi-4", "raspberry-pi-5", "mali-400", "desktop"};
	for (int i = 0; i < 5; i++) {
		struct lx_board b;
		char err[256];
		if (!lx_board_load(names[i], &b, err, sizeof err))
			fail_msg("%s", err);
		assert_string_equal(b.name, names[i]);
		assert_true(b.method_count >= 2);
		assert_true(b.lixels.plane_lixels == 350 && b.lixels.fallback_lixels == 128 && b.lixels.uniform_lixels == 512);
		assert_non_null(strstr(lx_board_names(), names[i]));
	}
	struct lx_board pi4;
	char err[256];
	assert_true(lx_board_load("raspberry-pi-4", &pi4, err, sizeof err));
	assert_string_equal(pi4.display, ""); /* auto: which card is the display varies there */
	assert_string_equal(pi4.gpio_chip, "gpiochip0");
	assert_int_equal(pi4.gpio_line, 17);
	assert_true(pi4.active_low);
	assert_int_equal(pi4.bias, LX_BIAS_PULL_UP);
	assert_int_equal(pi4.debounce_ms, 30);
	assert_int_equal(pi4.mode_w, 0);
	struct lx_board pi3;
	assert_true(lx_board_load("raspberry-pi-3", &pi3, err, sizeof err));
	assert_true(pi3.mode_w == 1280 && pi3.mode_h == 720 && pi3.mode_hz == 60);
	/* a second light's maps at half the lixels there (light-budget 1,0.5): later lights
	 * take the list's last share, and a light's sides shrink by its square root */
	assert_true(pi3.lixels.light_share[0] == 1 && pi3.lixels.light_share[1] == 0.5 && pi3.lixels.light_share[3] == 0.5);
	struct lx_method_options second = lx_method_options_for_light(&pi3.lixels, 1);
	assert_int_equal(second.plane_lixels, 247); /* 350 / sqrt(2) */
	assert_int_equal(second.uniform_lixels, 362);
	assert_int_equal(lx_method_options_for_light(&pi3.lixels, 0).plane_lixels, 350);
	assert_true(pi4.lixels.light_share[1] == 0); /* no key: every light the whole budget */
	assert_int_equal(lx_method_options_for_light(&pi4.lixels, 1).plane_lixels, 350);
	struct lx_board desk;
	assert_true(lx_board_load("desktop", &desk, err, sizeof err));
	assert_string_equal(desk.gpio_chip, ""); /* no button: the keyboard */
}

/* The filters the button steps through: none alone unless the profile says more. */
static void filters_key(void **state)
{
	(void)state;
	struct lx_board b;
	char err[256];
	lx_board_defaults(&b);
	assert_int_equal(b.filter_count, 1);
	assert_int_equal(b.filters[0], LX_FILTER_NONE);
	if (!lx_board_parse("filters pcf3x3,none,pcf2x2\n", "f.profile", &b, err, sizeof err))
		fail_msg("%s", err);
	assert_int_equal(b.filter_count, 3);
	assert_true(b.filters[0] == LX_FILTER_PCF3X3 && b.filters[1] == LX_FILTER_NONE && b.filters[2] == LX_FILTER_PCF2X2);
	assert_true(lx_board_load("raspberry-pi-5", &b, err, sizeof err));
	assert_true(b.filter_count == 2 && b.filters[0] == LX_FILTER_NONE && b.filters[1] == LX_FILTER_PCF2X2);
	assert_true(lx_board_load("mali-400", &b, err, sizeof err));
	assert_int_equal(b.filter_count, 1); /* fill-limited: NEAREST only */
}

static void modes(void **state)
{
	(void)state;
	int w, h, hz;
	assert_true(lx_parse_mode("1920x1080", &w, &h, &hz) && w == 1920 && h == 1080 && hz == 0);
	assert_true(lx_parse_mode("800x480@75", &w, &h, &hz) && hz == 75);
	assert_false(lx_parse_mode("1920", &w, &h, &hz));
	assert_false(lx_parse_mode("0x480", &w, &h, &hz));
	assert_false(lx_parse_mode("800x480@", &w, &h, &hz));
	assert_false(lx_parse_mode("axb", &w, &h, &hz));
}

static void malformed_profiles(void **state)
{
	(void)state;
	static const struct {
		const char *text;
		int line;
		const char *expect;
	} cases[] = {
		{"gpio-line seventeen\n", 1, "expected a line offset"},
		{"# a comment\ngpio-active sideways\n", 2, "expected gpio-active low or high"},
		{"gpio-bias pull-sideways\n", 1, "expected gpio-bias"},
		{"debounce-ms -5\n", 1, "expected debounce-ms from 0 to 1000"},
		{"mode big\n", 1, "expected mode preferred"},
		{"methods plane,teapot\n", 1, "got 'teapot'"},
		{"methods ,\n", 1, "expected method names separated by single commas"},
		{"methods plane,,uniform\n", 1, "expected method names separated by single commas"},
		{"methods plane uniform\n", 1, "got 'plane uniform'"},
		{"gpio-line 0x5\n", 1, "not a decimal number"},
		{"gpio-line 99999999999999999999\n", 1, "too large to hold"},
		{"debounce-ms 5.0\n", 1, "not a decimal number"},
		{"gpio-line-name\n", 1, "expected a value after 'gpio-line-name'"},
		{"depth-precision fp16\n", 1, "expected depth-precision auto, highp, mediump or texture"},
		{"frobnicate 3\n", 1, "got 'frobnicate'"},
		{"gpio-chip gpiochip0\n", 2, "expected a gpio-line"},
		{"name\n", 1, "expected a value after 'name'"},
		{"filters pcf4x4\n", 1, "expected filters from none, pcf2x2 or pcf3x3, got 'pcf4x4'"},
		{"filters none,,pcf2x2\n", 1, "expected filter names separated by single commas"},
		{"filters ,\n", 1, "expected filter names separated by single commas"},
		{"filters pcf2x2,none,pcf2x2\n", 1, "expected each filter once, got 'pcf2x2' twice"},
		{"filters none pcf2x2\n", 1, "got 'none pcf2x2'"},
		{"light-budget 1,0\n", 1, "expected light-budget as 1 to 4 shares from 0.01 to 1"},
		{"light-budget 1,0.5,0.5,0.5,0.5\n", 1, "got '1,0.5,0.5,0.5,0.5'"},
		{"light-budget half\n", 1, "got 'half'"},
	};
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		struct lx_board b;
		char err[512], prefix[64]; /* the kiosk's own buffer: the unknown key's line lists every key */
		lx_board_defaults(&b);
		if (lx_board_parse(cases[i].text, "bad.profile", &b, err, sizeof err))
			fail_msg("case %zu parsed: %s", i, cases[i].text);
		snprintf(prefix, sizeof prefix, "bad.profile:%d: ", cases[i].line);
		if (strncmp(err, prefix, strlen(prefix)) || !strstr(err, cases[i].expect))
			fail_msg("case %zu: got \"%s\", expected \"%s...%s\"", i, err, prefix, cases[i].expect);
	}
	struct lx_board b;
	char err[256];
	assert_false(lx_board_load("no-such-board", &b, err, sizeof err));
	assert_non_null(strstr(err, "no such built-in board"));
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(built_in_profiles),
		cmocka_unit_test(modes),
		cmocka_unit_test(filters_key),
		cmocka_unit_test(malformed_profiles),
	};
	return cmocka_run_group_tests_name("board", tests, NULL, NULL);
}
