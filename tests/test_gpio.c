/* The GPIO backend on a machine without GPIO: a missing chip is one clear message, not
 * a crash, and the kiosk can go on with the keyboard. */
#include "gpio_button.h"
#include "gpio_lookup.h"
#include "test_util.h"
#include <stdio.h>
#include <string.h>

static void missing_chip_is_one_clear_line(void **state)
{
	(void)state;
	struct lx_board b;
	lx_board_defaults(&b);
	snprintf(b.gpio_chip, sizeof b.gpio_chip, "lixel-test-no-such-chip");
	b.gpio_line = 17;
	char err[256];
	struct lx_gpio_button *g = lx_gpio_button_open(&b, err, sizeof err);
	print_message("%s: %s\n", lx_gpio_button_api(), err);
	assert_null(g);
	assert_non_null(strstr(err, "gpio: "));
	assert_non_null(strstr(err, "lixel-test-no-such-chip"));
	assert_null(strchr(err, '\n'));
	snprintf(b.gpio_chip, sizeof b.gpio_chip, "/dev/gpiochip-lixel-test");
	assert_null(lx_gpio_button_open(&b, err, sizeof err));
	assert_non_null(strstr(err, "gpio: cannot open chip /dev/gpiochip-lixel-test"));
	/* the Raspberry Pi 5's profile names its line: here there is no chip to find it on */
	char perr[256];
	assert_true(lx_board_load("raspberry-pi-5", &b, perr, sizeof perr));
	assert_null(lx_gpio_button_open(&b, err, sizeof err));
	print_message("raspberry-pi-5 here: %s\n", err);
	assert_non_null(strstr(err, "pinctrl-rp1"));
	assert_null(strchr(err, '\n'));
}

/* Fake chips as the Raspberry Pi 5 shows them: before Linux 6.6.45 the header's GPIOs
 * (chip label pinctrl-rp1, lines GPIO0..GPIO27 among 54) are gpiochip4, from 6.6.45 on
 * gpiochip0. The Pi 5 profile finds GPIO17 on either; offsets would not survive. */
static const char *rp1_names[54];
static char rp1_buf[54][16];
static const char *brcm_names[32] = {"RP1_SDA", "RP1_SCL", "RP1_RUN", "SD_IOVDD_SEL", "SD_PWR_ON", "SD_CDET_N"};

static void fake_pi5(struct lx_gpio_chip_info *chips, bool new_kernel)
{
	for (int k = 0; k < 54; k++) {
		snprintf(rp1_buf[k], sizeof rp1_buf[k], k < 28 ? "GPIO%d" : "PCIE_%d", k);
		rp1_names[k] = rp1_buf[k];
	}
	static const char *const labels[5] = {"gpio-brcmstb@107d508500", "gpio-brcmstb@107d508540", "gpio-brcmstb@107d517c00",
					      "gpio-brcmstb@107d517c20", "pinctrl-rp1"};
	for (int i = 0; i < 5; i++) {
		int label = new_kernel ? (i + 4) % 5 : i; /* 6.6.45: the RP1 first */
		snprintf(chips[i].name, sizeof chips[i].name, "gpiochip%d", i);
		snprintf(chips[i].path, sizeof chips[i].path, "/dev/gpiochip%d", i);
		snprintf(chips[i].label, sizeof chips[i].label, "%s", labels[label]);
		bool rp1 = label == 4;
		chips[i].lines = rp1 ? 54 : 32;
		chips[i].line_names = rp1 ? rp1_names : brcm_names;
	}
}

static void pi5_button_is_found_by_name(void **state)
{
	(void)state;
	struct lx_board b;
	char err[256];
	assert_true(lx_board_load("raspberry-pi-5", &b, err, sizeof err));
	assert_string_equal(b.gpio_line_name, "GPIO17");
	struct lx_gpio_chip_info chips[5];
	for (int k = 0; k < 2; k++) {
		fake_pi5(chips, k == 1);
		unsigned offset = 99;
		int i = lx_gpio_find(&b, chips, 5, &offset, err, sizeof err);
		if (i < 0)
			fail_msg("%s", err);
		print_message("%s kernel: %s (%s) line %u\n", k ? "6.6.45+" : "older", chips[i].name, chips[i].label, offset);
		assert_string_equal(chips[i].name, k ? "gpiochip0" : "gpiochip4");
		assert_int_equal(offset, 17);
		/* an offset-only profile on gpiochip4 finds the wrong chip after the move */
		struct lx_board old = b;
		snprintf(old.gpio_chip, sizeof old.gpio_chip, "gpiochip4");
		old.gpio_line_name[0] = 0, old.gpio_line = 17;
		i = lx_gpio_find(&old, chips, 5, &offset, err, sizeof err);
		assert_string_equal(chips[i].label, k ? "gpio-brcmstb@107d517c20" : "pinctrl-rp1");
	}
	/* by name on any chip, a name found nowhere, a name on two chips, a chip not there */
	struct lx_board any = b;
	snprintf(any.gpio_chip, sizeof any.gpio_chip, "auto");
	unsigned offset;
	assert_int_equal(lx_gpio_find(&any, chips, 5, &offset, err, sizeof err), 0);
	snprintf(any.gpio_line_name, sizeof any.gpio_line_name, "GPIO99");
	assert_int_equal(lx_gpio_find(&any, chips, 5, &offset, err, sizeof err), -1);
	assert_non_null(strstr(err, "no line named GPIO99"));
	snprintf(any.gpio_line_name, sizeof any.gpio_line_name, "RP1_SDA");
	assert_int_equal(lx_gpio_find(&any, chips, 5, &offset, err, sizeof err), -1);
	assert_non_null(strstr(err, "on both"));
	struct lx_board none = b;
	snprintf(none.gpio_chip, sizeof none.gpio_chip, "pinctrl-rp2");
	assert_int_equal(lx_gpio_find(&none, chips, 5, &offset, err, sizeof err), -1);
	assert_non_null(strstr(err, "no chip named pinctrl-rp2"));
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(missing_chip_is_one_clear_line),
		cmocka_unit_test(pi5_button_is_found_by_name),
	};
	return cmocka_run_group_tests_name("gpio", tests, NULL, NULL);
}
