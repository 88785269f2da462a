/* No shadows: the baseline every other method's frame time is compared with. */
#include "shadow_method.h"

static int none_regions(const struct lx_scene *s, const struct lx_method_options *o, struct lx_region_request *out)
{
	(void)s;
	(void)o;
	(void)out;
	return 0;
}

static void none_build(const struct lx_frame *f, const struct lx_atlas *atlas, const struct lx_method_options *opt,
			 struct lx_shadow_result *out)
{
	(void)opt;
	(void)f;
	(void)atlas;
	(void)out; /* no map: lx_shadow_method_frame cleared it */
}

const struct lx_shadow_method lx_method_none = {
	.name = "none", .summary = "no shadows (the baseline)", .regions = none_regions, .build = none_build};
