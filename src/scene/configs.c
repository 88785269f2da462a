#include "configs.h"
#include <string.h>

const struct lx_config lx_configs[] = {
	{.name = "default", .summary = "the scene as it is"},
	{.name = "overhead", .summary = "point light straight above the scene", .light = 1, .light_pos = {0.2, 7.0, 0.3}},
	{.name = "low", .summary = "low point light, long shadows across the floor", .light = 1, .light_pos = {6.0, 1.6, 1.5}},
	{.name = "facing", .summary = "light in front of the camera, shining towards it", .light = 1,
	 .light_pos = {0.5, 3.5, -4.0}},
	{.name = "behind", .summary = "light behind the camera", .light = 1, .light_pos = {0.8, 4.0, 8.5}},
	{.name = "miner", .summary = "miner's lamp: the light at the eye", .light = 3},
	{.name = "floor-close", .summary = "camera close to the floor, looking at shadows on the wall", .set_camera = true,
	 .eye = {0.6, 0.15, 3.5}, .at = {0.0, 1.4, -5.0}, .light = 1, .light_pos = {1.0, 2.2, 4.0}},
	{.name = "horizon", .summary = "camera looking level: the floor's horizon is in view", .set_camera = true,
	 .eye = {0.0, 1.0, 4.5}, .at = {0.0, 1.0, -5.0}},
	{.name = "directional", .summary = "directional light from above and to the side", .light = 2,
	 .light_dir = {-0.4, -1.0, -0.3}},
	{.name = "near-wall", .summary = "point light close to the wall, a plane of interest", .light = 1,
	 .light_pos = {1.0, 3.0, -4.9}},
};
const int lx_config_count = sizeof lx_configs / sizeof lx_configs[0];

const struct lx_config *lx_config_find(const char *name)
{
	for (int i = 0; i < lx_config_count; i++)
		if (!strcmp(lx_configs[i].name, name))
			return &lx_configs[i];
	return NULL;
}

void lx_config_apply(const struct lx_config *c, struct lx_scene *s)
{
	if (c->set_camera) {
		s->camera.eye = c->eye;
		s->camera.at = c->at;
	}
	switch (c->light) {
	case 1:
		s->light = lx_light_white(c->light_pos);
		break;
	case 2:
		s->light.directional = true;
		v3_normalize(c->light_dir, &s->light.direction); /* table entries are non-zero */
		break;
	case 3:
		s->light = lx_light_white(s->camera.eye);
		break;
	default:
		break;
	}
}
