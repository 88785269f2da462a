#include "span_merge.h"
#include <stdlib.h>

/* A chain's rectangles are at most this many bands: a 2048-pixel window's 64. */
#define CHAIN_MAX 128

static int width(struct lx_rect r) { return r.x1 - r.x0; }
static int height(struct lx_rect r) { return r.y1 - r.y0; }

/* A remainder beside a run's core also puts a new edge up its side, unaligned. */
static long remainder_cost(int w, int h) { return w > 0 ? (long)w + 2L * h + LX_SPAN_RECT_COST : 0; }

/* The cost of drawing chain rectangles c[s..e) as one run: the core they all share and
 * each band's rest beside it; -1 when several share no column (a run of one is itself,
 * empty or not). */
static long run_cost(const struct lx_rect *c, int s, int e, int *cx0, int *cx1)
{
	int a = c[s].x0, b = c[s].x1;
	for (int k = s + 1; k < e; k++)
		a = c[k].x0 > a ? c[k].x0 : a, b = c[k].x1 < b ? c[k].x1 : b;
	*cx0 = a, *cx1 = b;
	if (e - s == 1)
		return (long)(b > a ? b - a : 0) + (height(c[s]) > 0 ? height(c[s]) : 0) + LX_SPAN_RECT_COST;
	if (b <= a)
		return -1;
	long cost = (long)(b - a) + (c[e - 1].y1 - c[s].y0) + LX_SPAN_RECT_COST;
	for (int k = s; k < e; k++)
		cost += remainder_cost(a - c[k].x0, height(c[k])) + remainder_cost(c[k].x1 - b, height(c[k]));
	return cost;
}

/* Chain c[0..m) drawn in the runs of least total cost (dynamic programming over where
 * each run ends), appended to out at *k. */
static void split_chain(const struct lx_rect *c, int m, struct lx_rect *out, int *k)
{
	long best[CHAIN_MAX + 1];
	int from[CHAIN_MAX + 1], a, b;
	best[0] = 0;
	for (int e = 1; e <= m; e++) {
		best[e] = -1;
		for (int s = e - 1; s >= 0; s--) {
			long cost = run_cost(c, s, e, &a, &b);
			if (cost < 0)
				break; /* longer runs share no column either */
			if (best[e] < 0 || best[s] + cost < best[e])
				best[e] = best[s] + cost, from[e] = s;
		}
	}
	for (int e = m; e > 0; e = from[e]) {
		int s = from[e];
		run_cost(c, s, e, &a, &b);
		if (e - s == 1) {
			out[(*k)++] = c[s];
			continue;
		}
		out[(*k)++] = (struct lx_rect){a, c[s].y0, b, c[e - 1].y1};
		for (int j = s; j < e; j++) {
			if (c[j].x0 < a)
				out[(*k)++] = (struct lx_rect){c[j].x0, c[j].y0, a, c[j].y1};
			if (c[j].x1 > b)
				out[(*k)++] = (struct lx_rect){b, c[j].y0, c[j].x1, c[j].y1};
		}
	}
}

/* A rectangle's place in an order: by its top, then its left (the order chains are
 * linked in), or by its bottom (to find what lies just above a rectangle). */
struct key {
	int y, x, i;
};

static int by_key(const void *a, const void *b)
{
	const struct key *p = a, *q = b;
	return p->y != q->y ? (p->y > q->y) - (p->y < q->y) : (p->x > q->x) - (p->x < q->x);
}

int lx_span_merge(const struct lx_rect *in, int n, struct lx_rect *out, int room)
{
	if (n < 0 || n > LX_SPAN_MERGE_MAX || room < 3 * n)
		return -1;
	struct key top[LX_SPAN_MERGE_MAX], bottom[LX_SPAN_MERGE_MAX];
	int prev[LX_SPAN_MERGE_MAX], next[LX_SPAN_MERGE_MAX];
	for (int i = 0; i < n; i++) {
		top[i] = (struct key){in[i].y0, in[i].x0, i}, bottom[i] = (struct key){in[i].y1, 0, i};
		prev[i] = next[i] = -1;
	}
	qsort(top, (size_t)n, sizeof *top, by_key);
	qsort(bottom, (size_t)n, sizeof *bottom, by_key);
	/* each rectangle below the one just above it that it overlaps most and that has none
	 * below it yet */
	for (int t = 0; t < n; t++) {
		int i = top[t].i, lo = 0, hi = n; /* the first of bottom[] ending at in[i].y0 or below */
		while (lo < hi) {
			int mid = (lo + hi) / 2;
			if (bottom[mid].y < in[i].y0)
				lo = mid + 1;
			else
				hi = mid;
		}
		int best = -1, most = 0;
		for (int u = lo; u < n && bottom[u].y == in[i].y0; u++) {
			int j = bottom[u].i;
			int a = in[i].x0 > in[j].x0 ? in[i].x0 : in[j].x0, b = in[i].x1 < in[j].x1 ? in[i].x1 : in[j].x1;
			if (next[j] < 0 && b - a > most && width(in[j]) > 0 && height(in[j]) > 0)
				best = j, most = b - a;
		}
		if (best >= 0 && width(in[i]) > 0 && height(in[i]) > 0)
			next[best] = i, prev[i] = best;
	}
	int k = 0;
	for (int t = 0; t < n; t++) {
		int i = top[t].i;
		if (prev[i] >= 0)
			continue; /* drawn with the chain it ends */
		struct lx_rect c[CHAIN_MAX];
		int m = 0;
		for (int j = i; j >= 0; j = next[j]) {
			c[m++] = in[j];
			if (m == CHAIN_MAX || next[j] < 0) {
				split_chain(c, m, out, &k);
				m = 0;
			}
		}
	}
	return k;
}
