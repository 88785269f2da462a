/* The soft reference: how much of a small area light each pixel's point sees, by the
 * exact ray caster of reference.h (double precision, the same triangles) with stratified
 * rays. It is what a filtered shadow (--filter) is measured against. GL-free.
 *
 * The light: a point light becomes a sphere, a directional one a disc of directions (a
 * sun), of angular diameter `size` degrees: for a point light as seen from the camera's
 * target (radius = distance * sin(size / 2)), for a directional light as seen from
 * anywhere. The default, half a degree, is about the sun's; on the default scene it gives
 * penumbrae of 1 to 6 cm on the floor, one to a few lixels of its maps, so about the
 * widths the filters blur over.
 *
 * Per point: a face turned away from the light's centre sees none of it (the face rule of
 * the hard reference); otherwise the share of LX_SOFT_SIDE^2 rays, one through each
 * stratum of a grid over the light's disc (as seen from the point; jittered, the same for
 * every run), that no triangle of another object stops. The point's own object is left
 * out: every mesh is a convex solid or a plane, so it hides the light only where the face
 * rule already says so, and the renderer's second-depth maps never let it cast onto
 * itself either. Where no other object comes near the cone to the light (a conservative
 * test on the BVH's boxes) the point sees all of it, with no ray cast. */
#ifndef LX_SOFT_REFERENCE_H
#define LX_SOFT_REFERENCE_H
#include "reference.h"

/* The default angular diameter of the area light, degrees (--light-size). */
#define LX_DEFAULT_LIGHT_SIZE_DEG 0.5
/* The largest --light-size takes, degrees. */
#define LX_MAX_LIGHT_SIZE_DEG 20.0
/* Rays per partly hidden point: this squared, one per stratum. */
#define LX_SOFT_SIDE 12

struct lx_area_light {
	bool directional;
	vec3 centre;   /* point light: the sphere's centre */
	vec3 toward;   /* directional: the unit direction towards the light */
	double radius; /* point light: the sphere's radius; directional: tan of half its angular size */
	double reach;  /* directional: the scene's size, beyond which nothing can stop a ray */
};

/* The frame's light grown to angular size size_deg (0: a point, the hard reference). */
void lx_area_light_make(const struct lx_frame *f, const struct lx_raycaster *rc, double size_deg,
			struct lx_area_light *out);
/* The share of the light world point p on triangle tri sees, from 0 to 1; seed picks the
 * strata's jitter (the pixel's index in the image). */
double lx_soft_visibility(const struct lx_raycaster *rc, const struct lx_area_light *light, vec3 p, int tri,
			  unsigned long long seed);
/* Per pixel, rows bottom to top as GL reads them, the visibility of the visible point (1
 * where no object is seen); width*height floats. Uses `threads` threads. False when out
 * of memory. */
bool lx_soft_reference_image(const struct lx_frame *f, double size_deg, float *visibility, int threads);

#endif
