#include "silhouette.h"
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

int lx_fan_as_polygon(unsigned short *fan, int count, const float *pos, vec4 centre, int *next, unsigned short *loop)
{
	int m = count / 3;
	if (m < 3)
		return count;
	/* the corners in order: each edge (apex, a, b) leads from a to b */
	for (int k = 0; k < count; k += 3)
		next[fan[k + 1]] = fan[k + 2];
	int v = fan[1], n = 0;
	do
		loop[n++] = (unsigned short)v, v = next[v];
	while (v != fan[1] && v >= 0 && n < m);
	for (int k = 0; k < count; k += 3)
		next[fan[k + 1]] = -1;
	if (n != m || v != fan[1])
		return count; /* not one loop: cannot happen for lx_silhouette_fan's */
	/* the way the fan's triangles face the light, and every corner turning that way */
	double way = 0;
	for (int k = 0; k < count; k += 3)
		way += v4_dot(centre, v4_cross3(point_at(pos, fan[k]), point_at(pos, fan[k + 1]), point_at(pos, fan[k + 2])));
	for (int i = 0; i < m; i++) {
		vec4 a = point_at(pos, loop[i]), b = point_at(pos, loop[(i + 1) % m]), c = point_at(pos, loop[(i + 2) % m]);
		if (!(way * v4_dot(centre, v4_cross3(a, b, c)) >= 0))
			return count; /* a corner turns the other way: not convex */
	}
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
