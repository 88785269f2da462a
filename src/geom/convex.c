#include "convex.h"
#include <math.h>

#define POLY_MAX 32

typedef struct {
	vec3 n;
	double d; /* inside: dot(n, p) + d >= 0 */
} plane_t;

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

static int clip_faces(const vec3 faces[6][4], const plane_t *planes, int np, vec3 *out, int count, int max_out)
{
	for (int f = 0; f < 6; f++) {
		vec3 buf[2][POLY_MAX], *a = buf[0], *b = buf[1]; /* each cut from a into b, then the two swap */
		int n = 4;
		for (int i = 0; i < 4; i++)
			a[i] = faces[f][i];
		for (int p = 0; p < np && n > 0; p++) {
			n = lx_clip_polygon(a, n, (vec4){planes[p].n.x, planes[p].n.y, planes[p].n.z, planes[p].d}, b, POLY_MAX);
			vec3 *t = a;
			a = b, b = t;
		}
		for (int i = 0; i < n && count < max_out; i++)
			out[count++] = a[i];
	}
	return count;
}

static plane_t plane_through(vec3 a, vec3 b, vec3 c, vec3 inside)
{
	plane_t p = {v3(0, 0, 0), 0};
	vec3 n;
	if (!v3_normalize(v3_cross(v3_sub(b, a), v3_sub(c, a)), &n))
		return (plane_t){v3(0, 0, 0), 1}; /* degenerate face: constrains nothing */
	p.n = n;
	p.d = -v3_dot(n, a);
	if (v3_dot(p.n, inside) + p.d < 0) {
		p.n = v3_scale(p.n, -1);
		p.d = -p.d;
	}
	return p;
}

int lx_frustum_box_points(const vec3 fc[8], vec3 bmin, vec3 bmax, vec3 *out, int max_out)
{
	vec3 centre = v3(0, 0, 0);
	for (int i = 0; i < 8; i++)
		centre = v3_add(centre, v3_scale(fc[i], 1.0 / 8));
	static const int fq[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
	vec3 ffaces[6][4];
	plane_t fplanes[6];
	for (int f = 0; f < 6; f++) {
		for (int i = 0; i < 4; i++)
			ffaces[f][i] = fc[fq[f][i]];
		fplanes[f] = plane_through(ffaces[f][0], ffaces[f][1], ffaces[f][2], centre);
	}
	vec3 c[8];
	for (int i = 0; i < 8; i++)
		c[i] = v3(i & 1 ? bmax.x : bmin.x, i & 2 ? bmax.y : bmin.y, i & 4 ? bmax.z : bmin.z);
	static const int bq[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
	vec3 bfaces[6][4];
	for (int f = 0; f < 6; f++)
		for (int i = 0; i < 4; i++)
			bfaces[f][i] = c[bq[f][i]];
	/* A box inside the frustum by more than rounding (a caster in view, every frame): its
	 * faces' corners, as the clipping below would give them, the frustum's faces missing
	 * the box. */
	bool inside = true;
	for (int i = 0; i < 8 && inside; i++)
		for (int f = 0; f < 6 && inside; f++) {
			double d = v3_dot(fplanes[f].n, c[i]) + fplanes[f].d;
			inside = d > 1e-9 * (fabs(c[i].x) + fabs(c[i].y) + fabs(c[i].z) + fabs(fplanes[f].d));
		}
	if (inside) {
		int n = 0;
		for (int f = 0; f < 6; f++)
			for (int i = 0; i < 4 && n < max_out; i++)
				out[n++] = bfaces[f][i];
		return n;
	}
	/* The box's planes written directly: a flat box (zero height) keeps both y planes. */
	plane_t bplanes[6] = {{v3(1, 0, 0), -bmin.x}, {v3(-1, 0, 0), bmax.x}, {v3(0, 1, 0), -bmin.y},
			      {v3(0, -1, 0), bmax.y}, {v3(0, 0, 1), -bmin.z}, {v3(0, 0, -1), bmax.z}};
	/* Every vertex of the intersection lies on a face of one volume, inside the other. */
	int n = clip_faces(ffaces, bplanes, 6, out, 0, max_out);
	return clip_faces(bfaces, fplanes, 6, out, n, max_out);
}
