#include "frame.h"
#include "light_image.h"
#include "convex.h"
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

static void note(struct lx_frame *f, const char *fmt, ...)
{
	if (f->note_count == LX_FRAME_NOTES)
		return;
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(f->notes[f->note_count++], sizeof f->notes[0], fmt, ap);
	va_end(ap);
}

/* The distance from p to the box [lo, hi] (0 inside). */
static double box_distance(vec3 p, vec3 lo, vec3 hi)
{
	double d2 = 0;
	for (int k = 0; k < 3; k++) {
		double e = (&p.x)[k], a = (&lo.x)[k], b = (&hi.x)[k];
		double d = e < a ? a - e : e > b ? e - b : 0;
		d2 += d * d;
	}
	return sqrt(d2); /* d2 >= 0 */
}

/* Whether the box may be inside the view's infinite frustum: false only when all its
 * corners lie outside one side plane (or behind the eye). */
static bool box_in_view(const struct lx_view *v, double aspect, vec3 lo, vec3 hi)
{
	double ty = tan(v->fovy / 2), tx = ty * aspect; /* fovy in (0, pi) */
	int out[5] = {0};
	for (int k = 0; k < 8; k++) {
		vec4 q = m4_mul_point(&v->view, v3_box_corner(lo, hi, k));
		double d = -q.z; /* depth in front of the eye */
		out[0] += q.x > tx * d, out[1] += q.x < -tx * d;
		out[2] += q.y > ty * d, out[3] += q.y < -ty * d, out[4] += d <= 0;
	}
	for (int p = 0; p < 5; p++)
		if (out[p] == 8)
			return false;
	return true;
}

/* f->view_min, view_max: the box of the objects in view, the only receivers there are;
 * the whole scene's when none is. Returns which objects are in view (bit id). */
static unsigned long long view_box(struct lx_frame *f, double aspect)
{
	vec3 lo = v3(INFINITY, INFINITY, INFINITY), hi = v3(-INFINITY, -INFINITY, -INFINITY);
	unsigned long long in_view = 0;
	for (int id = 0; id < f->object_count; id++)
		if (box_in_view(&f->view, aspect, f->bmin[id], f->bmax[id])) {
			in_view |= 1ull << id; /* ids < LX_MAX_PLANES + LX_MAX_CASTERS = 40 */
			lo = v3_min(lo, f->bmin[id]), hi = v3_max(hi, f->bmax[id]);
		}
	if (!(lo.x <= hi.x))
		lo = f->scene_min, hi = f->scene_max;
	f->view_min = lo, f->view_max = hi;
	return in_view;
}

/* A point light LX_FAR_LIGHT_RATIO times farther than the size of what is in view (the
 * objects whose boxes reach the view) is directional for every purpose here, and its
 * perspective maps would lose their depth precision to the distance in the shaders' floats:
 * it becomes the directional light from there to the centre of what is in view. */
static void far_light(struct lx_frame *f)
{
	if (f->light.directional || f->light.projective != LX_LIGHT_PLAIN) /* a projective light keeps its frustum */
		return;
	vec3 lo = f->view_min, hi = f->view_max, d;
	vec3 c = v3_scale(v3_add(lo, hi), 0.5);
	double size = v3_len(v3_sub(hi, lo)), dist = box_distance(f->light.position, lo, hi);
	if (!(dist > LX_FAR_LIGHT_RATIO * size) || !v3_normalize(v3_sub(c, f->light.position), &d))
		return;
	/* the same light from afar: its colour stays */
	vec3 color = f->light.color;
	f->light = (struct lx_light){.directional = true, .position = v3(0, 0, 0), .direction = d, .color = color};
	note(f, "light: the point light is %.3g times farther than the view's objects are wide; taken as directional "
		"(its rays spread by less than 1e-6 rad over them)", dist / size);
}

/* A point light inside a caster's bounds: that caster may hide it from everything. */
static void light_inside_casters(struct lx_frame *f)
{
	if (f->light.directional)
		return;
	vec3 l = f->light.position;
	for (int id = f->scene->plane_count; id < f->object_count; id++)
		if (box_distance(l, f->bmin[id], f->bmax[id]) == 0) {
			note(f, "light: the light is inside the bounds of caster %d (a %s); what it hides is in "
				"shadow", id - f->scene->plane_count + 1,
			     lx_shape_name(f->scene->casters[id - f->scene->plane_count].shape));
			return;
		}
}

/* f->lit_min, lit_max: the view box within a projective light's frustum, as a box (the
 * frustum's apex at the light, its far face at its range or past the whole scene). */
static void lit_box(struct lx_frame *f)
{
	f->lit_min = f->view_min, f->lit_max = f->view_max;
	vec3 fc[8], pts[LX_CONVEX_MAX_POINTS];
	if (!lx_light_frustum(&f->light, f->view_min, f->view_max, fc))
		return;
	int n = lx_frustum_box_points(fc, f->view_min, f->view_max, pts, LX_CONVEX_MAX_POINTS);
	vec3 lo = v3(INFINITY, INFINITY, INFINITY), hi = v3(-INFINITY, -INFINITY, -INFINITY);
	for (int i = 0; i < n; i++) {
		lo = v3_min(lo, pts[i]), hi = v3_max(hi, pts[i]);
	}
	f->lit_min = lo, f->lit_max = hi; /* n == 0: an empty box, lo > hi */
}

bool lx_frame_setup(struct lx_frame *f, const struct lx_scene *s, const struct lx_scene_meshes *m, double t,
		    int width, int height, char *err, size_t errlen)
{
	memset(f, 0, sizeof(*f));
	f->scene = s;
	f->meshes = m;
	f->time = t;
	f->object_count = m->count;
	f->scene_min = v3(INFINITY, INFINITY, INFINITY);
	f->scene_max = v3(-INFINITY, -INFINITY, -INFINITY);
	for (int id = 0; id < m->count; id++) {
		vec3 o = lx_object_offset(s, id, t);
		f->offset[id] = o;
		f->bmin[id] = v3_add(m->mesh[id].bmin, o);
		f->bmax[id] = v3_add(m->mesh[id].bmax, o);
		f->scene_min = v3_min(f->scene_min, f->bmin[id]), f->scene_max = v3_max(f->scene_max, f->bmax[id]);
	}
	struct lx_view *v = &f->view;
	v->width = width;
	v->height = height;
	v->eye = s->camera.eye;
	v->fovy = s->camera.fovy_deg * M_PI / 180;
	v->dir = v3(0, 0, -1);
	v3_normalize(v3_sub(s->camera.at, s->camera.eye), &v->dir); /* look_at below refuses eye == at */
	if (!m4_look_at(s->camera.eye, s->camera.at, s->camera.up, &v->view)) {
		snprintf(err, errlen, "camera: eye equals at, or up is along the view direction");
		return false;
	}
	unsigned long long in_view = view_box(f, (double)width / height);
	/* far: the farthest scene corner; near: the distance to the scene box, at least
	 * far / 1000, but never beyond the nearest object (one caster far from the rest
	 * must not push the near plane past the others), and at least far * 1e-6. */
	double far = 0, nearest = INFINITY;
	for (int id = 0; id < f->object_count; id++) {
		if (!(in_view >> id & 1))
			continue; /* out of view: no reason to stretch the depth range */
		nearest = lx_fmin(nearest, box_distance(v->eye, f->bmin[id], f->bmax[id]));
		for (int i = 0; i < 8; i++)
			far = lx_fmax(far, v3_len(v3_sub(v3_box_corner(f->bmin[id], f->bmax[id], i), v->eye)));
	}
	if (!(far > 0)) /* nothing in view: the whole scene's range */
		for (int i = 0; i < 8; i++)
			far = lx_fmax(far, v3_len(v3_sub(v3_box_corner(f->scene_min, f->scene_max, i), v->eye)));
	double scale = v3_len(v3_sub(f->scene_max, f->scene_min));
	far = far * 1.01 + 1e-9 * scale + 1e-300; /* a scene of a single point still gets a valid range */
	v->far = far;
	v->near = lx_fmin(lx_fmax(box_distance(v->eye, f->view_min, f->view_max) * 0.9, far / 1000), nearest * 0.9);
	if (!(v->near >= far * LX_NEAR_MIN_RATIO)) {
		if (nearest < far * LX_NEAR_MIN_RATIO)
			note(f, "view: an object %.3g m from the eye is nearer than the near plane (%.3g m, a millionth of "
				"the far plane at %.3g m): it is clipped", nearest, far * LX_NEAR_MIN_RATIO, far);
		v->near = far * LX_NEAR_MIN_RATIO;
	}
	if (!(v->near < v->far * 0.5)) /* the whole scene is a speck far away */
		v->near = v->far * 0.5;
	if (!m4_perspective(v->fovy, (double)width / height, v->near, v->far, &v->proj)) {
		snprintf(err, errlen, "camera: cannot build a projection for fov %g degrees and size %dx%d",
			 s->camera.fovy_deg, width, height);
		return false;
	}
	v->view_proj = m4_mul(&v->proj, &v->view);
	if (!m4_invert(&v->view_proj, &v->inv_view_proj)) {
		snprintf(err, errlen, "camera: the view projection is singular");
		return false;
	}
	f->view_note_count = f->note_count;
	f->light_index = -1; /* no light's yet */
	lx_frame_for_light(f, 0, f);
	return true;
}

void lx_frame_for_light(const struct lx_frame *f, int light, struct lx_frame *out)
{
	if (out != f)
		*out = *f;
	if (light == f->light_index)
		return; /* made for that light already (light 0's by lx_frame_setup): a copy is all */
	out->note_count = f->view_note_count;
	out->light_index = light;
	out->light = f->scene->lights[light];
	light_inside_casters(out);
	far_light(out);
	lit_box(out);
}

void lx_frame_plane_corners(const struct lx_frame *f, int id, vec3 out[4])
{
	const struct lx_plane *p = &f->scene->planes[id];
	out[0] = v3_add(p->corner, f->offset[id]);
	out[1] = v3_add(out[0], p->edge1), out[2] = v3_add(out[1], p->edge2), out[3] = v3_add(out[0], p->edge2);
}

/* Plane p's infinite plane as seen from the eye: side(x) > 0 on the eye's side, < 0
 * beyond it. False when the eye lies on it (every side is then 0). */
struct eye_side {
	vec3 n, c0;
	double eye; /* n . (eye - c0) */
};

static bool eye_side(const struct lx_frame *f, int p, struct eye_side *s)
{
	const struct lx_plane *pl = &f->scene->planes[p];
	s->n = v3_cross(pl->edge1, pl->edge2), s->c0 = v3_add(pl->corner, f->offset[p]);
	s->eye = v3_dot(s->n, v3_sub(f->view.eye, s->c0));
	return s->eye != 0;
}

static double side(const struct eye_side *s, vec3 x) { return s->eye * v3_dot(s->n, v3_sub(x, s->c0)); }

/* Whether plane p's infinite plane has every corner of object id's box on its far side
 * from the eye (or on it); false when the eye is on the plane. */
static bool behind_plane(const struct lx_frame *f, int p, int id)
{
	struct eye_side s;
	if (!eye_side(f, p, &s))
		return false;
	for (int k = 0; k < 8; k++)
		if (side(&s, v3_box_corner(f->bmin[id], f->bmax[id], k)) > 0)
			return false;
	return true;
}

void lx_frame_draw_order(const struct lx_frame *f, int *order)
{
	int pc = f->scene->plane_count, n = 0;
	bool front[LX_MAX_PLANES] = {0}, hidden[LX_MAX_PLANES + LX_MAX_CASTERS] = {0};
	for (int id = pc; id < f->object_count; id++)
		for (int p = 0; p < pc; p++)
			if (behind_plane(f, p, id))
				front[p] = hidden[id] = true;
	for (int id = pc; id < f->object_count; id++) /* the casters no plane hides */
		if (!hidden[id])
			order[n++] = id;
	for (int p = 0; p < pc; p++) /* the planes that hide casters */
		if (front[p])
			order[n++] = p;
	for (int id = pc; id < f->object_count; id++) /* the casters they hide */
		if (hidden[id])
			order[n++] = id;
	for (int p = 0; p < pc; p++) /* the other planes */
		if (!front[p])
			order[n++] = p;
}

bool lx_frame_plane_hides(const struct lx_frame *f, int front, int back, struct lx_poly *win)
{
	struct eye_side s;
	vec3 corner[4];
	win->n = 0;
	if (front == back || !eye_side(f, back, &s))
		return false;
	lx_frame_plane_corners(f, front, corner);
	for (int k = 0; k < 4; k++) {
		vec4 c = m4_mul_point(&f->view.view_proj, corner[k]);
		if (!(side(&s, corner[k]) > 0) || !(c.w > 0) || !(c.z > -c.w))
			return false; /* on back's far side, or reaching the near plane, which clips it */
		win->v[k] = lx_view_window_point(&f->view, c);
	}
	win->n = 4;
	return true;
}

bool lx_frame_box_hides(const struct lx_frame *f, int id, int back, vec2 window[8])
{
	struct eye_side s;
	if (id == back || !eye_side(f, back, &s))
		return false;
	double touch = -1e-6 * fabs(s.eye) * v3_len(s.n); /* a micrometre beyond it: on it */
	for (int k = 0; k < 8; k++) {
		vec3 x = v3_box_corner(f->bmin[id], f->bmax[id], k);
		vec4 c = m4_mul_point(&f->view.view_proj, x);
		if (!(side(&s, x) >= touch) || !(c.w > 1e-12 * (fabs(c.x) + fabs(c.y) + fabs(c.z))))
			return false;
		window[k] = lx_view_window_point(&f->view, c);
	}
	return true;
}

/* An octagon in the plane through c with unit normal n, drawn around the circle of radius
 * r there (its corners r / cos(pi/8) out, and a millionth more: the meshes' vertices are
 * floats, and the matrices that carry these points round); for a level circle its sides
 * face the axes, so that it lies within the circle's square, and a cylinder's or cone's
 * outline within its box. */
static void octagon(vec3 c, vec3 n, double r, vec3 *out)
{
	/* cos and sin of (k + 1/2) pi / 4 times 1 / cos(pi / 8): the corners lie at (+-1, +-t)
	 * and (+-t, +-1) times r, t = tan(pi / 8) */
	const double t = 0.41421356237309503; /* an automatic table: t is no constant in C */
	const double u[8][2] = {{1, t}, {t, 1}, {-t, 1}, {-1, t}, {-1, -t}, {-t, -1}, {t, -1}, {1, -t}};
	vec3 a = fabs(n.x) < 0.6 ? v3(1, 0, 0) : v3(0, 1, 0), e1 = a, e2;
	v3_normalize(v3_cross(n, a), &e1); /* |n x a| >= 0.6 for a unit n */
	e2 = v3_cross(n, e1);
	double R = r * (1 + 1e-6);
	for (int k = 0; k < 8; k++)
		out[k] = v3_add(c, v3_add(v3_scale(e1, R * u[k][0]), v3_scale(e2, R * u[k][1])));
}

/* Around a sphere (centre c, radius r), 16 points whose hull holds it and whose image from
 * the light is an octagon drawn around its outline: for a point light at distance d > r,
 * the frustum of the octagonal cone around the rays that touch it (they touch along a
 * circle r^2 / d from c towards the light, of radius r sqrt(1 - r^2 / d^2)), cut where
 * the sphere begins and ends along its axis (d - r and d + r from the light); for a
 * directional light, the prism around it along the direction. False when the light is
 * inside it or on it. */
static bool sphere_outline(const struct lx_light *l, vec3 c, double r, vec3 *out)
{
	if (l->directional) {
		octagon(v3_sub(c, v3_scale(l->direction, r)), l->direction, r, out);
		octagon(v3_add(c, v3_scale(l->direction, r)), l->direction, r, out + 8);
		return true;
	}
	vec3 away = v3_sub(c, l->position);
	double d = v3_len(away);
	if (!(d > r * (1 + 1e-6)) || !isfinite(d))
		return false;
	vec3 u = v3_scale(away, 1 / d); /* d > r > 0 */
	double k = r / d, s = d * (1 - k * k), rho = r * sqrt(1 - k * k); /* k < 1: s, rho > 0 */
	for (int e = 0; e < 2; e++) { /* the cone widens in proportion to the distance */
		double t = e ? d + r : d - r;
		octagon(v3_add(l->position, v3_scale(u, t)), u, rho * t / s, out + 8 * e);
	}
	return true;
}

int lx_frame_object_outline(const struct lx_frame *f, int id, bool image_only, vec3 pts[LX_OUTLINE_POINTS])
{
	int pc = f->scene->plane_count;
	if (id >= pc) {
		const struct lx_caster *c = &f->scene->casters[id - pc];
		vec3 o = f->offset[id], up = v3(0, 1, 0);
		double r = c->size.x, h = c->size.y;
		switch (c->shape) {
		case LX_SPHERE: /* the far octagon lies on the near one's rays from the light */
			if (sphere_outline(&f->light, v3_add(o, v3(0, r, 0)), r, pts))
				return image_only ? 8 : 16;
			break;
		case LX_CYLINDER:
			octagon(o, up, r, pts);
			octagon(v3_add(o, v3(0, h, 0)), up, r, pts + 8);
			return 16;
		case LX_CONE:
			octagon(o, up, r, pts);
			pts[8] = v3_add(o, v3(0, h, 0));
			return 9;
		default:
			break;
		}
	}
	for (int k = 0; k < 8; k++)
		pts[k] = v3_box_corner(f->bmin[id], f->bmax[id], k);
	return 8;
}

bool lx_view_box_beyond_near(const struct lx_view *v, vec3 lo, vec3 hi)
{
	for (int k = 0; k < 8; k++)
		if (!(v3_dot(v3_sub(v3_box_corner(lo, hi, k), v->eye), v->dir) > v->near))
			return false;
	return true;
}

void lx_view_frustum_corners(const struct lx_view *v, vec3 fc[8])
{
	static const double cx[4] = {-1, 1, 1, -1}, cy[4] = {-1, -1, 1, 1};
	for (int i = 0; i < 8; i++) {
		vec4 p = m4_mul_v4(&v->inv_view_proj, (vec4){cx[i % 4], cy[i % 4], i < 4 ? -1 : 1, 1});
		/* w > 0 for the corners of a valid perspective frustum */
		fc[i] = v3(p.x / p.w, p.y / p.w, p.z / p.w);
	}
}
