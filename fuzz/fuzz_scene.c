/* libFuzzer harness: scene files (lx_scene_parse). A scene that parses must be one the
 * renderer can take: counts within the arrays, every number finite, unique named planes
 * whose normal is a unit vector square to both edges on the lit side, a unit light
 * direction, a camera that makes a view matrix, and casters whose sizes, periods,
 * bounces, colours and height at time 0 are in range. */
#include "fuzz_util.h"
#include "scene.h"
#include <math.h>

static int finite3(vec3 v) { return isfinite(v.x) && isfinite(v.y) && isfinite(v.z); }
static int unit(vec3 v) { return finite3(v) && fabs(v3_len(v) - 1) < 1e-9; }
static int color_ok(vec3 c) { return c.x >= 0 && c.x <= 1 && c.y >= 0 && c.y <= 1 && c.z >= 0 && c.z <= 1; }

static void check_scene(const struct lx_scene *s)
{
	FUZZ_CHECK(s->plane_count >= 0 && s->plane_count <= LX_MAX_PLANES);
	FUZZ_CHECK(s->caster_count >= 0 && s->caster_count <= LX_MAX_CASTERS);
	FUZZ_CHECK(lx_scene_object_count(s) >= 1);
	for (int i = 0; i < s->plane_count; i++) {
		const struct lx_plane *p = &s->planes[i];
		size_t nl = strnlen(p->name, sizeof p->name);
		FUZZ_CHECK(nl >= 1 && nl < sizeof p->name);
		for (int j = 0; j < i; j++)
			FUZZ_CHECK(strcmp(p->name, s->planes[j].name) != 0);
		FUZZ_CHECK(finite3(p->corner) && finite3(p->edge1) && finite3(p->edge2));
		FUZZ_CHECK(color_ok(p->color));
		/* "planes are validated non-degenerate" (scene.h): the normal is the real one */
		vec3 n = lx_plane_normal(p);
		double l1 = v3_len(p->edge1), l2 = v3_len(p->edge2);
		FUZZ_CHECK(isfinite(l1) && l1 > 0 && isfinite(l2) && l2 > 0);
		FUZZ_CHECK(unit(n));
		/* square to the edges, to what the cross product of edges the parser lets be
		 * nearly parallel (down to 1e-9 rad) can give in double */
		FUZZ_CHECK(fabs(v3_dot(n, p->edge1)) <= 1e-5 * l1 && fabs(v3_dot(n, p->edge2)) <= 1e-5 * l2);
		FUZZ_CHECK(v3_dot(v3_cross(p->edge1, p->edge2), n) > 0); /* the lit side: edge1 x edge2 */
	}
	for (int i = 0; i < s->caster_count; i++) {
		const struct lx_caster *c = &s->casters[i];
		FUZZ_CHECK(c->shape >= 0 && c->shape < LX_SHAPE_COUNT);
		FUZZ_CHECK(finite3(c->size) && c->size.x > 0 && c->size.y > 0 && c->size.z > 0);
		FUZZ_CHECK(isfinite(c->x) && isfinite(c->z) && isfinite(c->low) && isfinite(c->high));
		FUZZ_CHECK(c->low <= c->high);
		FUZZ_CHECK(isfinite(c->period) && c->period > 0 && isfinite(c->phase));
		FUZZ_CHECK(color_ok(c->color));
		double b = lx_caster_bottom(c, 0);
		double tol = 1e-12 * (fabs(c->low) + fabs(c->high));
		FUZZ_CHECK(isfinite(b) && b >= c->low - tol && b <= c->high + tol);
	}
	if (s->light.directional)
		FUZZ_CHECK(unit(s->light.direction));
	else
		FUZZ_CHECK(finite3(s->light.position));
	const struct lx_camera *cam = &s->camera;
	FUZZ_CHECK(finite3(cam->eye) && finite3(cam->at) && finite3(cam->up));
	FUZZ_CHECK(cam->fovy_deg > 0 && cam->fovy_deg < 180);
	mat4 view;
	FUZZ_CHECK(m4_look_at(cam->eye, cam->at, cam->up, &view));
	for (int k = 0; k < 16; k++)
		FUZZ_CHECK(isfinite(view.m[k]));
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	char *text = fuzz_text(data, size);
	struct lx_scene s;
	char err[256];
	memset(err, 0x55, sizeof err);
	if (lx_scene_parse(text, "fuzz.scene", &s, err, sizeof err))
		check_scene(&s);
	else
		fuzz_check_error(err, sizeof err, "fuzz.scene");
	free(text);
	return 0;
}
