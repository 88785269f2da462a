#include "shadow_filter.h"
#include <string.h>

static const struct {
	const char *name, *define;
	double reach;
	int taps;
} filters[LX_FILTER_COUNT] = {
	[LX_FILTER_NONE] = {"none", "", 0.0, 1},
	[LX_FILTER_PCF2X2] = {"pcf2x2", "#define LX_FILTER 1\n", 0.5, 4},
	[LX_FILTER_PCF3X3] = {"pcf3x3", "#define LX_FILTER 2\n", 1.0, 9},
};

static enum lx_filter valid(enum lx_filter f) { return (unsigned)f < LX_FILTER_COUNT ? f : LX_FILTER_NONE; }

const char *lx_filter_name(enum lx_filter f) { return filters[valid(f)].name; }

bool lx_filter_parse(const char *s, enum lx_filter *out)
{
	for (int f = 0; f < LX_FILTER_COUNT; f++)
		if (s && !strcmp(s, filters[f].name)) {
			*out = (enum lx_filter)f;
			return true;
		}
	return false;
}

const char *lx_filter_names(void) { return "none, pcf2x2 or pcf3x3"; }

double lx_filter_reach(enum lx_filter f) { return filters[valid(f)].reach; }

int lx_filter_taps(enum lx_filter f) { return filters[valid(f)].taps; }

const char *lx_filter_define(enum lx_filter f) { return filters[valid(f)].define; }
