#include "soft_reference.h"
#include <math.h>

void lx_area_light_make(const struct lx_frame *f, const struct lx_raycaster *rc, double size_deg,
			struct lx_area_light *out)
{
	const struct lx_light *l = &f->light;
	double half = fmin(fmax(size_deg, 0.0), LX_MAX_LIGHT_SIZE_DEG) * M_PI / 360.0;
	*out = (struct lx_area_light){.directional = l->directional, .centre = l->position,
				      .toward = v3_scale(l->direction, -1), .reach = lx_raycaster_scale(rc)};
	out->radius = l->directional ? tan(half) : v3_len(v3_sub(l->position, f->scene->camera.at)) * sin(half);
}

/* Two unit vectors across the unit axis a, and a. */
static void across(vec3 a, vec3 *e1, vec3 *e2)
{
	vec3 helper = fabs(a.x) < 0.9 ? v3(1, 0, 0) : v3(0, 1, 0);
	v3_normalize(v3_cross(a, helper), e1); /* a is unit and not along helper */
	*e2 = v3_cross(a, *e1);
}

/* A 64-bit mix (splitmix64's finaliser): the strata's jitter, the same in every run. */
static unsigned long long mix64(unsigned long long z)
{
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
	return z ^ (z >> 31);
}

/* The square [-1, 1]^2 onto the unit disc keeping strata compact ([Shirley-Chiu]'s
 * concentric map): squares round the centre become rings. */
static void square_to_disc(double u, double v, double *x, double *y)
{
	double r, phi;
	if (u == 0 && v == 0) {
		*x = *y = 0;
		return;
	}
	if (fabs(u) > fabs(v))
		r = u, phi = M_PI / 4 * (v / u);
	else
		r = v, phi = M_PI / 2 - M_PI / 4 * (u / v);
	*x = r * cos(phi), *y = r * sin(phi);
}

/* The cone from p to the light: its axis (not normalised; for a point light it ends at
 * the centre), the disc's radius across it at the axis's end, and how far a ray goes (as
 * a multiple of its direction). False when p lies inside the light's sphere. */
static bool cone(const struct lx_area_light *L, vec3 p, vec3 *axis, double *disc, double *smax)
{
	if (L->directional) {
		*axis = v3_scale(L->toward, L->reach);
		*disc = L->reach * L->radius; /* the cone's width where nothing lies beyond */
		*smax = INFINITY;
		return true;
	}
	*axis = v3_sub(L->centre, p);
	double d = v3_len(*axis);
	if (!(d > L->radius * (1 + 1e-9)))
		return false;
	/* the disc through the centre that subtends the sphere's cone from p */
	*disc = L->radius / sqrt(1 - (L->radius / d) * (L->radius / d));
	*smax = 1.0 - 1e-9; /* as the hard reference: a hair before the light */
	return true;
}

double lx_soft_visibility(const struct lx_raycaster *rc, const struct lx_area_light *light, vec3 p, int tri,
			  unsigned long long seed)
{
	int object = lx_raycaster_object(rc, tri);
	vec3 to_light = light->directional ? light->toward : v3_sub(light->centre, p);
	if (!(v3_dot(lx_raycaster_normal(rc, tri), to_light) > 0))
		return 0; /* faces away from the light's centre */
	vec3 axis, e1 = v3(0, 0, 0), e2; /* across() always sets e1: the compiler cannot see it */
	double disc, smax;
	if (!cone(light, p, &axis, &disc, &smax))
		return 1; /* inside the light */
	if (!(disc > 0)) /* a point: the hard reference's one ray (less the own object) */
		return !lx_raycast_blocked(rc, p, to_light, 1e-9 * lx_raycaster_scale(rc) / v3_len(to_light), smax, object);
	double len = v3_len(axis);
	vec3 unit = v3_scale(axis, 1 / len); /* len > 0: the dot product above was positive */
	if (!lx_raycast_near(rc, p, v3_add(p, axis), disc, object))
		return 1;
	across(unit, &e1, &e2);
	/* directional: a ray's direction is the axis's unit plus the disc's offset scaled */
	double scale = light->directional ? 1.0 / len : 1.0;
	int seen = 0, side = LX_SOFT_SIDE, hint = -1;
	for (int k = 0; k < side * side; k++) {
		unsigned long long h = mix64(seed * (unsigned long long)(side * side) + (unsigned long long)k + 1);
		double u = -1 + 2 * (k % side + (h >> 11) * 0x1p-53 * 0.999999) / side;
		double v = -1 + 2 * (k / side + mix64(h) * 0x1p-64 * 0.999999) / side;
		double dx, dy;
		square_to_disc(u, v, &dx, &dy);
		vec3 d = v3_add(v3_scale(axis, scale), v3_scale(v3_add(v3_scale(e1, dx), v3_scale(e2, dy)), disc * scale));
		double smin = 1e-9 * lx_raycaster_scale(rc) / v3_len(d);
		seen += !lx_raycast_blocked_hint(rc, p, d, smin, smax, object, &hint);
	}
	return (double)seen / (side * side);
}

struct soft_job {
	const struct lx_frame *f;
	const struct lx_raycaster *rc;
	struct lx_area_light light;
	float *visibility;
};

static void soft_row(void *ctx, int y)
{
	struct soft_job *j = ctx;
	int w = j->f->view.width;
	for (int x = 0; x < w; x++) {
		size_t i = (size_t)y * w + x;
		vec3 p;
		int tri = lx_reference_pixel(j->f, j->rc, x, y, &p);
		j->visibility[i] = tri < 0 ? 1.0f : (float)lx_soft_visibility(j->rc, &j->light, p, tri, i);
	}
}

bool lx_soft_reference_image(const struct lx_frame *f, double size_deg, float *visibility, int threads)
{
	struct lx_raycaster *rc = lx_raycaster_create(f);
	if (!rc)
		return false;
	struct soft_job job = {f, rc, {0}, visibility};
	lx_area_light_make(f, rc, size_deg, &job.light);
	lx_reference_rows(f->view.height, threads, soft_row, &job);
	lx_raycaster_destroy(rc);
	return true;
}
