/* A shadow method built for one frame of a scene, GL-free: the fixture of the method
 * tests. Include after test_util.h. */
#ifndef LX_METHOD_FIXTURE_H
#define LX_METHOD_FIXTURE_H
#include "shadow_method.h"

struct setup {
	struct lx_scene scene;
	struct lx_scene_meshes meshes;
	struct lx_frame frame;
	struct lx_atlas atlas;
	struct lx_shadow_result res;
};

/* The radius at height y of caster id's exact shape, a cylinder or a cone standing on
 * f->offset[id] (its mesh lies inside it). */
static inline double caster_radius_at(const struct lx_frame *f, int id, double y)
{
	const struct lx_caster *c = &f->scene->casters[id - f->scene->plane_count];
	return c->shape == LX_CONE ? c->size.x * (1 - (y - f->offset[id].y) / c->size.y) : c->size.x;
}

/* Builds s->scene's meshes and frame at time t and runs the method's build with options
 * o; false (and nothing to free) when the camera is degenerate. Free with
 * lx_meshes_free(&s->meshes). */
static bool build_with(struct setup *s, const char *method, int w, int h, double t, const struct lx_method_options *o)
{
	struct lx_region_request req[LX_MAX_MAPS];
	const struct lx_shadow_method *m = lx_shadow_method_find(method);
	char err[256];
	assert_non_null(m);
	assert_true(lx_meshes_build(&s->scene, &s->meshes));
	if (!lx_frame_setup(&s->frame, &s->scene, &s->meshes, t, w, h, err, sizeof err)) {
		lx_meshes_free(&s->meshes);
		return false;
	}
	assert_true(lx_atlas_layout(&s->atlas, req, lx_shadow_method_regions(m, &s->scene, o, req), 1, 2048, err, sizeof err));
	lx_shadow_method_frame(m, &s->frame, &s->atlas, o, &s->res);
	return true;
}

/* The same with the default options. */
static bool build(struct setup *s, const char *method, int w, int h, double t)
{
	struct lx_method_options o = LX_METHOD_OPTIONS_DEFAULT;
	return build_with(s, method, w, h, t, &o);
}

#endif
