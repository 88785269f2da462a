/* What a projective light (scene.h) casts: its image (a spotlight's beam or a projector's
 * slide) and the projective texture matrix that maps the world onto it [Segal]. The
 * renderer samples the image through the matrix in the main pass; the reference does the
 * same in double precision, texel for texel. GL-free. */
#ifndef LX_LIGHT_IMAGE_H
#define LX_LIGHT_IMAGE_H
#include "png_in.h"
#include "scene.h"

/* lixel's own round beam: this many texels a side, its intensity falling smoothly from
 * full at half the cone's half-angle to none at the cone's edge. */
#define LX_ROUND_BEAM_SIZE 64

/* The light's image, RGBA8, rows bottom to top (as GL takes them): the PNG it names, the
 * built-in slide, or the round beam made for its fov. False with one line in err (the
 * file and what is wrong with it). A plain light has none: *out stays empty (rgba NULL). */
bool lx_light_image_load(const struct lx_light *l, struct lx_image *out, char *err, size_t errlen);
/* World -> (s q, t q, d, q): s, t in [0, 1] across the image inside the light's frustum,
 * q = d the depth along its axis (positive in front); the frustum's aspect is l->aspect.
 * False when the light is not projective or its frame is degenerate. */
bool lx_light_projection(const struct lx_light *l, mat4 *out);
/* The light's frustum as 8 corners (near face 0-3, far face 4-7, as lx_frustum_box_points
 * takes them): its apex a hair off the light, its far face at range_far or past the box
 * [lo, hi]. False for other lights. */
bool lx_light_frustum(const struct lx_light *l, vec3 lo, vec3 hi, vec3 fc[8]);
/* The image at (s, t) as GL's LINEAR filter with CLAMP_TO_EDGE reads it: texel centres at
 * (i + 0.5) / width; RGB in [0, 1]. */
vec3 lx_image_bilinear(const struct lx_image *im, double s, double t);
/* The colour a projective light sends to world point p (before the surface's own
 * colour and the cosine): image x light colour x range fall-off; zero behind the light,
 * outside its frustum, or past its range. A plain light: its colour everywhere. */
vec3 lx_projective_light_at(const struct lx_light *l, const mat4 *proj, const struct lx_image *im, vec3 p);
/* Whether p is inside the light's frustum (in front, within the image, within its range);
 * plain lights reach everywhere. */
bool lx_light_reaches(const struct lx_light *l, const mat4 *proj, vec3 p);

#endif
