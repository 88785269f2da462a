/* The GPIO backend on a machine without GPIO: a missing chip is one clear message, not
 * a crash, and the kiosk can go on with the keyboard. */
#include "gpio_button.h"
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
	assert_non_null(strstr(err, "gpio: cannot open chip"));
	assert_non_null(strstr(err, "lixel-test-no-such-chip"));
	assert_null(strchr(err, '\n'));
	snprintf(b.gpio_chip, sizeof b.gpio_chip, "/dev/gpiochip-lixel-test");
	assert_null(lx_gpio_button_open(&b, err, sizeof err));
	assert_non_null(strstr(err, "/dev/gpiochip-lixel-test"));
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(missing_chip_is_one_clear_line),
	};
	return cmocka_run_group_tests_name("gpio", tests, NULL, NULL);
}
