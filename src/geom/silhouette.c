#include "silhouette.h"
#include "polygon2d.h"
#include <math.h>
#include <stdlib.h>

/* An edge of a triangle, keyed by its two ends (smaller first), for sorting. */
struct edge {
	unsigned key;
	int slot; /* 3 t + e */
	bool forward; /* runs from the smaller index to the larger */
};

static int cmp_edge(const void *pa, const void *pb)
{
	const struct edge *a = pa, *b = pb;
	return a->key < b->key ? -1 : a->key > b->key;
}

/* A position's x and its index, sorted by x (a comparison without the positions). */
struct keyed_x {
	float x;
	int i;
};

static int cmp_x(const void *pa, const void *pb)
{
	const struct keyed_x *a = pa, *b = pb;
	return a->x < b->x ? -1 : a->x > b->x;
}

static int root(int *rep, int i)
{
	while (rep[i] != i)
		i = rep[i] = rep[rep[i]];
	return i;
}

bool lx_mesh_weld(const float *pos, int np, double eps, int *rep)
{
	for (int i = 0; i < np; i++)
		rep[i] = i;
	struct keyed_x *order = malloc((size_t)(np > 0 ? np : 1) * sizeof *order);
	if (!order)
		return false;
	for (int i = 0; i < np; i++)
		order[i] = (struct keyed_x){pos[3 * i], i};
	qsort(order, (size_t)np, sizeof *order, cmp_x);
	/* sorted by x, each position's neighbours within eps follow it closely */
	for (int i = 0; i < np; i++)
		for (int j = i + 1; j < np && order[j].x - order[i].x <= eps; j++) {
			const float *a = pos + 3 * order[i].i, *b = pos + 3 * order[j].i;
			if (fabs((double)a[1] - b[1]) <= eps && fabs((double)a[2] - b[2]) <= eps) {
				int ra = root(rep, order[i].i), rb = root(rep, order[j].i);
				if (ra != rb)
					rep[ra > rb ? ra : rb] = ra < rb ? ra : rb; /* the first index stands */
			}
		}
	for (int i = 0; i < np; i++)
		rep[i] = root(rep, i);
	free(order);
	return true;
}

bool lx_mesh_adjacency(const unsigned short *index, int triangles, int *adj)
{
	struct edge *e = malloc((size_t)(3 * triangles + 1) * sizeof *e);
	if (!e)
		return false;
	int n = 0;
	for (int t = 0; t < triangles; t++) {
		const unsigned short *c = index + 3 * t;
		adj[3 * t] = adj[3 * t + 1] = adj[3 * t + 2] = -1;
		if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2])
			continue; /* two corners welded into one (a pole's): no area, no neighbour */
		for (int k = 0; k < 3; k++) {
			unsigned a = c[k], b = c[(k + 1) % 3];
			e[n++] = (struct edge){a < b ? a << 16 | b : b << 16 | a, 3 * t + k, a < b};
		}
	}
	qsort(e, (size_t)n, sizeof *e, cmp_edge);
	/* sorted, each edge's two runs side by side: more or fewer than two, or two the same
	 * way (a face turned over), is no closed mesh */
	bool closed = n % 2 == 0;
	for (int s = 0; closed && s < n; s += 2)
		closed = e[s].key == e[s + 1].key && (s + 2 >= n || e[s + 2].key != e[s].key) &&
			 e[s].forward != e[s + 1].forward;
	for (int s = 0; closed && s < n; s += 2)
		adj[e[s].slot] = e[s + 1].slot / 3, adj[e[s + 1].slot] = e[s].slot / 3;
	free(e);
	return closed;
}

int lx_silhouette_fan(const unsigned short *index, const int *adj, int triangles, const bool *kept,
		      unsigned short apex, int *next, unsigned short *out, int max_out)
{
	int edges = 0, count = 0;
	bool simple = true;
	for (int t = 0; t < triangles; t++) {
		if (!kept[t] || adj[3 * t] < 0)
			continue; /* not kept, or of no area (lx_mesh_adjacency) */
		for (int e = 0; e < 3; e++) {
			if (kept[adj[3 * t + e]])
				continue;
			int a = index[3 * t + e], b = index[3 * t + (e + 1) % 3];
			if (next[a] >= 0 || count + 3 > max_out) { /* two boundary edges leave a: pinched */
				simple = false;
				continue;
			}
			next[a] = b, edges++;
			out[count++] = apex, out[count++] = (unsigned short)a, out[count++] = (unsigned short)b;
		}
	}
	/* one loop: from one edge's start, `edges` steps come back to it and no sooner */
	int steps = 0;
	if (simple && edges > 0) {
		int start = out[1], v = start;
		do
			v = next[v], steps++;
		while (v >= 0 && v != start && steps <= edges);
		simple = v == start && steps == edges;
	}
	for (int k = 1; k < count; k += 3)
		next[out[k]] = -1;
	return simple && edges > 0 ? count : -1;
}

static vec4 point_at(const float *pos, unsigned short i)
{
	const float *q = pos + 3 * i;
	return (vec4){q[0], q[1], q[2], 1};
}

/* A fan's boundary loop, in order (each edge (apex, a, b) leads from a to b), into loop
 * (the fan's count / 3 corners); the count written, or -1 where it is not one loop of
 * three corners or more. */
static int fan_loop(const unsigned short *fan, int count, int *next, unsigned short *loop)
{
	int m = count / 3, n = 0;
	if (m < 3)
		return -1;
	for (int k = 0; k < count; k += 3)
		next[fan[k + 1]] = fan[k + 2];
	int v = fan[1];
	do
		loop[n++] = (unsigned short)v, v = next[v];
	while (v != fan[1] && v >= 0 && n < m);
	for (int k = 0; k < count; k += 3)
		next[fan[k + 1]] = -1;
	return n == m && v == fan[1] ? n : -1;
}

/* Where a position's image lies (x, y) as the matrix m (its light clip) projects it; false
 * behind the light. */
static bool image_of(const float *pos, const mat4 *m, unsigned short v, vec2 *at)
{
	vec4 c = m4_mul_v4(m, point_at(pos, v));
	if (!(c.w > 0))
		return false;
	*at = (vec2){c.x / c.w, c.y / c.w};
	return true;
}

/* The most corners of a polygon cut at its shortest inner edges (lx_fan_as_polygon): a
 * box's silhouette has four or six; a round caster's, more, cut the cheap way. */
#define SHORT_CUT_MAX 8

/* Convex polygon loop[0, m) (3 <= m <= SHORT_CUT_MAX; its corners' images at[]) cut into
 * the m - 2 triangles whose inner edges are shortest in all (the classic programme over
 * the parts between two corners), each wound in the loop's order, into out; returns the
 * indices written. */
static int cut_shortest(const unsigned short *loop, const vec2 *at, int m, unsigned short *out)
{
	double best[SHORT_CUT_MAX][SHORT_CUT_MAX] = {{0}};
	int split[SHORT_CUT_MAX][SHORT_CUT_MAX] = {{0}};
	for (int len = 2; len < m; len++)
		for (int i = 0; i + len < m; i++) {
			int j = i + len;
			best[i][j] = INFINITY, split[i][j] = i + 1;
			for (int k = i + 1; k < j; k++) {
				double c = best[i][k] + best[k][j] + (k - i > 1 ? hypot(at[i].x - at[k].x, at[i].y - at[k].y) : 0) +
					   (j - k > 1 ? hypot(at[k].x - at[j].x, at[k].y - at[j].y) : 0);
				if (c < best[i][j])
					best[i][j] = c, split[i][j] = k;
			}
		}
	int part[4 * SHORT_CUT_MAX], np = 0, n = 0; /* (i, j) pairs still to cut */
	part[np++] = 0, part[np++] = m - 1;
	while (np > 0) {
		int j = part[--np], i = part[--np];
		if (j - i < 2)
			continue;
		int k = split[i][j];
		out[n++] = loop[i], out[n++] = loop[k], out[n++] = loop[j];
		part[np++] = i, part[np++] = k, part[np++] = k, part[np++] = j;
	}
	return n;
}

int lx_fan_as_polygon(unsigned short *fan, int count, const float *pos, vec4 centre, const mat4 *light_clip, int *next,
		      unsigned short *loop)
{
	int m = fan_loop(fan, count, next, loop);
	if (m < 0)
		return count; /* under three corners, or not one loop: neither from lx_silhouette_fan */
	/* the way the fan's triangles face the light, and every corner turning that way */
	double way = 0;
	for (int k = 0; k < count; k += 3)
		way += v4_dot(centre, v4_cross3(point_at(pos, fan[k]), point_at(pos, fan[k + 1]), point_at(pos, fan[k + 2])));
	for (int i = 0; i < m; i++) {
		vec4 a = point_at(pos, loop[i]), b = point_at(pos, loop[(i + 1) % m]), c = point_at(pos, loop[(i + 2) % m]);
		if (!(way * v4_dot(centre, v4_cross3(a, b, c)) >= 0))
			return count; /* a corner turns the other way: not convex */
	}
	vec2 at[SHORT_CUT_MAX];
	bool seen = light_clip && m <= SHORT_CUT_MAX;
	for (int i = 0; seen && i < m; i++)
		seen = image_of(pos, light_clip, loop[i], &at[i]) && isfinite(at[i].x) && isfinite(at[i].y);
	if (seen)
		return cut_shortest(loop, at, m, fan);
	int out = 0;
	while (m > 2) { /* (0, 1, 2), (2, 3, 4), ...; the even corners stay for the next round */
		int kept = 0;
		for (int i = 0; i < m; i += 2) {
			if (i + 1 < m)
				fan[out++] = loop[i], fan[out++] = loop[i + 1], fan[out++] = loop[(i + 2) % m];
			loop[kept++] = loop[i];
		}
		m = kept;
	}
	return out;
}

/* Twice the signed area of triangle (a, b, c): positive where it turns counter-clockwise. */
static double turning(vec2 a, vec2 b, vec2 c)
{
	return (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
}

/* The angle round `centre` from `from` to p in the loops' turning (`turn` +1 or -1),
 * 0 to 2 pi. */
static double turned_by(vec2 centre, double from, int turn, vec2 p)
{
	double a = turn * (atan2(p.y - centre.y, p.x - centre.x) - from);
	a = fmod(a, 2 * M_PI);
	return a < 0 ? a + 2 * M_PI : a;
}

int lx_fan_band_strip(const unsigned short *outer, int outer_count, const unsigned short *inner, int inner_count,
		      const float *pos, const mat4 *light_clip, int *next, unsigned short *loop, double *work,
		      unsigned short *out, int max_out)
{
	unsigned short *o = loop;
	int no = fan_loop(outer, outer_count, next, o);
	unsigned short *in = no > 0 ? loop + no : NULL;
	int ni = in ? fan_loop(inner, inner_count, next, in) : -1;
	if (ni < 0 || 3 * (no + ni) > max_out)
		return -1;
	/* each corner's image (outer loop first), once, and below its angle */
	vec2 *img = (vec2 *)work, mid = {0, 0};
	double *angle = work + 2 * (no + ni);
	for (int i = 0; i < no + ni; i++)
		if (!image_of(pos, light_clip, loop[i], &img[i]))
			return -1;
	/* the inner loop's images' mean, the point the angles are taken round: inside both
	 * loops for a round caster's two caps (each step's triangle is checked all the same) */
	for (int j = 0; j < ni; j++)
		mid.x += img[no + j].x / ni, mid.y += img[no + j].y / ni; /* ni >= 3 */
	double area = 0; /* twice the outer loop's image's, its sign the loops' turning */
	for (int i = 0; i < no; i++)
		area += turning(mid, img[i], img[(i + 1) % no]);
	if (!(area != 0))
		return -1;
	int turn = area > 0 ? 1 : -1;
	double from = atan2(img[0].y - mid.y, img[0].x - mid.x);
	for (int i = 0; i < no + ni; i++)
		angle[i] = turned_by(mid, from, turn, img[i]);
	/* from the inner corner last before the outer loop's first, round by angle: each step
	 * to whichever loop's next corner comes first */
	int j0 = 0;
	for (int j = 1; j < ni; j++)
		if (angle[no + j] > angle[no + j0])
			j0 = j;
	int n = 0;
	for (int i = 0, j = 0; i < no || j < ni;) {
		int a = i % no, b = (i + 1) % no, c = no + (j0 + j) % ni, d = no + (j0 + j + 1) % ni;
		/* along the outer loop (a, b, c) or the inner one (a, d, c): of those whose image
		 * turns as the loops (as the fans' triangles), the one whose new corner comes
		 * first round */
		bool along_outer = i < no && turn * turning(img[a], img[b], img[c]) >= 0;
		bool along_inner = j < ni && turn * turning(img[a], img[d], img[c]) >= 0;
		if (!along_outer && !along_inner)
			return -1;
		bool outer_step = !along_inner;
		if (along_outer && along_inner)
			outer_step = (i + 1 == no ? 2 * M_PI : angle[b]) <= angle[d];
		out[n++] = loop[a], out[n++] = loop[outer_step ? b : d], out[n++] = loop[c];
		if (outer_step)
			i++;
		else
			j++;
	}
	return n;
}
