/* The GL passes: shadow passes into atlas regions, then the main pass into an
 * off-screen target, one additive pass per light [Segal]. Knows nothing of the platform
 * underneath. */
#ifndef LX_RENDERER_H
#define LX_RENDERER_H
#include "depth_selftest.h"
#include "gl_caps.h"
#include "shadow_method.h"
#include "shadow_filter.h"
#include "png_in.h"
#include <stdint.h>

struct lx_renderer;

struct lx_renderer_desc {
	const struct lx_scene *scene;
	const struct lx_scene_meshes *meshes;
	const struct lx_gl_caps *caps;
	/* the lights drawn (1 to LX_MAX_LIGHTS): each light's part of the atlas (the parts
	 * share one texture, lx_atlas_stack) and a projective light's beam or slide (rows
	 * bottom to top; NULL for other lights) */
	int light_count;
	struct {
		const struct lx_atlas *atlas;
		const struct lx_image *image;
	} lights[LX_MAX_LIGHTS];
	int map_count; /* maps the method returns per frame and light */
	int width, height;
	/* the depth path lx_depth_choose took: 24-bit codes in RGBA8 (LX_DEPTH_HIGHP, and
	 * LX_DEPTH_AUTO, a desc's zero, as that), 11-bit ones at mediump (LX_DEPTH_MEDIUMP) or
	 * the maps in a depth texture (LX_DEPTH_TEXTURE) */
	enum lx_depth_precision depth;
	double bias_codes; /* depth bias in 24-bit depth codes */
	bool to_window;     /* the main pass draws into the default framebuffer (a window) */
	/* clear the atlas once per frame, as on a tiler (caps->tiler), here too; also set by
	 * LIXEL_CLEAR_WHOLE_ATLAS=1 in the environment, so that the tests run that path */
	bool clear_whole_atlas;
	bool lookup_everywhere; /* every receiver pixel reads its maps (--lookup-region all), not
				 * only where a shadow can fall (lookup_region.h) */
	bool caster_face_depth; /* a caster's faces compared along their planes (--caster-depth
				 * face: LX_FACES_CASTER, shader_text.h), not at their pixels' depth */
	int depth_slots; /* --depth-slots: the atlas cleared once every this many frames (renderer.c);
			  * taken on the depth-texture path of a GPU that is not a tiler, else 1 */
	enum lx_filter filter;  /* the main pass's shadow filter to start with (shadow_filter.h) */
};

struct lx_renderer *lx_renderer_create(const struct lx_renderer_desc *d, char *err, size_t errlen);
void lx_renderer_destroy(struct lx_renderer *r);
/* The main pass's shadow filter from the next frame on; its programs are built now, so
 * false (err set, the filter as it was) when they do not build. */
bool lx_renderer_set_filter(struct lx_renderer *r, enum lx_filter filter, char *err, size_t errlen);
/* Every receiver pixel reads its maps (lookup_everywhere) or only where a shadow can
 * fall, from the next main pass on: the draws are cut per frame, nothing else changes. */
void lx_renderer_set_lookup_everywhere(struct lx_renderer *r, bool everywhere);
/* Shadow passes for the rendered maps of n lights: f[i] and res[i] are a light's frame
 * (its f[i]->light_index says which) and maps. Their CPU work (which triangles each map
 * keeps) is the plan made ahead when there is one, else done now. */
void lx_renderer_shadow_passes(struct lx_renderer *r, const struct lx_frame *const *f,
			       const struct lx_shadow_result *const *res, int n);
/* The next shadow pass's CPU work, done now (no GL call: while the GL draws this frame)
 * for frames f, maps res and atlas layouts atlas that the caller will hand to
 * lx_renderer_shadow_passes byte for byte the same, the layouts as the renderer's lights'
 * atlases then hold them; or dropped, when the next pass is another's. */
void lx_renderer_plan_shadows(struct lx_renderer *r, const struct lx_frame *const *f,
			      const struct lx_shadow_result *const *res, const struct lx_atlas *const *atlas, int n);
void lx_renderer_drop_plan(struct lx_renderer *r);
/* The main pass's CPU work for n lights (where each draw looks a map up, which of a
 * caster's faces it draws, the planes' pieces, into their buffers), done before the main
 * pass: after the shadow passes and a glFlush (lx_renderer_flush) it runs while the GL
 * draws the maps, which it does not read. */
void lx_renderer_main_prepare(struct lx_renderer *r, const struct lx_frame *const *f,
			      const struct lx_shadow_result *const *res, int n);
/* The shaded main pass: the first light's pass with the ambient term, each other light's
 * added to it. Draws what lx_renderer_main_prepare worked out for the same f and res since
 * the last main or decision pass, else works it out first. */
void lx_renderer_main_pass(struct lx_renderer *r, const struct lx_frame *const *f,
			   const struct lx_shadow_result *const *res, int n);
/* The main pass's per-pixel shadow decision for one light (main.frag's LX_DECISION). */
void lx_renderer_decision_pass(struct lx_renderer *r, const struct lx_frame *f, const struct lx_shadow_result *res);
/* The main target's pixels, RGBA, rows bottom to top (width * height * 4 bytes). */
void lx_renderer_read(struct lx_renderer *r, uint8_t *rgba);
/* The atlas texture's texels, RGBA (its texture_width * texture_height * 4 bytes), as
 * 24-bit codes over the whole depth range (with depth slots, the last pass's slot
 * stretched back over it, an earlier frame's depth as far). */
void lx_renderer_read_atlas(struct lx_renderer *r, uint8_t *rgba);
/* The atlas texture's texels replaced (texture_width * texture_height * 4 bytes, RGBA, codes
 * over the whole range): what the next main pass reads, for tests of what a lookup may
 * read. With depth slots, the next shadow pass starts a new cycle (a whole clear). */
void lx_renderer_write_atlas(struct lx_renderer *r, const uint8_t *rgba);
/* Whether the atlas's framebuffer holds its depth in a texture (the depth-texture path),
 * as GL reports the attachment: for tests. */
bool lx_renderer_atlas_is_depth_texture(struct lx_renderer *r);
/* The depth slots taken: 1 (the regions cleared every frame) or the desc's depth_slots. */
int lx_renderer_depth_slots(const struct lx_renderer *r);
/* The pixels of the planes' spans in the last pass worked out (their window rectangles),
 * by how many maps they read: pixels[0..LX_MAX_MAPS]. For tests: where two pieces of a
 * plane overlap, a pixel reads one map. */
void lx_renderer_span_reads(const struct lx_renderer *r, long *pixels);
/* Whether some draw of the main pass cannot test two fronts (a GPU short of varyings):
 * then the maps keep every face of the flat boxes (lx_method_options.keep_flat_boxes). */
bool lx_renderer_covers_short(const struct lx_renderer *r);
/* Every main-pass variant this renderer may draw with (each count of maps read, each light's
 * pass, each filter set up so far) built and drawn once, a triangle of no area each: a
 * driver compiles a program for the state it is drawn with the first time, which costs a
 * visible stall on a board and a few megabytes on llvmpipe. The kiosk pays it at start,
 * not when a new set of maps first comes into view. Leaves the main target cleared. */
void lx_renderer_warm(struct lx_renderer *r);
void lx_renderer_finish(void);
/* glFlush: the GL starts on what was sent while the CPU goes on. */
void lx_renderer_flush(void);

#endif
