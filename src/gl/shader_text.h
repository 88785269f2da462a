/* A shader's text as the loader compiles it, GL-free (so the tests can hand every
 * variant to glslangValidator): the embedded file with "#define" lines after its first
 * line and its "//!include FILE" lines expanded. */
#ifndef LX_SHADER_TEXT_H
#define LX_SHADER_TEXT_H
#include "depth_selftest.h"
#include <stdbool.h>
#include <stddef.h>

/* The text to compile (free it), or NULL with err set. simulate_lima_fragment: every
 * highp made mediump, as Mesa's lima computes fragment shaders (LIXEL_SIMULATE_LIMA). */
char *lx_shader_text(const char *name, const char *text, const char *defines, bool simulate_lima_fragment, char *err,
		     size_t errlen);
/* What a main-pass draw knows of its faces' side of the light (a face turned away from
 * it is in its own shadow): every face turned towards it, or the draw need not tell
 * (a flat-shaded object's shading, whose Lambert term is 0 where it is turned away);
 * some of each, the shader tests each (LX_FACE_TEST); every face turned away (LX_FACE_AWAY,
 * read nothing: shadowed); or as LX_FACES_TOWARD, a caster's faces, each compared along
 * its plane at the centre of the lixel read (LX_FACE_PLANE, main.vert and main.frag: no
 * acne at the caster's silhouette in a coarse map; --caster-depth face) and passing over
 * its own texels (LX_SELF, self_id below). */
enum lx_faces { LX_FACES_TOWARD, LX_FACES_TESTED, LX_FACES_AWAY, LX_FACES_CASTER, LX_FACES_COUNT };

/* A main-pass variant: how many maps the method has, how many of them a draw reads (0 to
 * maps; the draw puts them in the first slots), the decision output, its faces (where the
 * method has maps; LX_FACES_AWAY reads none: main.frag), the depth path (LX_DEPTH_AUTO as
 * LX_DEPTH_HIGHP), a shadow filter (no face plane then), a projective light (one more
 * varying), the lit fronts' cover tests (LX_COVER and LX_COVER2, plane_cover.h: one more
 * varying each, where the method has maps and the faces are not turned away), and the
 * GPU's GL_MAX_VARYING_VECTORS (0: no limit). */
struct lx_main_variant {
	int maps, reads;
	bool decision;
	enum lx_faces faces;
	enum lx_depth_precision path;
	bool filtered, projective;
	int covers; /* 0 to LX_MAX_COVERS */
	int max_varyings;
	/* the atlas's alpha bytes hold which object drew each texel (shadow_depth.frag): a
	 * LX_FACES_CASTER draw reading maps passes over its own (LX_SELF, main.frag); not on
	 * the depth-texture path, which has no colour */
	bool self_id;
};
/* The varying vectors main.vert writes for a draw reading `reads` maps: the light's
 * direction and the normal, a point per map, with edges an edge vector per map, with a
 * face plane a slope (two numbers) per map, a projective light's point and each cover
 * tested (`covers`: a row each; their floats go beside the two vec3s, and a face test's
 * with two covers takes one more). Without edges and a face plane, with one cover, at
 * most 8 (4 maps): every GPU holds it. */
int lx_main_varyings(int reads, bool edges, bool face_plane, bool projective, int covers);
/* How many covers a variant tests (LX_COVER, LX_COVER2): none where it has no maps or its
 * faces are turned away; the first is never given up (it decides shadows, not their
 * cost), the second only where the varyings cannot hold it even without edges and a
 * face plane (a draw reading 4 maps for a projective light on a GPU of 8). */
int lx_main_covers(const struct lx_main_variant *v);
/* Whether a variant draws casters' faces along their planes (LX_FACE_PLANE): faces
 * LX_FACES_CASTER, reading maps, unfiltered, and within the varyings (without edges,
 * which give way first); on the mediump path the face's nearest depth over half a lixel
 * each way (main.frag). */
bool lx_main_face_plane(const struct lx_main_variant *v);
/* Whether a variant passes over the caster's own texels (LX_SELF): self_id, faces
 * LX_FACES_CASTER, reading maps, off the depth-texture path; filtered or not. */
bool lx_main_self(const struct lx_main_variant *v);
/* The main pass's defines for a variant: besides the above, where it reads maps off the
 * mediump path and the varyings hold them, the served test on edge functions (LX_EDGES;
 * else the test compares the divided point, which needs no varying: a VideoCore IV has 8,
 * and four maps read with edges take 10). */
void lx_main_defines(const struct lx_main_variant *v, char *out, size_t len);
/* The shadow pass's defines for a depth path (NULL: none). */
const char *lx_shadow_defines(enum lx_depth_precision path);

/* Whether LIXEL_SIMULATE_LIMA=1 is set: fragment shaders are then compiled with every
 * highp made mediump (Mesa's lima computes fragments in fp16 while claiming highp). */
bool lx_simulating_lima(void);

#endif
