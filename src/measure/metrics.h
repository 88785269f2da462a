/* The accuracy metrics of docs/lixel.md ("The exact reference and the metrics"): shadow mismatch against the
 * exact reference, and the sampling figures of a map on a plane computed exactly from
 * the matrices. GL-free. */
#ifndef LX_METRICS_H
#define LX_METRICS_H
#include "reference.h"
#include "shadow_method.h"
#include <stdint.h>

struct lx_mismatch {
	long compared;       /* receiver pixels where both agree on the visible object */
	long silhouette;     /* pixels where they disagree on the visible object */
	long edge_on;        /* pixels the light grazes (LX_REF_EDGE_ON): not compared */
	long unlit;          /* pixels a projective light does not reach (LX_REF_UNLIT): not compared */
	long false_shadow;   /* renderer shadowed, reference lit */
	long missing_shadow; /* renderer lit, reference shadowed */
	double mismatch_pct, false_shadow_pct, missing_shadow_pct; /* of compared; 0 when none compared */
};

void lx_mismatch_compare(const int16_t *ref_object, const uint8_t *ref_shadow, const int16_t *object,
			 const uint8_t *shadow, long pixels, struct lx_mismatch *out);
/* total += part: the counts added, the shares of the sum (several lights' mismatch as one). */
void lx_mismatch_add(struct lx_mismatch *total, const struct lx_mismatch *part);
/* colour_error: the mean absolute difference of two RGBA8 images over their pixels and the
 * R, G and B channels, in 8-bit levels (0 to 255). */
double lx_colour_error(const uint8_t *a, const uint8_t *b, long pixels);

/* soft_error_pct: the mean of |visibility - ref_visibility| over the pixels
 * lx_mismatch_compare compares (both see the same object, the light reaches it and does
 * not graze it),
 * times 100; 0 when none is compared. visibility is the renderer's, 0 (in shadow) to 255
 * (lit); ref_visibility the soft reference's share of an area light, 0 to 1. A hard
 * shadow against a hard reference: the mismatch; against an area light it also counts
 * how far each penumbra pixel is from either side. */
double lx_soft_error(const int16_t *ref_object, const uint8_t *ref_shadow, const float *ref_visibility,
		     const int16_t *object, const uint8_t *visibility, long pixels);

struct lx_plane_sampling {
	int map;         /* the map the figures are of: the plane's own map, else -1 (each pixel's serving map) */
	long seen;       /* pixels that see the plane */
	long no_lookup;  /* of those, pixels that ran no shadow lookup: they read no map */
	long pixels;     /* pixels of the plane the figures cover: those that read a map */
	long unserved;   /* pixels of the plane no map serves, or (own map) another map serves */
	long degenerate; /* pixels skipped: the map's projection is singular there */
	double lpp_median, lpp_min, lpp_max, m_median, m_max, aniso_max;
	double lixels_used; /* budget use: the lixels inside the footprint of these pixels (sum of lpp) */
};

/* Where each pixel of ref_object that is a plane meets that plane, worked out once for a
 * frame whose decisions several methods (or lights) are measured against. */
struct lx_plane_points {
	vec3 *p;     /* the pixel's point on its plane */
	uint8_t *on; /* 1 where the pixel's ray meets the plane's parallelogram within the view's depth */
};
bool lx_plane_points_make(const struct lx_frame *f, const int16_t *ref_object, struct lx_plane_points *out);
void lx_plane_points_free(struct lx_plane_points *pts);
/* The Jacobian figures of the screen-to-lixel homographies on plane `plane`, over the
 * pixels whose visible object (ref_object, or every pixel that sees the plane's
 * parallelogram when ref_object is NULL) is that plane and, when looked is not NULL,
 * that a map decided (looked[i] nonzero, lx_decision_served: a lookup ran, or a caster's
 * sure shadow was drawn without one): a pixel where no shadow can fall reads no map, and
 * no lixel serves it. If a map is optimal for the
 * plane, the figures cover the pixels that map serves; otherwise each pixel counts
 * with the map that serves it (lx_shadow_select_map). pts, when not NULL, holds those
 * pixels' points (lx_plane_points_make of the same frame and ref_object), worked out once
 * for every method measured; the figures are the same either way. False when no pixel
 * counts. */
bool lx_plane_sampling(const struct lx_frame *f, const struct lx_atlas *atlas, const struct lx_shadow_result *res,
		       int plane, const int16_t *ref_object, const struct lx_plane_points *pts, const uint8_t *looked,
		       struct lx_plane_sampling *out);
/* The same figures on every stride-th pixel in x and y of the plane's parallelogram
 * (casters not hidden): cheap enough for a live overlay. */
bool lx_plane_sampling_sparse(const struct lx_frame *f, const struct lx_atlas *atlas, const struct lx_shadow_result *res,
			      int plane, int stride, struct lx_plane_sampling *out);

/* The 3x3 homography from window pixel (x, y, 1) (GL window coordinates) to the map's
 * lixel coordinates (u, v, 1) for points on the plane; false when the plane is seen
 * edge-on (no homography). */
bool lx_plane_homography(const struct lx_frame *f, const struct lx_atlas *atlas, const struct lx_shadow_map *map,
			 int plane, mat3 *h);
/* Singular values of the Jacobian of homography h at (x, y); false where w' ~ 0. */
bool lx_homography_jacobian(const mat3 *h, double x, double y, double *s_max, double *s_min);

/* The median of v[0..n-1] (n >= 1); sorts v. */
double lx_median(double *v, long n);

/* One method's frame against another's, view by view (configurations of one run): a
 * pooled median over every frame of every view compares whichever views land in each
 * method's middle, so the pairs say where a method costs more. */
struct lx_paired_ratios {
	double median, least, most; /* of the views' ratios a[i] / b[i] */
	int most_at;                /* the view of the most, -1 when count is 0 */
	int at_most_one, count;     /* views with a ratio <= 1, views compared */
};

/* The ratios a[i] / b[i] of n views' median times. A view where either time is not
 * positive and finite is left out (count says how many were kept; 0, also when out of
 * memory: the figures are NaN). */
void lx_paired_ratios(const double *a, const double *b, int n, struct lx_paired_ratios *out);

/* Whether a view's difference is one its rounds resolve: a[r] and b[r] are two methods'
 * median times in each of n rounds of one view (the same frames, the machine's noise
 * shared within a round). +1 when a is the slower in every round, -1 when the faster in
 * every round, 0 otherwise, also for n < 2 or a round without two positive finite times.
 * A sign test: where the two cost the same, each round is a coin toss, so +1 comes by
 * chance once in 2^n views (once in 32 with 5 rounds). */
int lx_rounds_sign(const double *a, const double *b, int n);

/* World point of window pixel centre (x + 0.5, y + 0.5) on a plane; false when the
 * pixel's ray misses the plane's parallelogram or meets it outside the view depth range. */
bool lx_pixel_on_plane(const struct lx_frame *f, int plane, int x, int y, vec3 *p);

#endif
