/* The main pass's shadow filter (--filter), GL-free: percentage-closer filtering
 * ([Reeves]; [Segal] notes projective shadow maps take it easily) done by hand on the
 * RGBA8 depth (ES 2.0 has no depth-compare sampling). Each texel of a small
 * footprint around the lookup point is fetched, decoded and compared with the point's
 * depth (the same bias as one NEAREST lookup), and the 0/1 results are averaged with
 * weights (shaders_es/pcf.glsl):
 *   none    one NEAREST lookup, the shader lixel drew before filters (bit for bit);
 *   pcf2x2  the 4 nearest texels, weighted bilinearly by the point's place between their
 *           centres (what hardware PCF does): a box one lixel wide over the texels' results;
 *   pcf3x3  9 texels weighted by a box two lixels wide centred on the point: per axis
 *           (1 - g, 1, g) / 2, g the point's place within its texel.
 * Both average the texels' 0/1 results over a square window around the point, so a
 * straight shadow edge ramps over 1 (pcf2x2) or 2 (pcf3x3) lixels and the half-way
 * point of the ramp lies where the NEAREST edge lay. Samples are clamped to the texel
 * centres of the map's own atlas region: a neighbour's depths never leak in. */
#ifndef LX_SHADOW_FILTER_H
#define LX_SHADOW_FILTER_H
#include <stdbool.h>

enum lx_filter { LX_FILTER_NONE, LX_FILTER_PCF2X2, LX_FILTER_PCF3X3, LX_FILTER_COUNT };

/* "none", "pcf2x2", "pcf3x3" */
const char *lx_filter_name(enum lx_filter f);
/* A filter by its name; false (and *out untouched) for any other text. */
bool lx_filter_parse(const char *s, enum lx_filter *out);
/* The names for messages and help texts: "none, pcf2x2 or pcf3x3". */
const char *lx_filter_names(void);
/* How much farther than a NEAREST lookup the filter reads, in lixels: half the width of
 * its window (0, 0.5, 1). The main pass's lookup region grows by this. */
double lx_filter_reach(enum lx_filter f);
/* The texels one filtered lookup fetches (1, 4, 9). */
int lx_filter_taps(enum lx_filter f);
/* The shader's define for the filter: "" for none (the main pass's text unchanged),
 * else "#define LX_FILTER 1\n" (pcf2x2) or "... 2\n" (pcf3x3). */
const char *lx_filter_define(enum lx_filter f);

#endif
