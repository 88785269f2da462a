#include "metrics.h"
#include "reference.h"
#include "plane_optimal.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The shares of the compared pixels; 0 when none is compared. */
static void percentages(struct lx_mismatch *m)
{
	double c = m->compared > 0 ? (double)m->compared : 1;
	m->false_shadow_pct = 100.0 * m->false_shadow / c;
	m->missing_shadow_pct = 100.0 * m->missing_shadow / c;
	m->mismatch_pct = 100.0 * (m->false_shadow + m->missing_shadow) / c;
}

void lx_mismatch_compare(const int16_t *ref_object, const uint8_t *ref_shadow, const int16_t *object,
			 const uint8_t *shadow, long pixels, struct lx_mismatch *out)
{
	memset(out, 0, sizeof(*out));
	for (long i = 0; i < pixels; i++) {
		if (ref_object[i] == LX_NO_OBJECT && object[i] == LX_NO_OBJECT)
			continue; /* background in both */
		if (ref_object[i] != object[i]) {
			out->silhouette++;
			continue;
		}
		if (ref_shadow[i] == LX_REF_EDGE_ON) {
			out->edge_on++; /* the light grazes it: either decision shades it alike */
			continue;
		}
		if (ref_shadow[i] == LX_REF_UNLIT) {
			out->unlit++; /* the light does not reach it: either decision shades it alike */
			continue;
		}
		out->compared++;
		if (shadow[i] && !ref_shadow[i])
			out->false_shadow++;
		else if (!shadow[i] && ref_shadow[i])
			out->missing_shadow++;
	}
	percentages(out);
}

void lx_mismatch_add(struct lx_mismatch *total, const struct lx_mismatch *part)
{
	total->compared += part->compared, total->silhouette += part->silhouette;
	total->edge_on += part->edge_on, total->unlit += part->unlit;
	total->false_shadow += part->false_shadow, total->missing_shadow += part->missing_shadow;
	percentages(total);
}

double lx_soft_error(const int16_t *ref_object, const uint8_t *ref_shadow, const float *ref_visibility,
		     const int16_t *object, const uint8_t *visibility, long pixels)
{
	double sum = 0;
	long compared = 0;
	for (long i = 0; i < pixels; i++) {
		if (ref_object[i] == LX_NO_OBJECT || ref_object[i] != object[i] || ref_shadow[i] == LX_REF_EDGE_ON ||
		    ref_shadow[i] == LX_REF_UNLIT)
			continue; /* background, silhouette, grazed, unlit: as lx_mismatch_compare */
		compared++;
		sum += fabs(visibility[i] / 255.0 - ref_visibility[i]);
	}
	return compared ? 100.0 * sum / compared : 0.0;
}

double lx_colour_error(const uint8_t *a, const uint8_t *b, long pixels)
{
	double sum = 0;
	for (long i = 0; i < pixels; i++)
		for (int c = 0; c < 3; c++)
			sum += abs(a[i * 4 + c] - b[i * 4 + c]);
	return pixels > 0 ? sum / (3.0 * pixels) : 0;
}

/* rows of a 3x4 "viewport" map from clip (x, y, z, w) to (px * w, py * w, w) */
static void viewport_rows(double x0, double y0, double w, double h, double r[12])
{
	double v[12] = {w / 2, 0, 0, x0 + w / 2, 0, h / 2, 0, y0 + h / 2, 0, 0, 0, 1};
	memcpy(r, v, sizeof v);
}

/* (3x4 rows) * (4x4 column-major) * (4x3 plane basis) -> 3x3 column-major */
static mat3 project_plane(const double vp[12], const mat4 *m, const struct lx_plane *p)
{
	double basis[4][3] = {{p->edge1.x, p->edge2.x, p->corner.x},
			      {p->edge1.y, p->edge2.y, p->corner.y},
			      {p->edge1.z, p->edge2.z, p->corner.z},
			      {0, 0, 1}};
	double mb[4][3];
	for (int r = 0; r < 4; r++)
		for (int c = 0; c < 3; c++) {
			double s = 0;
			for (int k = 0; k < 4; k++)
				s += m->m[k * 4 + r] * basis[k][c];
			mb[r][c] = s;
		}
	mat3 out;
	for (int r = 0; r < 3; r++)
		for (int c = 0; c < 3; c++) {
			double s = 0;
			for (int k = 0; k < 4; k++)
				s += vp[r * 4 + k] * mb[k][c];
			out.m[c * 3 + r] = s;
		}
	return out;
}

bool lx_plane_homography(const struct lx_frame *f, const struct lx_atlas *atlas, const struct lx_shadow_map *map,
			 int plane, mat3 *h)
{
	const struct lx_plane *p = &f->scene->planes[plane];
	const struct lx_region *g = &atlas->regions[map->region];
	double vs[12], vl[12];
	viewport_rows(0, 0, f->view.width, f->view.height, vs);
	viewport_rows(0, 0, g->w, g->h, vl);
	mat3 screen = project_plane(vs, &f->view.view_proj, p), light = project_plane(vl, &map->light_clip, p), inv;
	if (!m3_invert(&screen, &inv))
		return false;
	*h = m3_mul(&light, &inv);
	return true;
}

bool lx_homography_jacobian(const mat3 *hm, double x, double y, double *s_max, double *s_min)
{
	const double *h = hm->m; /* column-major: h[c * 3 + r] */
	double wq = h[2] * x + h[5] * y + h[8];
	double scale = fabs(h[2] * x) + fabs(h[5] * y) + fabs(h[8]);
	if (!(fabs(wq) > 1e-12 * scale))
		return false;
	double u = (h[0] * x + h[3] * y + h[6]) / wq, v = (h[1] * x + h[4] * y + h[7]) / wq;
	double a = (h[0] - u * h[2]) / wq, b = (h[3] - u * h[5]) / wq;
	double c = (h[1] - v * h[2]) / wq, d = (h[4] - v * h[5]) / wq;
	/* closed-form singular values of [[a, b], [c, d]] */
	double e = (a + d) / 2, fq = (a - d) / 2, g = (c + b) / 2, hh = (c - b) / 2;
	double q = sqrt(e * e + hh * hh), r = sqrt(fq * fq + g * g);
	*s_max = q + r;
	*s_min = fabs(q - r);
	return isfinite(*s_max) && isfinite(*s_min);
}

/* The k-th smallest of v[0..n-1] (0-based), reordering v: Hoare's selection with the
 * median of three as pivot, linear on average; the per-pixel arrays here hold up to a
 * screen's pixels, where a full sort was most of the metrics' time. NaN-free input. */
static double select_kth(double *v, long n, long k)
{
	long lo = 0, hi = n - 1;
	while (hi > lo) {
		long mid = lo + (hi - lo) / 2;
		double a = v[lo], b = v[mid], c = v[hi];
		double pivot = a < b ? (b < c ? b : (a < c ? c : a)) : (a < c ? a : (b < c ? c : b));
		long i = lo, j = hi;
		while (i <= j) {
			while (v[i] < pivot)
				i++;
			while (v[j] > pivot)
				j--;
			if (i <= j) {
				double t = v[i];
				v[i++] = v[j];
				v[j--] = t;
			}
		}
		if (k <= j)
			hi = j;
		else if (k >= i)
			lo = i;
		else
			return v[k];
	}
	return v[k];
}

double lx_median(double *v, long n)
{
	if (n <= 0)
		return NAN;
	double upper = select_kth(v, n, n / 2);
	if (n % 2)
		return upper;
	/* the lower middle is the largest of the part select_kth left below n/2 */
	double lower = v[0];
	for (long i = 1; i < n / 2; i++)
		lower = v[i] > lower ? v[i] : lower;
	return 0.5 * (lower + upper);
}

void lx_paired_ratios(const double *a, const double *b, int n, struct lx_paired_ratios *out)
{
	*out = (struct lx_paired_ratios){NAN, NAN, NAN, -1, 0, 0};
	double *r = n > 0 ? malloc((size_t)n * sizeof *r) : NULL;
	if (!r)
		return;
	for (int i = 0; i < n; i++) {
		/* a time of 0, a NaN (a view not timed) or an infinity gives no ratio */
		if (!(isfinite(a[i]) && isfinite(b[i]) && a[i] > 0 && b[i] > 0))
			continue;
		double q = a[i] / b[i];
		if (out->count == 0 || q < out->least)
			out->least = q;
		if (out->count == 0 || q > out->most)
			out->most = q, out->most_at = i;
		out->at_most_one += q <= 1;
		r[out->count++] = q;
	}
	out->median = lx_median(r, out->count); /* NaN for none */
	free(r);
}

int lx_rounds_sign(const double *a, const double *b, int n)
{
	int over = 0, under = 0;
	for (int r = 0; r < n; r++) {
		if (!(isfinite(a[r]) && isfinite(b[r]) && a[r] > 0 && b[r] > 0))
			return 0;
		over += a[r] > b[r], under += a[r] < b[r];
	}
	return n < 2 ? 0 : over == n ? 1 : under == n ? -1 : 0;
}

/* World point of pixel centre x of row r (lx_window_row of its y + 0.5) on plane eq; false
 * when the pixel's ray misses the parallelogram g or meets it outside the view depth range. */
static bool on_plane(const struct lx_window_row *r, const struct lx_plane_gram *g, vec4 eq, int x, vec3 *out)
{
	double t;
	return lx_window_row_on_plane(r, eq, x + 0.5, out, &t) && t >= 0 && t <= 1 && lx_plane_gram_contains(g, *out);
}

bool lx_pixel_on_plane(const struct lx_frame *f, int plane, int x, int y, vec3 *out)
{
	const struct lx_plane *p = &f->scene->planes[plane];
	struct lx_plane_gram g = lx_plane_gram(p);
	struct lx_window_row r = lx_window_row(&f->view, y + 0.5);
	return on_plane(&r, &g, lx_plane_equation(p), x, out);
}

bool lx_plane_points_make(const struct lx_frame *f, const int16_t *ref_object, struct lx_plane_points *out)
{
	int w = f->view.width, h = f->view.height, planes = f->scene->plane_count;
	out->p = malloc((size_t)w * h * sizeof(vec3));
	out->on = calloc((size_t)w * h, 1);
	if (!out->p || !out->on) {
		lx_plane_points_free(out);
		return false;
	}
	struct lx_plane_gram gram[LX_MAX_PLANES];
	vec4 eq[LX_MAX_PLANES];
	for (int k = 0; k < planes; k++)
		gram[k] = lx_plane_gram(&f->scene->planes[k]), eq[k] = lx_plane_equation(&f->scene->planes[k]);
	for (int y = 0; y < h; y++) {
		struct lx_window_row r = lx_window_row(&f->view, y + 0.5);
		for (int x = 0; x < w; x++) {
			long i = (long)y * w + x;
			int k = ref_object[i];
			if (k >= 0 && k < planes)
				out->on[i] = on_plane(&r, &gram[k], eq[k], x, &out->p[i]);
		}
	}
	return true;
}

void lx_plane_points_free(struct lx_plane_points *pts)
{
	free(pts->p);
	free(pts->on);
	pts->p = NULL, pts->on = NULL;
}

/* pts: each pixel's point where ref_object names a plane (stride 1 only), else NULL. */
static bool sampling(const struct lx_frame *f, const struct lx_atlas *atlas, const struct lx_shadow_result *res,
		     int plane, const int16_t *ref_object, const struct lx_plane_points *pts, const uint8_t *looked,
		     int stride, struct lx_plane_sampling *out)
{
	memset(out, 0, sizeof(*out));
	out->map = -1;
	int w = f->view.width, hgt = f->view.height;
	mat3 h[LX_MAX_MAPS];
	bool hok[LX_MAX_MAPS] = {false};
	for (int m = 0; m < res->map_count; m++) {
		if (res->maps[m].rendered)
			hok[m] = lx_plane_homography(f, atlas, &res->maps[m], plane, &h[m]);
		if (res->maps[m].rendered && res->maps[m].plane == plane && out->map < 0)
			out->map = m; /* the first of the plane's own maps names them */
	}
	long n = (long)((w + stride - 1) / stride) * ((hgt + stride - 1) / stride); /* pixels visited */
	double *lpp = malloc((size_t)n * sizeof(double)), *mm = malloc((size_t)n * sizeof(double));
	if (!lpp || !mm) {
		free(lpp);
		free(mm);
		return false;
	}
	const struct lx_plane *pl = &f->scene->planes[plane];
	vec4 eq = lx_plane_equation(pl); /* once, not per pixel: it was a sixth of the sampling */
	struct lx_plane_gram gram = lx_plane_gram(pl); /* and the parallelogram's Gram matrix: a fifth */
	long k = 0;
	out->lpp_min = INFINITY;
	unsigned reads = lx_shadow_receiver_maps(res, plane); /* once, not per pixel */
	for (int y = stride / 2; y < hgt; y += stride) {
		struct lx_window_row row = lx_window_row(&f->view, y + 0.5);
		for (int x = stride / 2; x < w; x += stride) {
			vec3 p;
			long i = (long)y * w + x;
			if (ref_object ? ref_object[i] != plane : false)
				continue;
			if (pts ? !pts->on[i] : !on_plane(&row, &gram, eq, x, &p))
				continue;
			out->seen++;
			if (looked && !looked[i]) { /* no lookup ran: the pixel reads no map */
				out->no_lookup++;
				continue;
			}
			if (pts)
				p = pts->p[i];
			int m = lx_shadow_select_map_in(res, reads, p);
			if (m < 0 || !hok[m]) {
				out->unserved++;
				continue;
			}
			double smax, smin;
			/* s_min below 1e-12 lixels per pixel: a lixel spans the whole screen or more */
			if (!lx_homography_jacobian(&h[m], x + 0.5, y + 0.5, &smax, &smin) || !(smin > 1e-12)) {
				out->degenerate++;
				continue;
			}
			lpp[k] = smax * smin;
			mm[k] = 1.0 / smin;
			out->lixels_used += lpp[k] * stride * stride;
			/* finite and positive here: comparisons, not fmin/fmax's library calls */
			out->lpp_min = lpp[k] < out->lpp_min ? lpp[k] : out->lpp_min;
			out->lpp_max = lpp[k] > out->lpp_max ? lpp[k] : out->lpp_max;
			out->m_max = mm[k] > out->m_max ? mm[k] : out->m_max;
			out->aniso_max = smax / smin > out->aniso_max ? smax / smin : out->aniso_max;
			k++;
		}
	}
	out->pixels = k;
	if (k) {
		out->lpp_median = lx_median(lpp, k);
		out->m_median = lx_median(mm, k);
	} else
		out->lpp_min = 0;
	free(lpp);
	free(mm);
	return k > 0;
}

bool lx_plane_sampling(const struct lx_frame *f, const struct lx_atlas *atlas, const struct lx_shadow_result *res,
		       int plane, const int16_t *ref_object, const struct lx_plane_points *pts, const uint8_t *looked,
		       struct lx_plane_sampling *out)
{
	return sampling(f, atlas, res, plane, ref_object, pts, looked, 1, out);
}

bool lx_plane_sampling_sparse(const struct lx_frame *f, const struct lx_atlas *atlas, const struct lx_shadow_result *res,
			      int plane, int stride, struct lx_plane_sampling *out)
{
	return sampling(f, atlas, res, plane, NULL, NULL, NULL, stride < 1 ? 1 : stride, out);
}
