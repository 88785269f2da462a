#include "gpio_lookup.h"
#include <stdio.h>
#include <string.h>

/* Whether the board's gpio-chip names this chip: empty or "auto" names any. */
static bool chip_matches(const char *want, const struct lx_gpio_chip_info *c)
{
	return !want[0] || !strcmp(want, "auto") || !strcmp(want, c->name) || !strcmp(want, c->path) ||
	       !strcmp(want, c->label);
}

int lx_gpio_find(const struct lx_board *b, const struct lx_gpio_chip_info *chips, int n, unsigned *offset, char *err,
		 size_t errlen)
{
	const char *chip = b->gpio_chip;
	int found = -1, candidates = 0;
	for (int i = 0; i < n; i++) {
		const struct lx_gpio_chip_info *c = &chips[i];
		if (!chip_matches(chip, c))
			continue;
		candidates++;
		if (!b->gpio_line_name[0]) { /* by offset: the first chip that matches */
			if (b->gpio_line < 0 || b->gpio_line >= c->lines) {
				snprintf(err, errlen, "gpio: chip %s (%s) has %d lines, no line %d", c->name, c->label, c->lines,
					 b->gpio_line);
				return -1;
			}
			*offset = (unsigned)b->gpio_line;
			return i;
		}
		for (int k = 0; k < c->lines; k++)
			if (c->line_names && c->line_names[k] && !strcmp(c->line_names[k], b->gpio_line_name)) {
				if (found >= 0) {
					snprintf(err, errlen, "gpio: line %s is on both %s and %s; name the chip (gpio-chip)",
						 b->gpio_line_name, chips[found].name, c->name);
					return -1;
				}
				found = i, *offset = (unsigned)k;
				break;
			}
	}
	if (found >= 0)
		return found;
	const char *where = chip[0] && strcmp(chip, "auto") ? chip : "any chip";
	if (!candidates)
		snprintf(err, errlen, "gpio: no chip named %s among the %d found", where, n);
	else if (b->gpio_line_name[0])
		snprintf(err, errlen, "gpio: no line named %s on %s (%d chip%s looked at)", b->gpio_line_name, where,
			 candidates, candidates == 1 ? "" : "s");
	else
		snprintf(err, errlen, "gpio: no line %d on %s", b->gpio_line, where);
	return -1;
}
