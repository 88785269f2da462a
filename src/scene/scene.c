#include "scene.h"
#include "number.h"
#include "png_in.h"
#include "text_lines.h"
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const shape_names[LX_SHAPE_COUNT] = {"sphere", "box", "cylinder", "cone"};

const char *lx_shape_name(enum lx_shape s) { return s < LX_SHAPE_COUNT ? shape_names[s] : "?"; }

double lx_caster_bottom(const struct lx_caster *c, double t)
{
	/* period > 0 is enforced by the parser and the default scene */
	return c->low + (c->high - c->low) * fabs(sin(M_PI * t / c->period + c->phase));
}

vec3 lx_caster_position(const struct lx_caster *c, double t) { return v3(c->x, lx_caster_bottom(c, t), c->z); }

vec3 lx_plane_normal(const struct lx_plane *p)
{
	vec3 n = v3(0, 1, 0);
	v3_normalize(v3_cross(p->edge1, p->edge2), &n);
	return n;
}

static void add_plane(struct lx_scene *s, const char *name, vec3 corner, vec3 e1, vec3 e2, vec3 color)
{
	struct lx_plane *p = &s->planes[s->plane_count++];
	snprintf(p->name, sizeof p->name, "%s", name);
	p->corner = corner, p->edge1 = e1, p->edge2 = e2, p->color = color;
}

static void add_caster(struct lx_scene *s, enum lx_shape shape, vec3 size, double x, double z, double period,
		       double phase, vec3 color)
{
	s->casters[s->caster_count++] = (struct lx_caster){
		.shape = shape, .size = size, .x = x, .z = z, .low = 0.3, .high = 2.0,
		.period = period, .phase = phase, .color = color};
}

const char *lx_light_kind_name(const struct lx_light *l)
{
	return l->projective == LX_LIGHT_SPOT ? "spot" : l->projective == LX_LIGHT_PROJECTOR ? "projector" : l->directional ? "directional" : "point";
}

struct lx_light lx_light_white(vec3 position)
{
	return (struct lx_light){.position = position, .direction = v3(0, -1, 0), .color = v3(1, 1, 1), .up = v3(0, 1, 0),
				 .aspect = 1};
}

vec3 lx_light_default_up(vec3 position, vec3 at)
{
	vec3 axis;
	return v3_normalize(v3_sub(at, position), &axis) && fabs(axis.y) > 0.9999 ? v3(0, 0, -1) : v3(0, 1, 0);
}

void lx_scene_default(struct lx_scene *s)
{
	memset(s, 0, sizeof(*s));
	/* floor y = 0 over x, z in [-5, 5], facing +y; wall z = -5 facing +z */
	add_plane(s, "floor", v3(-5, 0, 5), v3(10, 0, 0), v3(0, 0, -10), v3(0.80, 0.78, 0.72));
	add_plane(s, "wall", v3(-5, 0, -5), v3(10, 0, 0), v3(0, 5, 0), v3(0.70, 0.74, 0.82));
	add_caster(s, LX_SPHERE, v3(0.6, 0.6, 0.6), -1.3, 0.4, 1.7, 0.0, v3(0.85, 0.25, 0.2));
	add_caster(s, LX_BOX, v3(0.8, 0.8, 0.8), 1.4, -0.6, 2.3, 0.9, v3(0.25, 0.55, 0.85));
	add_caster(s, LX_CYLINDER, v3(0.35, 1.1, 0.35), 0.4, 1.6, 1.9, 2.1, v3(0.3, 0.75, 0.35));
	add_caster(s, LX_CONE, v3(0.5, 1.0, 0.5), -0.3, -2.0, 2.9, 0.5, v3(0.9, 0.7, 0.2));
	s->light = lx_light_white(v3(2.5, 6, 3));
	s->light_count = 1;
	s->camera = (struct lx_camera){.eye = v3(0, 2, 6), .at = v3(0, 0.8, 0), .up = v3(0, 1, 0), .fovy_deg = 60};
}

static void add_static_box(struct lx_scene *s, vec3 size, double x, double z, double bottom, vec3 color)
{
	s->casters[s->caster_count++] = (struct lx_caster){.shape = LX_BOX, .size = size, .x = x, .z = z, .low = bottom,
							   .high = bottom, .period = 1, .phase = 0, .color = color};
}

void lx_scene_table(struct lx_scene *s)
{
	memset(s, 0, sizeof(*s));
	/* the table top 0.75 m high; its 4 cm slab stops 1 mm below it, so the top is a
	 * surface of its own and the slab casts the table's shadow */
	add_plane(s, "table", v3(-1.2, 0.75, 0.8), v3(2.4, 0, 0), v3(0, 0, -1.6), v3(0.62, 0.45, 0.30));
	add_plane(s, "floor", v3(-5, 0, 5), v3(10, 0, 0), v3(0, 0, -10), v3(0.80, 0.78, 0.72));
	vec3 wood = v3(0.45, 0.32, 0.22);
	add_static_box(s, v3(2.4, 0.04, 1.6), 0, 0, 0.709, wood);
	for (int i = 0; i < 4; i++)
		add_static_box(s, v3(0.08, 0.709, 0.08), i & 1 ? 1.1 : -1.1, i & 2 ? 0.7 : -0.7, 0, wood);
	s->casters[s->caster_count++] = (struct lx_caster){.shape = LX_SPHERE, .size = v3(0.25, 0.25, 0.25), .x = -0.4,
		.z = 0.1, .low = 0.8, .high = 1.8, .period = 1.7, .phase = 0.3, .color = v3(0.85, 0.25, 0.2)};
	s->casters[s->caster_count++] = (struct lx_caster){.shape = LX_CONE, .size = v3(0.22, 0.5, 0.22), .x = 0.55,
		.z = -0.25, .low = 0.8, .high = 1.6, .period = 2.3, .phase = 1.1, .color = v3(0.9, 0.7, 0.2)};
	s->casters[s->caster_count++] = (struct lx_caster){.shape = LX_CYLINDER, .size = v3(0.3, 0.8, 0.3), .x = 2.3,
		.z = 1.3, .low = 0.3, .high = 1.5, .period = 1.9, .phase = 2.0, .color = v3(0.3, 0.75, 0.35)};
	s->light = lx_light_white(v3(2.0, 5.5, 2.5));
	s->light_count = 1;
	s->camera = (struct lx_camera){.eye = v3(0, 2.6, 4.2), .at = v3(0, 0.6, 0), .up = v3(0, 1, 0), .fovy_deg = 60};
}

/* The default scene under a warm spotlight with lixel's round beam, from above and to the
 * right, its light ending 12 m away. */
void lx_scene_spotlight(struct lx_scene *s)
{
	lx_scene_default(s);
	struct lx_light *l = &s->light;
	l->position = v3(1.5, 5, 2.5), l->projective = LX_LIGHT_SPOT, l->at = v3(-0.3, 0, -1.2), l->fov_deg = 65;
	l->color = v3(1, 0.92, 0.75), l->range_near = 4, l->range_far = 12;
}

/* The default scene lit by a projector beside the camera showing lixel's own slide on
 * the wall, the casters cutting it. */
void lx_scene_projector(struct lx_scene *s)
{
	lx_scene_default(s);
	struct lx_light *l = &s->light;
	l->position = v3(1.2, 2.6, 5), l->projective = LX_LIGHT_PROJECTOR, l->at = v3(-0.2, 1.9, -5), l->fov_deg = 30;
	l->image = LX_IMAGE_BUILTIN_SLIDE;
	l->aspect = 256.0 / 192; /* the slide's size (tools/make-slide.c) */
}

void lx_scene_two_lights(struct lx_scene *s)
{
	lx_scene_default(s);
	s->light.color = v3(0.75, 0.68, 0.55); /* the two together stay under full white */
	struct lx_light *l = &s->lights[1];
	*l = lx_light_white(v3(-3.5, 4.5, 2));
	l->projective = LX_LIGHT_SPOT, l->at = v3(0.3, 0, -1), l->fov_deg = 70;
	l->color = v3(0.35, 0.48, 0.8), l->range_near = 5, l->range_far = 14;
	s->light_count = 2;
}

bool lx_scene_builtin(const char *name, struct lx_scene *s)
{
	if (!strcmp(name, "default"))
		lx_scene_default(s);
	else if (!strcmp(name, "table"))
		lx_scene_table(s);
	else if (!strcmp(name, "spotlight"))
		lx_scene_spotlight(s);
	else if (!strcmp(name, "projector"))
		lx_scene_projector(s);
	else if (!strcmp(name, "twolights"))
		lx_scene_two_lights(s);
	else
		return false;
	return true;
}

/* ---- scene file parser ---- */

struct parser {
	const char *file;
	int line;
	char *tok[64];
	int ntok, pos;
	char *err;
	size_t errlen;
};

static bool fail(struct parser *p, const char *fmt, ...)
{
	char msg[256];
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(msg, sizeof msg, fmt, ap);
	va_end(ap);
	snprintf(p->err, p->errlen, "%s:%d: %s", p->file, p->line, msg);
	return false;
}

static const char *peek(struct parser *p) { return p->pos < p->ntok ? p->tok[p->pos] : NULL; }

/* Every number of a scene is within +-LX_SCENE_NUMBER_MAX: beyond it squares and products
 * of coordinates would leave double's exact range long before they overflow. */
static bool number(struct parser *p, const char *what, double *out)
{
	const char *t = peek(p);
	if (!t)
		return fail(p, "expected a number for %s, got end of line", what);
	enum lx_number_error e = lx_number_real(t, -LX_SCENE_NUMBER_MAX, LX_SCENE_NUMBER_MAX, out);
	if (e == LX_NUMBER_OUT_OF_RANGE)
		return fail(p, "expected a number for %s from -%g to %g, got '%s'", what, LX_SCENE_NUMBER_MAX,
			    LX_SCENE_NUMBER_MAX, t);
	if (e)
		return fail(p, "expected a number for %s, got '%s' (%s)", what, t, lx_number_why(e));
	p->pos++;
	return true;
}

static bool triple(struct parser *p, const char *what, vec3 *out)
{
	return number(p, what, &out->x) && number(p, what, &out->y) && number(p, what, &out->z);
}

/* A size: positive, and at least LX_SCENE_SIZE_MIN, so that the GL meshes (single
 * precision) still hold its triangles. */
static bool positive(struct parser *p, const char *what, double *out)
{
	if (!number(p, what, out))
		return false;
	if (!(*out > 0))
		return fail(p, "expected %s > 0, got %g", what, *out);
	if (!(*out >= LX_SCENE_SIZE_MIN))
		return fail(p, "expected %s of at least %g (the meshes are single precision), got %g", what,
			    LX_SCENE_SIZE_MIN, *out);
	return true;
}

static bool color(struct parser *p, vec3 *c)
{
	if (!triple(p, "color (three values in [0, 1])", c))
		return false;
	if (c->x < 0 || c->x > 1 || c->y < 0 || c->y > 1 || c->z < 0 || c->z > 1)
		return fail(p, "expected color components in [0, 1]");
	return true;
}

static bool parse_camera(struct parser *p, struct lx_scene *s)
{
	bool eye = false, at = false;
	while (peek(p)) {
		const char *k = p->tok[p->pos++];
		if (!strcmp(k, "eye")) {
			if (!triple(p, "camera eye", &s->camera.eye))
				return false;
			eye = true;
		} else if (!strcmp(k, "at")) {
			if (!triple(p, "camera at", &s->camera.at))
				return false;
			at = true;
		} else if (!strcmp(k, "up")) {
			if (!triple(p, "camera up", &s->camera.up))
				return false;
		} else if (!strcmp(k, "fov")) {
			if (!number(p, "camera fov (degrees)", &s->camera.fovy_deg))
				return false;
			if (!(s->camera.fovy_deg > 0 && s->camera.fovy_deg < 180))
				return fail(p, "expected camera fov in (0, 180) degrees, got %g", s->camera.fovy_deg);
		} else
			return fail(p, "expected eye, at, up or fov after 'camera', got '%s'", k);
	}
	if (!eye || !at)
		return fail(p, "expected 'camera eye X Y Z at X Y Z [up X Y Z] [fov DEG]'");
	mat4 m;
	if (!m4_look_at(s->camera.eye, s->camera.at, s->camera.up, &m))
		return fail(p, "expected a camera whose eye differs from at and whose up is not along the view");
	return true;
}

/* FILE of a beam or slide, against the scene file's folder unless absolute; it must be
 * readable and start like a PNG (the pixels are read when the light is set up). */
static bool image_file(struct parser *p, const char *what, struct lx_light *l)
{
	const char *f = peek(p);
	if (!f)
		return fail(p, "expected a PNG file after '%s', got end of line", what);
	p->pos++;
	const char *slash = strrchr(p->file, '/');
	int dir = f[0] != '/' && slash ? (int)(slash - p->file) + 1 : 0;
	if (snprintf(l->image_path, sizeof l->image_path, "%.*s%s", dir, p->file, f) >= (int)sizeof l->image_path)
		return fail(p, "expected a %s path under %d characters", what, LX_PATH_MAX);
	bool is_png = false;
	int w = 0, h = 0;
	if (!lx_png_header(l->image_path, &is_png, &w, &h))
		return fail(p, "%s '%s': cannot read it (%s)", what, l->image_path, strerror(errno));
	if (!is_png)
		return fail(p, "%s '%s': expected a PNG file", what, l->image_path);
	if (w < 1 || h < 1 || w > LX_PNG_IN_MAX_SIDE || h > LX_PNG_IN_MAX_SIDE)
		return fail(p, "%s '%s': a %dx%d image, expected sides from 1 to %d", what, l->image_path, w, h,
			    LX_PNG_IN_MAX_SIDE);
	l->aspect = (double)w / h;
	l->image = LX_IMAGE_FILE;
	return true;
}

/* The options after a projective light's position: at, fov, up, beam or slide, color,
 * range, in any order, at and fov required. */
static bool projective_options(struct parser *p, struct lx_light *l, const char *kind)
{
	bool at = false, fov = false, up = false;
	while (peek(p)) {
		const char *k = p->tok[p->pos++];
		if (!strcmp(k, "at")) {
			if (!triple(p, "light at", &l->at))
				return false;
			at = true;
		} else if (!strcmp(k, "up")) {
			if (!triple(p, "light up", &l->up))
				return false;
			up = true;
		} else if (!strcmp(k, "fov")) {
			if (!number(p, "light fov (degrees)", &l->fov_deg))
				return false;
			if (!(l->fov_deg > 0 && l->fov_deg < LX_SPOT_FOV_MAX))
				return fail(p, "expected light fov in (0, %g) degrees, got %g", LX_SPOT_FOV_MAX, l->fov_deg);
			fov = true;
		} else if (!strcmp(k, l->projective == LX_LIGHT_SPOT ? "beam" : "slide")) {
			if (!image_file(p, k, l))
				return false;
		} else if (!strcmp(k, "color")) {
			if (!color(p, &l->color))
				return false;
		} else if (!strcmp(k, "range")) {
			if (!number(p, "range near", &l->range_near) || !number(p, "range far", &l->range_far))
				return false;
			if (!(l->range_near >= 0 && l->range_far > l->range_near))
				return fail(p, "expected range NEAR FAR with 0 <= NEAR < FAR, got %g %g", l->range_near,
					    l->range_far);
		} else
			return fail(p, "expected at, fov, up, %s, color or range in a %s light, got '%s'",
				    l->projective == LX_LIGHT_SPOT ? "beam" : "slide", kind, k);
	}
	if (!at || !fov)
		return fail(p, "expected 'light %s X Y Z at X Y Z fov DEG ...'", kind);
	if (l->projective == LX_LIGHT_PROJECTOR && l->image != LX_IMAGE_FILE)
		return fail(p, "expected 'slide FILE.png' in a projector light");
	if (!up)
		l->up = lx_light_default_up(l->position, l->at);
	mat4 m;
	if (!m4_look_at(l->position, l->at, l->up, &m))
		return fail(p, "expected a %s light whose position differs from at and whose up is not along its axis",
			    kind);
	return true;
}

/* A point or directional light's one option: its colour (white without). */
static bool plain_options(struct parser *p, struct lx_light *l)
{
	const char *k = peek(p);
	if (!k)
		return true;
	p->pos++;
	if (strcmp(k, "color"))
		return fail(p, "expected 'color R G B' or the end of the light line, got '%s'", k);
	return color(p, &l->color);
}

static bool parse_light(struct parser *p, struct lx_scene *s)
{
	const char *k = peek(p);
	if (!k)
		return fail(p, "expected 'point', 'directional', 'spot' or 'projector' after 'light'");
	p->pos++;
	if (s->light_count == LX_MAX_LIGHTS)
		return fail(p, "expected at most %d light lines, found one more", LX_MAX_LIGHTS);
	struct lx_light *l = &s->lights[s->light_count++];
	*l = lx_light_white(v3(0, 0, 0));
	if (!strcmp(k, "point")) {
		/* direction unused for a point light; kept canonical */
		if (!triple(p, "light position", &l->position))
			return false;
		return plain_options(p, l);
	} else if (!strcmp(k, "directional")) {
		l->directional = true;
		vec3 d;
		if (!triple(p, "light direction", &d))
			return false;
		if (!v3_normalize(d, &l->direction))
			return fail(p, "expected a non-zero light direction");
		return plain_options(p, l);
	} else if (!strcmp(k, "spot") || !strcmp(k, "projector")) {
		l->projective = !strcmp(k, "spot") ? LX_LIGHT_SPOT : LX_LIGHT_PROJECTOR;
		if (!triple(p, "light position", &l->position))
			return false;
		return projective_options(p, l, k);
	} else
		return fail(p, "expected 'point', 'directional', 'spot' or 'projector' after 'light', got '%s'", k);
	return true;
}

static bool parse_plane(struct parser *p, struct lx_scene *s)
{
	if (s->plane_count == LX_MAX_PLANES)
		return fail(p, "expected at most %d planes", LX_MAX_PLANES);
	struct lx_plane pl = {.color = v3(0.8, 0.8, 0.8)};
	const char *name = peek(p);
	/* names go into JSON keys, CSV columns and the atlas's region names: ASCII words only */
	size_t word = name ? strspn(name, "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_-") : 0;
	if (!name || !isalpha((unsigned char)name[0]) || name[word] || word >= LX_NAME_MAX)
		return fail(p, "expected a plane name after 'plane' (1 to %d of A-Z a-z 0-9 _ -, a letter first)",
			    LX_NAME_MAX - 1);
	if (!strcmp(name, "fallback")) /* the fallback map's own name */
		return fail(p, "expected a plane name other than 'fallback' (the fallback map's name)");
	p->pos++;
	for (int i = 0; i < s->plane_count; i++)
		if (!strcmp(s->planes[i].name, name))
			return fail(p, "expected a new plane name, '%s' is already defined", name);
	strcpy(pl.name, name);
	int have = 0;
	while (peek(p)) {
		const char *k = p->tok[p->pos++];
		if (!strcmp(k, "corner")) {
			if (!triple(p, "plane corner", &pl.corner))
				return false;
			have |= 1;
		} else if (!strcmp(k, "edge1")) {
			if (!triple(p, "plane edge1", &pl.edge1))
				return false;
			have |= 2;
		} else if (!strcmp(k, "edge2")) {
			if (!triple(p, "plane edge2", &pl.edge2))
				return false;
			have |= 4;
		} else if (!strcmp(k, "color")) {
			if (!color(p, &pl.color))
				return false;
		} else
			return fail(p, "expected corner, edge1, edge2 or color in a plane, got '%s'", k);
	}
	if (have != 7)
		return fail(p, "expected 'plane NAME corner X Y Z edge1 X Y Z edge2 X Y Z [color R G B]'");
	vec3 n = v3_cross(pl.edge1, pl.edge2);
	/* relative: the sine of the edges' angle, so a scene in micrometres passes as one in metres */
	if (!(v3_len(n) > 1e-9 * v3_len(pl.edge1) * v3_len(pl.edge2)))
		return fail(p, "expected plane edges that are non-zero and not parallel");
	/* (numbers within +-1e15 keep |edge1 x edge2| near 1e31 at most: its unit normal
	 * exists; HIGH - LOW of a bounce stays finite likewise) */
	s->planes[s->plane_count++] = pl;
	return true;
}

static bool parse_caster(struct parser *p, struct lx_scene *s, enum lx_shape shape)
{
	if (s->caster_count == LX_MAX_CASTERS)
		return fail(p, "expected at most %d casters", LX_MAX_CASTERS);
	struct lx_caster c = {.shape = shape, .low = 0.3, .high = 2.0, .period = 2.0, .color = v3(0.7, 0.7, 0.7)};
	bool size = false, at = false;
	double r = 0, h = 0;
	while (peek(p)) {
		const char *k = p->tok[p->pos++];
		if (shape != LX_BOX && !strcmp(k, "radius")) {
			if (!positive(p, "radius", &r))
				return false;
			size = shape == LX_SPHERE || h > 0;
		} else if ((shape == LX_CYLINDER || shape == LX_CONE) && !strcmp(k, "height")) {
			if (!positive(p, "height", &h))
				return false;
			size = r > 0;
		} else if (shape == LX_BOX && !strcmp(k, "size")) {
			if (!positive(p, "box size x", &c.size.x) || !positive(p, "box size y", &c.size.y) ||
			    !positive(p, "box size z", &c.size.z))
				return false;
			size = true;
		} else if (!strcmp(k, "at")) {
			if (!number(p, "position x", &c.x) || !number(p, "position z", &c.z))
				return false;
			at = true;
		} else if (!strcmp(k, "bounce")) {
			if (!number(p, "bounce low", &c.low) || !number(p, "bounce high", &c.high))
				return false;
			if (!(c.low <= c.high))
				return fail(p, "expected bounce LOW HIGH with LOW <= HIGH");
		} else if (!strcmp(k, "period")) {
			if (!positive(p, "period (seconds)", &c.period))
				return false;
		} else if (!strcmp(k, "phase")) {
			if (!number(p, "phase (radians)", &c.phase))
				return false;
		} else if (!strcmp(k, "color")) {
			if (!color(p, &c.color))
				return false;
		} else
			return fail(p, "unexpected '%s' in a %s", k, lx_shape_name(shape));
	}
	if (shape != LX_BOX)
		c.size = v3(r, shape == LX_SPHERE ? r : h, r);
	if (!size || !at)
		return fail(p, "expected %s", shape == LX_SPHERE ? "'sphere radius R at X Z'" :
					       shape == LX_BOX	  ? "'box size SX SY SZ at X Z'" :
									    "'cylinder|cone radius R height H at X Z'");
	s->casters[s->caster_count++] = c;
	return true;
}

bool lx_scene_parse(const char *text, const char *name, struct lx_scene *s, char *err, size_t errlen)
{
	memset(s, 0, sizeof(*s));
	s->camera = (struct lx_camera){.eye = v3(0, 2, 6), .at = v3(0, 0.8, 0), .up = v3(0, 1, 0), .fovy_deg = 60};
	struct parser p = {.file = name, .err = err, .errlen = errlen};
	bool camera = false;
	const char *line = text;
	char buf[1024];
	for (int r; (r = lx_text_line(&line, buf, sizeof buf)) != 0;) {
		p.line++;
		if (r < 0)
			return fail(&p, "expected a line shorter than %zu characters", sizeof buf);
		p.ntok = p.pos = 0;
		for (char *t = strtok(buf, " \t\r"); t; t = strtok(NULL, " \t\r")) {
			if (p.ntok == 64)
				return fail(&p, "expected at most 64 words on a line");
			p.tok[p.ntok++] = t;
		}
		if (!p.ntok)
			continue;
		const char *k = p.tok[p.pos++];
		bool ok;
		if (!strcmp(k, "camera")) {
			if (camera)
				return fail(&p, "expected one camera line, found a second");
			camera = ok = parse_camera(&p, s);
		} else if (!strcmp(k, "light")) {
			ok = parse_light(&p, s);
		} else if (!strcmp(k, "plane"))
			ok = parse_plane(&p, s);
		else if (!strcmp(k, "sphere"))
			ok = parse_caster(&p, s, LX_SPHERE);
		else if (!strcmp(k, "box"))
			ok = parse_caster(&p, s, LX_BOX);
		else if (!strcmp(k, "cylinder"))
			ok = parse_caster(&p, s, LX_CYLINDER);
		else if (!strcmp(k, "cone"))
			ok = parse_caster(&p, s, LX_CONE);
		else
			return fail(&p, "expected camera, light, plane, sphere, box, cylinder or cone, got '%s'", k);
		if (!ok)
			return false;
		if (peek(&p))
			return fail(&p, "unexpected '%s' at the end of the line", peek(&p));
	}
	if (s->light_count == 0) {
		p.line++;
		return fail(&p, "expected a 'light point X Y Z' or 'light directional DX DY DZ' line");
	}
	if (s->plane_count == 0 && s->caster_count == 0) {
		p.line++;
		return fail(&p, "expected at least one plane or caster");
	}
	return true;
}

bool lx_scene_load(const char *path, struct lx_scene *s, char *err, size_t errlen)
{
	FILE *f = fopen(path, "rb");
	if (!f) {
		snprintf(err, errlen, "%s: cannot open scene file: %s", path, strerror(errno));
		return false;
	}
	char *text = NULL;
	size_t cap = 0, len = 0;
	for (;;) {
		if (len + 4096 + 1 > cap) {
			if (cap > (1u << 24)) {
				free(text);
				fclose(f);
				snprintf(err, errlen, "%s: expected a scene file under 16 MiB", path);
				return false;
			}
			cap = cap ? cap * 2 : 8192;
			char *t = realloc(text, cap);
			if (!t) {
				free(text);
				fclose(f);
				snprintf(err, errlen, "%s: out of memory", path);
				return false;
			}
			text = t;
		}
		size_t n = fread(text + len, 1, 4096, f);
		len += n;
		if (n < 4096)
			break;
	}
	bool rd_err = ferror(f);
	fclose(f);
	if (rd_err) {
		free(text);
		snprintf(err, errlen, "%s: cannot read scene file", path);
		return false;
	}
	text[len] = 0;
	if (memchr(text, 0, len)) {
		free(text);
		snprintf(err, errlen, "%s:1: expected a text file, found a NUL byte", path);
		return false;
	}
	bool ok = lx_scene_parse(text, path, s, err, errlen);
	free(text);
	return ok;
}

void lx_scene_scale(struct lx_scene *s, double k)
{
	for (int i = 0; i < s->plane_count; i++) {
		struct lx_plane *p = &s->planes[i];
		p->corner = v3_scale(p->corner, k), p->edge1 = v3_scale(p->edge1, k), p->edge2 = v3_scale(p->edge2, k);
	}
	for (int i = 0; i < s->caster_count; i++) {
		struct lx_caster *c = &s->casters[i];
		c->size = v3_scale(c->size, k);
		c->x *= k, c->z *= k, c->low *= k, c->high *= k;
	}
	for (int i = 0; i < lx_scene_light_count(s); i++) {
		struct lx_light *l = &s->lights[i];
		if (!l->directional)
			l->position = v3_scale(l->position, k);
		l->at = v3_scale(l->at, k);
		l->range_near *= k, l->range_far *= k;
	}
	s->camera.eye = v3_scale(s->camera.eye, k), s->camera.at = v3_scale(s->camera.at, k);
}
