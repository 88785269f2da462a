/* The kiosk's push button on a GPIO line through libgpiod: the v1 API (1.6, Debian 12)
 * or the v2 API (2.x, Debian 13 and current Raspberry Pi OS), chosen by the build from
 * pkg-config's version (LX_GPIOD_V2). Both edges are watched; v2 debounces in the kernel,
 * v1 leaves it to the button logic (button.h). Bias comes from the board profile;
 * active-low is applied by the button logic, so the edges here are raw levels. */
#ifndef LX_GPIO_BUTTON_H
#define LX_GPIO_BUTTON_H
#include "board.h"
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

struct lx_gpio_edge {
	bool high;    /* the level after the edge */
	int64_t t_ns; /* CLOCK_MONOTONIC */
};

struct lx_gpio_button;

/* NULL with one line in err when the chip or line cannot be had (the caller warns and
 * goes on with the keyboard). */
struct lx_gpio_button *lx_gpio_button_open(const struct lx_board *board, char *err, size_t errlen);
void lx_gpio_button_close(struct lx_gpio_button *g);
int lx_gpio_button_fd(const struct lx_gpio_button *g); /* becomes readable on an edge */
bool lx_gpio_button_level(struct lx_gpio_button *g);   /* the line's level now (high = true) */
/* Reads the pending edges (call when the fd is readable); returns the count or -1. */
int lx_gpio_button_read(struct lx_gpio_button *g, struct lx_gpio_edge *edges, int max);
/* True when the kernel debounces (v2): the button logic then uses a debounce of 0. */
bool lx_gpio_button_kernel_debounce(void);
/* "libgpiod 1.6.3 (v1 API)" or the like. */
const char *lx_gpio_button_api(void);

#endif
