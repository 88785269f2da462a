/* The scene: planes of interest, bouncing shadow casters, one to four lights, the camera.
 * GL-free. Distances in metres. A scene comes from lx_scene_default() or from a
 * text file (format in docs/scene-format.md) through lx_scene_load(). */
#ifndef LX_SCENE_H
#define LX_SCENE_H
#include "linalg.h"
#include <stdbool.h>
#include <stddef.h>

#define LX_MAX_PLANES 8
#define LX_MAX_CASTERS 32
/* Lights drawn as additive passes [Segal], each with its own maps in the one atlas. */
#define LX_MAX_LIGHTS 4
#define LX_NAME_MAX 16
/* No coordinate, size or time of a scene beyond this (options included): products of two
 * stay far inside double's range. */
#define LX_SCENE_NUMBER_MAX 1e15
/* No size (radius, height, box side) below this: the GL meshes are single precision. */
#define LX_SCENE_SIZE_MIN 1e-30

/* A plane of interest: the parallelogram corner + s*edge1 + t*edge2, s, t in [0, 1].
 * Its lit side faces along normalize(edge1 x edge2). */
struct lx_plane {
	char name[LX_NAME_MAX];
	vec3 corner, edge1, edge2;
	vec3 color;
};

enum lx_shape { LX_SPHERE, LX_BOX, LX_CYLINDER, LX_CONE, LX_SHAPE_COUNT };

/* A caster standing at (x, bottom(t), z); bottom(t) = low + (high - low) * |sin(pi t / period + phase)|. */
struct lx_caster {
	enum lx_shape shape;
	vec3 size; /* sphere: radius in x; box: x, y, z extents; cylinder, cone: radius in x, height in y */
	double x, z;
	double low, high, period, phase;
	vec3 color;
};

/* A projective light [Segal]: a point light at position that lights only through its
 * frustum, looking at `at` with a vertical field of view fov_deg, the frustum's aspect
 * that of its image: a spotlight's beam (an intensity map of the beam's cross-section,
 * the angular fall-off in it; without a file, lixel's round beam) or a projector's
 * slide. Nothing behind it is lit. */
enum lx_projective { LX_LIGHT_PLAIN, LX_LIGHT_SPOT, LX_LIGHT_PROJECTOR };
/* Where a projective light's image comes from. */
enum lx_light_image_source { LX_IMAGE_ROUND_BEAM, LX_IMAGE_FILE, LX_IMAGE_BUILTIN_SLIDE };
#define LX_PATH_MAX 512
#define LX_SPOT_FOV_MAX 150.0 /* degrees: the shadow maps' cone stops at 150 (light_space.c) */

struct lx_light {
	bool directional;
	vec3 position;  /* point light */
	vec3 direction; /* directional: the direction light travels, unit length */
	vec3 color;     /* every kind's colour, each in [0, 1]: (1, 1, 1) unless the scene sets one */
	enum lx_projective projective;
	vec3 at, up;        /* projective: where it points, and which way is up in its image */
	double fov_deg;     /* projective: vertical field of view, in (0, LX_SPOT_FOV_MAX) */
	/* projective, when range_far > 0: lit only up to range_far along its axis, the light
	 * falling linearly from full at range_near to none at range_far (a function of the
	 * light's depth, as [Segal] suggests for distance attenuation) */
	double range_near, range_far;
	double aspect; /* projective: the image's width / height, the frustum's too */
	enum lx_light_image_source image;
	char image_path[LX_PATH_MAX]; /* LX_IMAGE_FILE: the PNG, resolved against the scene's folder */
};

struct lx_camera {
	vec3 eye, at, up;
	double fovy_deg;
};

struct lx_scene {
	int plane_count, caster_count;
	struct lx_plane planes[LX_MAX_PLANES];
	struct lx_caster casters[LX_MAX_CASTERS];
	/* light is lights[0], the only light most scenes have: the shadow methods and the
	 * tests that build scenes by hand work on it; light_count says how many of lights[] are
	 * in use (0, in a scene built by hand, counts as 1: see lx_scene_light_count) */
	union {
		struct lx_light light;
		struct lx_light lights[LX_MAX_LIGHTS];
	};
	int light_count;
	struct lx_camera camera;
};
static inline int lx_scene_light_count(const struct lx_scene *s) { return s->light_count > 1 ? s->light_count : 1; }

void lx_scene_default(struct lx_scene *s);
/* The table scene: a table top (a plane of interest, listed first so its map is tried
 * first) on a slab and four legs, over the floor, with casters above and beside it. */
void lx_scene_table(struct lx_scene *s);
/* "point", "directional", "spot" or "projector". */
const char *lx_light_kind_name(const struct lx_light *l);
/* A point light at position, white: what every light starts from, so that its colour is
 * (1, 1, 1) unless set. */
struct lx_light lx_light_white(vec3 position);
/* A projective light's up when none is given: +y, or -z when it looks straight up or down. */
vec3 lx_light_default_up(vec3 position, vec3 at);
/* The default scene under a spotlight (lixel's round beam), and lit by a projector
 * showing lixel's own slide. */
void lx_scene_spotlight(struct lx_scene *s);
void lx_scene_projector(struct lx_scene *s);
/* The default scene under two lights: a warm point light and a cool spotlight from the
 * other side, each casting its own shadows. */
void lx_scene_two_lights(struct lx_scene *s);
/* Fills *s with the built-in scene of that name ("default", "table", "spotlight", "projector",
 * "twolights"); false if none. */
bool lx_scene_builtin(const char *name, struct lx_scene *s);
/* Loads a scene file. On error returns false with "FILE:LINE: what was expected" in err
 * and leaves *s unspecified. */
bool lx_scene_load(const char *path, struct lx_scene *s, char *err, size_t errlen);
bool lx_scene_parse(const char *text, const char *name, struct lx_scene *s, char *err, size_t errlen);

double lx_caster_bottom(const struct lx_caster *c, double t);
vec3 lx_caster_position(const struct lx_caster *c, double t);
vec3 lx_plane_normal(const struct lx_plane *p); /* unit; planes are validated non-degenerate */
const char *lx_shape_name(enum lx_shape s);
/* The same scene k times larger (k > 0): every position and size, the light and the
 * camera; times and angles unchanged. */
void lx_scene_scale(struct lx_scene *s, double k);
/* Object ids: planes 0..plane_count-1, then casters. */
static inline int lx_scene_object_count(const struct lx_scene *s) { return s->plane_count + s->caster_count; }

#endif
