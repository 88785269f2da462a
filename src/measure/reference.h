/* The exact reference: a CPU ray caster in double precision over the very triangles
 * the renderer draws. For every pixel centre it finds the visible triangle and calls
 * the point lit or shadowed, with no resolution and no bias. GL-free.
 *
 * The shadow rule is the renderer's, stated exactly: a point on a triangle that faces
 * away from the light is shadowed (the meshes are closed, or planes whose back is
 * unlit); otherwise it is shadowed when the segment to the light (the ray against the
 * light direction, for a directional light) hits any other triangle. */
#ifndef LX_REFERENCE_H
#define LX_REFERENCE_H
#include "frame.h"
#include <stdint.h>

#define LX_NO_OBJECT (-1)

struct lx_raycaster;
/* The reference's BVH: no inner node deeper than this (leaves below take the rest). */
#define LX_BVH_MAX_DEPTH 40

struct lx_raycaster *lx_raycaster_create(const struct lx_frame *f);
void lx_raycaster_destroy(struct lx_raycaster *rc);
/* Nearest hit with t in (tmin, tmax); returns the triangle index or -1. */
int lx_raycast_first(const struct lx_raycaster *rc, vec3 o, vec3 d, double tmin, double tmax, double *t);
bool lx_raycast_any(const struct lx_raycaster *rc, vec3 o, vec3 d, double tmin, double tmax, int skip);
int lx_raycaster_object(const struct lx_raycaster *rc, int tri);
/* The BVH's deepest node (at most LX_BVH_MAX_DEPTH): for tests. */
int lx_raycaster_depth(const struct lx_raycaster *rc);
/* Whether a triangle of an object other than skip_object (LX_NO_OBJECT: any) meets
 * o + t d, t in (tmin, tmax). */
bool lx_raycast_blocked(const struct lx_raycaster *rc, vec3 o, vec3 d, double tmin, double tmax, int skip_object);
/* The same, trying first the triangle *hint (-1: none), which becomes the triangle found
 * blocking: the rays from one point to an area light's samples are mostly blocked by the
 * same triangle, so that most cost one triangle test instead of a walk of the BVH. */
bool lx_raycast_blocked_hint(const struct lx_raycaster *rc, vec3 o, vec3 d, double tmin, double tmax, int skip_object,
			     int *hint);
/* Whether a triangle of an object other than skip_object may come within r of the
 * segment from a to b: conservative (boxes grown by r), so false means none does. */
bool lx_raycast_near(const struct lx_raycaster *rc, vec3 a, vec3 b, double r, int skip_object);
/* Triangle tri's unit face normal; the scene's size (its bounds' diagonal). */
vec3 lx_raycaster_normal(const struct lx_raycaster *rc, int tri);
double lx_raycaster_scale(const struct lx_raycaster *rc);
/* The eye ray through pixel (x, y)'s centre (GL window coordinates): the triangle it meets
 * first, and *p the point there, or -1. */
int lx_reference_pixel(const struct lx_frame *f, const struct lx_raycaster *rc, int x, int y, vec3 *p);
/* row(ctx, y) for every y in [0, height), over `threads` threads (1 to 16), rows
 * interleaved. */
void lx_reference_rows(int height, int threads, void (*row)(void *ctx, int y), void *ctx);
/* Whether world point p on triangle tri is in shadow. */
bool lx_reference_shadowed(const struct lx_raycaster *rc, const struct lx_light *light, vec3 p, int tri);

/* The light grazing a surface: |cos| of the incidence at most this, 1/1000, a tenth of one
 * 8-bit step of the diffuse light. */
#define LX_EDGE_ON_COS 1e-3
#define LX_REF_EDGE_ON 2
/* Per pixel, rows bottom to top as GL reads them: the visible object id (or
 * LX_NO_OBJECT) and 1 where shadowed, LX_REF_EDGE_ON where the light grazes the surface
 * (either decision is right there: the metrics do not compare it). Arrays of
 * width*height. Uses `threads` threads. */
bool lx_reference_image(const struct lx_frame *f, int16_t *object, uint8_t *shadowed, int threads);
/* The pixels that a projective light does not reach (behind it, outside its image or past
 * its range): unlit, shaded alike whatever the decision; the metrics do not compare them. */
#define LX_REF_UNLIT 3
/* The same decisions, and from the same rays the renderer's shaded image as it should be,
 * RGBA8 rows bottom to top: the visible triangle shaded with main.frag's model in double
 * precision, with those decisions and the light's colour and image (a projective light's
 * beam or slide, sampled as GL's LINEAR filter does; NULL for other lights). False when out
 * of memory, or when a projective light's image is missing. lx_reference_lights with one
 * light. */
struct lx_image;
bool lx_reference_image_shaded(const struct lx_frame *f, const struct lx_image *light_image, int16_t *object,
				uint8_t *shadowed, uint8_t *rgba, int threads);
/* The same for n lights (1 to LX_MAX_LIGHTS) from one eye ray per pixel: frames[i] is the
 * view at the same time lit by light i (only its light is read for i > 0; the view, scene
 * and BVH come from frames[0]), images[i] that light's image or NULL (images itself may be
 * NULL when no colours are asked or no light is projective). shadowed[i] gets light i's
 * decisions, exactly what lx_reference_image_shaded gives for that light alone. rgba (or
 * NULL) gets what the renderer's additive passes make [Segal]: per channel the first
 * light's shading with the ambient term, plus each later light's diffuse term alone, each
 * quantised to 8 bits, the sum clamped at 255; the clear colour on the background. False
 * when n is out of range, out of memory, or a projective light's image is missing. */
bool lx_reference_lights(const struct lx_frame *const *frames, const struct lx_image *const *images, int n,
			 int16_t *object, uint8_t *const *shadowed, uint8_t *rgba, int threads);

#endif
