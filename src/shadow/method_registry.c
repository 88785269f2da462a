/* The shadow methods lixel knows, in the order its reports list them (the baseline
 * first). Adding a method: its file (method_NAME.c, defining lx_method_NAME) and one line
 * here; the command line, the help texts, the bench's default list, the board profiles'
 * checks and the kiosk's default order all read this list. */
#include "shadow_method.h"
#include <stddef.h>

extern const struct lx_shadow_method lx_method_none, lx_method_uniform, lx_method_psm, lx_method_lispsm,
	lx_method_xpsm, lx_method_tsm, lx_method_plane;

static const struct lx_shadow_method *const registry[] = {
	&lx_method_none,
	&lx_method_uniform,
	&lx_method_psm,
	&lx_method_lispsm,
	&lx_method_xpsm,
	&lx_method_tsm,
	&lx_method_plane,
};

int lx_shadow_method_count(void) { return (int)(sizeof registry / sizeof registry[0]); }

const struct lx_shadow_method *lx_shadow_method_at(int i)
{
	return i >= 0 && i < lx_shadow_method_count() ? registry[i] : NULL;
}
