/* The named view and light configurations every comparison covers (docs/lixel.md,
 * "The exact reference and the metrics"), applied on top of a scene. GL-free. */
#ifndef LX_CONFIGS_H
#define LX_CONFIGS_H
#include "scene.h"

struct lx_config {
	const char *name;
	const char *summary;
	bool set_camera;
	vec3 eye, at;
	int light; /* 0: keep the scene's; 1: point at `light_pos`; 2: directional along `light_dir`; 3: point at the eye */
	vec3 light_pos, light_dir;
};

extern const struct lx_config lx_configs[];
extern const int lx_config_count;

const struct lx_config *lx_config_find(const char *name);
void lx_config_apply(const struct lx_config *c, struct lx_scene *s);

#endif
