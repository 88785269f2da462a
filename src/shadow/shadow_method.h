/* The interface every shadow method implements, GL-free.
 *
 * A method names the atlas regions it needs (with their lixel budgets) once, then per
 * frame turns the frame's geometry into one light matrix per region: world space to
 * the region's clip space, where x, y in [-1, 1] cover the region and z in [-1, 1]
 * spans the depth stored. A region whose map is not needed this frame is marked not
 * rendered: it gets no pass and every lookup into it reads "lit". */
#ifndef LX_SHADOW_METHOD_H
#define LX_SHADOW_METHOD_H
#include "atlas.h"
#include "frame.h"
#include "plane_cover.h"

/* A method's maps in one frame (plane-optimal: two planes, the fallback and four spare
 * pieces), of which one draw of the main pass reads at most LX_MAX_READS (main.vert's
 * varyings; a plane reads its own pieces, a caster its few densest maps). */
#define LX_MAX_MAPS 8
#define LX_MAX_READS 4
#define LX_MAX_WARNINGS 8
#define LX_WARNING_MAX 160

struct lx_shadow_map {
	int region; /* index into the atlas */
	bool rendered;
	mat4 light_clip; /* world -> region clip space */
	int plane;       /* the plane of interest this map is optimal for, or -1 */
	double lixel_scale; /* plane maps: lixels per pixel along each axis (1: a lixel for every pixel),
			     * their geometric mean when stretched */
	double lixel_stretch; /* plane maps: along the map's x lixel_scale / this, along its y
			       * lixel_scale * this (1: a similarity; method_plane.c) */
	int w, h;           /* the lixels it takes this frame in its own axes; 0: its region's fixed size */
	bool pancake;       /* casters may lie nearer than the near plane: the shadow pass flattens them onto it */
	/* Which rays the map serves, in region clip x, y (after the divide): the rectangle
	 * bounds (x0, y0, x1, y1). A draw's maps are tried in order; the first that serves a
	 * ray is read. */
	double bounds[4];
	/* A plane map's reach on the screen: window pixels (x0, y0, x1, y1) outside which
	 * none of its plane's pixels can be shadowed (has_screen false: unknown). The main
	 * pass draws the plane without a lookup outside its maps' rectangles. */
	bool has_screen;
	double screen[4];
	/* The map serves every pixel of its plane inside `screen` (a piece aligned with the
	 * screen's axes, whose rectangle is the one it serves): where two such pieces
	 * overlap, the main pass reads one of them. */
	bool screen_served;
};

/* PSM's kinds of light in post-perspective space (lx_shadow_result.variant) */
enum { LX_PSM_POINT = 1, LX_PSM_INVERTED = 2, LX_PSM_DIRECTIONAL = 3 };

struct lx_shadow_result {
	int variant; /* which branch a method took, where it has several (PSM); 0 otherwise */
	int map_count;
	struct lx_shadow_map maps[LX_MAX_MAPS];
	int warning_count;
	char warnings[LX_MAX_WARNINGS][LX_WARNING_MAX];
	/* Per object, the maps it reads (a bit mask), where the method chose them; 0: the
	 * rule of lx_shadow_receiver_maps. */
	unsigned object_maps[LX_MAX_PLANES + LX_MAX_CASTERS];
	/* Per caster in view, whether another object's shadow may reach it, where the method
	 * found it (the plane method: its fallback's receivers, or every one where that is not
	 * known); the others look no map up. */
	bool shadow_reaches[LX_MAX_PLANES + LX_MAX_CASTERS];
	/* The frame's lit fronts and the ones each object tests (lx_plane_covers; none for a
	 * method without maps), and the flat boxes' faces the maps leave out
	 * (lx_slab_faces_left_out; none with keep_flat_boxes): found once a frame, before the
	 * method builds its maps, for it, the shadow pass and the main pass. */
	struct lx_plane_covers covers;
	vec4 slab_front[LX_MAX_PLANES + LX_MAX_CASTERS];
	bool slab_face_out[LX_MAX_PLANES + LX_MAX_CASTERS], slab_out[LX_MAX_PLANES + LX_MAX_CASTERS];
};

/* Lixel budgets: each map holds budget x budget lixels. */
struct lx_method_options {
	int uniform_lixels;  /* one-map methods (512) */
	int plane_lixels;    /* each plane-optimal map (350) */
	int fallback_lixels; /* the plane-optimal method's fallback map (128) */
	bool square_regions; /* plane maps: the paper's square maps, not shapes fitted per frame */
	bool shared_budget;  /* plane maps: one needing less than its budget hands the rest on */
	bool plane_dense_budget; /* plane maps: as dense as the budget allows, past a lixel per pixel
				  * too (else only as dense as the casters reading them need) */
	bool caster_fallback_only; /* a caster reads the fallback alone (--caster-maps fallback), not
				    * first the plane maps denser on it: less shadow-pass work, coarser
				    * shadows of casters on casters */
	bool filtered; /* the main pass filters its lookups (set with the filter): the plane maps
			* take the budget's density, which shapes their own pixels' edges */
	double plane_max_lpp; /* plane maps: the highest density given, lixels per pixel (0 or less: no cap) */
	bool plane_twist;     /* plane maps: the paper's twist (the floor/wall line level), not screen-aligned */
	bool plane_one_piece; /* plane maps: one rectangle per plane, never two pieces */
	bool plane_similar;   /* plane maps: square lixels (an exact similarity) even short of a
			       * lixel per pixel, never stretched along a plane's shadow edges */
	bool plane_unslabbed; /* plane maps: a footprint is never cut in slabs (method_plane.c) */
	/* The main pass (every method): every receiver pixel reads its maps, not only where a
	 * shadow can fall (--lookup-region all, for comparison; the decisions are the same). */
	bool lookup_everywhere;
	/* Set by the renderer, not the user: some draw of the main pass cannot test two
	 * fronts (a GPU short of varyings), so the maps keep every face of the flat boxes and
	 * their footprints stay in the wanted regions (lx_shadow_result.slab_out). */
	bool keep_flat_boxes;
	/* The main pass (every method): a caster's face compared along its plane at the centre
	 * of the lixel read (--caster-depth face, main.frag's LX_FACE_PLANE: no acne where a
	 * coarse map meets its silhouette, for a few ALU operations per lookup), not at the
	 * pixel's own depth. */
	bool caster_face_depth;
	/* The shadow pass (every method): the atlas cleared once every depth_slots frames,
	 * each frame's depths in its own slot of the depth range (--depth-slots, default
	 * LX_DEPTH_SLOTS_DEFAULT; 1: cleared every frame). */
	int depth_slots;
	/* Several lights: light i's maps get light_share[i] of the lixels above (0: all of
	 * them; a share of area, the sides scaled by its square root); only the first
	 * max_lights lights are drawn (0: all). */
	double light_share[LX_MAX_LIGHTS];
	int max_lights;
};
/* Shares a light may take: a map of a hundredth of the lixels is still ten lixels a side
 * of a 1024-lixel one. */
#define LX_LIGHT_SHARE_MIN 0.01
#define LX_DEPTH_SLOTS_DEFAULT 8
#define LX_DEPTH_SLOTS_MAX 64

#define LX_METHOD_OPTIONS_DEFAULT \
	((struct lx_method_options){.uniform_lixels = 512, .plane_lixels = 350, .fallback_lixels = 128, \
				    .depth_slots = LX_DEPTH_SLOTS_DEFAULT, .caster_face_depth = true})

struct lx_light_space; /* light_space.h: where the warping methods start */
struct lx_uniform_fit;
struct lx_shadow_method {
	const char *name;
	const char *summary;
	/* Region requests (at most LX_MAX_MAPS) for a scene; returns the count. NULL: one
	 * square map of uniform_lixels, named after the method (the one-map methods). */
	int (*regions)(const struct lx_scene *s, const struct lx_method_options *o, struct lx_region_request *out);
	/* Fills one map per region, in the order regions() gave them, into *out as
	 * lx_shadow_method_frame cleared it (its covers found). A map of a variable region
	 * says the lixels it wants this frame (w, h). */
	void (*build)(const struct lx_frame *f, const struct lx_atlas *atlas, const struct lx_method_options *o,
		      struct lx_shadow_result *out);
	/* Or, for a one-map method that warps the uniform map (PSM, LiSPSM, TSM, XPSM):
	 * called once lx_uniform_map has built the uniform map (map, rendered) in light space
	 * ls, focused on fit; it replaces the map's matrix where it can and leaves it standing,
	 * with a warning, where it cannot. Not called when there is nothing to shadow. */
	void (*warp)(const struct lx_frame *f, const struct lx_light_space *ls, const struct lx_uniform_fit *fit,
		     struct lx_shadow_map *map, struct lx_shadow_result *out);
};

const struct lx_shadow_method *lx_shadow_method_find(const char *name);
/* A method with options, "NAME[/OPTION...]": for every method all or footprint (lookup
 * region) and lightsN (the first N lights only); for the plane method square or fitted
 * (region shape), shared or fixed (budget split), lppX (the densest a plane map gets,
 * lixels per pixel). Applies the options to *o; NULL with one line in err when the spec
 * is not one. Lets the bench run the same method twice with different settings. */
const struct lx_shadow_method *lx_shadow_method_spec(const char *spec, struct lx_method_options *o, char *err,
						     size_t errlen);
/* The list of method names, separated by '|', for help and error messages. */
/* The registry (method_registry.c): how many methods, the i-th (NULL past the end). */
int lx_shadow_method_count(void);
const struct lx_shadow_method *lx_shadow_method_at(int i);
/* Their names, "none|uniform|...", for messages and help texts; and "none,uniform,...",
 * the bench's default list. */
const char *lx_shadow_method_names(void);
const char *lx_shadow_method_list(void);
/* The default method (render's and the kiosk's first). */
#define LX_DEFAULT_METHOD "plane"
/* The budgets of light `light`'s maps: o's with every side scaled by the square root of
 * its share (at least one lixel). */
struct lx_method_options lx_method_options_for_light(const struct lx_method_options *o, int light);
/* "S1[,S2...]": each light's share of the budget, 1 to LX_MAX_LIGHTS numbers in
 * [LX_LIGHT_SHARE_MIN, 1]; lights past the list take its last. False when s is not such
 * a list (o unchanged). */
#define LX_LIGHT_BUDGET_EXPECTED "1 to 4 shares from 0.01 to 1 separated by commas, one per light"
bool lx_light_budget_parse(const char *s, struct lx_method_options *o);
/* How many of the scene's lights a method run draws (max_lights, at most the scene's). */
int lx_method_lights(const struct lx_method_options *o, const struct lx_scene *s);
/* The method's region requests: its regions(), or its one square map. */
int lx_shadow_method_regions(const struct lx_shadow_method *m, const struct lx_scene *s,
			     const struct lx_method_options *o, struct lx_region_request *out);

/* A map that serves every ray of its region: bounds [-1, 1]^2, no plane. */
void lx_shadow_map_full(struct lx_shadow_map *m);
/* The maps a receiver object reads in the main pass, as a bit mask: a plane of interest
 * with rendered maps of its own (map.plane == object) reads only those, since its pixels
 * are their receivers and where they do not serve no caster's shadow falls; every other
 * object reads the rendered maps that belong to no plane (the one map of a one-map
 * method, the plane method's fallback), unless the method chose its maps (object_maps).
 * At most the first LX_MAX_READS of them, the most one draw reads: the methods keep
 * within it (a plane's pieces, choose_caster_maps), so that drops nothing. */
unsigned lx_shadow_receiver_maps(const struct lx_shadow_result *r, int object);
/* The map the main pass would use for world point p of receiver object `object` (the
 * shader's choice, in double): the first of its maps that serves p, or -1. */
int lx_shadow_select_map(const struct lx_shadow_result *r, int object, vec3 p);
/* The same among the maps in mask (lx_shadow_receiver_maps of the object, worked out once
 * for the many points of one receiver). */
int lx_shadow_select_map_in(const struct lx_shadow_result *r, unsigned mask, vec3 p);

/* The shadow passes cull front faces in the map's image, so a face turned towards the
 * light must wind counter-clockwise there. A warp built in a mirrored space (a point
 * light's post-perspective space is left-handed) would flip that: this mirrors the
 * image's x when a small triangle facing the light winds clockwise, tried at the scene's
 * centre, the camera's target and the view's near centre until one is in front. */
void lx_shadow_fix_winding(mat4 *clip, const struct lx_frame *f);
/* The last step of a warped map (PSM, LiSPSM, TSM): crop * m as the map's light matrix,
 * its winding fixed; where that is not finite the map keeps the uniform matrix it had and
 * the warning "NAME: non-finite warp; uniform this frame" says so. */
void lx_shadow_map_warp(struct lx_shadow_map *map, const struct lx_frame *f, const mat4 *crop, const mat4 *m,
			const char *name, struct lx_shadow_result *out);

/* One frame of a method: build, then place this frame's maps in the atlas (packed
 * again when their shapes vary; a map placed a quarter turn round gets its matrix and
 * bounds turned with it). */
void lx_shadow_method_frame(const struct lx_shadow_method *m, const struct lx_frame *f, struct lx_atlas *atlas,
			    const struct lx_method_options *o, struct lx_shadow_result *out);
/* Turns a map a quarter turn in its region's clip space: (x, y) -> (-y, x), which keeps
 * the winding and takes lixel centres to lixel centres of the turned region. */
void lx_shadow_map_turn(struct lx_shadow_map *m);

void lx_shadow_warn(struct lx_shadow_result *r, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* World -> (atlas texture s, t, depth in [0, 1], q): the matrix the main pass samples
 * with. Region clip x, y in [-1, 1] land on the region's lixels in the atlas. */
mat4 lx_shadow_texture_matrix(const struct lx_atlas *atlas, int region, const mat4 *light_clip);

#endif
