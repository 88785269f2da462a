/* --lookup-region footprint against all (test_render, test_filter). Footprint draws no
 * lookup where only the receiver itself could shadow it (src/shadow/lookup_region.h), so
 * the two may differ where all read a caster's own texels on its side turned to the
 * light, and there only. Include after test_util.h. */
#ifndef LX_LOOKUP_CHECK_H
#define LX_LOOKUP_CHECK_H
#include "frame.h"
#include "reference.h"
#include <math.h>

/* Whether another object blocks the light where pixel i's exact eye ray meets `object`;
 * false where the ray meets another object first (a silhouette pixel, which the metrics
 * do not compare either), true where it meets nothing. */
static inline bool others_block(const struct lx_frame *f, const struct lx_raycaster *rc, long i, int object)
{
	vec3 p;
	int tri = lx_reference_pixel(f, rc, (int)(i % f->view.width), (int)(i / f->view.width), &p);
	if (tri < 0)
		return true;
	if (lx_raycaster_object(rc, tri) != object)
		return false;
	const struct lx_light *L = &f->light;
	vec3 d = L->directional ? v3_scale(L->direction, -1) : v3_sub(L->position, p);
	return lx_raycast_blocked(rc, p, d, 0, L->directional ? INFINITY : 1, object);
}

/* Whether pixel i, where footprint and all differ, may: it shows caster `object` in both,
 * footprint's is the lighter decision, and no other object blocks the light there. The
 * reference's caster *rc is made on first use (free it with lx_raycaster_destroy). */
static inline bool own_texels(const struct lx_frame *f, struct lx_raycaster **rc, long i, int object,
			      bool footprint_lighter)
{
	if (object < f->scene->plane_count || !footprint_lighter)
		return false;
	if (!*rc)
		assert_non_null(*rc = lx_raycaster_create(f));
	return !others_block(f, *rc, i, object);
}

#endif
