/* Uniform shadow map: one 512x512 map from the light, orthographic for a directional
 * light and perspective for a point light, focused by unit cube clipping ([Kapoulkine]):
 * x, y cover the intersection of what receivers and casters project to, near is the
 * casters' minimum depth (no caster is clipped), far is the receivers' maximum depth.
 * The geometry lives in light_space.c, shared with the plane-optimal fallback map. */
#include "light_space.h"

static void uniform_build(const struct lx_frame *f, const struct lx_atlas *atlas, const struct lx_method_options *opt,
			 struct lx_shadow_result *out)
{
	(void)opt;
	(void)atlas;
	struct lx_light_space ls;
	lx_uniform_map(f, &ls, out, "uniform", NULL);
}

const struct lx_shadow_method lx_method_uniform = {.name = "uniform",
	.summary = "one map (512x512) focused by unit cube clipping",
	.build = uniform_build};
