/* A plane's window spans of one kind, cut in the lookup region's bands, redrawn as fewer
 * and taller rectangles: the same pixels, each once. GL-free.
 *
 * Why: the main pass draws each span as the part of its plane inside it, a fan of
 * triangles, and a rasterizer shades every block of pixels a triangle's edge crosses once
 * for each triangle that covers part of it (llvmpipe: a 4x4 block, the fragment program
 * run on all 16). A band 32 rows tall and 1000 pixels wide crosses some 260 blocks along
 * its diagonal, shaded twice: an eighth of its pixels again. A rectangle several bands
 * tall pays for its diagonal once. */
#ifndef LX_SPAN_MERGE_H
#define LX_SPAN_MERGE_H
#include "lookup_region.h"

/* The pixels of the n disjoint rectangles in[] as rectangles into out[] (room for room):
 * those lying above one another in touching bands are chained, and each chain is split in
 * runs of bands, each drawn as the rectangle all its bands share (its core) and what each
 * band holds left and right of it, the runs chosen to give the least total of widths and
 * heights (the blocks along the rectangles' diagonals and edges) and a fixed cost per
 * rectangle. Returns the count, at most 3 n, or -1 when n exceeds LX_SPAN_MERGE_MAX or
 * room is short of 3 n (out is then left as it was). */
#define LX_SPAN_MERGE_MAX 1024
int lx_span_merge(const struct lx_rect *in, int n, struct lx_rect *out, int room);
/* What lx_span_merge minimises, for one rectangle: its width, its height and this. */
#define LX_SPAN_RECT_COST 32

#endif
