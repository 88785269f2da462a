#include "renderer.h"
#include "gl_api.h"
#include "gl_program.h"
#include "depth_rgba.h"
#include "light_image.h"
#include "lookup_region.h"
#include "plane_cover.h"
#include "shader_text.h"
#include "silhouette.h"
#include "span_merge.h"
#include "sure_shadow.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef GL_DEPTH_COMPONENT24_OES
#define GL_DEPTH_COMPONENT24_OES 0x81A6
#endif

struct main_program {
	GLuint prog;
	GLint view_proj, offset, shadow_tex, region, bias, light, color, object_id, atlas;
	GLint served; /* decision variants: B where a map decides without a lookup (main.frag) */
	GLint clamp, texel; /* filtered variants (pcf.glsl): the maps' regions, the atlas's texel */
	GLint face_tex;     /* LX_FACE_PLANE variants: the maps' inverse transposes (main.vert) */
	GLint origin;       /* the mediump path: each map's centre, its coordinates' origin (main.frag) */
	GLint light_color;           /* a coloured or projective light's colour (-1 in other variants) */
	GLint beam, beam_tex, range; /* a projective light's (-1 in other variants) */
	GLint cover[LX_MAX_COVERS];  /* LX_COVER, LX_COVER2 variants: planes' cover matrices (plane_cover.h) */
	GLint cover_pair;            /* LX_COVER2: whether the two are a flat box's bottom and top (main.frag) */
};

/* How a main-pass variant shades: 0 the decision; else 1 + 4 projective + 2 added (an
 * added light's pass, no ambient term) + coloured (a plain light that is not white). The
 * first light's pass of a white light keeps the text lixel always had: constants the
 * compiler folds (a uniform ambient and colour made llvmpipe's unshadowed main pass 10 to
 * 30% slower). */
enum { SHADING_DECISION = 0, SHADINGS = 9 };
static int shading_of(bool projective, bool added, bool coloured)
{
	return 1 + 4 * projective + 2 * added + (coloured && !projective);
}
enum { SHADING_COLOURED, SHADING_ADDED, SHADING_PROJECTIVE }; /* shading_bit's bits */
static bool shading_bit(int shading, int bit) { return shading != SHADING_DECISION && ((shading - 1) >> bit & 1); }

/* A window rectangle of a plane and the maps it reads there. */
struct span {
	unsigned mask; /* the maps read, and COVER_SPAN, COVERED_SPAN, SURE_SPAN */
	struct lx_rect box;
};
/* A plane's span that tests the cover over it, and one wholly in the cover's shadow,
 * drawn in it without a lookup (object_draws, cover_spans): bits no map has. */
#define COVER_SPAN (1u << LX_MAX_MAPS)
#define COVERED_SPAN (1u << (LX_MAX_MAPS + 1))
/* with COVERED_SPAN: drawn in a caster's sure shadow, which its map decides (sure_spans) */
#define SURE_SPAN (1u << (LX_MAX_MAPS + 2))
#define MAP_BITS (COVER_SPAN - 1)

/* One draw of the main pass: an object with the maps it reads, and what of it: its whole
 * mesh, `count` vertices from `first` of the frame's piece buffer (a plane in pieces), or
 * `count` indices from `first` of the frame's index buffer (a caster's triangles facing
 * the light, or the others). */
enum draw_kind { WHOLE, PIECES, INDEXED };
struct draw {
	int object;
	unsigned mask;
	enum lx_faces faces; /* its faces' side of the light, which picks the variant */
	enum draw_kind kind;
	int first, count;
	int covers; /* tests the first `covers` planes of covers.of[object] (their matrices
		     * cover[that plane]) */
	bool sure;  /* in a caster's sure shadow: its map decides it, with no lookup */
};

/* What a pass of the main pass draws: the first light's shading (the target cleared, the
 * ambient term), another light's added to it, or one light's decision. */
enum pass_kind { FIRST_LIGHT, ADDED_LIGHT, DECISION };

/* One light's pass of the main pass as the CPU works it out (prepare_light) before any
 * of it is drawn (light_pass): its draws, and the fronts whose covers they test (covers->of:
 * the result's, which outlives the pass), each front's cover matrix as the shader takes it.
 * A plane draws once per set of the maps it reads (at most LX_MAX_READS:
 * lx_shadow_receiver_maps), with the cover test or without, and once in a cover's shadow
 * (object_draws); a caster at most three times. */
struct light_draws {
	const struct lx_frame *f;
	const struct lx_shadow_result *res;
	enum pass_kind kind;
	bool reaches;  /* false: an added projective light that lights nothing in view */
	int shading;   /* the variants' */
	struct draw draws[LX_MAX_PLANES * (2 * (1 << LX_MAX_READS) + 1) + 3 * LX_MAX_CASTERS];
	int n;
	const struct lx_plane_covers *covers;
	float cover[LX_MAX_FRONTS][16];
};

/* the most spans slab_spans makes of k rectangles (k <= LX_MAX_MAPS) */
#define SLAB_SPANS(k) ((4 * (k) + 1) * (4 * (k) + 1))
/* room for a plane's spans in a frame */
#define PLANE_SPANS 2048

/* A shadow pass's CPU work (shadow_draws): per light, map and object, the triangles the
 * map keeps (from `first`, `count` indices of kept_index, uploaded into kept_ibo) with the
 * object's light-clip matrix they were chosen with, which the draw takes, and a round
 * caster's fan corners (outline_index: their images' hull lies inside the caster's image
 * in that map, which holds it: sure_spans); per light (by frame) the objects each map
 * draws, and the maps that drew each caster (drawn_in, by light: what the atlas holds).
 * Made in the pass, or ahead for the next one (lx_renderer_plan_shadows). */
struct kept_draw {
	int first, count;
	float light_clip[16];
	int outline_first, outline_count;
	/* a caster that reads the map itself only around its own faces that read it
	 * (band_rect): there the triangles above, scissored to rect (lixels of the map's
	 * region: x0, y0, x1, y1), elsewhere the polygon over all its faces turned away
	 * (whole_count indices from whole_first); whole_count 0: the triangles above alone */
	int whole_first, whole_count;
	int rect[4];
};
struct shadow_plan {
	struct kept_draw kept[LX_MAX_LIGHTS][LX_MAX_MAPS][LX_MAX_PLANES + LX_MAX_CASTERS];
	unsigned short *kept_index, *outline_index;
	int kept_count, outline_count;
	unsigned drawn[LX_MAX_LIGHTS][LX_MAX_PLANES + LX_MAX_CASTERS];
	unsigned drawn_in[LX_MAX_LIGHTS][LX_MAX_PLANES + LX_MAX_CASTERS];
};

struct lx_renderer {
	struct lx_renderer_desc d;
	int objects;
	/* the main pass's lights worked out (lx_renderer_main_prepare), `prepared` of them
	 * (0: none waiting to be drawn) */
	struct light_draws pass[LX_MAX_LIGHTS];
	int prepared;
	/* casters' triangles sorted by facing this frame, 16-bit indices into their meshes
	 * (every light's main pass one after the other) */
	unsigned short *facing_index;
	int facing_count, facing_room;
	GLuint facing_ibo; /* a frame's main-pass draws */
	struct span spans[PLANE_SPANS];    /* a plane's spans */
	struct span seen[PLANE_SPANS];     /* the same without what another plane hides */
	struct lx_span parts[PLANE_SPANS]; /* the lookup region's spans in one of them */
	long span_reads[LX_MAX_MAPS + 1];  /* the last pass's plane spans' pixels by maps read */
	struct lx_rect merge_in[LX_SPAN_MERGE_MAX], merge_out[3 * LX_SPAN_MERGE_MAX]; /* lx_span_merge's */
	struct lx_lookup_volumes lookup;   /* this frame's casters seen through each map */
	/* the planes' pieces this frame: LX_VERTEX_FLOATS per vertex, in a stream buffer */
	float *piece_v;
	int piece_vertices, piece_room;
	GLuint piece_vbo;
	GLuint vbo[LX_MAX_PLANES + LX_MAX_CASTERS];
	GLsizei vertices[LX_MAX_PLANES + LX_MAX_CASTERS];
	bool flat[LX_MAX_PLANES + LX_MAX_CASTERS]; /* every vertex's normal its face's (object_draws) */
	/* a caster's triangles in runs of RUN_TRIANGLES, each run's box in object space (lo,
	 * hi), so that a frame asks each run whether a shadow can fall on it (sort_by_facing) */
	vec3 *run_box[LX_MAX_PLANES + LX_MAX_CASTERS];
	/* the shadow passes' meshes: positions only, each once, and triangles as indices
	 * into them (llvmpipe's draw module shades each index once; the sphere's 2976
	 * vertices are 482 positions), kept on the CPU with each triangle's plane in object
	 * space (v4_cross3 of its corners): a frame uploads the triangles each map's culling
	 * keeps (keep_back_faces, into kept_ibo) */
	GLuint shadow_vbo[LX_MAX_PLANES + LX_MAX_CASTERS];
	GLsizei shadow_indices[LX_MAX_PLANES + LX_MAX_CASTERS];
	unsigned short *shadow_index[LX_MAX_PLANES + LX_MAX_CASTERS];
	vec4 *shadow_plane[LX_MAX_PLANES + LX_MAX_CASTERS];
	/* a round caster's faces turned away from the light drawn into a plane's maps as a fan
	 * from its centre, the last position of its shadow mesh (silhouette.h): the
	 * triangles' corners with the positions of one point taken as one (welded: a seam's),
	 * the triangle across each edge (adj), the centre's index (fan_apex, -1: no fan), and
	 * the scratch of a frame's fans (a convex one drawn as its polygon: fan_loop) */
	unsigned short *welded[LX_MAX_PLANES + LX_MAX_CASTERS];
	int *adj[LX_MAX_PLANES + LX_MAX_CASTERS];
	float *fan_pos[LX_MAX_PLANES + LX_MAX_CASTERS]; /* its positions, the centre last */
	int fan_apex[LX_MAX_PLANES + LX_MAX_CASTERS];
	bool *fan_kept;
	int *fan_next;
	unsigned short *fan_index, *fan_loop;
	/* where the caster reads the map itself: the faces turned away by more than BAND_FACES
	 * (band_kept), their fan, both fans' loops, their corners' images and angles (work) and
	 * the strip across the band between them and the faces turned well away (keep_band) */
	bool *band_kept;
	bool *away_kept; /* its faces turned away, whose fan's corners are then its outline */
	unsigned short *band_fan, *band_loop, *band_strip;
	double *band_work;
	bool faces_not_fans; /* LIXEL_ROUND_CASTERS_AS_FACES=1: every round caster drawn as its faces, its
			      * fan's outline (sure_spans) made all the same */
	bool boxes_as_faces; /* LIXEL_BOXES_AS_FACES=1: every box drawn as its faces */
	bool whole_bands; /* LIXEL_WHOLE_BANDS=1: a band kept whole where only some faces read (band_rect) */
	bool no_ids; /* LIXEL_NO_CASTER_IDS=1: no ids in the atlas's alpha (caster_ids), as the
		      * depth-texture path draws */
	/* plans[plan]: the last shadow pass's work, which the main pass reads; planned:
	 * plans[1 - plan] made for the next shadow pass. Each holds kept_room indices. */
	struct shadow_plan plans[2];
	int plan, kept_room;
	bool planned;
	GLuint kept_ibo;
	GLuint atlas_tex, atlas_fbo, atlas_depth;
	GLuint beam_tex[LX_MAX_LIGHTS]; /* a projective light's image, 0 for other lights */
	int texture_width, texture_height; /* the atlas texture's, which every light's part shares */
	GLuint target_color, target_depth, target_fbo;
	GLuint shadow_prog, clear_prog, clear_vbo;
	GLint shadow_light_clip, shadow_pancake, shadow_caster;
	/* main-pass variants, built when first used: [shading][filter][faces][how many maps a
	 * draw reads][how many planes' covers it tests] (whichever maps: a draw puts theirs in
	 * the first slots, set_maps; the faces: object_draws; LX_FACES_AWAY reads none, its
	 * other slots stay empty, and tests no cover) */
	struct main_program variant[SHADINGS][LX_FILTER_COUNT][LX_FACES_COUNT][LX_MAX_READS + 1][LX_MAX_COVERS + 1];
	const struct lx_plane_covers *covers; /* the fronts of the light pass being worked out */
	int max_covers; /* the most covers a frame may test over one object (lx_scene_covers_needed) */
	bool covers_short; /* some draw tests fewer (covers_fit): the maps keep every face */
	enum lx_filter filter; /* the main pass's, lx_renderer_set_filter */
	float bias_uniform;
	/* Depth slots: the depth range cut into `slots` slots, each frame's shadow pass writing
	 * into the next one down (glDepthRange), below every depth an earlier frame left, so
	 * that a lookup reads those as far and the atlas is cleared once every `slots` frames
	 * (a fill like any other draw on an immediate-mode renderer) instead of every frame.
	 * 1: every frame's regions cleared, the whole range. */
	int slots;
	int slot; /* the last shadow pass's, which the main pass reads (slot_range); -1: none yet,
		   * or the atlas written whole (lx_renderer_write_atlas), the whole range */
};

/* The depth path's two departures from 24-bit codes in RGBA8. */
static bool mediump(const struct lx_renderer *r) { return r->d.depth == LX_DEPTH_MEDIUMP; }
static bool depth_texture(const struct lx_renderer *r) { return r->d.depth == LX_DEPTH_TEXTURE; }
/* Casters' faces drawn with LX_FACES_CASTER: --caster-depth face (else as
 * LX_FACES_TOWARD). */
static bool face_plane(const struct lx_renderer *r) { return r->d.caster_face_depth; }
/* Each texel's alpha byte holds the id of the object that drew it (shadow_depth.frag), so
 * that a caster's faces turned towards the light pass over their own (LX_SELF): a convex
 * caster cannot shadow them. Then no caster need draw its faces near its silhouette into a
 * map it reads (keep_back_faces). The depth-texture path has no colour to hold it. */
static bool caster_ids(const struct lx_renderer *r) { return !depth_texture(r) && !r->no_ids; }
_Static_assert(LX_MAX_PLANES + LX_MAX_CASTERS < 255, "an object's id and the clear colour's 255 in one byte");
/* Casters' faces turned towards the light drawn as LX_FACES_CASTER (else LX_FACES_TOWARD). */
static bool caster_faces(const struct lx_renderer *r) { return face_plane(r) || caster_ids(r); }

static void to_float(const mat4 *m, float out[16])
{
	for (int i = 0; i < 16; i++)
		out[i] = (float)m->m[i];
}

/* A framebuffer of w x h: colour into color_tex (0: none), depth into depth_tex, or when
 * that is 0 into a depth renderbuffer made here (*depth_rb). */
static bool framebuffer(GLuint *fbo, GLuint color_tex, GLuint depth_tex, GLuint *depth_rb, int w, int h, bool depth24,
			char *err, size_t errlen, const char *what)
{
	if (!depth_tex) {
		lx_gl.GenRenderbuffers(1, depth_rb);
		lx_gl.BindRenderbuffer(GL_RENDERBUFFER, *depth_rb);
		lx_gl.RenderbufferStorage(GL_RENDERBUFFER, depth24 ? GL_DEPTH_COMPONENT24_OES : GL_DEPTH_COMPONENT16, w, h);
	}
	lx_gl.GenFramebuffers(1, fbo);
	lx_gl.BindFramebuffer(GL_FRAMEBUFFER, *fbo);
	if (color_tex)
		lx_gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color_tex, 0);
	if (depth_tex)
		lx_gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_tex, 0);
	else
		lx_gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, *depth_rb);
	GLenum st = lx_gl.CheckFramebufferStatus(GL_FRAMEBUFFER);
	if (st != GL_FRAMEBUFFER_COMPLETE) {
		snprintf(err, errlen, "GL: the %s framebuffer (%dx%d) is incomplete (status 0x%x)", what, w, h, st);
		return false;
	}
	return true;
}

/* The main-pass variant for a shading, faces, maps read and filter, on this GPU. */
static struct lx_main_variant variant_of(const struct lx_renderer *r, int shading, enum lx_faces faces, int reads,
					 enum lx_filter filter, int covers)
{
	return (struct lx_main_variant){.maps = r->d.map_count, .reads = reads, .decision = shading == SHADING_DECISION,
					.faces = faces, .path = r->d.depth, .filtered = filter != LX_FILTER_NONE,
					.projective = shading_bit(shading, SHADING_PROJECTIVE), .covers = covers,
					.max_varyings = r->d.caps->max_varying_vectors, .self_id = caster_ids(r)};
}

static bool main_program(struct main_program *p, const struct lx_renderer *r, int shading, enum lx_faces faces,
			 int reads, enum lx_filter filter, int covers, char *err, size_t errlen)
{
	char defines[400];
	struct lx_main_variant v = variant_of(r, shading, faces, reads, filter, covers);
	lx_main_defines(&v, defines, sizeof defines);
	static const char *const shading_define[3] = {"#define LX_LIGHT_COLOR 1\n", "#define LX_AMBIENT 0.0\n",
						      "#define LX_PROJECTIVE 1\n"};
	for (int bit = SHADING_COLOURED; bit <= SHADING_PROJECTIVE; bit++) /* none for the decision: the shadow test alone */
		if (shading_bit(shading, bit))
			strncat(defines, shading_define[bit], sizeof defines - strlen(defines) - 1);
	/* nothing for none: the text it always had */
	strncat(defines, lx_filter_define(filter), sizeof defines - strlen(defines) - 1);
	p->prog = lx_program_build("main.vert", "main.frag", defines, err, errlen);
	if (!p->prog)
		return false;
	p->view_proj = lx_gl.GetUniformLocation(p->prog, "u_view_proj");
	p->offset = lx_gl.GetUniformLocation(p->prog, "u_offset");
	p->shadow_tex = lx_gl.GetUniformLocation(p->prog, "u_shadow_tex");
	p->region = lx_gl.GetUniformLocation(p->prog, "u_region");
	p->bias = lx_gl.GetUniformLocation(p->prog, "u_bias");
	p->light = lx_gl.GetUniformLocation(p->prog, "u_light");
	p->color = lx_gl.GetUniformLocation(p->prog, "u_color");
	p->object_id = lx_gl.GetUniformLocation(p->prog, "u_object_id");
	p->served = lx_gl.GetUniformLocation(p->prog, "u_served");
	p->atlas = lx_gl.GetUniformLocation(p->prog, "u_atlas");
	p->beam = lx_gl.GetUniformLocation(p->prog, "u_beam");
	p->beam_tex = lx_gl.GetUniformLocation(p->prog, "u_beam_tex");
	p->light_color = lx_gl.GetUniformLocation(p->prog, "u_light_color");
	p->range = lx_gl.GetUniformLocation(p->prog, "u_range");
	p->clamp = lx_gl.GetUniformLocation(p->prog, "u_clamp");
	p->texel = lx_gl.GetUniformLocation(p->prog, "u_texel");
	p->face_tex = lx_gl.GetUniformLocation(p->prog, "u_face_tex");
	p->origin = lx_gl.GetUniformLocation(p->prog, "u_origin");
	static const char *const cover_name[LX_MAX_COVERS] = {"u_cover", "u_cover2"}; /* main.vert */
	for (int c = 0; c < LX_MAX_COVERS; c++)
		p->cover[c] = lx_gl.GetUniformLocation(p->prog, cover_name[c]);
	p->cover_pair = lx_gl.GetUniformLocation(p->prog, "u_cover_pair");
	return true;
}

/* Whether a light is drawn with its colour (a plain light that is not white). */
static bool light_coloured(const struct lx_light *l)
{
	return !(l->color.x == 1 && l->color.y == 1 && l->color.z == 1);
}

/* How many rules of the faces the renderer draws with: without maps (method none) only
 * the first, LX_FACES_TOWARD, whose text is every rule's there (variant_for). */
static int face_rules(const struct lx_renderer *r) { return r->d.map_count > 0 ? LX_FACES_COUNT : 1; }

/* The most maps one draw reads: every map of the method, up to LX_MAX_READS. */
static int most_reads(const struct lx_renderer *r) { return r->d.map_count < LX_MAX_READS ? r->d.map_count : LX_MAX_READS; }

/* Light i's shaded variants' shading. */
static int light_shading(const struct lx_renderer *r, int i)
{
	return shading_of(r->beam_tex[i] != 0, i > 0, light_coloured(&r->d.scene->lights[i]));
}

/* --caster-depth face on a GPU whose varyings cannot hold it for a caster reading every
 * map (main.vert) in some light's pass: one line saying so; those draws compare at their
 * pixels' depth (lx_main_face_plane), draws reading fewer maps may still take it. */
static void face_plane_fits(const struct lx_renderer *r)
{
	for (int i = 0; face_plane(r) && r->d.map_count > 0 && i < r->d.light_count; i++) {
		struct lx_main_variant v =
			variant_of(r, light_shading(r, i), LX_FACES_CASTER, most_reads(r), LX_FILTER_NONE, 0);
		if (!lx_main_face_plane(&v)) {
			fprintf(stderr,
				"lixel: --caster-depth face: a caster reading %d maps needs %d varying vectors, this GPU has "
				"%d: such casters are compared at their pixels' depth\n",
				v.reads, lx_main_varyings(v.reads, false, true, v.projective, lx_main_covers(&v)), v.max_varyings);
			return;
		}
	}
}

/* A scene with objects under two lit fronts on a GPU whose varyings cannot hold the
 * second's test for a draw reading every map in some light's pass: one line saying so;
 * those draws test the first front only (lx_main_covers), and the second's shadow on
 * them is lost where it falls outside the first's, and the maps keep the flat boxes' faces
 * that the fronts' tests would otherwise decide (lx_method_options.keep_flat_boxes). */
static void covers_fit(struct lx_renderer *r)
{
	r->covers_short = false;
	for (int i = 0; r->max_covers > 1 && i < r->d.light_count; i++) {
		struct lx_main_variant v =
			variant_of(r, light_shading(r, i), LX_FACES_TOWARD, most_reads(r), LX_FILTER_NONE, r->max_covers);
		if (lx_main_covers(&v) < r->max_covers) {
			fprintf(stderr,
				"lixel: an object under two lit fronts (planes or flat boxes) read with %d maps needs %d varying "
				"vectors for both fronts' shadows, this GPU has %d: only the first front's shadow is tested there\n",
				v.reads, lx_main_varyings(v.reads, false, false, v.projective, r->max_covers), v.max_varyings);
			r->covers_short = true;
			return;
		}
	}
}

/* The decision variant and each light's shaded variants of a filter for each rule of the
 * faces, those that read reading every map (built now, so that a shader error shows when
 * the filter is chosen). */
static bool filter_programs(struct lx_renderer *r, enum lx_filter filter, char *err, size_t errlen)
{
	for (int i = -1; i < r->d.light_count; i++) {
		int shading = i < 0 ? SHADING_DECISION : light_shading(r, i);
		for (int faces = 0; faces < face_rules(r); faces++) {
			if (faces == LX_FACES_CASTER && !caster_faces(r))
				continue; /* drawn as LX_FACES_TOWARD (variant_for) */
			int reads = faces == LX_FACES_AWAY ? 0 : most_reads(r);
			struct main_program *p = &r->variant[shading][filter][faces][reads][0];
			if (!p->prog && !main_program(p, r, shading, (enum lx_faces)faces, reads, filter, 0, err, errlen))
				return false;
		}
	}
	return true;
}

bool lx_renderer_set_filter(struct lx_renderer *r, enum lx_filter filter, char *err, size_t errlen)
{
	if ((unsigned)filter >= LX_FILTER_COUNT) {
		snprintf(err, errlen, "no such shadow filter (%d)", (int)filter);
		return false;
	}
	if (!filter_programs(r, filter, err, errlen))
		return false;
	r->filter = filter;
	return true;
}

void lx_renderer_set_lookup_everywhere(struct lx_renderer *r, bool everywhere)
{
	r->d.lookup_everywhere = everywhere;
	r->planned = false; /* a plan made ahead drew what lookups read as they were */
}

struct keyed_position {
	float p[3];
	int vertex;
};

static int cmp_position(const void *pa, const void *pb)
{
	const struct keyed_position *a = pa, *b = pb;
	for (int k = 0; k < 3; k++)
		if (a->p[k] != b->p[k])
			return a->p[k] < b->p[k] ? -1 : 1;
	return 0;
}

/* A sphere, cylinder or cone: convex, and of more triangles than its silhouette has edges. */
static bool round_caster(const struct lx_renderer *r, int id)
{
	const struct lx_scene *s = r->d.scene;
	return id >= s->plane_count && s->casters[id - s->plane_count].shape != LX_BOX;
}

/* A caster's fan: its corners welded, its triangles' neighbours, and its centre
 * (the mean of its np positions, inside it: it is convex), appended to pos. False when
 * the mesh is not closed (no fan, its faces drawn) or out of memory. */
static bool fan_mesh(struct lx_renderer *r, int id, const unsigned short *index, int triangles, float *pos, int np)
{
	int *rep = malloc((size_t)(np > 0 ? np : 1) * sizeof *rep);
	r->welded[id] = malloc((size_t)(3 * triangles + 1) * sizeof *r->welded[id]);
	r->adj[id] = malloc((size_t)(3 * triangles + 1) * sizeof(int));
	double extent = 0;
	for (int i = 0; i < 3 * np; i++)
		extent = fmax(extent, fabs(pos[i]));
	bool ok = rep && r->welded[id] && r->adj[id] && np >= 1 && lx_mesh_weld(pos, np, 1e-6 * extent, rep);
	for (int k = 0; ok && k < 3 * triangles; k++)
		r->welded[id][k] = (unsigned short)rep[index[k]];
	ok = ok && lx_mesh_adjacency(r->welded[id], triangles, r->adj[id]);
	free(rep);
	if (!ok) {
		free(r->welded[id]), free(r->adj[id]);
		r->welded[id] = NULL, r->adj[id] = NULL;
		return false;
	}
	double c[3] = {0, 0, 0};
	for (int i = 0; i < np; i++)
		for (int k = 0; k < 3; k++)
			c[k] += pos[3 * i + k];
	for (int k = 0; k < 3; k++)
		pos[3 * np + k] = (float)(c[k] / np); /* np >= 1 */
	return true;
}

/* Mesh id for the shadow passes: its distinct positions and its triangles as 16-bit
 * indices into them, the same triangles in the same winding. */
static bool shadow_mesh(struct lx_renderer *r, int id, const struct lx_mesh *m)
{
	int n = m->vertex_count;
	struct keyed_position *key = malloc((size_t)n * sizeof *key);
	float *pos = malloc((size_t)(n + 1) * 3 * sizeof(float)); /* and a round caster's centre */
	unsigned short *index = malloc((size_t)n * sizeof(unsigned short));
	bool ok = key && pos && index && n <= 65536;
	if (ok) {
		for (int i = 0; i < n; i++) {
			memcpy(key[i].p, m->v + (size_t)i * LX_VERTEX_FLOATS, sizeof key[i].p);
			key[i].vertex = i;
		}
		qsort(key, (size_t)n, sizeof *key, cmp_position);
		int np = 0;
		for (int i = 0; i < n; i++) {
			if (np == 0 || cmp_position(&key[i - 1], &key[i]))
				memcpy(pos + 3 * np++, key[i].p, sizeof key[i].p);
			index[key[i].vertex] = (unsigned short)(np - 1);
		}
		r->fan_apex[id] = -1;
		if (id >= r->d.scene->plane_count && np < 65536 && fan_mesh(r, id, index, n / 3, pos, np)) {
			r->fan_apex[id] = np++;
			r->fan_pos[id] = malloc((size_t)np * 3 * sizeof(float));
			if (r->fan_pos[id])
				memcpy(r->fan_pos[id], pos, (size_t)np * 3 * sizeof(float));
			else
				r->fan_apex[id] = -1;
		}
		lx_gl.BindBuffer(GL_ARRAY_BUFFER, r->shadow_vbo[id]);
		lx_gl.BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)np * 3 * sizeof(float), pos, GL_STATIC_DRAW);
		r->shadow_indices[id] = n;
		r->shadow_plane[id] = malloc((size_t)(n / 3 + 1) * sizeof(vec4));
		ok = r->shadow_plane[id] != NULL;
		for (int t = 0; ok && t < n / 3; t++) { /* the corners as the GL gets them: floats */
			vec4 c[3];
			for (int k = 0; k < 3; k++) {
				const float *q = pos + 3 * index[3 * t + k];
				c[k] = (vec4){q[0], q[1], q[2], 1};
			}
			vec4 pl = v4_cross3(c[0], c[1], c[2]);
			double len = v4_len(pl); /* 0 for a triangle of no area, which is never kept */
			r->shadow_plane[id][t] = len > 0 ? v4_lin(1 / len, pl, 0, pl) : pl;
		}
		r->shadow_index[id] = index;
		index = NULL; /* kept */
	}
	free(key), free(pos), free(index);
	return ok;
}

/* The programs: the shadow pass's, the main pass's variants with every map (built now
 * so that a shader error shows at start), the atlas clear's. */
static bool renderer_programs(struct lx_renderer *r, char *err, size_t errlen)
{
	const struct lx_renderer_desc *d = &r->d;
	r->shadow_prog = lx_program_build("shadow_depth.vert", "shadow_depth.frag",
					  lx_shadow_defines(d->depth), err, errlen);
	if (!r->shadow_prog || !lx_renderer_set_filter(r, d->filter, err, errlen))
		return false;
	r->shadow_light_clip = lx_gl.GetUniformLocation(r->shadow_prog, "u_light_clip");
	r->shadow_pancake = lx_gl.GetUniformLocation(r->shadow_prog, "u_pancake");
	r->shadow_caster = lx_gl.GetUniformLocation(r->shadow_prog, "u_caster");
	r->clear_prog = lx_program_build("atlas_clear.vert", "atlas_clear.frag", NULL, err, errlen);
	return r->clear_prog != 0;
}

/* A caster's triangles in runs of this many, as its mesh lists them: a band of a ring of
 * a sphere (a quarter of it), a wedge of a cylinder or a cone, so that each run's box is
 * small. */
#define RUN_TRIANGLES 16

/* Each run's box of caster id's mesh m (r->run_box). False when out of memory. */
static bool run_boxes(struct lx_renderer *r, int id, const struct lx_mesh *m)
{
	int tris = m->vertex_count / 3, runs = (tris + RUN_TRIANGLES - 1) / RUN_TRIANGLES;
	if (runs < 1)
		return true;
	vec3 *b = r->run_box[id] = malloc((size_t)runs * 2 * sizeof(vec3));
	if (!b)
		return false;
	for (int k = 0; k < runs; k++) {
		vec3 lo = v3(INFINITY, INFINITY, INFINITY), hi = v3(-INFINITY, -INFINITY, -INFINITY);
		for (int v = 3 * RUN_TRIANGLES * k; v < 3 * RUN_TRIANGLES * (k + 1) && v < 3 * tris; v++) {
			const float *p = m->v + (size_t)v * LX_VERTEX_FLOATS;
			vec3 q = v3(p[0], p[1], p[2]);
			lo = v3_min(lo, q), hi = v3_max(hi, q);
		}
		b[2 * k] = lo, b[2 * k + 1] = hi;
	}
	return true;
}

/* The buffers: the clear's quad, each mesh for the main pass and indexed for the shadow
 * pass, the planes' pieces and the facing-sorted indices (room for every triangle). */
static bool renderer_buffers(struct lx_renderer *r, char *err, size_t errlen)
{
	const struct lx_scene_meshes *meshes = r->d.meshes;
	static const float quad[12] = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};
	lx_gl.GenBuffers(1, &r->clear_vbo);
	lx_gl.BindBuffer(GL_ARRAY_BUFFER, r->clear_vbo);
	lx_gl.BufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STATIC_DRAW);
	lx_gl.GenBuffers(r->objects, r->vbo);
	lx_gl.GenBuffers(r->objects, r->shadow_vbo);
	lx_gl.GenBuffers(1, &r->piece_vbo);
	lx_gl.GenBuffers(1, &r->facing_ibo);
	lx_gl.GenBuffers(1, &r->kept_ibo);
	int triangles = 0;
	for (int i = 0; i < r->objects; i++)
		triangles += meshes->mesh[i].vertex_count;
	r->facing_room = triangles * r->d.light_count; /* every light's main pass */
	r->facing_index = malloc((size_t)r->facing_room * sizeof(unsigned short) + 1);
	/* at most every triangle in every map of every light, twice: a caster reading a map
	 * around a few faces only keeps its polygon beside its band (band_rect) */
	r->kept_room = 2 * triangles * r->d.light_count * (r->d.map_count > 0 ? r->d.map_count : 1);
	for (int k = 0; k < 2; k++) {
		r->plans[k].kept_index = malloc((size_t)r->kept_room * sizeof(unsigned short) + 1);
		r->plans[k].outline_index = malloc((size_t)r->kept_room * sizeof(unsigned short) + 1);
	}
	int most = 1; /* the most vertices (so positions, and indices of kept faces) of one mesh */
	for (int i = 0; i < r->objects; i++)
		most = meshes->mesh[i].vertex_count > most ? meshes->mesh[i].vertex_count : most;
	r->fan_kept = malloc((size_t)most * sizeof(bool));
	r->fan_next = malloc((size_t)(most + 1) * sizeof(int));
	r->fan_index = malloc((size_t)most * sizeof(unsigned short));
	r->fan_loop = malloc((size_t)most * sizeof(unsigned short));
	r->band_kept = malloc((size_t)most * sizeof(bool));
	r->away_kept = malloc((size_t)most * sizeof(bool));
	r->band_fan = malloc((size_t)most * sizeof(unsigned short));
	r->band_loop = malloc((size_t)most * sizeof(unsigned short));
	r->band_strip = malloc((size_t)most * sizeof(unsigned short));
	r->band_work = malloc((size_t)2 * most * sizeof(double)); /* both fans' indices, each at most `most` */
	for (int i = 0; r->fan_next && i <= most; i++)
		r->fan_next[i] = -1;
	bool plans = r->plans[0].kept_index && r->plans[0].outline_index && r->plans[1].kept_index &&
		     r->plans[1].outline_index;
	if (!r->facing_index || !plans || !r->fan_kept || !r->fan_next || !r->fan_index || !r->fan_loop || !r->band_kept ||
	    !r->away_kept || !r->band_fan || !r->band_loop || !r->band_strip || !r->band_work) {
		snprintf(err, errlen, "out of memory");
		return false;
	}
	for (int i = 0; i < r->objects; i++) {
		const struct lx_mesh *m = &meshes->mesh[i];
		lx_gl.BindBuffer(GL_ARRAY_BUFFER, r->vbo[i]);
		lx_gl.BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)m->vertex_count * LX_VERTEX_FLOATS * sizeof(float), m->v,
				 GL_STATIC_DRAW);
		r->vertices[i] = m->vertex_count;
		r->flat[i] = lx_mesh_is_flat(m);
		if ((i >= r->d.scene->plane_count && !run_boxes(r, i, m)) || !shadow_mesh(r, i, m)) {
			snprintf(err, errlen, "out of memory indexing the meshes");
			return false;
		}
	}
	return true;
}

/* The atlas (RGBA8: depth textures may be missing in ES 2.0), all "far" to start with,
 * guard bands included (passes only ever clear and draw inside their own region, so the
 * guards keep it); and off screen, the main target (an RGBA texture: RGBA8
 * renderbuffers are an extension in ES 2.0, OES_rgb8_rgba8). */
static bool renderer_targets(struct lx_renderer *r, char *err, size_t errlen)
{
	const struct lx_renderer_desc *d = &r->d;
	/* the depth-texture path: the texture is the atlas's depth and its only attachment, so
	 * the shadow pass writes no colour */
	bool dt = depth_texture(r);
	r->atlas_tex = dt ? lx_texture_depth(r->texture_width, r->texture_height)
			  : lx_texture_rgba8(r->texture_width, r->texture_height);
	if (!framebuffer(&r->atlas_fbo, dt ? 0 : r->atlas_tex, dt ? r->atlas_tex : 0, &r->atlas_depth, r->texture_width,
			 r->texture_height, d->caps->depth24, err, errlen, "atlas"))
		return false;
	lx_gl.Disable(GL_SCISSOR_TEST);
	lx_gl.Viewport(0, 0, r->texture_width, r->texture_height);
	lx_gl.ClearColor(1, 1, 1, 1);
	lx_gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
	if (!d->to_window) {
		r->target_color = lx_texture_rgba8(d->width, d->height);
		if (!framebuffer(&r->target_fbo, r->target_color, 0, &r->target_depth, d->width, d->height, d->caps->depth24,
				 err, errlen, "main target"))
			return false;
	}
	GLenum e = lx_gl.GetError();
	if (e != GL_NO_ERROR) {
		snprintf(err, errlen, "GL error 0x%x while setting up the renderer", e);
		return false;
	}
	return true;
}

/* Light i's image (a projective light's) as a texture on unit 1: LINEAR and
 * CLAMP_TO_EDGE, no mipmaps, so that any size works in ES 2.0 and the reference can
 * sample it texel for texel. */
static bool renderer_beam(struct lx_renderer *r, int i, char *err, size_t errlen)
{
	const struct lx_image *im = r->d.lights[i].image;
	if (!im || r->d.scene->lights[i].projective == LX_LIGHT_PLAIN)
		return true;
	if (im->width > r->d.caps->max_texture_size || im->height > r->d.caps->max_texture_size) {
		snprintf(err, errlen, "the light's %dx%d image exceeds the GL's texture limit of %d", im->width, im->height,
			 r->d.caps->max_texture_size);
		return false;
	}
	lx_gl.GenTextures(1, &r->beam_tex[i]);
	lx_gl.ActiveTexture(GL_TEXTURE1);
	lx_gl.BindTexture(GL_TEXTURE_2D, r->beam_tex[i]);
	lx_gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
	lx_gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, im->width, im->height, 0, GL_RGBA, GL_UNSIGNED_BYTE, im->rgba);
	lx_gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
	lx_gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
	lx_gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
	lx_gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
	lx_gl.ActiveTexture(GL_TEXTURE0);
	return true;
}

void lx_renderer_destroy(struct lx_renderer *r)
{
	if (!r)
		return;
	if (r->objects) {
		lx_gl.DeleteBuffers(r->objects, r->vbo);
		lx_gl.DeleteBuffers(r->objects, r->shadow_vbo);
	}
	lx_gl.DeleteTextures(1, &r->atlas_tex);
	for (int i = 0; i < LX_MAX_LIGHTS; i++)
		if (r->beam_tex[i])
			lx_gl.DeleteTextures(1, &r->beam_tex[i]);
	if (r->atlas_depth)
		lx_gl.DeleteRenderbuffers(1, &r->atlas_depth);
	lx_gl.DeleteFramebuffers(1, &r->atlas_fbo);
	if (r->target_fbo) { /* 0 is the window's */
		lx_gl.DeleteTextures(1, &r->target_color);
		lx_gl.DeleteRenderbuffers(1, &r->target_depth);
		lx_gl.DeleteFramebuffers(1, &r->target_fbo);
	}
	if (r->clear_vbo)
		lx_gl.DeleteBuffers(1, &r->clear_vbo);
	/* the programs are the context's (lx_program_build): kept for the next renderer */
	if (r->piece_vbo)
		lx_gl.DeleteBuffers(1, &r->piece_vbo);
	if (r->facing_ibo)
		lx_gl.DeleteBuffers(1, &r->facing_ibo);
	if (r->kept_ibo)
		lx_gl.DeleteBuffers(1, &r->kept_ibo);
	for (int i = 0; i < LX_MAX_PLANES + LX_MAX_CASTERS; i++)
		free(r->shadow_index[i]), free(r->shadow_plane[i]), free(r->run_box[i]), free(r->adj[i]), free(r->welded[i]), free(r->fan_pos[i]);
	free(r->piece_v);
	free(r->facing_index);
	for (int k = 0; k < 2; k++)
		free(r->plans[k].kept_index), free(r->plans[k].outline_index);
	free(r->fan_kept), free(r->fan_next), free(r->fan_index), free(r->fan_loop);
	free(r->band_kept), free(r->away_kept), free(r->band_fan), free(r->band_loop), free(r->band_strip);
	free(r->band_work);
	free(r);
}

/* Whether test hook `name` is set to 1 in the environment. */
static bool hook_set(const char *name)
{
	const char *v = getenv(name);
	return v && !strcmp(v, "1");
}

struct lx_renderer *lx_renderer_create(const struct lx_renderer_desc *d, char *err, size_t errlen)
{
	const struct lx_gl_caps *caps = d->caps;
	if ((!d->to_window && (d->width > caps->max_renderbuffer_size || d->height > caps->max_renderbuffer_size)) ||
	    d->width > caps->max_viewport[0] || d->height > caps->max_viewport[1]) {
		snprintf(err, errlen, "size %dx%d exceeds the GL's limit (renderbuffer %d, viewport %dx%d)", d->width,
			 d->height, caps->max_renderbuffer_size, caps->max_viewport[0], caps->max_viewport[1]);
		return NULL;
	}
	if (d->map_count > LX_MAX_MAPS) {
		snprintf(err, errlen, "a method returned %d maps; the main pass handles at most %d", d->map_count, LX_MAX_MAPS);
		return NULL;
	}
	if (d->light_count < 1 || d->light_count > LX_MAX_LIGHTS) {
		snprintf(err, errlen, "%d lights to draw, expected 1 to %d", d->light_count, LX_MAX_LIGHTS);
		return NULL;
	}
	struct lx_renderer *r = calloc(1, sizeof(*r));
	if (!r) {
		snprintf(err, errlen, "out of memory");
		return NULL;
	}
	r->d = *d;
	r->objects = d->meshes->count;
	r->max_covers = d->map_count > 0 ? lx_scene_covers_needed(d->scene, d->meshes) : 0;
	r->d.clear_whole_atlas |= hook_set("LIXEL_CLEAR_WHOLE_ATLAS");
	/* test hooks: what the fans decide alike with, what the boxes' polygons are measured against */
	r->faces_not_fans = hook_set("LIXEL_ROUND_CASTERS_AS_FACES"), r->boxes_as_faces = hook_set("LIXEL_BOXES_AS_FACES");
	r->whole_bands = hook_set("LIXEL_WHOLE_BANDS"), r->no_ids = hook_set("LIXEL_NO_CASTER_IDS");
	/* the mediump path compares 11-bit codes: one code there is 8192 of the 24-bit ones */
	r->bias_uniform = (float)(mediump(r) ? fmax(d->bias_codes / 8192.0, 1.0) : d->bias_codes);
	/* slots need the 24-bit depth texture (a slot keeps 24 - log2(slots) bits) and a GPU
	 * that pays for clears (a tiler's clear is free; not clearing would cost it a load) */
	r->slots = depth_texture(r) && !d->caps->tiler && !r->d.clear_whole_atlas && d->depth_slots > 1 ? d->depth_slots : 1;
	r->slot = -1;
	r->texture_width = d->lights[0].atlas->texture_width;
	r->texture_height = d->lights[0].atlas->texture_height;
	bool ok = true;
	for (int i = 0; i < d->light_count && ok; i++)
		ok = renderer_beam(r, i, err, errlen);
	if (ok)
		face_plane_fits(r), covers_fit(r);
	if (!ok || !renderer_programs(r, err, errlen) || !renderer_buffers(r, err, errlen) ||
	    !renderer_targets(r, err, errlen)) {
		lx_renderer_destroy(r);
		return NULL;
	}
	return r;
}

/* The vertex arrays a pass reads: positions, and with them normals and face normals or not. */
static void vertex_arrays(bool normals)
{
	lx_gl.EnableVertexAttribArray(LX_ATTR_POSITION);
	if (normals) {
		lx_gl.EnableVertexAttribArray(LX_ATTR_NORMAL);
		lx_gl.EnableVertexAttribArray(LX_ATTR_FACE_NORMAL);
	} else {
		lx_gl.DisableVertexAttribArray(LX_ATTR_NORMAL);
		lx_gl.DisableVertexAttribArray(LX_ATTR_FACE_NORMAL);
	}
}

/* The quad over the viewport (clear_vbo: 2D corners) as the positions. */
static void bind_quad(const struct lx_renderer *r)
{
	lx_gl.BindBuffer(GL_ARRAY_BUFFER, r->clear_vbo);
	lx_gl.VertexAttribPointer(LX_ATTR_POSITION, 2, GL_FLOAT, GL_FALSE, 0, (const void *)0);
}

/* The vertex attributes from the bound buffer (positions, then normals and face normals). */
static void set_attributes(bool normals)
{
	const GLsizei stride = LX_VERTEX_FLOATS * sizeof(float);
	lx_gl.VertexAttribPointer(LX_ATTR_POSITION, 3, GL_FLOAT, GL_FALSE, stride, (const void *)0);
	if (normals) {
		lx_gl.VertexAttribPointer(LX_ATTR_NORMAL, 3, GL_FLOAT, GL_FALSE, stride, (const void *)(3 * sizeof(float)));
		lx_gl.VertexAttribPointer(LX_ATTR_FACE_NORMAL, 3, GL_FLOAT, GL_FALSE, stride,
					  (const void *)(6 * sizeof(float)));
	}
}

static void bind_mesh(const struct lx_renderer *r, int id, bool normals)
{
	lx_gl.BindBuffer(GL_ARRAY_BUFFER, r->vbo[id]);
	set_attributes(normals);
}

/* Sets an atlas region and its guard ring to "far": the whole atlas with no scissor when
 * the ring spans it (llvmpipe's one fast clear), else a far quad over the ring. llvmpipe
 * clears a scissored rectangle by a slower path than the quad's fill at every size
 * measured: plane's three regions (about 211k lixels) took 1.37-1.45 ms of shadow pass
 * with quads against 1.52-1.62 ms with the two large ones cleared scissored. */
/* The whole atlas far, in one clear. */
static void clear_atlas(struct lx_renderer *r)
{
	lx_gl.Viewport(0, 0, r->texture_width, r->texture_height);
	lx_gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

static void clear_region(struct lx_renderer *r, const struct lx_atlas *a, const struct lx_region *g)
{
	int gd = a->guard, x = g->x - gd, y = g->y - gd, w = g->w + 2 * gd, h = g->h + 2 * gd;
	if (x <= 0 && y <= 0 && x + w >= r->texture_width && y + h >= r->texture_height) {
		clear_atlas(r);
	} else { /* the far quad: its program and state are set by the caller, once */
		lx_gl.Viewport(x, y, w, h);
		lx_gl.DrawArrays(GL_TRIANGLES, 0, 6);
	}
}

/* The lookup volumes' margin for a filter: a filtered lookup reads up to lx_filter_reach
 * lixels farther than a NEAREST one. */
static double lookup_margin(const struct lx_renderer *r, enum lx_filter filter)
{
	return (mediump(r) ? LX_LOOKUP_MARGIN_MEDIUMP : LX_LOOKUP_MARGIN_HIGHP) + lx_filter_reach(filter);
}

/* The shadow pass's margin: the widest filter's, since the main pass may change filters
 * (lx_renderer_set_filter) and read the same maps again. */
static double shadow_margin(const struct lx_renderer *r)
{
	double m = 0;
	for (int k = 0; k < LX_FILTER_COUNT; k++)
		m = fmax(m, lookup_margin(r, (enum lx_filter)k));
	return m;
}

/* Every rendered region of the n lights and its guard ring "far" (a per-frame layout
 * moves the guards over what earlier frames drew): on a tiler, or when the regions cover
 * half the texture or more, the whole atlas in one clear (on llvmpipe, two lights'
 * uniform maps' shadow passes took 5.3 ms with their regions cleared one by one,
 * scissored, and 3.0 ms with one clear), else region by region, all with one program and
 * one state. */
static void clear_regions(struct lx_renderer *r, const struct lx_frame *const *f,
			  const struct lx_shadow_result *const *res, int n)
{
	const struct lx_atlas *atlas[LX_MAX_LIGHTS * LX_MAX_MAPS];
	const struct lx_region *region[LX_MAX_LIGHTS * LX_MAX_MAPS];
	int nr = 0;
	double covered = 0;
	for (int i = 0; i < n; i++) {
		const struct lx_atlas *a = r->d.lights[f[i]->light_index].atlas;
		for (int m = 0; m < res[i]->map_count; m++) {
			const struct lx_region *g = &a->regions[res[i]->maps[m].region];
			if (!res[i]->maps[m].rendered || g->w < 1 || g->h < 1)
				continue;
			atlas[nr] = a, region[nr++] = g;
			covered += (double)(g->w + 2 * a->guard) * (g->h + 2 * a->guard);
		}
	}
	if (r->d.caps->tiler || r->d.clear_whole_atlas || 2 * covered >= (double)r->texture_width * r->texture_height) {
		clear_atlas(r);
		return;
	}
	lx_gl.UseProgram(r->clear_prog);
	lx_gl.Disable(GL_CULL_FACE);
	lx_gl.DepthFunc(GL_ALWAYS);
	bind_quad(r);
	for (int k = 0; k < nr; k++)
		clear_region(r, atlas[k], region[k]);
}

/* A slot's gap below the next one up: a depth at the far plane, rounded up, still below
 * an earlier frame's nearest */
#define SLOT_GAP (16.0 / 16777215.0)

/* The depth range the last shadow pass wrote: slot k of `slots`, counted down from the
 * top, or the whole range (no slots, or slot -1). */
static void slot_range(const struct lx_renderer *r, double *lo, double *hi)
{
	if (r->slots <= 1 || r->slot < 0) {
		*lo = 0, *hi = 1;
		return;
	}
	*lo = (double)(r->slots - 1 - r->slot) / r->slots;
	*hi = *lo + 1.0 / r->slots - SLOT_GAP;
}

/* This frame's depth range, and what must be far before the casters are drawn: with
 * slots, the whole atlas once every `slots` frames (the maps move over the atlas from
 * frame to frame, onto texels an earlier frame of the cycle may have written), and
 * nothing between; without, the regions (clear_regions). */
static void begin_atlas_frame(struct lx_renderer *r, const struct lx_frame *const *f,
			      const struct lx_shadow_result *const *res, int n)
{
	if (r->slots <= 1) {
		clear_regions(r, f, res, n);
		return;
	}
	r->slot = (r->slot + 1) % r->slots;
	if (r->slot == 0)
		clear_atlas(r);
	double lo, hi;
	slot_range(r, &lo, &hi);
	lx_gl.DepthRangef((float)lo, (float)hi);
}

/* Whether a triangle's plane (object space, homogeneous, any scale) is `front`'s (unit
 * normal, offset): a flat box's face that its front's test decides
 * (lx_shadow_result.slab_front). */
static bool in_front(const vec4 *pl, const vec4 *front)
{
	double nn = sqrt(pl->x * pl->x + pl->y * pl->y + pl->z * pl->z);
	if (!(nn > 0))
		return false; /* a triangle of no area, never kept anyway */
	double c = (pl->x * front->x + pl->y * front->y + pl->z * front->z) / nn;
	return fabs(fabs(c) - 1) < 1e-9 && fabs(pl->w / nn - (c > 0 ? front->w : -front->w)) < 1e-5;
}

/* A fan over the faces of a caster that reads the map itself leaves out the faces turned
 * away by less than this (the cosine of their normal's angle with the direction away from
 * the light): they lie along its silhouette, where its own faces at its terminator read
 * the map, and stay faces, its far side. A sphere's are 30 degrees of it from edge-on, a
 * seventh of its radius in the image. */
#define FAN_WELL_AWAY 0.5

/* Of that band, the faces turned away by less than this stay faces, and a strip of
 * triangles from corner to corner (keep_band) covers the rest: a sphere's faces within
 * one mesh step of edge-on. There the far side's depth changes fastest across a lixel,
 * and a lixel's centre on the strip, nearer the light than the faces, shadowed a pixel
 * the faces left lit (one in test_render's 210 frames with the strip from the edge-on). */
#define BAND_FACES 0.2

/* The light as turned_from_light takes it, from the map's centre of projection in the
 * object's space (homogeneous): a point, or a direction (of either sign). */
struct light_seen {
	bool point;
	vec3 at;
};

static struct light_seen light_seen(vec4 centre)
{
	if (fabs(centre.w) > 1e-12 * v4_len(centre))
		return (struct light_seen){true, v3(centre.x / centre.w, centre.y / centre.w, centre.z / centre.w)};
	return (struct light_seen){false, v3(centre.x, centre.y, centre.z)};
}

/* How far triangle t of caster id (its plane pl) is turned from the light: the cosine of
 * its normal's angle with the direction to the light, unsigned (FAN_WELL_AWAY and
 * BAND_FACES are taken against it); 0 where either has no length. */
static double turned_from_light(const struct lx_renderer *r, int id, int t, struct light_seen l, vec4 pl)
{
	vec3 n = v3(pl.x, pl.y, pl.z), to = l.at;
	if (l.point) { /* from the triangle's first corner */
		const float *q = r->fan_pos[id] + 3 * r->welded[id][3 * t];
		to = v3_sub(l.at, v3(q[0], q[1], q[2]));
	}
	double size = v3_len(to) * v3_len(n);
	return size > 0 ? fabs(v3_dot(n, to)) / size : 0;
}

/* Whether every triangle of a fan (indices first to k in fan_index) faces away from the
 * light (centre as above), as the faces it stands for: then its image covers theirs once. */
static bool fan_faces_away(const struct lx_renderer *r, int id, vec4 centre, int first, int k)
{
	const float *p = r->fan_pos[id];
	for (int i = first; i < k; i += 3) {
		vec4 c[3];
		for (int j = 0; j < 3; j++) {
			const float *q = p + 3 * r->fan_index[i + j];
			c[j] = (vec4){q[0], q[1], q[2], 1};
		}
		if (!(v4_dot(centre, v4_cross3(c[0], c[1], c[2])) <= 0))
			return false;
	}
	return true;
}

/* After a reading caster's polygon (k indices in fan_index, over its faces turned well
 * away from the light), the rest of its faces turned away: those within BAND_FACES of
 * edge-on as faces, and between them and the polygon the strip across (strip indices in
 * band_strip, lx_fan_band_strip; -1: none) where it fits in room and faces away from the
 * light as the faces do; else all of them as faces. Either way with the faces within
 * `tolerance` of edge-on (as keep_back_faces measures it) not turned away, which the GL
 * may draw or cull. On the default scene's facing view the sphere's band is 100 strip
 * triangles and 44 faces where it was 264 faces. The new count of indices, or -1 out of
 * room. */
static int keep_band(struct lx_renderer *r, int id, vec4 centre, int k, int strip, int room, double tolerance)
{
	bool strips = false;
	if (strip > 0 && k + strip <= room) {
		memcpy(r->fan_index + k, r->band_strip, (size_t)strip * sizeof *r->band_strip);
		strips = fan_faces_away(r, id, centre, k, k + strip);
		k += strips ? strip : 0;
	}
	const unsigned short *index = r->shadow_index[id];
	for (int t = 0; t < r->shadow_indices[id] / 3; t++) {
		double side = v4_dot(centre, r->shadow_plane[id][t]);
		if (side < tolerance && !r->fan_kept[t] && (!strips || !r->band_kept[t])) {
			if (k + 3 > room)
				return -1;
			memcpy(r->fan_index + k, index + 3 * t, 3 * sizeof *index);
			k += 3;
		}
	}
	return k;
}

/* Whether every corner of object id's box lies in front of the light and inside the
 * depth range of light clip matrix lc (the object's): then a map that flattens casters
 * onto its near plane flattens none of it, and neither plane clips it. */
static bool box_in_depth_range(const struct lx_renderer *r, int id, const mat4 *lc)
{
	const struct lx_mesh *me = &r->d.meshes->mesh[id];
	for (int k = 0; k < 8; k++) {
		vec4 c = m4_mul_point(lc, v3_box_corner(me->bmin, me->bmax, k));
		if (!(c.w > 0 && c.z > -c.w && c.z < c.w))
			return false;
	}
	return true;
}

/* Caster id's outline in map m (sure_spans), after keep_back_faces' loop: the corners
 * of its fan (k indices in fan_index). Where the caster reads the map itself the map
 * holds its band's faces too (or all its faces turned away), so its whole silhouette,
 * whose corners are those of the fan over all its faces turned away (away_kept): a sure
 * shadow as wide as the caster's, not only the fan's (plane-optimal's lookups on the
 * default scene's facing view at 1024x1024, depth-texture path: 5.43% of the pixels ->
 * 4.61%). */
static void keep_outline(struct lx_renderer *r, struct shadow_plan *pl, int light, int m, int id, int k,
			 bool reads_itself, int room)
{
	const unsigned short *ring = r->fan_index;
	int corners = k;
	if (k > 0 && reads_itself) {
		int whole = lx_silhouette_fan(r->welded[id], r->adj[id], r->shadow_indices[id] / 3, r->away_kept,
					      (unsigned short)r->fan_apex[id], r->fan_next, r->band_fan, room);
		if (whole > 0)
			ring = r->band_fan, corners = whole;
	}
	struct kept_draw *kd = &pl->kept[light][m][id];
	kd->outline_first = pl->outline_count, kd->outline_count = 0;
	for (int i = 0; i + 2 < corners && pl->outline_count < r->kept_room; i += 3) /* (apex, a, b): each corner once, as a */
		pl->outline_index[pl->outline_count++] = ring[i + 1];
	kd->outline_count = pl->outline_count - kd->outline_first;
}

/* The triangles of object id that map m's culling keeps (the pass culls GL_FRONT: those
 * whose image turns clockwise), appended to kept_index: a triangle the GL culls still
 * costs its vertices and set-up (on a board's vertex stage, its shading and tiling; on
 * llvmpipe little, 0.015-0.06 ms a frame), and half of each closed caster's are. The sign
 * of a triangle's projected area is that of its plane against the map's centre of
 * projection (v4_cross3 of the light-clip x, y and w rows), whatever the map's warp and
 * through the clipping of a triangle that crosses w = 0; one within a hundredth of edge-on
 * (in that measure) is kept and left to the GL, so that float rounding cannot drop one
 * it would draw. */
static void keep_back_faces(struct lx_renderer *r, struct shadow_plan *pl, const struct lx_frame *f,
			    const struct lx_shadow_map *map, const struct lx_region *g, int light, int m, int id,
			    const vec4 *front, bool reads_itself)
{
	mat4 t = m4_translate(f->offset[id]), lc = m4_mul(&map->light_clip, &t); /* the object's */
	to_float(&lc, pl->kept[light][m][id].light_clip);
	vec4 centre = v4_cross3(m4_row(&lc, 0), m4_row(&lc, 1), m4_row(&lc, 3));
	double tolerance = 1e-2 * v4_len(centre);
	int first = pl->kept_count, n = r->shadow_indices[id] / 3;
	const vec4 *plane = r->shadow_plane[id];
	const unsigned short *index = r->shadow_index[id];
	/* a round caster drawn as the fan over the faces turned away, where it has fewer
	 * triangles, into a plane's map (never flattened onto its near plane: draw_map) or
	 * another that flattens and clips none of it; where the caster reads the map itself,
	 * over those turned well away only (its own faces at its terminator compare with its
	 * far side there, as before). A box, into a plane's map it does not read, as its
	 * silhouette's polygon (lx_fan_as_polygon), four or six corners in two or four
	 * triangles for its faces' four or six, cut at its shortest inner edges: under the
	 * table scene's low light each leg's image runs the whole floor map, and each block an
	 * inner edge crosses is shaded once for each triangle beside it (the shadow passes
	 * 0.05 ms shorter at 1024x1024, measured frame by frame). Its depths lie inside it,
	 * nearer than its far side: a receiver touching it (a leg's foot on the floor) may
	 * compare as shadowed over a lixel more, so not in coarser maps. With the casters'
	 * ids in the atlas (caster_ids) no caster reads its own texels: reads_itself false */
	bool round = round_caster(r, id);
	bool fan = r->fan_apex[id] >= 0 && (map->plane >= 0 || box_in_depth_range(r, id, &lc)) && !front &&
		   (round || (map->plane >= 0 && !reads_itself && !r->boxes_as_faces));
	struct light_seen seen = light_seen(centre);
	for (int t = 0; t < n; t++) {
		double side = v4_dot(centre, plane[t]);
		double turned = fan && reads_itself && side < 0 ? turned_from_light(r, id, t, seen, plane[t]) : 0;
		if (fan)
			r->fan_kept[t] = side < 0 && (!reads_itself || turned > FAN_WELL_AWAY);
		if (fan && reads_itself)
			r->band_kept[t] = side < 0 && turned > BAND_FACES, r->away_kept[t] = side < 0;
		if (side < tolerance && !(front && in_front(&plane[t], front)) &&
		    pl->kept_count + 3 <= r->kept_room) { /* room: every triangle, map and light */
			memcpy(pl->kept_index + pl->kept_count, index + 3 * t, 3 * sizeof *index);
			pl->kept_count += 3;
		}
	}
	int faces = pl->kept_count - first, room = faces - 3; /* fewer indices than the faces' */
	/* a box's fan has as many triangles as its faces; its polygon has fewer (below) */
	int k = fan ? lx_silhouette_fan(r->welded[id], r->adj[id], n, r->fan_kept, (unsigned short)r->fan_apex[id], r->fan_next,
					r->fan_index, round ? room : faces)
		    : -1;
	keep_outline(r, pl, light, m, id, k, reads_itself, room);
	if (k > 0 && !fan_faces_away(r, id, centre, 0, k))
		k = -1;
	/* the band's strip, from the fan over the faces turned well away, before it turns polygon */
	int strip = -1;
	if (k > 0 && reads_itself) {
		int outer = lx_silhouette_fan(r->welded[id], r->adj[id], n, r->band_kept, (unsigned short)r->fan_apex[id],
					      r->fan_next, r->band_fan, room);
		strip = lx_fan_band_strip(r->band_fan, outer, r->fan_index, k, r->fan_pos[id], &lc, r->fan_next, r->band_loop,
					  r->band_work, r->band_strip, room);
	}
	if (k > 0) { /* its polygon where convex: the same lixels, shorter inner edges (cut by its image in lixels) */
		mat4 scale = m4_identity();
		scale.m[0] = 0.5 * g->w, scale.m[5] = 0.5 * g->h;
		mat4 lixels = m4_mul(&scale, &lc);
		k = lx_fan_as_polygon(r->fan_index, k, r->fan_pos[id], centre, &lixels, r->fan_next, r->fan_loop);
	}
	if (k >= faces)
		k = -1; /* a box's fan that did not turn polygon */
	if (k > 0 && reads_itself)
		k = keep_band(r, id, centre, k, strip, room, tolerance);
	if (k > 0 && !(round && r->faces_not_fans)) { /* in place of the faces (the test hook: its outline kept, the faces drawn) */
		memcpy(pl->kept_index + first, r->fan_index, (size_t)k * sizeof *r->fan_index);
		pl->kept_count = first + k;
	}
	pl->kept[light][m][id].first = first, pl->kept[light][m][id].count = pl->kept_count - first;
}

/* Triangle t of object id's mesh m in frame f, as the main pass draws it: FACE_UNSEEN
 * where the GL culls (cull) and it is turned away from the eye by more than a hundredth
 * of edge-on, FACE_AWAY where it is turned away from the light or lies in a plane
 * through it, else FACE_TOWARD. The shader's v_facing, dot(face normal, to the light),
 * is one value over a flat triangle: its first vertex's, in world space. */
enum face_side { FACE_TOWARD, FACE_AWAY, FACE_UNSEEN };
static enum face_side face_side(const struct lx_mesh *m, const struct lx_frame *f, int id, int t, bool cull)
{
	const float *v = m->v + (size_t)t * 3 * LX_VERTEX_FLOATS;
	vec3 p = v3_add(v3(v[0], v[1], v[2]), f->offset[id]), n = v3(v[6], v[7], v[8]);
	vec3 to_light = f->light.directional ? v3_scale(f->light.direction, -1) : v3_sub(f->light.position, p);
	vec3 to_eye = v3_sub(f->view.eye, p);
	double e = v3_dot(n, to_eye);
	if (cull && e < 0 && e * e > 1e-4 * v3_dot(n, n) * v3_dot(to_eye, to_eye))
		return FACE_UNSEEN;
	return v3_dot(n, to_light) > 0 ? FACE_TOWARD : FACE_AWAY;
}

static bool culls_back_faces(const struct lx_frame *f, int id, int plane_count);

/* Point x's image through clip matrix lc (divided) into the bounds lo, hi; false where it
 * lies behind the light, and the bounds with it. */
static bool image_bounds(const mat4 *lc, vec3 x, double lo[2], double hi[2])
{
	vec4 q = m4_mul_point(lc, x);
	if (!(q.w > 0))
		return false;
	lo[0] = fmin(lo[0], q.x / q.w), hi[0] = fmax(hi[0], q.x / q.w);
	lo[1] = fmin(lo[1], q.y / q.w), hi[1] = fmax(hi[1], q.y / q.w);
	return true;
}

/* Where caster id's faces that read map m may read it (band_rect), in lixels of its
 * region g, into rect (x0, y0, x1, y1): the images of the runs of its triangles the main
 * pass may draw with a lookup of a map in `reads` (as sort_by_facing asks, with the
 * shadow pass's wider margin), grown by that margin and a lixel. Only there need the map
 * hold its band (its far side near its silhouette, keep_back_faces): a lit face reads the
 * lixel its point falls in, or with a filter those around it. False where that is 30%
 * of its image or more, or cannot be told (a run's corner behind the light): the band
 * whole. On the default scene's facing view the ball's faces read the floor's map in 4
 * triangles. */
static bool band_rect(struct lx_renderer *r, const struct lx_frame *f, const struct lx_shadow_map *map,
		      const struct lx_region *g, int id, unsigned reads, int *rect)
{
	const struct lx_mesh *me = &r->d.meshes->mesh[id];
	/* none for a box, which keeps its faces in a map it reads (its polygon lies nearer
	 * than its far side), nor where object_draws reads the maps from every face it draws:
	 * --lookup-region all, a flat-shaded caster's shaded draw, a mesh sort_by_facing
	 * cannot sort */
	if (!round_caster(r, id) || r->fan_apex[id] < 0 || r->faces_not_fans || r->whole_bands || r->d.lookup_everywhere ||
	    r->flat[id] || me->vertex_count > 65536 || !r->run_box[id] || g->w < 1 || g->h < 1)
		return false;
	mat4 t = m4_translate(f->offset[id]), lc = m4_mul(&map->light_clip, &t); /* the object's */
	double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY}, size[2] = {g->w, g->h};
	double img_lo[2] = {INFINITY, INFINITY}, img_hi[2] = {-INFINITY, -INFINITY};
	bool cull = culls_back_faces(f, id, r->d.scene->plane_count);
	int tris = me->vertex_count / 3;
	for (int k = 0; k * RUN_TRIANGLES < tris; k++) {
		vec3 a = r->run_box[id][2 * k], b = r->run_box[id][2 * k + 1];
		for (int c = 0; c < 8; c++) /* the image, from the runs' boxes */
			if (!image_bounds(&lc, v3_box_corner(a, b, c), img_lo, img_hi))
				return false;
		if (!lx_lookup_box_may_meet(&r->lookup, id, reads, v3_add(a, f->offset[id]), v3_add(b, f->offset[id])))
			continue;
		/* the run's faces that read: turned towards the light and drawn (sort_by_facing) */
		for (int tr = k * RUN_TRIANGLES; tr < (k + 1) * RUN_TRIANGLES && tr < tris; tr++) {
			if (face_side(me, f, id, tr, cull) != FACE_TOWARD)
				continue;
			const float *v = me->v + (size_t)tr * 3 * LX_VERTEX_FLOATS;
			for (int c = 0; c < 3; c++)
				if (!image_bounds(&lc, v3(v[c * LX_VERTEX_FLOATS], v[c * LX_VERTEX_FLOATS + 1], v[c * LX_VERTEX_FLOATS + 2]),
						  lo, hi))
					return false;
		}
	}
	double grow = shadow_margin(r) + 1, image = 1;
	for (int d = 0; d < 2; d++) { /* clip space to the region's lixels */
		double x0 = (lo[d] * 0.5 + 0.5) * size[d] - grow, x1 = (hi[d] * 0.5 + 0.5) * size[d] + grow;
		if (!(hi[d] >= lo[d]))
			x0 = x1 = 0; /* no face reads: an empty rectangle, the band nowhere */
		rect[d] = (int)fmax(0, fmin(size[d], floor(x0)));
		rect[d + 2] = (int)fmax(0, fmin(size[d], ceil(x1)));
		image *= fmax(0, img_hi[d] - img_lo[d]) * 0.5 * size[d];
	}
	/* worth four more draws of the polygon where the band keeps under 30% of the image
	 * (its runs' boxes' bounds): at 40% on uniform's default view the shadow passes took
	 * 0.03 ms longer, at 2% on facing 0.04 ms shorter (frame by frame) */
	return (double)(rect[2] - rect[0]) * (rect[3] - rect[1]) < 0.3 * image;
}

/* Object id's kept triangles in map m of light `light` (keep_back_faces; reads: the maps
 * the caster reads itself), with the polygon beside a band kept only where its faces read
 * (band_rect), and the map marked as drawing it. */
static void keep_map_draw(struct lx_renderer *r, struct shadow_plan *pl, const struct lx_frame *f,
			  const struct lx_shadow_result *res, const struct lx_atlas *atlas, int light, int m, int id,
			  unsigned reads)
{
	const struct lx_shadow_map *map = &res->maps[m];
	const struct lx_region *g = &atlas->regions[map->region];
	const vec4 *front = res->slab_face_out[id] ? &res->slab_front[id] : NULL;
	bool itself = reads & 1u << m;
	int rect[4] = {0, 0, 0, 0}, whole_first = 0, whole_count = 0;
	if (itself && band_rect(r, f, map, g, id, reads, rect)) {
		keep_back_faces(r, pl, f, map, g, light, m, id, front, false);
		whole_first = pl->kept[light][m][id].first, whole_count = pl->kept[light][m][id].count;
	}
	keep_back_faces(r, pl, f, map, g, light, m, id, front, itself);
	struct kept_draw *kd = &pl->kept[light][m][id];
	kd->whole_first = whole_first, kd->whole_count = whole_count;
	memcpy(kd->rect, rect, sizeof rect);
	if (kd->count > 0 && !res->slab_face_out[id])
		pl->drawn_in[light][id] |= 1u << m;
}

/* Kept draw k of a caster that reads its map only inside k->rect, in region g: the band's
 * triangles there, the polygon over all its faces turned away around it, each inside a
 * scissor (the four strips around the rectangle, then the rectangle). */
static void draw_split(const struct lx_region *g, const struct kept_draw *k)
{
	const int *q = k->rect;
	const int strip[4][4] = {{0, 0, g->w, q[1]}, {0, q[3], g->w, g->h}, {0, q[1], q[0], q[3]}, {q[2], q[1], g->w, q[3]}};
	lx_gl.Enable(GL_SCISSOR_TEST);
	for (int s = 0; s < 4; s++)
		if (strip[s][2] > strip[s][0] && strip[s][3] > strip[s][1]) {
			lx_gl.Scissor(g->x + strip[s][0], g->y + strip[s][1], strip[s][2] - strip[s][0], strip[s][3] - strip[s][1]);
			lx_gl.DrawElements(GL_TRIANGLES, k->whole_count, GL_UNSIGNED_SHORT,
					   (const void *)((size_t)k->whole_first * sizeof(unsigned short)));
		}
	if (q[2] > q[0] && q[3] > q[1]) {
		lx_gl.Scissor(g->x + q[0], g->y + q[1], q[2] - q[0], q[3] - q[1]);
		lx_gl.DrawElements(GL_TRIANGLES, k->count, GL_UNSIGNED_SHORT,
				   (const void *)((size_t)k->first * sizeof(unsigned short)));
	}
	lx_gl.Disable(GL_SCISSOR_TEST);
}

/* Of the maps in mask a caster reads as a receiver, those its main-pass draws read with the
 * frame's lookup volumes (r->lookup): the ones that can serve a point of it in view, none
 * where no shadow can fall on it (--lookup-region all: every one). A wider margin keeps
 * as many or more. */
static unsigned caster_reads(const struct lx_renderer *r, int id, unsigned mask)
{
	if (r->d.lookup_everywhere || !mask)
		return mask;
	mask = lx_lookup_maps(&r->lookup, id, mask);
	return mask && lx_lookup_any(&r->lookup, id, mask) ? mask : 0;
}

/* A shadow pass's CPU work into pl: which objects each light's maps draw (drawn[i][object]
 * for frame i, a mask of maps: those a lookup can read, lx_lookup_caster_maps; none for a
 * flat box in no map), the triangles each keeps (a flat box's face its front decides left
 * out, res->slab_front) and the maps that draw each caster (drawn_in); atlas[i] is frame
 * i's light's layout; any: some map of theirs is rendered (else nothing is drawn). No GL
 * call: it may run for the next frame while the GL draws. */
static void shadow_draws(struct lx_renderer *r, struct shadow_plan *pl, const struct lx_frame *const *f,
			 const struct lx_shadow_result *const *res, const struct lx_atlas *const *atlas, int n, bool any)
{
	pl->kept_count = pl->outline_count = 0;
	memset(pl->drawn_in, 0, sizeof pl->drawn_in); /* what the atlas holds: nothing of this frame yet */
	for (int i = 0; any && i < n; i++) {
		int light = f[i]->light_index; /* kept and drawn_in by light, which the main pass knows */
		/* with the widest margin; the main pass prepares its own, with its filter's */
		lx_lookup_prepare(f[i], atlas[i], res[i], shadow_margin(r), &r->lookup);
		for (int id = 0; id < r->objects; id++) {
			pl->drawn[i][id] = lx_lookup_caster_maps(&r->lookup, id, r->d.lookup_everywhere);
			/* the maps its own main-pass draws read, asked as object_draws asks with its
			 * own margin, no wider than this one's: it reads none this keeps out. Asked
			 * only where keep_back_faces takes it, for a caster's fan (a box's polygon),
			 * in a map that draws it (lx_lookup_any clips the receiver's faces by each
			 * volume: asked of every object, 6-17 us of the table's shadow_draws); not
			 * with ids in the atlas, where its own texels shadow none of it */
			unsigned reads = pl->drawn[i][id] && r->fan_apex[id] >= 0 && !caster_ids(r)
						 ? caster_reads(r, id, r->lookup.reads[id])
						 : 0;
			for (int m = 0; m < res[i]->map_count; m++)
				if (pl->drawn[i][id] & 1u << m && res[i]->maps[m].rendered)
					keep_map_draw(r, pl, f[i], res[i], atlas[i], light, m, id, reads);
		}
	}
}

/* Light `light`'s map `m`: the triangles pl keeps of the objects it draws (drawn, the
 * light's frame's), inside its region. */
static void draw_map(struct lx_renderer *r, const struct shadow_plan *pl, const struct lx_atlas *a,
		     const struct lx_shadow_map *map, int light, int m, const unsigned *drawn)
{
	const struct lx_region *g = &a->regions[map->region];
	if (!map->rendered || g->w < 1 || g->h < 1)
		return;
	lx_gl.Viewport(g->x, g->y, g->w, g->h);
	/* a plane map's depth range holds every caster inside its cone (fit_depth), so
	 * nothing need be flattened; flattening a vertex of a long triangle crossing the
	 * near plane would drag the depth of the triangle's visible part past the far
	 * plane (a caster beside a table under a grazing light lost its shadow) */
	lx_gl.Uniform1f(r->shadow_pancake, map->plane < 0 ? 1.0f : 0.0f);
	for (int id = 0; id < r->objects; id++) {
		const struct kept_draw *k = &pl->kept[light][m][id];
		if (!(drawn[id] & 1u << m) || k->count == 0)
			continue; /* no fill and no vertices for what no lookup reads */
		lx_gl.UniformMatrix4fv(r->shadow_light_clip, 1, GL_FALSE, k->light_clip);
		/* its id in the alpha byte, rounded or truncated alike; 255 (none) as cleared */
		if (r->shadow_caster >= 0) /* not on the depth-texture path */
			lx_gl.Uniform1f(r->shadow_caster, caster_ids(r) ? ((float)id + 0.25f) / 255.0f : 1.0f);
		lx_gl.BindBuffer(GL_ARRAY_BUFFER, r->shadow_vbo[id]);
		lx_gl.VertexAttribPointer(LX_ATTR_POSITION, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), (const void *)0);
		if (k->whole_count > 0)
			draw_split(g, k);
		else
			lx_gl.DrawElements(GL_TRIANGLES, k->count, GL_UNSIGNED_SHORT,
					   (const void *)((size_t)k->first * sizeof(unsigned short)));
	}
}

/* Whether the n frames' lights are the renderer's, and any of their maps is rendered. */
static bool lights_known(const struct lx_renderer *r, const struct lx_frame *const *f,
			 const struct lx_shadow_result *const *res, int n, bool *any)
{
	*any = false;
	for (int i = 0; i < n; i++) {
		if (f[i]->light_index < 0 || f[i]->light_index >= r->d.light_count)
			return false; /* a light the renderer was not made for: cannot happen through lx_method_run */
		for (int m = 0; m < res[i]->map_count; m++)
			*any |= res[i]->maps[m].rendered;
	}
	return true;
}

void lx_renderer_plan_shadows(struct lx_renderer *r, const struct lx_frame *const *f,
			      const struct lx_shadow_result *const *res, const struct lx_atlas *const *atlas, int n)
{
	bool any;
	r->planned = false;
	if (!lights_known(r, f, res, n, &any))
		return;
	shadow_draws(r, &r->plans[1 - r->plan], f, res, atlas, n, any);
	r->planned = true;
}

void lx_renderer_drop_plan(struct lx_renderer *r) { r->planned = false; }

void lx_renderer_shadow_passes(struct lx_renderer *r, const struct lx_frame *const *f,
			       const struct lx_shadow_result *const *res, int n)
{
	bool any;
	if (!lights_known(r, f, res, n, &any))
		return;
	const struct lx_atlas *atlas[LX_MAX_LIGHTS];
	for (int i = 0; i < n; i++)
		atlas[i] = r->d.lights[f[i]->light_index].atlas;
	if (r->planned) /* made ahead for these frames (lx_renderer_plan_shadows) */
		r->plan = 1 - r->plan;
	else
		shadow_draws(r, &r->plans[r->plan], f, res, atlas, n, any);
	r->planned = false;
	if (!any)
		return;
	const struct shadow_plan *pl = &r->plans[r->plan];
	/* left bound for the draws (nothing else of the pass binds an index buffer) */
	lx_gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, r->kept_ibo);
	lx_gl.BufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)pl->kept_count * sizeof(unsigned short), pl->kept_index,
			 GL_STREAM_DRAW);
	lx_gl.BindFramebuffer(GL_FRAMEBUFFER, r->atlas_fbo);
	vertex_arrays(false);
	lx_gl.Disable(GL_SCISSOR_TEST); /* the viewport bounds every draw: triangles are clipped to it */
	lx_gl.Enable(GL_DEPTH_TEST);
	lx_gl.ClearColor(1, 1, 1, 1);
	begin_atlas_frame(r, f, res, n);
	/* Regions never overlap, so the casters can then be drawn map after map with another
	 * program. Back faces only (second-depth shadow maps): lit front faces never compare
	 * against themselves, so there is no acne; the meshes are closed or are planes. */
	lx_gl.UseProgram(r->shadow_prog);
	lx_gl.Enable(GL_CULL_FACE);
	lx_gl.CullFace(GL_FRONT);
	lx_gl.DepthFunc(GL_LESS);
	for (int i = 0; i < n; i++)
		for (int m = 0; m < res[i]->map_count; m++)
			draw_map(r, pl, atlas[i], &res[i]->maps[m], f[i]->light_index, m, pl->drawn[i]);
	lx_gl.Disable(GL_CULL_FACE);
	lx_gl.DepthRangef(0, 1);
}

/* How many maps a set holds. */
static int maps_in(unsigned mask)
{
	int n = 0;
	for (; mask; mask &= mask - 1)
		n++;
	return n;
}

/* The main-pass variant for a shading, a draw's faces and the maps it reads (none for
 * faces turned away; without maps, method none, there is one variant for every draw),
 * built when first used; when it cannot be (cannot happen once the variants built at
 * the start compiled), the one that tests each face and reads the most maps, *mask its
 * maps and the first others. */
static struct main_program *variant_for(struct lx_renderer *r, int shading, enum lx_faces faces, unsigned *mask,
				       int covers)
{
	if (r->d.map_count == 0 || (faces == LX_FACES_CASTER && !caster_faces(r)))
		faces = LX_FACES_TOWARD;
	if (faces == LX_FACES_AWAY)
		*mask = 0;
	covers = r->d.map_count > 0 && faces != LX_FACES_AWAY ? covers : 0;
	int reads = maps_in(*mask);
	struct main_program *p = &r->variant[shading][r->filter][faces][reads][covers];
	if (!p->prog) {
		char err[1024];
		if (!main_program(p, r, shading, faces, reads, r->filter, covers, err, sizeof err)) {
			fprintf(stderr, "lixel: %s\n", err);
			/* the draw's maps first, then others up to the most a draw reads */
			for (int m = 0; m < r->d.map_count && maps_in(*mask) < most_reads(r); m++)
				*mask |= 1u << m;
			p = &r->variant[shading][r->filter][r->d.map_count > 0 ? LX_FACES_TESTED : LX_FACES_TOWARD]
				       [most_reads(r)][0];
		}
	}
	return p;
}

/* Sorts n ints in place (a handful: a slab's edges). */
static void sort_ints(int *v, int n)
{
	for (int i = 1; i < n; i++)
		for (int j = i; j > 0 && v[j] < v[j - 1]; j--) {
			int t = v[j];
			v[j] = v[j - 1];
			v[j - 1] = t;
		}
}

/* Box cut into horizontal slabs at the rectangles' edges and their sure parts' edges,
 * and each slab into spans: outside every rectangle (mask 0, no lookup); inside one or
 * more, the first map whose sure part (sure[k]: pixels its map surely serves, empty
 * when unknown) holds the span, else every map of those around it. Each map holds every
 * caster over its rectangle, so any one decides a pixel it surely serves: where two
 * pieces meet or overlap, a pixel reads one map, not both (on llvmpipe a read costs the
 * same whether or not it serves; on the default scene's near-wall view at 1024x1024,
 * 0.13-0.24 ms of plane-optimal's main pass). Returns the new count. */
static int slab_spans(struct lx_rect box, const struct lx_rect *rect, const struct lx_rect *sure, const unsigned *bit,
		      int nr, struct span *out, int n)
{
	int ys[4 * LX_MAX_MAPS + 2], ny = 0;
	ys[ny++] = box.y0, ys[ny++] = box.y1;
	for (int k = 0; k < nr; k++) {
		ys[ny++] = rect[k].y0, ys[ny++] = rect[k].y1;
		if (sure[k].x1 > sure[k].x0 && sure[k].y1 > sure[k].y0)
			ys[ny++] = sure[k].y0, ys[ny++] = sure[k].y1;
	}
	sort_ints(ys, ny);
	for (int i = 0; i + 1 < ny; i++) {
		int y0 = ys[i], y1 = ys[i + 1];
		if (y1 <= y0 || y0 < box.y0 || y1 > box.y1)
			continue;
		int xs[4 * LX_MAX_MAPS + 2], nx = 0, in[LX_MAX_MAPS], ni = 0;
		xs[nx++] = box.x0, xs[nx++] = box.x1;
		for (int k = 0; k < nr; k++)
			if (rect[k].y0 <= y0 && rect[k].y1 >= y1 && rect[k].x1 > rect[k].x0) {
				in[ni++] = k;
				xs[nx++] = rect[k].x0, xs[nx++] = rect[k].x1;
				if (sure[k].y0 <= y0 && sure[k].y1 >= y1 && sure[k].x1 > sure[k].x0)
					xs[nx++] = sure[k].x0, xs[nx++] = sure[k].x1;
			}
		sort_ints(xs, nx);
		int slab = n;
		for (int j = 0; j + 1 < nx; j++) {
			int x0 = xs[j] > box.x0 ? xs[j] : box.x0, x1 = xs[j + 1] < box.x1 ? xs[j + 1] : box.x1;
			if (x1 <= x0)
				continue;
			unsigned m = 0, one = 0;
			for (int q = 0; q < ni; q++) {
				const struct lx_rect *a = &rect[in[q]], *b = &sure[in[q]];
				if (a->x0 <= x0 && a->x1 >= x1) {
					m |= bit[in[q]];
					if (!one && b->y0 <= y0 && b->y1 >= y1 && b->x0 <= x0 && b->x1 >= x1)
						one = bit[in[q]];
				}
			}
			m = one ? one : m;
			if (n > slab && out[n - 1].mask == m && out[n - 1].box.x1 == x0)
				out[n - 1].box.x1 = x1; /* the same maps on: one span */
			else
				out[n++] = (struct span){m, {x0, y0, x1, y1}};
		}
	}
	return n;
}

/* A plane's spans: the window cut at its own maps' screen rectangles (one map per
 * rectangle), then each part with maps cut where they can shadow it (lookup_region.h). */
static int plane_spans(struct lx_renderer *r, const struct lx_shadow_result *res, int id, unsigned mask,
		       struct span *out, int room)
{
	struct lx_rect screen = {0, 0, r->d.width, r->d.height}, rect[LX_MAX_MAPS], sure[LX_MAX_MAPS];
	unsigned bit[LX_MAX_MAPS];
	const struct lx_shadow_map *of[LX_MAX_MAPS];
	struct span first[SLAB_SPANS(LX_MAX_MAPS)];
	int nf = 0, nr = 0, n = 0;
	for (int m = 0; m < res->map_count && m < LX_MAX_MAPS && nr >= 0; m++) {
		const struct lx_shadow_map *map = &res->maps[m];
		if (!(mask & 1u << m))
			continue;
		if (map->plane != id || !lx_map_screen_rect(map, r->d.width, r->d.height, &rect[nr])) {
			nr = -1; /* a map that does not say where it reaches: no cut */
			break;
		}
		of[nr] = map;
		bit[nr++] = 1u << m;
	}
	/* only a rectangle that meets another is cut at its sure part: more cuts, more pieces */
	for (int k = 0; k < nr; k++) {
		bool meets = false;
		for (int j = 0; j < nr && !meets; j++)
			meets = j != k && rect[k].x0 < rect[j].x1 && rect[j].x0 < rect[k].x1 && rect[k].y0 < rect[j].y1 &&
				rect[j].y0 < rect[k].y1;
		sure[k] = meets ? lx_map_sure_rect(of[k], r->d.width, r->d.height) : (struct lx_rect){0, 0, 0, 0};
	}
	if (nr >= 0)
		nf = slab_spans(screen, rect, sure, bit, nr, first, 0);
	else
		first[nf++] = (struct span){mask, screen};
	for (int i = 0; i < nf; i++) {
		/* the room left keeps a place for each later span */
		struct lx_span *part = r->parts;
		int np = first[i].mask ? lx_lookup_spans(&r->lookup, id, first[i].mask, first[i].box, part,
							 room - n - (nf - i - 1))
				       : -1;
		if (np < 0) {
			out[n++] = first[i];
			continue;
		}
		for (int k = 0; k < np; k++)
			out[n++] = (struct span){part[k].lookup ? first[i].mask : 0, part[k].box};
	}
	return n;
}

/* Appends the part of plane id inside a window rectangle to the piece buffer as a
 * triangle fan, with the plane mesh's normals. */
static void add_piece(struct lx_renderer *r, const struct lx_frame *f, int id, struct lx_rect box)
{
	vec3 poly[LX_WINDOW_POLY_MAX];
	int n = lx_plane_in_window(f, id, box, poly);
	if (n < 3)
		return;
	int need = r->piece_vertices + 3 * (n - 2);
	if (need > r->piece_room) {
		int room = need * 2;
		float *v = realloc(r->piece_v, (size_t)room * LX_VERTEX_FLOATS * sizeof(float));
		if (!v)
			return; /* the piece is not drawn; cannot happen at these sizes */
		r->piece_v = v;
		r->piece_room = room;
	}
	const float *normals = r->d.meshes->mesh[id].v + 3; /* a plane's normals are all one */
	for (int t = 1; t + 1 < n; t++) {
		vec3 tri[3] = {poly[0], poly[t], poly[t + 1]};
		for (int k = 0; k < 3; k++) {
			float *o = r->piece_v + (size_t)r->piece_vertices++ * LX_VERTEX_FLOATS;
			vec3 q = v3_sub(tri[k], f->offset[id]); /* object space: the shader adds the offset */
			o[0] = (float)q.x, o[1] = (float)q.y, o[2] = (float)q.z;
			memcpy(o + 3, normals, (LX_VERTEX_FLOATS - 3) * sizeof(float));
		}
	}
}

/* The pixels [*x0, *x1) of rows [y0, y1) that may hold a point of convex w, a pixel
 * wider each way; false when none. */
static bool rows_touched(const struct lx_poly *w, int y0, int y1, int *x0, int *x1)
{
	struct lx_poly a, b;
	lx_poly_clip_halfplane(w, 0, 1, -(double)y0, &a); /* y >= y0 */
	lx_poly_clip_halfplane(&a, 0, -1, (double)y1, &b); /* y <= y1 */
	if (b.n < 1)
		return false;
	double lo, hi, ylo, yhi;
	lx_poly_bounds(&b, &lo, &ylo, &hi, &yhi);
	*x0 = (int)fmax(-1, floor(lo) - 1), *x1 = (int)fmin(1e9, ceil(hi) + 1);
	return *x1 > *x0;
}

/* The pieces of plane id in the spans of span[0]'s mask among span[0..n): where they read
 * no map and test no front (drawn lit, or in shadow without a lookup), as fewer and taller
 * rectangles (lx_span_merge: the same pixels, whose shading and decision depend on no
 * varying but the lighting's), else span by span, as the lookups' coordinates come. */
static void add_pieces(struct lx_renderer *r, const struct lx_frame *f, int id, const struct lx_poly *window,
		       const struct span *span, int n)
{
	unsigned m = span[0].mask;
	bool merge = !(m & (MAP_BITS | COVER_SPAN));
	int k = 0, got = -1;
	for (int j = 0; j < n; j++) {
		if (span[j].mask != m)
			continue;
		/* only spans the plane fills: where its outline or the near plane cuts one, the
		 * GL's edges would come from other corners, and pixels on them go either way */
		if (merge && k < LX_SPAN_MERGE_MAX && lx_plane_window_holds(window, span[j].box))
			r->merge_in[k++] = span[j].box;
		else
			add_piece(r, f, id, span[j].box);
	}
	if (k > 0)
		got = lx_span_merge(r->merge_in, k, r->merge_out, 3 * LX_SPAN_MERGE_MAX);
	for (int j = 0; j < got; j++)
		add_piece(r, f, id, r->merge_out[j]);
	for (int j = 0; j < k && got < 0; j++)
		add_piece(r, f, id, r->merge_in[j]);
}

/* Spans in[0..n) cut band by band (the lookup region's grid) by convex window polygon
 * win, into out (room for room): in each band, the pixels inside win by a pixel along
 * the row and by `rows` rows across (lx_poly_rows_inside) become a span of mask `inner`
 * (none when 0), and with `edge` nonzero those around them that win may reach become the
 * span's own mask | edge (with `edge` and no `inner`, all that win may reach); the rest,
 * and the rows of bands it leaves alone, stay as they were, together. Returns the new
 * count, or -1 short of room. */
static int cut_spans(const struct span *in, int n, const struct lx_poly *win, int rows, unsigned edge, unsigned inner,
		     struct span *out, int room)
{
	int k = 0;
	for (int i = 0; i < n; i++) {
		struct lx_rect b = in[i].box;
		unsigned m = in[i].mask;
		int run = b.y0; /* rows from run on, not yet written, are whole */
		for (int y = b.y0 - b.y0 % LX_LOOKUP_BAND; y < b.y1; y += LX_LOOKUP_BAND) {
			int y0 = y < b.y0 ? b.y0 : y, y1 = y + LX_LOOKUP_BAND < b.y1 ? y + LX_LOOKUP_BAND : b.y1;
			int ix0 = 0, ix1 = 0, ox0 = 0, ox1 = 0;
			bool touch = edge && rows_touched(win, y0, y1, &ox0, &ox1) && ox1 > b.x0 && ox0 < b.x1;
			bool inside = (inner || !edge) && lx_poly_rows_inside(win, y0 - rows, y1 + rows, 1.0, &ix0, &ix1);
			/* the inner pixels in to whole blocks, the edges out (LX_SPAN_ALIGN) */
			ix0 = lx_align_up(ix0), ix1 = lx_align_down(ix1), ox0 = lx_align_down(ox0), ox1 = lx_align_up(ox1);
			ix0 = ix0 > b.x0 ? ix0 : b.x0, ix1 = ix1 < b.x1 ? ix1 : b.x1;
			inside = inside && ix1 > ix0;
			if (!touch && !inside)
				continue;
			if (!touch) /* no edges: the inner pixels alone */
				ox0 = ix0, ox1 = ix1;
			ox0 = ox0 > b.x0 ? ox0 : b.x0, ox1 = ox1 < b.x1 ? ox1 : b.x1;
			if (k + 6 > room)
				return -1;
			if (y0 > run)
				out[k++] = (struct span){m, {b.x0, run, b.x1, y0}};
			if (ox0 > b.x0)
				out[k++] = (struct span){m, {b.x0, y0, ox0, y1}};
			if (!inside) {
				out[k++] = (struct span){m | edge, {ox0, y0, ox1, y1}};
			} else {
				ix0 = ix0 > ox0 ? ix0 : ox0, ix1 = ix1 < ox1 ? ix1 : ox1;
				if (ix0 > ox0)
					out[k++] = (struct span){m | edge, {ox0, y0, ix0, y1}};
				if (inner && ix1 > ix0)
					out[k++] = (struct span){inner, {ix0, y0, ix1, y1}};
				if (ox1 > ix1)
					out[k++] = (struct span){m | edge, {ix1, y0, ox1, y1}};
			}
			if (b.x1 > ox1)
				out[k++] = (struct span){m, {ox1, y0, b.x1, y1}};
			run = y1;
		}
		if (run < b.y1) {
			if (k + 1 > room)
				return -1;
			out[k++] = (struct span){m, {b.x0, run, b.x1, b.y1}};
		}
	}
	return k;
}

/* Plane id's spans without what the planes that hide it cover (lx_frame_plane_hides: a
 * table top over the floor): nothing of it is drawn there, in any pass, since the plane in
 * front is drawn whole. Returns the spans and their count (*ns). */
static struct span *visible_spans(struct lx_renderer *r, const struct lx_frame *f, int id, struct span *span, int *ns)
{
	for (int q = 0; q < r->d.scene->plane_count; q++) {
		struct lx_poly win;
		if (!lx_frame_plane_hides(f, q, id, &win))
			continue;
		struct span *to = span == r->seen ? r->spans : r->seen;
		int n = cut_spans(span, *ns, &win, 0, 0, 0, to, PLANE_SPANS); /* nothing of it inside */
		if (n >= 0) /* short of room: drawn as they were */
			span = to, *ns = n;
	}
	return span;
}

/* Plane id's spans cut by the shadow each lit front over it throws on it
 * (lx_plane_cover_image): inside one, a pixel and a row in, drawn in that shadow
 * (COVERED_SPAN: the floor under a table without a lookup), along its edges with the
 * tests (COVER_SPAN: every front over the plane), elsewhere as before. With a shadow not
 * to give (it reaches behind the eye), or short of room, every span tests them. Returns
 * the spans. */
static struct span *cover_spans(struct lx_renderer *r, const struct lx_frame *f, int id, struct span *span, int *ns)
{
	/* w[0]: a flat box's whole shadow (lx_plane_cover_pair_image: its thin sides' too,
	 * tested over all of it), w[1...]: each front's own */
	struct lx_poly w[LX_MAX_COVERS + 1];
	int nw = 1;
	bool given = true;
	if (r->covers->paired[id])
		given = lx_plane_cover_pair_image(f, r->covers, id, &w[1], &w[2], &w[0]), nw = 3;
	else
		for (int c = 0; c < LX_MAX_COVERS && r->covers->of[id][c] >= 0; c++, nw++)
			given = given && lx_plane_cover_image(f, r->covers, r->covers->of[id][c], id, &w[nw]);
	for (int c = r->covers->paired[id] ? 0 : 1; c < nw; c++) {
		struct span *to = span == r->seen ? r->spans : r->seen;
		int n = !given ? -1
			       : c == 0 ? cut_spans(span, *ns, &w[0], 0, COVER_SPAN, 0, to, PLANE_SPANS)
					: cut_spans(span, *ns, &w[c], 1, COVER_SPAN, COVERED_SPAN, to, PLANE_SPANS);
		if (n < 0) { /* a shadow not to give (it reaches behind the eye), or short of room */
			for (int i = 0; i < *ns; i++)
				span[i].mask |= COVER_SPAN;
			return span;
		}
		*ns = n, span = to;
	}
	return span;
}

/* The least depth (normalized, -1 to 1) by which a plane must lie beyond a caster for
 * every lookup of it to shadow it: the bias and a few codes of rounding (the decode's,
 * the floors', fp16's on the mediump path), twice over, in the slot's codes. */
static double sure_depth_gap(const struct lx_renderer *r)
{
	double lo, hi;
	slot_range(r, &lo, &hi);
	double codes = (mediump(r) ? 2047.0 : 16777215.0) * (hi - lo); /* hi > lo */
	return 4.0 * (r->bias_uniform * (hi - lo) + 4.0) / codes;
}

/* Plane id's spans that read one map alone cut by the shadows that map surely throws on
 * it (lx_sure_shadow_window, of each caster the last shadow pass drew in it): inside
 * one, a pixel in along the rows (the window already holds the lookup's margin), drawn in
 * the light's shadow without a lookup (COVERED_SPAN, as under a front; SURE_SPAN marks
 * the decision image's pixels a map decided), elsewhere as before. Short of room, a cut
 * is left undone. Returns the spans. */
static struct span *sure_spans(struct lx_renderer *r, const struct lx_frame *f, const struct lx_shadow_result *res,
			       int id, struct span *span, int *ns)
{
	const struct lx_atlas *a = r->d.lights[f->light_index].atlas;
	const struct shadow_plan *pl = &r->plans[r->plan]; /* the last shadow pass's */
	int plane_count = r->d.scene->plane_count, light = f->light_index;
	double inset = lookup_margin(r, r->filter), gap = sure_depth_gap(r);
	for (int m = 0; m < res->map_count && m < LX_MAX_MAPS; m++) {
		unsigned bit = 1u << m;
		const struct lx_shadow_map *map = &res->maps[m];
		bool reads = false; /* some span reads map m alone */
		for (int i = 0; i < *ns && !reads; i++)
			reads = (span[i].mask & (MAP_BITS | COVERED_SPAN)) == bit;
		for (int c = plane_count; reads && c < r->objects; c++) {
			if (!(pl->drawn_in[light][c] & bit)) /* else its kept triangles and outline are stale */
				continue;
			/* a round caster's fan corners; a box's corners are its bounds (pts NULL) */
			bool round = round_caster(r, c);
			int np = round ? pl->kept[light][m][c].outline_count : 8;
			struct lx_poly win;
			if ((round && np < 3) ||
			    !lx_sure_shadow_window(f, map, a->regions[map->region].w, a->regions[map->region].h, c,
						   round ? r->fan_pos[c] : NULL,
						   round ? pl->outline_index + pl->kept[light][m][c].outline_first : NULL, np, id,
						   inset, gap, &win))
				continue;
			struct span *to = span == r->seen ? r->spans : r->seen;
			int k = 0;
			for (int i = 0; i < *ns && k >= 0; i++) {
				if ((span[i].mask & (MAP_BITS | COVERED_SPAN)) != bit) {
					k = k < PLANE_SPANS ? k : -1;
					if (k >= 0)
						to[k++] = span[i];
					continue;
				}
				int got = cut_spans(span + i, 1, &win, 0, 0, COVERED_SPAN | SURE_SPAN, to + k, PLANE_SPANS - k);
				k = got < 0 ? -1 : k + got;
			}
			if (k >= 0)
				span = to, *ns = k;
		}
	}
	return span;
}

/* Whether object id's faces turned away from the eye can be left out of the main pass: a
 * caster's (a closed mesh wound counter-clockwise outwards) when its whole box lies
 * beyond the near plane, where each of them is hidden behind one of its own faces turned
 * towards the eye. A plane is seen from both sides, as the reference sees it; a caster
 * the near plane cuts shows its inner faces through the cut (the horizon view's did). */
static bool culls_back_faces(const struct lx_frame *f, int id, int plane_count)
{
	return id >= plane_count && lx_view_box_beyond_near(&f->view, f->bmin[id], f->bmax[id]);
}

/* Appends caster id's triangles to the frame's index buffer in three groups: those turned
 * towards the light in runs (RUN_TRIANGLES) where one of the maps in `mask` may shadow a
 * point (lx_lookup_box_may_meet; every run when !cut), those turned towards it elsewhere,
 * those turned away. Returns the first group's count of indices and *lit the second's, or
 * -1 when its mesh cannot be indexed so. A face lying in a plane through the light counts
 * as turned away, as the reference has it (where the light grazes a face the reference
 * calls neither side wrong). With `cull` (the GL culls the object's back faces) a face
 * turned away from the eye by more than a hundredth of edge-on is left out: the GL
 * would shade its vertices before culling it (llvmpipe's draw module, a board's vertex
 * stage), and each of a caster's triangles has its own three; nearer edge-on, the GL
 * decides, so no face it draws is lost to rounding. */
static int sort_by_facing(struct lx_renderer *r, const struct lx_frame *f, int id, unsigned mask, bool cut, bool cull,
			  int *lit)
{
	const struct lx_mesh *m = &r->d.meshes->mesh[id];
	*lit = 0;
	if (m->vertex_count > 65536 || r->facing_count + m->vertex_count > r->facing_room)
		return -1;
	enum { LOOKUP, LIT, AWAY, UNSEEN };
	unsigned char group[65536 / 3];
	int tris = m->vertex_count / 3, count[4] = {0, 0, 0, 0};
	for (int k = 0; k * RUN_TRIANGLES < tris; k++) {
		bool reads = !cut || !r->run_box[id] ||
			     lx_lookup_box_may_meet(&r->lookup, id, mask, v3_add(r->run_box[id][2 * k], f->offset[id]),
						    v3_add(r->run_box[id][2 * k + 1], f->offset[id]));
		for (int t = k * RUN_TRIANGLES; t < (k + 1) * RUN_TRIANGLES && t < tris; t++) {
			enum face_side side = face_side(m, f, id, t, cull);
			group[t] = side == FACE_UNSEEN ? UNSEEN : side == FACE_AWAY ? AWAY : reads ? LOOKUP : LIT;
			count[group[t]]++;
		}
	}
	/* the first two groups in the mesh's order, the third from its end */
	int kept = 3 * (count[LOOKUP] + count[LIT] + count[AWAY]);
	unsigned short *at[3] = {r->facing_index + r->facing_count, NULL, r->facing_index + r->facing_count + kept};
	at[LIT] = at[LOOKUP] + 3 * count[LOOKUP];
	for (int t = 0; t < tris; t++) {
		if (group[t] == UNSEEN)
			continue;
		unsigned short *o = group[t] == AWAY ? (at[AWAY] -= 3) : (at[group[t]] += 3) - 3;
		o[0] = (unsigned short)(3 * t), o[1] = (unsigned short)(3 * t + 1), o[2] = (unsigned short)(3 * t + 2);
	}
	r->facing_count += kept;
	*lit = 3 * count[LIT];
	return 3 * count[LOOKUP];
}

/* Plane id's draws (object_draws): its spans (plane_spans; then what hides it, the
 * fronts' shadows and the sure shadows cut out) drawn as pieces, one draw per set of
 * maps. --lookup-region all cuts the same spans (from the maps the shader would read) and
 * draws the same pieces, so that the two ways differ in their lookups only: each piece
 * but those in a front's shadow reads every map of the plane, a sure shadow's too. */
static int plane_draws(struct lx_renderer *r, const struct lx_frame *f, const struct lx_shadow_result *res, int id,
		       unsigned mask, int covers, struct draw *out, int n)
{
	unsigned need = lx_lookup_maps(&r->lookup, id, mask);
	bool all = r->d.lookup_everywhere;
	/* a plane turned away from the light is all in its own shadow (--lookup-region all:
	 * tested, reading its maps) */
	const struct lx_plane *pl = &r->d.scene->planes[id];
	vec3 nrm = v3_cross(pl->edge1, pl->edge2), to_light = f->light.directional
							      ? v3_scale(f->light.direction, -1)
							      : v3_sub(f->light.position, v3_add(pl->corner, f->offset[id]));
	bool away = !(v3_dot(nrm, to_light) > 0);
	enum lx_faces faces = !away ? LX_FACES_TOWARD : all ? LX_FACES_TESTED : LX_FACES_AWAY;
	if (away)
		need = 0;
	struct span *span = r->spans;
	int ns = plane_spans(r, res, id, need, span, PLANE_SPANS);
	span = visible_spans(r, f, id, span, &ns);
	if (!away && covers > 0)
		span = cover_spans(r, f, id, span, &ns);
	if (!away)
		span = sure_spans(r, f, res, id, span, &ns);
	for (int i = 0; i < ns; i++) /* lx_renderer_span_reads */
		r->span_reads[maps_in(span[i].mask & MAP_BITS)] +=
			(long)(span[i].box.x1 - span[i].box.x0) * (span[i].box.y1 - span[i].box.y0);
	struct lx_poly window;
	lx_plane_window(f, id, &window);
	/* one draw per set of maps, its spans' pieces together */
	for (int i = 0; i < ns; i++) {
		unsigned m = span[i].mask;
		bool seen = false;
		for (int j = 0; j < i && !seen; j++)
			seen = span[j].mask == m;
		if (seen)
			continue;
		int first = r->piece_vertices;
		add_pieces(r, f, id, &window, span + i, ns - i);
		if (r->piece_vertices == first)
			continue;
		struct draw d = {id, m & MAP_BITS, m & COVERED_SPAN ? LX_FACES_AWAY : faces, PIECES, first,
				 r->piece_vertices - first, m & COVER_SPAN ? covers : 0, (m & SURE_SPAN) != 0};
		if (all && (!(m & COVERED_SPAN) || (m & SURE_SPAN)))
			d.mask = mask, d.faces = faces, d.sure = false;
		out[n++] = d;
	}
	return n;
}

/* The draws of object id: with every map it reads over the region where one of them can
 * shadow it (lookup_region.h), without a lookup elsewhere (llvmpipe runs both sides of a
 * branch, and small GPUs pay for every fetch). A plane, large on the screen, is cut into
 * window spans and drawn as the pieces of itself inside them, one draw per set of maps
 * (on llvmpipe a draw, scissored or not, costs about a tenth of a millisecond). A caster,
 * small on the screen and costly to draw twice, is one draw with its maps where a shadow
 * can fall on it, else without; or, where its faces' side of the light shows (the
 * decision, and a caster's smooth normals, which light faces turned away), up to three:
 * its faces turned towards the light in runs a shadow can reach (each run's box asked;
 * whole, the sphere of floor-close at 1024x1024 ran 59,545 lookups for 2,713 shadowed
 * pixels), the others turned towards it without a lookup, and those turned away, in their
 * own shadow without a test or a lookup (--lookup-region all: tested, with one). A face's
 * side is one answer over it, so neither asks the shader's per-fragment face test (on
 * llvmpipe 0.25 ms of a 1024x1024 main pass). A flat-shaded caster's shading needs no
 * side (its Lambert term is 0 on a face turned away): one draw, its lookups on faces
 * turned away wasted, which cost less than a draw (the table's five boxes drawn so: 0.12
 * ms less a frame, measured frame by frame), of the faces the eye may see where its back
 * faces are culled (sort_by_facing). */
static int object_draws(struct lx_renderer *r, const struct lx_frame *f, const struct lx_shadow_result *res, int id,
			bool decision, struct draw *out, int n)
{
	unsigned mask = r->lookup.reads[id]; /* lx_shadow_receiver_maps, prepared by frame_draws */
	int covers = lx_plane_cover_count(r->covers, id); /* a caster, small on the screen, tests
							    * them all over; a plane along their shadows' edges */
	/* a plane reading no map but testing fronts is cut into spans all the same, so that
	 * it tests them only along their shadows' edges (drawn whole, a shelf over the floor
	 * with no map tested them over every pixel: 5.21 against 3.42 ms of main pass) */
	if (id >= r->d.scene->plane_count || (!mask && !covers)) {
		mask = caster_reads(r, id, mask);
		bool sides = r->d.map_count > 0 && (decision || !r->flat[id]);
		enum lx_faces toward = caster_faces(r) ? LX_FACES_CASTER : LX_FACES_TOWARD; /* one variant for a run of draws */
		/* its faces turned towards the light read the maps only in runs a shadow can reach */
		bool cull = culls_back_faces(f, id, r->d.scene->plane_count);
		int first = r->facing_count, lit = 0,
		    facing = sides || cull ? sort_by_facing(r, f, id, mask, sides && mask && !r->d.lookup_everywhere, cull, &lit)
					   : -1;
		if (facing < 0) {
			out[n++] = (struct draw){id, mask, sides ? LX_FACES_TESTED : toward, WHOLE, 0, 0, covers, false};
			return n;
		}
		if (!sides) { /* one draw of the faces the eye may see */
			out[n++] = (struct draw){id, mask, toward, INDEXED, first, r->facing_count - first, covers, false};
			return n;
		}
		if (facing > 0)
			out[n++] = (struct draw){id, mask, toward, INDEXED, first, facing, covers, false};
		if (lit > 0)
			out[n++] = (struct draw){id, 0, toward, INDEXED, first + facing, lit, covers, false};
		int away = first + facing + lit, away_count = r->facing_count - away;
		if (away_count > 0)
			out[n++] = r->d.lookup_everywhere
					   ? (struct draw){id, mask, LX_FACES_TESTED, INDEXED, away, away_count, covers, false}
					   : (struct draw){id, 0, LX_FACES_AWAY, INDEXED, away, away_count, 0, false};
		return n;
	}
	return plane_draws(r, f, res, id, mask, covers, out, n);
}

/* The uniforms of a frame every main-pass program takes. */
struct main_uniforms {
	float view_proj[16], light[4], tex[LX_MAX_MAPS][16], region[LX_MAX_MAPS][4], clamp[LX_MAX_MAPS][4];
	float face[LX_MAX_MAPS][16]; /* tex's inverse transposes, for planes (LX_FACE_PLANE) */
	float origin[LX_MAX_MAPS][3]; /* the mediump path: what tex's s, t and depth are taken from */
	float light_color[3];
	float beam[16], range[3]; /* a projective light's */
	GLuint beam_tex;          /* its image, else 0 */
};

/* The inverse transpose of m, which takes planes as m takes points; zero where m is
 * singular (an unrendered map's, never read). */
static void plane_matrix(const mat4 *m, float out[16])
{
	mat4 inv;
	memset(out, 0, 16 * sizeof(float));
	if (!m4_invert(m, &inv))
		return;
	for (int c = 0; c < 4; c++)
		for (int k = 0; k < 4; k++)
			out[c * 4 + k] = (float)inv.m[k * 4 + c];
}

/* The mediump path's origin of a map's texture coordinates (st: its region's clip space
 * -> texture, lx_region_to_texture): the region's centre, rounded to a multiple of
 * 2^-11, which fp16 holds exactly below 1 (11 significant bits), and in depth the far
 * end of the map's depths (hi), and t's rows taken from it (s - o q). main.frag divides
 * the smaller numbers that gives and adds the origin back: one rounding of the sum,
 * where the divide of the whole coordinate had cost up to a texel of the 1982-wide
 * atlas, and a code or two of the 11-bit depth of a receiver far from the light (rows
 * of lit pixels across shadows where caster and floor were that close in depth). */
static void map_origin(const double st[4], double hi, mat4 *t, double o[3])
{
	for (int a = 0; a < 2; a++) { /* the region's centre: s = st[1], t = st[3] */
		o[a] = round(st[1 + 2 * a] * 2048) / 2048;
		for (int c = 0; c < 4; c++)
			t->m[c * 4 + a] -= o[a] * t->m[c * 4 + 3];
	}
	o[2] = hi; /* 1 here, exact in fp16: depth slots are the depth texture path's alone */
	for (int c = 0; c < 4; c++)
		t->m[c * 4 + 2] -= o[2] * t->m[c * 4 + 3];
}

/* Per map, for the main pass: the texture matrix (world -> atlas s, t, depth, q), the
 * atlas-space bounds of the rays it serves (an empty box for a map not rendered: every
 * lookup misses and reads lit), for a filter the texel centres at its region's edges,
 * which its samples are clamped to, and for --caster-depth face the texture matrix's
 * inverse transpose (main.vert's u_face_tex). */
static void map_uniforms(const struct lx_renderer *r, const struct lx_atlas *atlas, const struct lx_shadow_result *res,
			 struct main_uniforms *u)
{
	float(*tex)[16] = u->tex, (*region)[4] = u->region, (*clamp)[4] = u->clamp;
	double tw = r->texture_width, th = r->texture_height, lo, hi;
	slot_range(r, &lo, &hi);
	for (int m = 0; m < r->d.map_count; m++) {
		const struct lx_shadow_map *map = &res->maps[m];
		mat4 t = map->rendered ? lx_shadow_texture_matrix(atlas, map->region, &map->light_clip) : m4_identity();
		if (map->rendered) /* depth d -> the slot's lo + (hi - lo) d, as the shadow pass wrote it */
			for (int c = 0; c < 4; c++)
				t.m[c * 4 + 2] = (hi - lo) * t.m[c * 4 + 2] + lo * t.m[c * 4 + 3];
		double o[3] = {0, 0, 0}, st[4]; /* st: region clip space -> atlas texture space */
		lx_region_to_texture(atlas, map->region, st);
		if (mediump(r) && map->rendered)
			map_origin(st, hi, &t, o);
		for (int a = 0; a < 3; a++)
			u->origin[m][a] = (float)o[a];
		to_float(&t, tex[m]);
		if (face_plane(r))
			plane_matrix(&t, u->face[m]);
		const struct lx_region *g = &atlas->regions[map->region];
		clamp[m][0] = (float)((g->x + 0.5) / tw), clamp[m][1] = (float)((g->y + 0.5) / th);
		clamp[m][2] = (float)((g->x + g->w - 0.5) / tw);
		clamp[m][3] = (float)((g->y + g->h - 0.5) / th);
		if (!map->rendered) {
			region[m][0] = region[m][1] = 2;
			region[m][2] = region[m][3] = -1;
			continue;
		}
		region[m][0] = (float)(st[1] + st[0] * map->bounds[0] - o[0]);
		region[m][1] = (float)(st[3] + st[2] * map->bounds[1] - o[1]);
		region[m][2] = (float)(st[1] + st[0] * map->bounds[2] - o[0]);
		region[m][3] = (float)(st[3] + st[2] * map->bounds[3] - o[1]);
	}
}

static bool boxes_meet(vec3 a0, vec3 a1, vec3 b0, vec3 b1)
{
	return a0.x <= b1.x && b0.x <= a1.x && a0.y <= b1.y && b0.y <= a1.y && a0.z <= b1.z && b0.z <= a1.z;
}

/* The window rectangle holding the box's image, a pixel wider each way; false when some
 * corner lies at or behind the eye plane (then it may cover anything) or the box is empty. */
static bool box_on_screen(const struct lx_frame *f, vec3 lo, vec3 hi, int rect[4])
{
	if (!(lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z))
		return false;
	double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
	for (int k = 0; k < 8; k++) {
		vec4 q = m4_mul_point(&f->view.view_proj, v3_box_corner(lo, hi, k));
		if (!(q.w > 1e-9 * fabs(q.z) + 1e-300))
			return false;
		vec2 w = lx_view_window_point(&f->view, q);
		x0 = fmin(x0, w.x), y0 = fmin(y0, w.y), x1 = fmax(x1, w.x), y1 = fmax(y1, w.y);
	}
	rect[0] = (int)fmax(0, floor(x0) - 1), rect[1] = (int)fmax(0, floor(y0) - 1);
	rect[2] = (int)fmin(f->view.width, ceil(x1) + 1), rect[3] = (int)fmin(f->view.height, ceil(y1) + 1);
	return true;
}

/* A light pass's draws into ld, in lx_frame_draw_order's order (mostly casters first: the
 * planes' pixels behind them then fail the depth test, which on llvmpipe costs about half
 * their shading; a table top before the slab and legs under it, which would otherwise be
 * shaded and then covered: 0.2-0.5 ms of the table's main pass), each object cut by where
 * a shadow can fall on it and a plane by what a plane in front hides (visible_spans); the
 * planes' pieces and the casters' facing-sorted indices appended to the frame's
 * (upload_draws sends them). */
static void frame_draws(struct lx_renderer *r, const struct lx_frame *f, const struct lx_shadow_result *res,
			bool lit_only, struct light_draws *ld)
{
	ld->n = 0;
	memset(r->span_reads, 0, sizeof r->span_reads);
	/* also for all: the same pieces */
	lx_lookup_prepare(f, r->d.lights[f->light_index].atlas, res, lookup_margin(r, r->filter), &r->lookup);
	int order[LX_MAX_PLANES + LX_MAX_CASTERS];
	lx_frame_draw_order(f, order);
	r->covers = ld->covers = &res->covers; /* the method's (lx_shadow_method_frame); none without maps */
	for (int p = 0; p < ld->covers->count; p++)
		if (ld->covers->lit[p])
			to_float(&ld->covers->m[p], ld->cover[p]);
	for (int k = 0; k < r->objects; k++) {
		int id = order[k];
		if (lit_only && !boxes_meet(f->bmin[id], f->bmax[id], f->lit_min, f->lit_max))
			continue; /* the light reaches none of it */
		ld->n = object_draws(r, f, res, id, ld->kind == DECISION, ld->draws, ld->n);
	}
}

/* The pieces and facing-sorted indices of every pass worked out, into their buffers. */
static void upload_draws(struct lx_renderer *r)
{
	if (r->piece_vertices > 0) {
		lx_gl.BindBuffer(GL_ARRAY_BUFFER, r->piece_vbo);
		lx_gl.BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)r->piece_vertices * LX_VERTEX_FLOATS * sizeof(float),
				 r->piece_v, GL_STREAM_DRAW);
	}
	if (r->facing_count > 0) {
		lx_gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, r->facing_ibo);
		lx_gl.BufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)r->facing_count * sizeof(unsigned short),
				 r->facing_index, GL_STREAM_DRAW);
	}
}

/* Whether light f's pass projects an image (a beam or slide): its matrix in *m. */
static bool beam_projects(const struct lx_renderer *r, const struct lx_frame *f, mat4 *m)
{
	return r->beam_tex[f->light_index] && lx_light_projection(&f->light, m);
}

/* A projective light's matrix and range, and its image bound to unit 1. */
static void beam_uniforms(const struct lx_renderer *r, const struct lx_frame *f, struct main_uniforms *u)
{
	const struct lx_light *L = &f->light;
	mat4 m;
	u->beam_tex = beam_projects(r, f, &m) ? r->beam_tex[f->light_index] : 0;
	if (!u->beam_tex)
		return;
	to_float(&m, u->beam);
	bool ranged = L->range_far > 0; /* then range_far > range_near: the parser checks it */
	u->range[0] = (float)L->range_near;
	u->range[1] = ranged ? (float)(1 / (L->range_far - L->range_near)) : 0.0f;
	u->range[2] = ranged ? 1.0f : 0.0f;
	lx_gl.ActiveTexture(GL_TEXTURE1);
	lx_gl.BindTexture(GL_TEXTURE_2D, u->beam_tex);
	lx_gl.ActiveTexture(GL_TEXTURE0);
}

/* One draw: its object's uniforms and its geometry (pieces, facing-sorted indices, or
 * the whole mesh). */
static void issue_draw(struct lx_renderer *r, const struct light_draws *ld, const struct main_program *p,
		       const struct draw *d)
{
	const struct lx_frame *f = ld->f;
	const struct lx_scene *s = r->d.scene;
	int id = d->object;
	vec3 c = id < s->plane_count ? s->planes[id].color : s->casters[id - s->plane_count].color;
	lx_gl.Uniform3f(p->offset, (float)f->offset[id].x, (float)f->offset[id].y, (float)f->offset[id].z);
	lx_gl.Uniform3f(p->color, (float)c.x, (float)c.y, (float)c.z);
	lx_gl.Uniform1f(p->object_id, (float)id);
	if (p->served >= 0)
		lx_gl.Uniform1f(p->served, d->sure ? 0.5f : 0.0f);
	for (int c = 0; c < d->covers; c++)
		if (p->cover[c] >= 0) /* -1: a variant short of varyings tests fewer (lx_main_covers) */
			lx_gl.UniformMatrix4fv(p->cover[c], 1, GL_FALSE, ld->cover[ld->covers->of[id][c]]);
	if (p->cover_pair >= 0)
		lx_gl.Uniform1f(p->cover_pair, d->covers > 1 && ld->covers->paired[id] ? 1.0f : 0.0f);
	if (d->kind == PIECES) {
		lx_gl.BindBuffer(GL_ARRAY_BUFFER, r->piece_vbo);
		set_attributes(true);
		lx_gl.DrawArrays(GL_TRIANGLES, d->first, d->count);
	} else if (d->kind == INDEXED) {
		bind_mesh(r, id, true);
		lx_gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, r->facing_ibo);
		lx_gl.DrawElements(GL_TRIANGLES, d->count, GL_UNSIGNED_SHORT,
				   (const void *)((size_t)d->first * sizeof(unsigned short)));
	} else {
		bind_mesh(r, id, true);
		lx_gl.DrawArrays(GL_TRIANGLES, 0, r->vertices[id]);
	}
}

/* The maps of a set, in their order, into a variant's first slots: matrices, regions and
 * (filtered) clamps. Set whenever the set changes: variants serve many sets. */
static void set_maps(const struct lx_renderer *r, const struct main_program *p, const struct main_uniforms *u,
		     unsigned mask)
{
	float tex[LX_MAX_MAPS][16], region[LX_MAX_MAPS][4], clamp[LX_MAX_MAPS][4], face[LX_MAX_MAPS][16];
	float origin[LX_MAX_MAPS][3];
	int n = 0;
	for (int m = 0; m < r->d.map_count; m++)
		if (mask & 1u << m) {
			memcpy(tex[n], u->tex[m], sizeof tex[n]);
			memcpy(origin[n], u->origin[m], sizeof origin[n]);
			if (p->face_tex >= 0)
				memcpy(face[n], u->face[m], sizeof face[n]);
			memcpy(region[n], u->region[m], sizeof region[n]);
			memcpy(clamp[n], u->clamp[m], sizeof clamp[n]);
			n++;
		}
	lx_gl.UniformMatrix4fv(p->shadow_tex, n, GL_FALSE, tex[0]);
	lx_gl.Uniform4fv(p->region, n, region[0]);
	if (r->filter != LX_FILTER_NONE)
		lx_gl.Uniform4fv(p->clamp, n, clamp[0]);
	if (p->face_tex >= 0)
		lx_gl.UniformMatrix4fv(p->face_tex, n, GL_FALSE, face[0]);
	if (p->origin >= 0)
		lx_gl.Uniform3fv(p->origin, n, origin[0]);
}

/* A program's uniforms for a frame, set when the program changes (a uniform the variant
 * lacks has location -1, which GL ignores). */
static void use_program(const struct lx_renderer *r, const struct main_program *p, const struct main_uniforms *u)
{
	double w = r->texture_width, h = r->texture_height; /* >= 1 */
	lx_gl.UseProgram(p->prog);
	lx_gl.UniformMatrix4fv(p->view_proj, 1, GL_FALSE, u->view_proj);
	lx_gl.Uniform4f(p->light, u->light[0], u->light[1], u->light[2], u->light[3]);
	lx_gl.Uniform3fv(p->light_color, 1, u->light_color);
	/* the same depth difference as without slots: a slot's code spans `slots` codes */
	double lo, hi;
	slot_range(r, &lo, &hi);
	lx_gl.Uniform1f(p->bias, r->bias_uniform * (float)(hi - lo));
	lx_gl.Uniform1i(p->atlas, 0);
	lx_gl.Uniform4f(p->texel, (float)w, (float)h, (float)(1.0 / w), (float)(1.0 / h));
	if (p->beam >= 0) {
		lx_gl.UniformMatrix4fv(p->beam, 1, GL_FALSE, u->beam);
		lx_gl.Uniform3fv(p->range, 1, u->range);
		lx_gl.Uniform1i(p->beam_tex, 1);
	}
}

/* The target's state for a pass: cleared for the first light and a decision (the state
 * every pass leaves: no blending, depth LESS and written, no offset); an added
 * light blended on (ONE, ONE) over the depth the first left, writing no depth, pulled 4
 * depth units nearer: its planes' pieces are cut elsewhere than the first light's, so
 * their depths differ in the last bits (with no offset 2883 of plane's 76800 pixels lost
 * the second light at 320x240). No slope factor: it let a face seen edge-on pull the face
 * behind it through as well, and both added their light (a bright seam along the box). */
static void pass_state(struct lx_renderer *r, enum pass_kind kind)
{
	lx_gl.BindFramebuffer(GL_FRAMEBUFFER, r->target_fbo);
	lx_gl.Viewport(0, 0, r->d.width, r->d.height);
	lx_gl.Disable(GL_SCISSOR_TEST);
	lx_gl.Disable(GL_CULL_FACE); /* each draw says (culls_back_faces) */
	lx_gl.CullFace(GL_BACK);
	lx_gl.Enable(GL_DEPTH_TEST);
	bool added = kind == ADDED_LIGHT;
	if (added) {
		lx_gl.Enable(GL_BLEND);
		lx_gl.BlendFunc(GL_ONE, GL_ONE);
		lx_gl.DepthFunc(GL_LEQUAL);
		lx_gl.DepthMask(GL_FALSE);
		lx_gl.Enable(GL_POLYGON_OFFSET_FILL);
		lx_gl.PolygonOffset(0.0f, -4.0f);
		return;
	}
	if (kind == DECISION)
		lx_gl.ClearColor(0, 0, 0, 1);
	else
		lx_gl.ClearColor(0.08f, 0.09f, 0.11f, 1);
	lx_gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

/* After a light's pass: back to the state every other pass expects (and the first
 * light's pass and a decision take as it is). Culling is left as the last draw had it:
 * each pass that draws sets its own (pass_state, the shadow pass, the atlas clear). */
static void light_pass_done(enum pass_kind kind)
{
	if (kind != ADDED_LIGHT)
		return;
	lx_gl.Disable(GL_BLEND);
	lx_gl.DepthMask(GL_TRUE);
	lx_gl.Disable(GL_POLYGON_OFFSET_FILL);
	lx_gl.DepthFunc(GL_LESS);
	lx_gl.Disable(GL_SCISSOR_TEST);
}

/* What one light's pass draws, worked out on the CPU (no GL call): its objects' draws. */
static void prepare_light(struct lx_renderer *r, const struct lx_frame *f, const struct lx_shadow_result *res,
			  enum pass_kind kind, struct light_draws *ld)
{
	mat4 m;
	bool projective = kind != DECISION && beam_projects(r, f, &m); /* the decision needs only the shadow test */
	ld->f = f, ld->res = res, ld->kind = kind, ld->n = 0; /* not the whole struct: its arrays are large */
	ld->shading = kind == DECISION ? SHADING_DECISION
				       : shading_of(projective, kind == ADDED_LIGHT, light_coloured(&f->light));
	/* an added projective light lights only inside its frustum (the lit box): nothing of
	 * its pass need be drawn outside the box's image, nor any object outside the box */
	bool lit_only = kind == ADDED_LIGHT && projective;
	ld->reaches = !lit_only || f->lit_min.x <= f->lit_max.x;
	if (ld->reaches)
		frame_draws(r, f, res, lit_only, ld);
}

/* One light's pass of the main pass, as prepare_light worked it out. */
static void light_pass(struct lx_renderer *r, const struct light_draws *ld)
{
	const struct lx_frame *f = ld->f;
	enum pass_kind kind = ld->kind;
	pass_state(r, kind);
	if (!ld->reaches) {
		light_pass_done(kind); /* it reaches nothing in view */
		return;
	}
	struct main_uniforms u;
	to_float(&f->view.view_proj, u.view_proj);
	const struct lx_light *L = &f->light;
	vec3 lv = L->directional ? L->direction : L->position;
	u.light[0] = (float)lv.x, u.light[1] = (float)lv.y, u.light[2] = (float)lv.z, u.light[3] = L->directional ? 0.0f : 1.0f;
	u.light_color[0] = (float)L->color.x, u.light_color[1] = (float)L->color.y, u.light_color[2] = (float)L->color.z;
	map_uniforms(r, r->d.lights[f->light_index].atlas, ld->res, &u);
	beam_uniforms(r, f, &u);
	int rect[4];
	if (kind == ADDED_LIGHT && u.beam_tex && box_on_screen(f, f->lit_min, f->lit_max, rect)) {
		lx_gl.Enable(GL_SCISSOR_TEST);
		lx_gl.Scissor(rect[0], rect[1], rect[2] - rect[0], rect[3] - rect[1]);
	}
	vertex_arrays(true);
	if (r->d.map_count > 0) {
		lx_gl.ActiveTexture(GL_TEXTURE0);
		lx_gl.BindTexture(GL_TEXTURE_2D, r->atlas_tex);
	}
	/* the maps set up whenever those read change, the program only when the variant does
	 * (one serves every set of as many maps), culling whenever it changes (a caster's two
	 * draws and the planes' pieces come in runs) */
	struct main_program *p = NULL;
	unsigned current = 0;
	enum lx_faces faces = LX_FACES_TOWARD;
	bool culling = false; /* as pass_state left it */
	int covers = 0;
	for (int k = 0; k < ld->n; k++) {
		const struct draw *d = &ld->draws[k];
		if (!p || d->mask != current || d->faces != faces || d->covers != covers) {
			current = d->mask, faces = d->faces, covers = d->covers;
			unsigned reads = current;
			struct main_program *v = variant_for(r, ld->shading, faces, &reads, covers);
			if (v != p)
				use_program(r, v, &u);
			p = v;
			if (reads)
				set_maps(r, p, &u, reads);
		}
		bool cull = culls_back_faces(f, d->object, r->d.scene->plane_count);
		if (cull != culling) {
			if (cull)
				lx_gl.Enable(GL_CULL_FACE);
			else
				lx_gl.Disable(GL_CULL_FACE);
			culling = cull;
		}
		issue_draw(r, ld, p, d);
	}
	light_pass_done(kind);
}

/* One light's variants of the current filter, each drawn once (a triangle of no area) in
 * that light's pass state, with the atlas (and a projective light's image) bound as when
 * it draws. */
static void warm_light(struct lx_renderer *r, int l, int shading)
{
	enum pass_kind kind = l > 0 ? ADDED_LIGHT : FIRST_LIGHT;
	struct main_uniforms u;
	memset(&u, 0, sizeof u);
	pass_state(r, kind);
	set_attributes(true);
	lx_gl.ActiveTexture(GL_TEXTURE1);
	lx_gl.BindTexture(GL_TEXTURE_2D, r->beam_tex[l]);
	lx_gl.ActiveTexture(GL_TEXTURE0);
	lx_gl.BindTexture(GL_TEXTURE_2D, r->atlas_tex);
	for (int faces = 0; faces < face_rules(r); faces++)
		for (int reads = 0; reads <= (faces == LX_FACES_AWAY ? 0 : most_reads(r)); reads++)
			for (int cover = 0; cover <= (faces != LX_FACES_AWAY ? r->max_covers : 0); cover++) {
				unsigned mask = (1u << reads) - 1;
				struct main_program *p = variant_for(r, shading, (enum lx_faces)faces, &mask, cover);
				use_program(r, p, &u);
				if (mask)
					set_maps(r, p, &u, mask);
				lx_gl.DrawArrays(GL_TRIANGLES, 0, 3);
			}
	light_pass_done(kind);
}

void lx_renderer_warm(struct lx_renderer *r)
{
	float none[3 * LX_VERTEX_FLOATS] = {0}; /* three vertices at one point */
	GLuint vbo;
	lx_gl.GenBuffers(1, &vbo);
	lx_gl.BindBuffer(GL_ARRAY_BUFFER, vbo);
	lx_gl.BufferData(GL_ARRAY_BUFFER, sizeof none, none, GL_STATIC_DRAW);
	vertex_arrays(true);
	enum lx_filter was = r->filter;
	for (int f = 0; f < LX_FILTER_COUNT; f++)
		for (int l = 0; l < r->d.light_count; l++) {
			int shading = light_shading(r, l);
			if (!r->variant[shading][f][LX_FACES_TOWARD][most_reads(r)][0].prog)
				continue; /* a filter not set up (lx_renderer_set_filter): not drawn with */
			r->filter = (enum lx_filter)f;
			warm_light(r, l, shading);
		}
	r->filter = was;
	lx_gl.DeleteBuffers(1, &vbo);
	lx_gl.Finish();
}

void lx_renderer_main_prepare(struct lx_renderer *r, const struct lx_frame *const *f,
			      const struct lx_shadow_result *const *res, int n)
{
	int k = 0;
	r->piece_vertices = r->facing_count = 0;
	for (int i = 0; i < n && i < LX_MAX_LIGHTS; i++)
		if (f[i]->light_index >= 0 && f[i]->light_index < r->d.light_count) {
			prepare_light(r, f[i], res[i], k == 0 ? FIRST_LIGHT : ADDED_LIGHT, &r->pass[k]);
			k++;
		}
	r->prepared = k;
	upload_draws(r);
}

/* Whether the passes worked out are those of these lights (the same frames and results). */
static bool prepared_for(const struct lx_renderer *r, const struct lx_frame *const *f,
			 const struct lx_shadow_result *const *res, int n)
{
	int k = 0;
	for (int i = 0; i < n && i < LX_MAX_LIGHTS; i++)
		if (f[i]->light_index >= 0 && f[i]->light_index < r->d.light_count) {
			if (k >= r->prepared || r->pass[k].f != f[i] || r->pass[k].res != res[i])
				return false;
			k++;
		}
	return k == r->prepared;
}

void lx_renderer_main_pass(struct lx_renderer *r, const struct lx_frame *const *f,
			   const struct lx_shadow_result *const *res, int n)
{
	if (!r->prepared || !prepared_for(r, f, res, n))
		lx_renderer_main_prepare(r, f, res, n);
	for (int k = 0; k < r->prepared; k++)
		light_pass(r, &r->pass[k]);
	r->prepared = 0; /* drawn: the next frame works its own out */
}

void lx_renderer_decision_pass(struct lx_renderer *r, const struct lx_frame *f, const struct lx_shadow_result *res)
{
	if (f->light_index < 0 || f->light_index >= r->d.light_count)
		return;
	r->piece_vertices = r->facing_count = r->prepared = 0;
	prepare_light(r, f, res, DECISION, &r->pass[0]);
	upload_draws(r);
	light_pass(r, &r->pass[0]);
}

void lx_renderer_read(struct lx_renderer *r, uint8_t *rgba)
{
	lx_gl.BindFramebuffer(GL_FRAMEBUFFER, r->target_fbo);
	lx_gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
	lx_gl.ReadPixels(0, 0, r->d.width, r->d.height, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
}

/* The depth-texture path's atlas as RGBA codes: drawn into a colour target of its size by
 * atlas_readback.frag, which is read back (ES 2.0 reads no depth). */
static void read_depth_atlas(struct lx_renderer *r, uint8_t *rgba)
{
	char err[1024];
	GLuint prog = lx_program_build("atlas_clear.vert", "atlas_readback.frag", NULL, err, sizeof err);
	GLuint tex = lx_texture_rgba8(r->texture_width, r->texture_height), fbo;
	lx_gl.GenFramebuffers(1, &fbo);
	lx_gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
	lx_gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
	if (!prog) /* cannot happen: the shaders are built in and checked by test_shaders */
		fprintf(stderr, "lixel: %s\n", err);
	lx_gl.Viewport(0, 0, r->texture_width, r->texture_height);
	lx_gl.Disable(GL_DEPTH_TEST);
	lx_gl.Disable(GL_CULL_FACE);
	lx_gl.Disable(GL_SCISSOR_TEST);
	lx_gl.UseProgram(prog);
	lx_gl.ActiveTexture(GL_TEXTURE0);
	lx_gl.BindTexture(GL_TEXTURE_2D, r->atlas_tex);
	lx_gl.Uniform1i(lx_gl.GetUniformLocation(prog, "u_atlas"), 0);
	lx_gl.Uniform2f(lx_gl.GetUniformLocation(prog, "u_inverse_size"), 1.0f / (float)r->texture_width,
			1.0f / (float)r->texture_height);
	vertex_arrays(false);
	bind_quad(r);
	lx_gl.DrawArrays(GL_TRIANGLES, 0, 6);
	lx_gl.Enable(GL_DEPTH_TEST);
	lx_gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
	lx_gl.ReadPixels(0, 0, r->texture_width, r->texture_height, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
	lx_gl.DeleteFramebuffers(1, &fbo);
	lx_gl.DeleteTextures(1, &tex);
}

/* Codes of the last shadow pass's slot stretched back over the whole range (a depth
 * above it, an earlier frame's, as far), so that an atlas reads the same with or without
 * slots but for the coarser steps. */
static void codes_from_slot(const struct lx_renderer *r, uint8_t *rgba)
{
	double lo, hi;
	slot_range(r, &lo, &hi);
	double span = hi - lo; /* > 0.01: slots <= LX_DEPTH_SLOTS_MAX */
	if (lo == 0 && span == 1)
		return;
	for (size_t i = 0; i < (size_t)r->texture_width * r->texture_height; i++) {
		uint8_t *t = rgba + 4 * i;
		double d = lx_depth_decode_code(t) / (double)LX_DEPTH_MAX_CODE;
		uint32_t n = d > hi ? LX_DEPTH_MAX_CODE
					    : (uint32_t)lround(fmin(fmax((d - lo) / span, 0), 1) * LX_DEPTH_MAX_CODE);
		t[0] = (uint8_t)(n >> 16), t[1] = (uint8_t)(n >> 8), t[2] = (uint8_t)n;
	}
}

void lx_renderer_read_atlas(struct lx_renderer *r, uint8_t *rgba)
{
	if (depth_texture(r)) {
		read_depth_atlas(r, rgba);
		codes_from_slot(r, rgba);
		return;
	}
	lx_gl.BindFramebuffer(GL_FRAMEBUFFER, r->atlas_fbo);
	lx_gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
	lx_gl.ReadPixels(0, 0, r->texture_width, r->texture_height, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
}

void lx_renderer_write_atlas(struct lx_renderer *r, const uint8_t *rgba)
{
	/* no caster known to be drawn in what is written */
	memset(r->plans[r->plan].drawn_in, 0, sizeof r->plans[r->plan].drawn_in);
	lx_gl.BindTexture(GL_TEXTURE_2D, r->atlas_tex);
	lx_gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
	/* the same size and format again: the texture (and the framebuffer holding it) stays */
	if (!depth_texture(r)) {
		lx_gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, r->texture_width, r->texture_height, 0, GL_RGBA,
				 GL_UNSIGNED_BYTE, rgba);
		return;
	}
	/* each 24-bit code n as the 32-bit depth n / (2^24 - 1), which the main pass decodes as n */
	size_t count = (size_t)r->texture_width * r->texture_height;
	uint32_t *depth = malloc(count * sizeof *depth);
	if (!depth)
		return; /* a test hook: the test then finds the old texels */
	for (size_t i = 0; i < count; i++) {
		uint32_t n = lx_depth_decode_code(rgba + 4 * i);
		depth[i] = n << 8 | n >> 16;
	}
	lx_gl.PixelStorei(GL_UNPACK_ALIGNMENT, 4);
	lx_gl.TexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, r->texture_width, r->texture_height, 0,
			 GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depth);
	free(depth);
	/* the codes span the whole range; the next shadow pass starts a new cycle of slots */
	r->slot = -1;
}

int lx_renderer_depth_slots(const struct lx_renderer *r) { return r->slots; }

void lx_renderer_span_reads(const struct lx_renderer *r, long *pixels)
{
	memcpy(pixels, r->span_reads, sizeof r->span_reads);
}

bool lx_renderer_covers_short(const struct lx_renderer *r) { return r->covers_short; }

bool lx_renderer_atlas_is_depth_texture(struct lx_renderer *r)
{
	GLint type = GL_NONE;
	lx_gl.BindFramebuffer(GL_FRAMEBUFFER, r->atlas_fbo);
	lx_gl.GetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE,
						  &type);
	return type == GL_TEXTURE;
}

void lx_renderer_finish(void) { lx_gl.Finish(); }

void lx_renderer_flush(void) { lx_gl.Flush(); }
