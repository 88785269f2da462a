/* Uniform shadow map: one 512x512 map from the light, orthographic for a directional
 * light and perspective for a point light, focused by unit cube clipping (papers/003):
 * x, y cover the intersection of what receivers and casters project to, near is the
 * casters' minimum depth (no caster is clipped), far is the receivers' maximum depth.
 * The geometry lives in light_space.c, shared with the plane-optimal fallback map. */
#include "light_space.h"
#include <math.h>
#include <string.h>

static int uniform_regions(const struct lx_scene *s, const struct lx_method_options *o, struct lx_region_request *out)
{
	(void)s;
	out[0] = (struct lx_region_request){"uniform", o->uniform_lixels, o->uniform_lixels};
	return 1;
}

static void uniform_build(const struct lx_frame *f, const struct lx_atlas *atlas, struct lx_shadow_result *out)
{
	(void)atlas;
	memset(out, 0, sizeof(*out)); /* nothing survives from an earlier frame */
	struct lx_shadow_map *map = &out->maps[0];
	out->map_count = 1;
	*map = (struct lx_shadow_map){.region = 0, .rendered = false, .light_clip = m4_identity()};
	lx_shadow_map_full(map);
	struct lx_light_space ls;
	lx_light_space_build(f, &ls);
	struct lx_poly wanted;
	double x0 = -INFINITY, x1 = INFINITY, y0 = -INFINITY, y1 = INFINITY;
	if (lx_light_space_wanted(&ls, &wanted)) {
		if (wanted.n < 3)
			return; /* nothing to shadow, or casters and receivers do not overlap */
		lx_poly_bounds(&wanted, &x0, &y0, &x1, &y1);
	}
	map->rendered = lx_light_space_map(&ls, x0, x1, y0, y1, &map->light_clip, out, "uniform");
}

const struct lx_shadow_method lx_method_uniform = {.name = "uniform",
	.summary = "one map (512x512) focused by unit cube clipping",
	.regions = uniform_regions,
	.build = uniform_build};
