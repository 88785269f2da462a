#include "shadow_method.h"
#include "light_space.h"
#include "number.h"
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const struct lx_shadow_method *lx_shadow_method_find(const char *name)
{
	for (int i = 0; i < lx_shadow_method_count(); i++)
		if (!strcmp(lx_shadow_method_at(i)->name, name))
			return lx_shadow_method_at(i);
	return NULL;
}

/* The registry's names joined by sep, in a buffer of its own per separator. */
static const char *joined(char sep, char *buf, size_t len)
{
	size_t used = 0;
	buf[0] = 0;
	for (int i = 0; i < lx_shadow_method_count(); i++)
		used += (size_t)snprintf(buf + used, used < len ? len - used : 0, "%s%s", i ? (char[2]){sep, 0} : "",
					 lx_shadow_method_at(i)->name);
	return buf;
}

const char *lx_shadow_method_names(void)
{
	static char buf[256];
	return buf[0] ? buf : joined('|', buf, sizeof buf);
}

const char *lx_shadow_method_list(void)
{
	static char buf[256];
	return buf[0] ? buf : joined(',', buf, sizeof buf);
}

const struct lx_shadow_method *lx_shadow_method_spec(const char *spec, struct lx_method_options *o, char *err,
						     size_t errlen)
{
	char buf[64];
	if (strlen(spec) >= sizeof buf) {
		snprintf(err, errlen, "method '%.20s...' is too long", spec);
		return NULL;
	}
	strcpy(buf, spec);
	char *rest = strchr(buf, '/');
	if (rest)
		*rest++ = 0;
	const struct lx_shadow_method *m = lx_shadow_method_find(buf);
	if (!m) {
		snprintf(err, errlen, "unknown method '%s', expected %s", buf, lx_shadow_method_names());
		return NULL;
	}
	while (rest) {
		char *opt = rest;
		rest = strchr(rest, '/');
		if (rest)
			*rest++ = 0;
		double lpp;
		int lights, slots;
		if (!strcmp(opt, "all") || !strcmp(opt, "footprint"))
			o->lookup_everywhere = opt[0] == 'a';
		else if (!strcmp(opt, "pointdepth") || !strcmp(opt, "facedepth"))
			o->caster_face_depth = opt[0] == 'f';
		else if (!strncmp(opt, "lights", 6) && !lx_number_int(opt + 6, 1, LX_MAX_LIGHTS, &lights))
			o->max_lights = lights;
		else if (!strncmp(opt, "slots", 5) && !lx_number_int(opt + 5, 1, LX_DEPTH_SLOTS_MAX, &slots))
			o->depth_slots = slots;
		else if (strcmp(m->name, "plane")) {
			snprintf(err, errlen,
				 "method '%s': option '%s', expected all, footprint, pointdepth, facedepth, lightsN (1 <= N <= %d) or slotsN (1 <= N <= %d)",
				 m->name, opt, LX_MAX_LIGHTS, LX_DEPTH_SLOTS_MAX);
			return NULL;
		} else if (!strcmp(opt, "square") || !strcmp(opt, "fitted"))
			o->square_regions = opt[0] == 's';
		else if (!strcmp(opt, "shared") || !strcmp(opt, "fixed"))
			o->shared_budget = opt[0] == 's';
		else if (!strcmp(opt, "twist") || !strcmp(opt, "aligned"))
			o->plane_twist = opt[0] == 't';
		else if (!strcmp(opt, "budget") || !strcmp(opt, "readers"))
			o->plane_dense_budget = opt[0] == 'b';
		else if (!strcmp(opt, "casterdense") || !strcmp(opt, "casterfallback"))
			o->caster_fallback_only = opt[6] == 'f';
		else if (!strcmp(opt, "uncapped"))
			o->plane_max_lpp = -1;
		else if (!strcmp(opt, "onepiece"))
			o->plane_one_piece = true;
		else if (!strcmp(opt, "similar") || !strcmp(opt, "stretch"))
			o->plane_similar = opt[1] == 'i';
		else if (!strcmp(opt, "unslabbed") || !strcmp(opt, "slabbed"))
			o->plane_unslabbed = opt[0] == 'u';
		else if (!strncmp(opt, "lpp", 3) && !lx_number_real(opt + 3, 0, 1e4, &lpp) && lpp > 0)
			o->plane_max_lpp = lpp;
		else {
			snprintf(err, errlen, "method '%s': option '%s', expected square, fitted, shared, fixed, twist, aligned, budget, readers, casterdense, casterfallback, uncapped, onepiece, similar, stretch, unslabbed, slabbed, lppX (0 < X <= 10000), all, footprint, pointdepth, facedepth, lightsN (1 <= N <= %d) or slotsN (1 <= N <= %d)",
				 spec, opt, LX_MAX_LIGHTS, LX_DEPTH_SLOTS_MAX);
			return NULL;
		}
	}
	return m;
}

static int scaled_side(int side, double k)
{
	long s = lround(side * k);
	return s < 1 ? 1 : s > side ? side : (int)s;
}

struct lx_method_options lx_method_options_for_light(const struct lx_method_options *o, int light)
{
	struct lx_method_options r = *o;
	double share = light >= 0 && light < LX_MAX_LIGHTS ? o->light_share[light] : 0;
	if (!(share > 0 && share < 1))
		return r; /* all of the budget */
	double k = sqrt(share); /* share > 0 */
	r.uniform_lixels = scaled_side(o->uniform_lixels, k);
	r.plane_lixels = scaled_side(o->plane_lixels, k);
	r.fallback_lixels = scaled_side(o->fallback_lixels, k);
	return r;
}

bool lx_light_budget_parse(const char *s, struct lx_method_options *o)
{
	int n = 1;
	for (const char *c = s; *c; c++)
		n += *c == ',';
	double share[LX_MAX_LIGHTS];
	if (n > LX_MAX_LIGHTS || lx_number_reals(s, n, LX_LIGHT_SHARE_MIN, 1, share, NULL))
		return false;
	for (int i = 0; i < LX_MAX_LIGHTS; i++)
		o->light_share[i] = i < n ? share[i] : share[n - 1];
	return true;
}

int lx_method_lights(const struct lx_method_options *o, const struct lx_scene *s)
{
	int n = lx_scene_light_count(s);
	return o->max_lights > 0 && o->max_lights < n ? o->max_lights : n;
}

int lx_shadow_method_regions(const struct lx_shadow_method *m, const struct lx_scene *s,
			     const struct lx_method_options *o, struct lx_region_request *out)
{
	if (m->regions)
		return m->regions(s, o, out);
	out[0] = (struct lx_region_request){m->name, o->uniform_lixels, o->uniform_lixels, 0, false, 0};
	return 1;
}


void lx_shadow_map_full(struct lx_shadow_map *m)
{
	m->plane = -1;
	m->bounds[0] = m->bounds[1] = -1;
	m->bounds[2] = m->bounds[3] = 1;
}

/* The first LX_MAX_READS maps of a set: the most one draw reads. */
static unsigned first_reads(unsigned mask)
{
	unsigned kept = 0;
	for (int i = 0, n = 0; i < LX_MAX_MAPS && n < LX_MAX_READS; i++)
		if (mask & 1u << i)
			kept |= 1u << i, n++;
	return kept;
}

unsigned lx_shadow_receiver_maps(const struct lx_shadow_result *r, int object)
{
	unsigned own = 0, shared = 0;
	if (object >= 0 && object < LX_MAX_PLANES + LX_MAX_CASTERS && r->object_maps[object])
		return first_reads(r->object_maps[object]);
	for (int i = 0; i < r->map_count && i < LX_MAX_MAPS; i++) {
		const struct lx_shadow_map *m = &r->maps[i];
		if (!m->rendered)
			continue;
		if (m->plane < 0)
			shared |= 1u << i;
		else if (m->plane == object)
			own |= 1u << i;
	}
	return first_reads(own ? own : shared);
}

int lx_shadow_select_map(const struct lx_shadow_result *r, int object, vec3 p)
{
	return lx_shadow_select_map_in(r, lx_shadow_receiver_maps(r, object), p);
}

int lx_shadow_select_map_in(const struct lx_shadow_result *r, unsigned mask, vec3 p)
{
	for (int i = 0; i < r->map_count; i++) {
		const struct lx_shadow_map *m = &r->maps[i];
		if (!m->rendered || !(mask & 1u << i))
			continue;
		vec4 c = m4_mul_point(&m->light_clip, p);
		if (!(c.w > 0))
			continue;
		double x = c.x / c.w, y = c.y / c.w;
		if (x >= m->bounds[0] && y >= m->bounds[1] && x < m->bounds[2] && y < m->bounds[3])
			return i;
	}
	return -1;
}

static bool fix_winding_at(mat4 *clip, const struct lx_light *light, vec3 p, double size)
{
	vec3 to_light = light->directional ? v3_scale(light->direction, -1) : v3_sub(light->position, p), n, a, b;
	if (!v3_normalize(to_light, &n))
		return false;
	/* two unit vectors spanning the plane through p facing the light: (a, b, n) right-handed */
	if (!v3_normalize(v3_cross(fabs(n.y) < 0.9 ? v3(0, 1, 0) : v3(1, 0, 0), n), &a))
		return false;
	b = v3_cross(n, a);
	double s = 1e-4 * size; /* a small step at the scene's own scale (an absolute one failed below a metre) */
	vec4 q[3] = {m4_mul_point(clip, p), m4_mul_point(clip, v3_add(p, v3_scale(a, s))),
		     m4_mul_point(clip, v3_add(p, v3_scale(b, s)))};
	for (int i = 0; i < 3; i++)
		if (!(q[i].w > 0))
			return false;
	double area = (q[1].x / q[1].w - q[0].x / q[0].w) * (q[2].y / q[2].w - q[0].y / q[0].w) -
		      (q[1].y / q[1].w - q[0].y / q[0].w) * (q[2].x / q[2].w - q[0].x / q[0].w);
	if (area < 0)
		for (int c = 0; c < 4; c++)
			clip->m[c * 4] = -clip->m[c * 4];
	return true;
}

void lx_shadow_fix_winding(mat4 *clip, const struct lx_frame *f)
{
	/* probes where the receivers are: the view's objects' centre (not the whole scene's:
	 * one caster far away would put it where a projective map's winding is the other) */
	vec3 probe[3] = {v3_scale(v3_add(f->view_min, f->view_max), 0.5), f->scene->camera.at,
			 v3_add(f->view.eye, v3_scale(f->view.dir, 2 * f->view.near))};
	double size = v3_len(v3_sub(f->view_max, f->view_min)) + 1e-300;
	for (int i = 0; i < 3 && !fix_winding_at(clip, &f->light, probe[i], size); i++) {
	}
}

void lx_shadow_map_warp(struct lx_shadow_map *map, const struct lx_frame *f, const mat4 *crop, const mat4 *m,
			const char *name, struct lx_shadow_result *out)
{
	mat4 c = m4_mul(crop, m);
	lx_shadow_fix_winding(&c, f);
	if (m4_finite(&c))
		map->light_clip = c;
	else
		lx_shadow_warn(out, "%s: non-finite warp; uniform this frame", name);
}

void lx_shadow_map_turn(struct lx_shadow_map *m)
{
	mat4 c = m->light_clip;
	for (int col = 0; col < 4; col++) { /* row 0 <- -row 1, row 1 <- row 0 */
		m->light_clip.m[col * 4] = -c.m[col * 4 + 1];
		m->light_clip.m[col * 4 + 1] = c.m[col * 4];
	}
	double b[4] = {-m->bounds[3], m->bounds[0], -m->bounds[1], m->bounds[2]};
	memcpy(m->bounds, b, sizeof b);
	int w = m->w;
	m->w = m->h;
	m->h = w;
}

/* A warping method: the uniform map first, focused by unit cube clipping; the warp
 * replaces its matrix where it can, and where it cannot the uniform map stands. */
static void warped_build(const struct lx_shadow_method *m, const struct lx_frame *f, struct lx_shadow_result *out)
{
	struct lx_light_space ls;
	struct lx_uniform_fit fit;
	if (lx_uniform_map(f, &ls, out, m->name, &fit))
		m->warp(f, &ls, &fit, &out->maps[0], out);
}

void lx_shadow_method_frame(const struct lx_shadow_method *m, const struct lx_frame *f, struct lx_atlas *atlas,
			    const struct lx_method_options *o, struct lx_shadow_result *out)
{
	memset(out, 0, sizeof(*out)); /* nothing survives from an earlier frame */
	bool hidden = lx_shadows_hidden(f);
	/* No map (method none), or the light at the eye (every shadow behind its caster, so no
	 * map is drawn): nothing shadowed, by the fronts' tests neither. Tested there, the
	 * table's slab had the floor and the table top run them along its shadow's edges, for
	 * no shadow in sight (0.15-0.2 ms of a 1024x1024 main pass; over every pixel, before
	 * object_draws cut a plane with no map into spans, 1.65 ms). */
	if (atlas->count == 0 || hidden)
		lx_plane_covers_none(&out->covers);
	else
		lx_plane_covers(f, &out->covers);
	if (atlas->count > 0 && !o->keep_flat_boxes)
		lx_slab_faces_left_out(f, &out->covers, out->slab_front, out->slab_face_out, out->slab_out);
	if (m->warp)
		warped_build(m, f, out);
	else
		m->build(f, atlas, o, out);
	for (int i = 0; i < f->note_count; i++)
		lx_shadow_warn(out, "%s", f->notes[i]);
	if (hidden)
		lx_shadow_warn(out, "light: the point light is at the eye, so every shadow lies behind what casts it; "
				    "no shadow map is drawn");
	int w[LX_ATLAS_MAX_REGIONS] = {0}, h[LX_ATLAS_MAX_REGIONS] = {0};
	for (int i = 0; i < out->map_count; i++) {
		const struct lx_shadow_map *map = &out->maps[i];
		if (!map->rendered || map->region < 0 || map->region >= atlas->count)
			continue;
		bool own = map->w > 0 && map->h > 0;
		w[map->region] = own ? map->w : atlas->regions[map->region].w;
		h[map->region] = own ? map->h : atlas->regions[map->region].h;
	}
	int shrunk = lx_atlas_pack(atlas, w, h);
	if (shrunk != 0)
		/* the atlas's own area: what its maps fit in, whatever texture it shares */
		lx_shadow_warn(out, shrunk > 0 ? "atlas: this frame's maps did not fit the %dx%d atlas and were shrunk"
					       : "atlas: this frame's maps do not fit the %dx%d atlas; they are skipped",
			       atlas->width, atlas->height);
	for (int i = 0; i < out->map_count; i++) {
		struct lx_shadow_map *map = &out->maps[i];
		if (!map->rendered || map->region < 0 || map->region >= atlas->count)
			continue;
		const struct lx_region *g = &atlas->regions[map->region];
		if (g->w < 1 || g->h < 1)
			map->rendered = false; /* not placed: no pass, every lookup reads lit */
		else if (g->turned)
			lx_shadow_map_turn(map);
	}
}

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
	double st[4];
	lx_region_to_texture(atlas, region, st);
	mat4 s = m4_identity();
	s.m[0] = st[0], s.m[12] = st[1], s.m[5] = st[2], s.m[13] = st[3];
	s.m[10] = 0.5;
	s.m[14] = 0.5;
	return m4_mul(&s, light_clip);
}
