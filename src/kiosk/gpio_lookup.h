/* Which GPIO chip and line the kiosk's button is on, GL-free and hardware-free: the
 * board names the chip by name (gpiochip0), path or label (pinctrl-rp1), or not at all,
 * and the line by offset or by name (GPIO17). Names survive what offsets do not: on the
 * Raspberry Pi 5 the header's GPIOs moved from gpiochip4 to gpiochip0 in Linux 6.6.45.
 * gpio_button.c lists the machine's chips; the tests give fake ones. */
#ifndef LX_GPIO_LOOKUP_H
#define LX_GPIO_LOOKUP_H
#include "board.h"

struct lx_gpio_chip_info {
	char name[32];  /* gpiochip4 */
	char path[272]; /* /dev/gpiochip4 */
	char label[64]; /* pinctrl-rp1 */
	int lines;
	const char *const *line_names; /* lines entries, NULL or "" where unnamed */
};

/* The chip (index into chips) and line offset for the board's button; -1 with one line
 * in err (what was looked for, and where) when there is none. A line named on more than
 * one chip of those that match is an error too: the board must then name the chip. */
int lx_gpio_find(const struct lx_board *b, const struct lx_gpio_chip_info *chips, int n, unsigned *offset, char *err,
		 size_t errlen);

#endif
