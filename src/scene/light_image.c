#include "light_image.h"
#include "embedded.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void flip_rows(struct lx_image *im)
{
	size_t row = (size_t)im->width * 4;
	for (int y = 0; y < im->height / 2; y++) {
		uint8_t *a = im->rgba + (size_t)y * row, *b = im->rgba + (size_t)(im->height - 1 - y) * row;
		for (size_t i = 0; i < row; i++) {
			uint8_t t = a[i];
			a[i] = b[i];
			b[i] = t;
		}
	}
}

static double smoothstep(double e0, double e1, double x)
{
	double t = (x - e0) / (e1 - e0); /* e1 > e0: constants below */
	t = t < 0 ? 0 : t > 1 ? 1 : t;
	return t * t * (3 - 2 * t);
}

/* The round beam: intensity by the angle from the axis, theta / half-angle, through the
 * texel's centre; square, so the beam is round whatever the fov. */
static bool round_beam(const struct lx_light *l, struct lx_image *out)
{
	int n = LX_ROUND_BEAM_SIZE;
	out->rgba = malloc((size_t)n * n * 4);
	if (!out->rgba)
		return false;
	out->width = out->height = n;
	double half = l->fov_deg * M_PI / 360, tan_half = tan(half); /* fov in (0, 150): both positive */
	for (int y = 0; y < n; y++)
		for (int x = 0; x < n; x++) {
			double u = (2.0 * (x + 0.5) / n - 1) * tan_half, v = (2.0 * (y + 0.5) / n - 1) * tan_half;
			double theta = atan(sqrt(u * u + v * v));
			double i = 1 - smoothstep(0.5, 1.0, theta / half);
			uint8_t c = (uint8_t)lround(255 * i);
			uint8_t *p = out->rgba + ((size_t)y * n + x) * 4;
			p[0] = p[1] = p[2] = c;
			p[3] = 255;
		}
	return true;
}

bool lx_light_image_load(const struct lx_light *l, struct lx_image *out, char *err, size_t errlen)
{
	memset(out, 0, sizeof *out);
	char why[256];
	if (l->projective == LX_LIGHT_PLAIN)
		return true; /* nothing to sample: its light is its colour */
	if (l->image == LX_IMAGE_ROUND_BEAM) {
		if (!round_beam(l, out))
			return snprintf(err, errlen, "out of memory for the spotlight's beam"), false;
		return true;
	}
	if (l->image == LX_IMAGE_BUILTIN_SLIDE) {
		if (!lx_png_read_memory(lx_builtin_slide_png, lx_builtin_slide_png_size, out, why, sizeof why))
			return snprintf(err, errlen, "the built-in slide: %s", why), false;
	} else if (!lx_png_read(l->image_path, out, why, sizeof why)) {
		snprintf(err, errlen, "%s '%s': %s", l->projective == LX_LIGHT_SPOT ? "beam" : "slide", l->image_path, why);
		return false;
	}
	flip_rows(out);
	return true;
}

/* A projective light's view (world -> light, looking down -z) and the tangents of its
 * half-angles across (tx) and up (ty); false for other lights or a degenerate frame. */
static bool light_view(const struct lx_light *l, mat4 *view, double *tx, double *ty)
{
	if (l->projective == LX_LIGHT_PLAIN || !(l->aspect > 0) || !m4_look_at(l->position, l->at, l->up, view))
		return false;
	*ty = tan(l->fov_deg * M_PI / 360), *tx = l->aspect * *ty; /* fov in (0, 150) degrees */
	return true;
}

bool lx_light_projection(const struct lx_light *l, mat4 *out)
{
	mat4 view;
	double tx, ty;
	if (!light_view(l, &view, &tx, &ty))
		return false;
	/* depth d = -z in the light's view; s = 0.5 + 0.5 x / (d tx), t = 0.5 + 0.5 y / (d ty) */
	mat4 m = {{0}};
	for (int c = 0; c < 4; c++) {
		double x = view.m[c * 4 + 0], y = view.m[c * 4 + 1], d = -view.m[c * 4 + 2];
		m.m[c * 4 + 0] = 0.5 * x / tx + 0.5 * d;
		m.m[c * 4 + 1] = 0.5 * y / ty + 0.5 * d;
		m.m[c * 4 + 2] = d;
		m.m[c * 4 + 3] = d;
	}
	*out = m;
	return m4_finite(out);
}

bool lx_light_frustum(const struct lx_light *l, vec3 lo, vec3 hi, vec3 fc[8])
{
	mat4 view;
	double tx, ty;
	if (!light_view(l, &view, &tx, &ty))
		return false;
	vec3 s = v3(view.m[0], view.m[4], view.m[8]), u = v3(view.m[1], view.m[5], view.m[9]);
	vec3 fw = v3(-view.m[2], -view.m[6], -view.m[10]);
	double far = l->range_far;
	if (!(far > 0)) /* no range: past the farthest corner of the box */
		for (int i = 0; i < 8; i++)
			far = fmax(far, v3_dot(v3_sub(v3_box_corner(lo, hi, i), l->position), fw));
	double near = 1e-9 * (v3_len(v3_sub(hi, lo)) + 1e-300);
	static const double corner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
	for (int k = 0; k < 8; k++) {
		double d = k < 4 ? near : fmax(far * 1.001, 2 * near);
		const double *c = corner[k % 4];
		fc[k] = v3_add(l->position, v3_add(v3_scale(fw, d), v3_add(v3_scale(s, c[0] * tx * d), v3_scale(u, c[1] * ty * d))));
	}
	return true;
}

static double texel(const struct lx_image *im, int x, int y, int ch)
{
	x = x < 0 ? 0 : x >= im->width ? im->width - 1 : x;
	y = y < 0 ? 0 : y >= im->height ? im->height - 1 : y;
	return im->rgba[((size_t)y * im->width + x) * 4 + ch] / 255.0;
}

vec3 lx_image_bilinear(const struct lx_image *im, double s, double t)
{
	double fx = s * im->width - 0.5, fy = t * im->height - 0.5;
	double x0 = floor(fx), y0 = floor(fy), ax = fx - x0, ay = fy - y0;
	int ix = (int)fmax(-2, fmin(x0, im->width + 1)), iy = (int)fmax(-2, fmin(y0, im->height + 1));
	double c[3];
	for (int ch = 0; ch < 3; ch++)
		c[ch] = (1 - ay) * ((1 - ax) * texel(im, ix, iy, ch) + ax * texel(im, ix + 1, iy, ch)) +
			ay * ((1 - ax) * texel(im, ix, iy + 1, ch) + ax * texel(im, ix + 1, iy + 1, ch));
	return v3(c[0], c[1], c[2]);
}

static bool project(const struct lx_light *l, const mat4 *proj, vec3 p, double *s, double *t, double *d)
{
	vec4 q = m4_mul_point(proj, p);
	if (!(q.w > 0))
		return false; /* behind the light, or in its plane */
	*s = q.x / q.w, *t = q.y / q.w, *d = q.w;
	return *s >= 0 && *s <= 1 && *t >= 0 && *t <= 1 && !(l->range_far > 0 && *d > l->range_far);
}

bool lx_light_reaches(const struct lx_light *l, const mat4 *proj, vec3 p)
{
	double s, t, d;
	return l->projective == LX_LIGHT_PLAIN || project(l, proj, p, &s, &t, &d);
}

vec3 lx_projective_light_at(const struct lx_light *l, const mat4 *proj, const struct lx_image *im, vec3 p)
{
	double s, t, d;
	if (l->projective == LX_LIGHT_PLAIN)
		return l->color; /* every light is multiplied by its colour */
	if (!project(l, proj, p, &s, &t, &d))
		return v3(0, 0, 0);
	double fall = 1;
	if (l->range_far > 0) /* range_far > range_near >= 0: the parser checks it */
		fall = fmin(1, (l->range_far - d) / (l->range_far - l->range_near));
	vec3 c = lx_image_bilinear(im, s, t);
	return v3(c.x * l->color.x * fall, c.y * l->color.y * fall, c.z * l->color.z * fall);
}
