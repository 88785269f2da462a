#include "convex.h"
#include <math.h>

#define POLY_MAX 32

int lx_clip_polygon(const vec3 *in, int n, vec4 p, vec3 *out, int max_out)
{
	int m = 0;
	for (int i = 0; i < n; i++) {
		vec3 a = in[i], b = in[lx_loop_next(i, n)];
		double da = p.x * a.x + p.y * a.y + p.z * a.z + p.w, db = p.x * b.x + p.y * b.y + p.z * b.z + p.w;
		if (da >= 0 && m < max_out)
			out[m++] = a;
		if ((da >= 0) != (db >= 0) && m < max_out) /* signs differ: da - db != 0 */
			out[m++] = v3_add(a, v3_scale(v3_sub(b, a), da / (da - db)));
	}
	return m;
}

static int clip_faces(const vec3 faces[6][4], const vec4 *planes, int np, vec3 *out, int count, int max_out)
{
	for (int f = 0; f < 6; f++) {
		vec3 buf[2][POLY_MAX], *a = buf[0], *b = buf[1]; /* each cut from a into b, then the two swap */
		int n = 4;
		for (int i = 0; i < 4; i++)
			a[i] = faces[f][i];
		for (int p = 0; p < np && n > 0; p++) {
			n = lx_clip_polygon(a, n, planes[p], b, POLY_MAX);
			vec3 *t = a;
			a = b, b = t;
		}
		for (int i = 0; i < n && count < max_out; i++)
			out[count++] = a[i];
	}
	return count;
}

/* The plane through a, b and c, as (n, d) with |n| = 1 and n . inside + d >= 0. */
static vec4 plane_through(vec3 a, vec3 b, vec3 c, vec3 inside)
{
	vec3 n;
	if (!v3_normalize(v3_cross(v3_sub(b, a), v3_sub(c, a)), &n))
		return (vec4){0, 0, 0, 1}; /* degenerate face: constrains nothing */
	vec4 p = {n.x, n.y, n.z, -v3_dot(n, a)};
	if (v4_dot_point(p, inside) < 0)
		p = (vec4){-p.x, -p.y, -p.z, -p.w};
	return p;
}

/* Box [lo, hi]'s six faces, each a quad of its corners. */
static void box_faces(vec3 lo, vec3 hi, vec3 faces[6][4])
{
	static const int q[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
	for (int f = 0; f < 6; f++)
		for (int i = 0; i < 4; i++)
			faces[f][i] = v3_box_corner(lo, hi, q[f][i]);
}

int lx_box_clip_points(vec3 lo, vec3 hi, const vec4 *planes, int np, vec3 *out, int max_out)
{
	vec3 faces[6][4];
	box_faces(lo, hi, faces);
	return clip_faces(faces, planes, np, out, 0, max_out);
}

void lx_box_halfspaces(vec3 lo, vec3 hi, vec4 out[6])
{
	out[0] = (vec4){1, 0, 0, -lo.x}, out[1] = (vec4){-1, 0, 0, hi.x}, out[2] = (vec4){0, 1, 0, -lo.y};
	out[3] = (vec4){0, -1, 0, hi.y}, out[4] = (vec4){0, 0, 1, -lo.z}, out[5] = (vec4){0, 0, -1, hi.z};
}

int lx_frustum_box_points(const vec3 fc[8], vec3 bmin, vec3 bmax, vec3 *out, int max_out)
{
	vec3 centre = v3(0, 0, 0);
	for (int i = 0; i < 8; i++)
		centre = v3_add(centre, v3_scale(fc[i], 1.0 / 8));
	static const int fq[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
	vec3 ffaces[6][4];
	vec4 fplanes[6];
	for (int f = 0; f < 6; f++) {
		for (int i = 0; i < 4; i++)
			ffaces[f][i] = fc[fq[f][i]];
		fplanes[f] = plane_through(ffaces[f][0], ffaces[f][1], ffaces[f][2], centre);
	}
	vec3 bfaces[6][4];
	box_faces(bmin, bmax, bfaces);
	/* A box inside the frustum by more than rounding (a caster in view, every frame): its
	 * faces' corners, as the clipping below would give them, the frustum's faces missing
	 * the box. */
	bool inside = true;
	for (int i = 0; i < 8 && inside; i++) {
		vec3 c = v3_box_corner(bmin, bmax, i);
		for (int f = 0; f < 6 && inside; f++)
			inside = v4_dot_point(fplanes[f], c) > 1e-9 * (fabs(c.x) + fabs(c.y) + fabs(c.z) + fabs(fplanes[f].w));
	}
	if (inside) {
		int n = 0;
		for (int f = 0; f < 6; f++)
			for (int i = 0; i < 4 && n < max_out; i++)
				out[n++] = bfaces[f][i];
		return n;
	}
	/* The box's planes written directly: a flat box (zero height) keeps both y planes. */
	vec4 bplanes[6];
	lx_box_halfspaces(bmin, bmax, bplanes);
	/* Every vertex of the intersection lies on a face of one volume, inside the other. */
	int n = clip_faces(ffaces, bplanes, 6, out, 0, max_out);
	return clip_faces(bfaces, fplanes, 6, out, n, max_out);
}
