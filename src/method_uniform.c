/* Uniform shadow map: one 512x512 map from the light, orthographic for a directional
 * light and perspective for a point light, focused by unit cube clipping (papers/003):
 * x, y cover the intersection of what receivers and casters project to, near is the
 * casters' minimum depth (no caster is clipped), far is the receivers' maximum depth.
 *
 * Receivers are the view frustum clipped to the scene's bounds; casters are the
 * objects' world bounding boxes (a plane counts as a caster only where its back face
 * is towards the light, since the shadow pass writes back faces). */
#include "convex.h"
#include "shadow_method.h"
#include <math.h>

#define UNIFORM_LIXELS 512
/* A point light's frustum is kept within this half-angle; a wider receiver cone would
 * spend the map on grazing directions (or need several maps), so what lies outside is
 * left unshadowed with a warning. */
#define MAX_HALF_ANGLE_DEG 75.0

static int uniform_regions(struct lx_region_request *out)
{
	out[0] = (struct lx_region_request){"uniform", UNIFORM_LIXELS, UNIFORM_LIXELS};
	return 1;
}

struct extent {
	double x0, x1, y0, y1, z0, z1;
};

static struct extent empty_extent(void) { return (struct extent){INFINITY, -INFINITY, INFINITY, -INFINITY, INFINITY, -INFINITY}; }

/* Grows e by world point p seen in light view space: x, y as they are for a directional
 * light, as tangents x/depth, y/depth for a point light. Returns false (e untouched) for
 * a point at or behind a point light, which has no finite projection. */
static bool grow(struct extent *e, const mat4 *lview, bool directional, double tiny, vec3 p)
{
	vec4 q = m4_mul_point(lview, p);
	double depth = -q.z, x = q.x, y = q.y;
	if (!directional) {
		if (!(depth > tiny))
			return false;
		x /= depth, y /= depth;
	}
	e->x0 = fmin(e->x0, x), e->x1 = fmax(e->x1, x);
	e->y0 = fmin(e->y0, y), e->y1 = fmax(e->y1, y);
	e->z0 = fmin(e->z0, depth), e->z1 = fmax(e->z1, depth);
	return true;
}

/* Receiver points: the frustum's corners from the inverse view projection, clipped to the scene box. */
static int receiver_points(const struct lx_frame *f, vec3 *pts)
{
	vec3 fc[8];
	static const double cx[4] = {-1, 1, 1, -1}, cy[4] = {-1, -1, 1, 1};
	for (int i = 0; i < 8; i++) {
		vec4 p = m4_mul_v4(&f->view.inv_view_proj, (vec4){cx[i % 4], cy[i % 4], i < 4 ? -1 : 1, 1});
		/* w > 0 for points inside the view frustum of a valid perspective */
		fc[i] = v3(p.x / p.w, p.y / p.w, p.z / p.w);
	}
	return lx_frustum_box_points(fc, f->scene_min, f->scene_max, pts, LX_CONVEX_MAX_POINTS);
}

/* Which objects can cast: casters always; planes only when their back face is lit. */
static bool can_cast(const struct lx_frame *f, int id)
{
	const struct lx_scene *s = f->scene;
	if (id >= s->plane_count)
		return true;
	const struct lx_plane *p = &s->planes[id];
	vec3 n = lx_plane_normal(p);
	if (f->light.directional)
		return v3_dot(n, f->light.direction) > 0;
	vec3 c = v3_add(p->corner, v3_scale(v3_add(p->edge1, p->edge2), 0.5));
	/* a point light anywhere off the front side sees some of the back face */
	return v3_dot(n, v3_sub(f->light.position, c)) < 0 || fabs(v3_dot(n, v3_sub(f->light.position, p->corner))) < 1e-12;
}

static void uniform_build(const struct lx_frame *f, const struct lx_atlas *atlas, struct lx_shadow_result *out)
{
	(void)atlas;
	struct lx_shadow_map *map = &out->maps[0];
	out->map_count = 1;
	map->region = 0;
	map->rendered = false;
	map->light_clip = m4_identity();

	vec3 rec[LX_CONVEX_MAX_POINTS];
	int nrec = receiver_points(f, rec);
	if (nrec == 0)
		return; /* the view holds nothing of the scene: nothing to shadow */
	vec3 centroid = v3(0, 0, 0);
	for (int i = 0; i < nrec; i++)
		centroid = v3_add(centroid, v3_scale(rec[i], 1.0 / nrec));
	double size = v3_len(v3_sub(f->scene_max, f->scene_min));
	double tiny = 1e-9 * (size + 1e-300);

	/* Light view: looking along the light direction (directional) or from the light
	 * towards the receivers' centroid (point). */
	vec3 eye, dir;
	const struct lx_light *L = &f->light;
	if (L->directional) {
		dir = L->direction;
		eye = v3_sub(centroid, v3_scale(dir, size + 1));
	} else {
		eye = L->position;
		if (!v3_normalize(v3_sub(centroid, eye), &dir)) {
			dir = v3(0, -1, 0); /* light exactly at the centroid: any axis works, the cone is clamped below */
		}
	}
	vec3 up = fabs(dir.y) < 0.9 ? v3(0, 1, 0) : v3(1, 0, 0);
	mat4 lview;
	m4_look_at(eye, v3_add(eye, dir), up, &lview); /* dir is unit and up not parallel: cannot fail */

	/* Extents in light space; for a point light x, y are tangents (x/depth, y/depth). */
	const double tmax = tan(MAX_HALF_ANGLE_DEG * M_PI / 180);
	struct extent re = empty_extent(), ce = empty_extent();
	bool clamped = false, receivers_behind = false;
	for (int i = 0; i < nrec; i++)
		if (!grow(&re, &lview, L->directional, tiny, rec[i]))
			receivers_behind = true;
	bool casters_unbounded = false;
	int ncasters = 0;
	for (int id = 0; id < f->object_count; id++) {
		if (!can_cast(f, id))
			continue;
		ncasters++;
		for (int k = 0; k < 8; k++) {
			vec3 c = v3(k & 1 ? f->bmax[id].x : f->bmin[id].x, k & 2 ? f->bmax[id].y : f->bmin[id].y,
				    k & 4 ? f->bmax[id].z : f->bmin[id].z);
			if (!grow(&ce, &lview, L->directional, tiny, c))
				casters_unbounded = true; /* a box reaching behind the light projects everywhere */
		}
	}
	if (ncasters == 0 || re.z0 > re.z1)
		return; /* nothing casts, or no receiver is in front of the light */
	if (receivers_behind) {
		/* The light is inside the receiver volume: the volume's front part reaches the
		 * light's own plane, so its projection is unbounded; only casters bound it. */
		re.x0 = re.y0 = -INFINITY;
		re.x1 = re.y1 = INFINITY;
	}
	struct extent e = re;
	if (!casters_unbounded) {
		e.x0 = fmax(re.x0, ce.x0), e.x1 = fmin(re.x1, ce.x1);
		e.y0 = fmax(re.y0, ce.y0), e.y1 = fmin(re.y1, ce.y1);
	}
	if (e.x0 > e.x1 || e.y0 > e.y1)
		return; /* casters and receivers do not overlap as seen from the light */
	double znear = casters_unbounded ? -INFINITY : ce.z0, zfar = re.z1;
	if (znear > zfar)
		return; /* every caster lies beyond every receiver */
	if (!L->directional) {
		/* Receivers behind the light can only be shadowed by casters behind it too:
		 * the segment from the light to such a receiver never enters the front half-space. */
		if (e.x0 < -tmax || e.x1 > tmax || e.y0 < -tmax || e.y1 > tmax || (receivers_behind && casters_unbounded)) {
			clamped = true;
			e.x0 = fmax(e.x0, -tmax), e.x1 = fmin(e.x1, tmax);
			e.y0 = fmax(e.y0, -tmax), e.y1 = fmin(e.y1, tmax);
		}
		double min_near = zfar * 1e-4;
		if (znear < min_near) {
			if (!casters_unbounded)
				lx_shadow_warn(out, "uniform: a caster within %.3g m of the point light is clipped by the near plane", min_near);
			znear = min_near;
		}
		if (clamped)
			lx_shadow_warn(out, "uniform: receivers span more than %.0f degrees around the point light; those outside the map are unshadowed",
				       2 * MAX_HALF_ANGLE_DEG);
	}
	/* Keep the frustum non-empty for flat configurations (a single plane edge-on). */
	double pad = L->directional ? 1e-6 * (size + 1e-300) : 1e-9;
	if (e.x1 - e.x0 < pad)
		e.x0 -= pad, e.x1 += pad;
	if (e.y1 - e.y0 < pad)
		e.y0 -= pad, e.y1 += pad;
	/* A sliver of depth margin so the extreme points do not fall exactly on the clip planes. */
	double zpad = fmax((zfar - znear) * 1e-4, L->directional ? 1e-6 * (size + 1e-300) : znear * 1e-4);
	mat4 proj;
	bool ok;
	if (L->directional)
		ok = m4_ortho(e.x0, e.x1, e.y0, e.y1, znear - zpad, zfar + zpad, &proj);
	else {
		double n = fmax(znear - zpad, znear * 0.5);
		ok = m4_frustum(e.x0 * n, e.x1 * n, e.y0 * n, e.y1 * n, n, zfar + zpad, &proj);
	}
	if (!ok) {
		lx_shadow_warn(out, "uniform: degenerate light frustum; the map is skipped this frame");
		return;
	}
	map->light_clip = m4_mul(&proj, &lview);
	map->rendered = m4_finite(&map->light_clip);
	if (!map->rendered)
		lx_shadow_warn(out, "uniform: non-finite light matrix; the map is skipped this frame");
}

const struct lx_shadow_method lx_method_uniform = {.name = "uniform",
	.summary = "one 512x512 map focused by unit cube clipping",
	.regions = uniform_regions,
	.build = uniform_build};
