#include "shadow_method.h"
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

extern const struct lx_shadow_method lx_method_none, lx_method_uniform;

static const struct lx_shadow_method *const methods[] = {&lx_method_none, &lx_method_uniform};

const struct lx_shadow_method *lx_shadow_method_find(const char *name)
{
	for (size_t i = 0; i < sizeof methods / sizeof methods[0]; i++)
		if (!strcmp(methods[i]->name, name))
			return methods[i];
	return NULL;
}

const char *lx_shadow_method_names(void) { return "none|uniform"; }

void lx_shadow_warn(struct lx_shadow_result *r, const char *fmt, ...)
{
	if (r->warning_count == LX_MAX_WARNINGS)
		return;
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(r->warnings[r->warning_count++], LX_WARNING_MAX, fmt, ap);
	va_end(ap);
}

mat4 lx_shadow_texture_matrix(const struct lx_atlas *atlas, int region, const mat4 *light_clip)
{
	const struct lx_region *g = &atlas->regions[region];
	mat4 s = m4_identity();
	/* atlas width and height are >= 1 once laid out */
	s.m[0] = 0.5 * g->w / atlas->width;
	s.m[12] = (g->x + 0.5 * g->w) / atlas->width;
	s.m[5] = 0.5 * g->h / atlas->height;
	s.m[13] = (g->y + 0.5 * g->h) / atlas->height;
	s.m[10] = 0.5;
	s.m[14] = 0.5;
	return m4_mul(&s, light_clip);
}
