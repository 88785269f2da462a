#version 100
#ifndef LX_SHADOWED
#define LX_SHADOWED 0
#endif
#ifndef LX_READS
#define LX_READS 0
#endif
#ifndef LX_FILTER
#define LX_FILTER 0
#endif
// A face turned away from the light is in its own shadow. The renderer draws a caster's
// faces turned towards it apart from those turned away (LX_FACE_AWAY: shadowed, nothing
// read), a plane as the one or the other, so the shader need not tell; LX_FACE_TEST tests
// each fragment, for a draw of both (a mesh too large to sort, --lookup-region all's
// away faces). On llvmpipe the test cost 0.25 ms of a 1024x1024 main pass.
#ifndef LX_FACE_TEST
#define LX_FACE_TEST 0
#endif
// LX_FACE_PLANE (unfiltered, off the mediump path: lx_main_face_plane): the draw is a
// caster's faces turned towards the light (a convex closed mesh, as every caster is). A
// coarse map's lixel near such a caster's silhouette holds its own back face at its
// centre, which can lie nearer the light than the pixel does: acne along a lit face's
// edges. The face's plane is compared there instead, moved only towards the light: the
// caster lies wholly beyond its face's plane, so none of its own depths is nearer than
// that plane at any lixel centre. main.vert gives the plane's slope in each map
// (v_slope01, v_slope23).
#if defined(GL_FRAGMENT_PRECISION_HIGH) && !defined(LX_FORCE_MEDIUMP)
precision highp float;
#else
precision mediump float;
#endif
// Main pass: shading and the shadow decision. With LX_DECISION defined it writes the
// decision instead of a colour: R = 1 where shadowed, G = (object id + 1) / 255, B = 1
// where the pixel ran a lookup (the variant reads a map), one half where a map decided it
// without one (u_served: a caster's sure shadow), else 0. With LX_FILTER (pcf.glsl), R is
// the filtered shadow thresholded at one half and A the visibility, 1 - the filtered shadow.
// The loader compiles one variant per count of maps a draw reads (LX_READS), whichever
// they are: the draw puts their matrices, regions and clamps in the first slots, in the
// maps' order. LX_SHADOWED: the method has maps (without, method none, nothing is shadowed).
//!include depth_rgba.glsl
uniform vec3 u_color;
uniform float u_object_id;
#ifdef LX_DECISION
uniform float u_served;
#endif
// Lights add up pass by pass [Segal]: the first light's pass has the ambient term, each
// later one's (LX_AMBIENT 0.0) adds only its own light, blended ONE, ONE. A light that is
// not white (LX_LIGHT_COLOR) and a projective one scale theirs by u_light_color.
#ifndef LX_AMBIENT
#define LX_AMBIENT 0.22
#endif
#if defined(LX_LIGHT_COLOR) || defined(LX_PROJECTIVE)
uniform vec3 u_light_color;
#endif
#if LX_FACE_TEST
varying float v_facing; // > 0 where the face is turned towards the light
#endif
#if LX_READS > 0
#if defined(LX_DEPTH_TEXTURE) && defined(GL_FRAGMENT_PRECISION_HIGH)
uniform highp sampler2D u_atlas; // a depth: samplers default to lowp, which may be fp16
#else
uniform sampler2D u_atlas;
#endif
#ifndef LX_EDGES
uniform vec4 u_region[LX_READS]; // the rays a map read serves: texture-space bounds (x0, y0,
                                 // x1, y1), empty when not rendered (else main.vert's)
#endif
uniform float u_bias;            // in depth codes
#ifdef LX_FORCE_MEDIUMP
// fp16 holds a coordinate of a 2048-wide atlas to about a texel, and the divide below
// loses as much again, and a code or two of a far depth: main.vert's coordinates are
// taken from each map's centre and its far depth, exact in fp16 (u_origin), so the
// divide works on small numbers; the sum is rounded once.
uniform vec3 u_origin[LX_READS];
#endif
#ifdef LX_FACE_PLANE
uniform vec4 u_texel; // the atlas's size in texels (w, h) and one texel (1 / w, 1 / h)
varying vec4 v_slope01; // d depth / d (s, t) of the face in maps 0 (xy) and 1 (zw)
#if LX_READS > 2
varying vec4 v_slope23;
#endif
#endif
#ifdef LX_SELF
// LX_SELF (the RGBA path): the draw is a caster's faces turned towards the light. A ray
// from the light meets a convex caster on such a face first, so none of its own texels
// can shadow them: a texel whose alpha byte (shadow_depth.frag) holds this object's id is
// passed over. Its maps may then hold its far side's outline, a polygon nearer the light
// than that side, where the faces near its silhouette had to be drawn for its own lookups.
float lx_other(vec4 texel)
{
	return float(abs(texel.a * 255.0 - u_object_id) > 0.5);
}
#endif
#if LX_FILTER > 0
// --filter pcf2x2 (1) or pcf3x3 (2): several texels of the map around the point, each
// compared, the results averaged (shaders_es/pcf.glsl)
//!include pcf.glsl
#endif
#endif
#if LX_READS > 0
varying vec4 v_shadow0;
#ifdef LX_EDGES
varying vec4 v_edges0;
#endif
#endif
#if LX_READS > 1
varying vec4 v_shadow1;
#ifdef LX_EDGES
varying vec4 v_edges1;
#endif
#endif
#if LX_READS > 2
varying vec4 v_shadow2;
#ifdef LX_EDGES
varying vec4 v_edges2;
#endif
#endif
#if LX_READS > 3
varying vec4 v_shadow3;
#ifdef LX_EDGES
varying vec4 v_edges3;
#endif
#endif
#ifdef LX_COVER
varying vec4 v_cover;  // main.vert: a plane lit on its front, over this object: its
varying float v_beyond; // parallelogram's edge functions, and > 0 beyond it
#ifdef LX_COVER2
varying vec4 v_cover2; // a second one's
varying float v_beyond2;
// 1.0 where the two are one flat box's bottom and top (plane_cover.h): a ray that crosses
// neither may still pass through the box, in by one thin side and out by another
uniform float u_cover_pair;

// Whether (x, y) / z lies in the unit square, from the edge functions (x, y, z - x, z - y)
// of h: the division only where they do not decide it exactly.
vec2 cover_point(vec4 e)
{
	return e.xy / (e.xy + e.zw);
}

// Whether segment a-b, its ends outside the unit square, meets it (lx_slab_sides_shadow):
// their bounds overlap, and the square's corners are not all on one side of its line.
float crosses_square(vec2 a, vec2 b)
{
	vec2 d = b - a;
	float e0 = d.y * a.x - d.x * a.y;
	vec4 e = vec4(e0) + vec4(0.0, -d.y, d.x, d.x - d.y);
	bool apart = any(greaterThan(min(a, b), vec2(1.0))) || any(lessThan(max(a, b), vec2(0.0)));
	bool ends_in = all(greaterThanEqual(a, vec2(0.0))) && all(lessThanEqual(a, vec2(1.0))) ||
		       all(greaterThanEqual(b, vec2(0.0))) && all(lessThanEqual(b, vec2(1.0)));
	bool sides = min(min(e.x, e.y), min(e.z, e.w)) <= 0.0 && max(max(e.x, e.y), max(e.z, e.w)) >= 0.0;
	return float(!apart && !ends_in && sides);
}
#endif
#endif
varying vec3 v_to_light; // towards the light, not normalised
varying vec3 v_normal;
#ifdef LX_PROJECTIVE
// A spotlight's beam or a projector's slide, looked up through the light's projective
// matrix [Segal]: nothing behind the light or outside its image is lit; past range_near
// the light falls linearly with its depth, to none at range_far.
uniform sampler2D u_beam_tex;
uniform vec3 u_range; // range_near, 1 / (range_far - range_near), 1 when a range is set else 0
varying vec4 v_beam;

vec3 projected_light()
{
	vec2 st = v_beam.xy / v_beam.w;
	bvec4 inside = bvec4(greaterThanEqual(st, vec2(0.0)), lessThanEqual(st, vec2(1.0)));
	float reach = float(all(inside)) * float(v_beam.w > 0.0);
	float fall = 1.0 - u_range.z * clamp((v_beam.w - u_range.x) * u_range.y, 0.0, 1.0);
	return texture2D(u_beam_tex, st).rgb * u_light_color * (reach * fall);
}
#endif

#if LX_READS > 0
// 1.0 where a map serves the point (in front of its light, inside its bounds), else 0.0.
// No branches and no && (it short-circuits): llvmpipe runs both sides of every branch
// and small GPUs pay for each; called with constant indices only, since indexing
// uniform arrays with a variable is slow or unsupported on small GPUs.
#ifdef LX_EDGES
// The bounds as the vertex shader's edge functions of the map's homogeneous coordinates,
// interpolated as those are: on llvmpipe the four compares of the divided point with the
// bounds cost 0.2-0.4 ms a frame at 1024x1024, these a fraction of it.
float served_by_edges(vec4 e, float w)
{
	bvec4 inside = bvec4(greaterThanEqual(e.xy, vec2(0.0)), greaterThan(e.zw, vec2(0.0)));
	return float(all(inside)) * float(w > 0.0);
}
#else
float served(vec3 p, float w, vec4 region)
{
	bvec4 inside = bvec4(greaterThanEqual(p.xy, region.xy), lessThan(p.xy, region.zw));
	return float(all(inside)) * float(w > 0.0);
}
#endif
#endif

void main()
{
	float shadowed = 0.0;
#if LX_SHADOWED
#if LX_READS > 0
	// The first map, in order, that serves the point is read: each later one only takes
	// over where no earlier one served (GLSL ES 1.00 has no token pasting, so each is
	// written out). Then one fetch and the compare (LX_FILTER: several, averaged); a point no
	// map serves is lit.
	vec3 p = vec3(0.0), q;
#ifdef LX_FACE_PLANE
	vec2 slope = vec2(0.0); /* the served map's */
#endif
	float found = 0.0, s;
#ifdef LX_FORCE_MEDIUMP
	vec3 origin = vec3(0.0); /* the served map's */
#endif
#if LX_FILTER > 0
	vec4 box = vec4(0.0); /* the served map's region, which its samples stay in */
#endif
	q = v_shadow0.xyz / v_shadow0.w;
#ifdef LX_EDGES
	s = served_by_edges(v_edges0, v_shadow0.w) * (1.0 - found);
#else
	s = served(q, v_shadow0.w, u_region[0]) * (1.0 - found);
#endif
	p = s > 0.5 ? q : p; /* a select: mix() would carry a NaN q (w <= 0) over */
#ifdef LX_FORCE_MEDIUMP
	origin = s > 0.5 ? u_origin[0] : origin;
#endif
#ifdef LX_FACE_PLANE
	slope = s > 0.5 ? v_slope01.xy : slope;
#endif
#if LX_FILTER > 0
	box = s > 0.5 ? u_clamp[0] : box;
#endif
	found += s;
#if LX_READS > 1
	q = v_shadow1.xyz / v_shadow1.w;
#ifdef LX_EDGES
	s = served_by_edges(v_edges1, v_shadow1.w) * (1.0 - found);
#else
	s = served(q, v_shadow1.w, u_region[1]) * (1.0 - found);
#endif
	p = s > 0.5 ? q : p; /* a select: mix() would carry a NaN q (w <= 0) over */
#ifdef LX_FORCE_MEDIUMP
	origin = s > 0.5 ? u_origin[1] : origin;
#endif
#ifdef LX_FACE_PLANE
	slope = s > 0.5 ? v_slope01.zw : slope;
#endif
#if LX_FILTER > 0
	box = s > 0.5 ? u_clamp[1] : box;
#endif
	found += s;
#endif
#if LX_READS > 2
	q = v_shadow2.xyz / v_shadow2.w;
#ifdef LX_EDGES
	s = served_by_edges(v_edges2, v_shadow2.w) * (1.0 - found);
#else
	s = served(q, v_shadow2.w, u_region[2]) * (1.0 - found);
#endif
	p = s > 0.5 ? q : p; /* a select: mix() would carry a NaN q (w <= 0) over */
#ifdef LX_FORCE_MEDIUMP
	origin = s > 0.5 ? u_origin[2] : origin;
#endif
#ifdef LX_FACE_PLANE
	slope = s > 0.5 ? v_slope23.xy : slope;
#endif
#if LX_FILTER > 0
	box = s > 0.5 ? u_clamp[2] : box;
#endif
	found += s;
#endif
#if LX_READS > 3
	q = v_shadow3.xyz / v_shadow3.w;
#ifdef LX_EDGES
	s = served_by_edges(v_edges3, v_shadow3.w) * (1.0 - found);
#else
	s = served(q, v_shadow3.w, u_region[3]) * (1.0 - found);
#endif
	p = s > 0.5 ? q : p; /* a select: mix() would carry a NaN q (w <= 0) over */
#ifdef LX_FORCE_MEDIUMP
	origin = s > 0.5 ? u_origin[3] : origin;
#endif
#ifdef LX_FACE_PLANE
	slope = s > 0.5 ? v_slope23.zw : slope;
#endif
#if LX_FILTER > 0
	box = s > 0.5 ? u_clamp[3] : box;
#endif
	found += s;
#endif
#ifdef LX_FORCE_MEDIUMP
	p += origin;
#endif
#if LX_FILTER > 0
	shadowed = found * lx_filtered_shadow(p, box); /* the share of the footprint in shadow */
#else
	vec4 texel = texture2D(u_atlas, p.xy);
	float stored = lx_decode_code(texel);
#ifdef LX_FACE_PLANE
#ifdef LX_FORCE_MEDIUMP
	// fp16 cannot tell where in its lixel a point of a wide atlas lies: the face's
	// nearest depth over half a lixel each way, which holds the lixel's centre
	p.z -= 0.5 * (abs(slope.x) * u_texel.z + abs(slope.y) * u_texel.w);
#else
	// the face's depth at the centre of the lixel read, where nearer the light
	vec2 off = (floor(p.xy * u_texel.xy) + 0.5) * u_texel.zw - p.xy;
	p.z += min(dot(slope, off), 0.0);
#endif
#endif
	shadowed = found * float(lx_depth_code(p.z) > stored + u_bias);
#ifdef LX_SELF
	shadowed *= lx_other(texel);
#endif
#endif
#endif
#endif
#ifdef LX_COVER
	// the light's ray crosses the plane's parallelogram on its way here
	shadowed = max(shadowed, float(all(greaterThanEqual(v_cover, vec4(0.0)))) * float(v_beyond > 0.0));
#ifdef LX_COVER2
	shadowed = max(shadowed, float(all(greaterThanEqual(v_cover2, vec4(0.0)))) * float(v_beyond2 > 0.0));
	// beyond the bottom, the ray crosses the two faces' planes at these points of their
	// shared coordinates; between them it runs inside the box's thickness
	shadowed = max(shadowed, u_cover_pair * float(v_beyond > 0.0 && v_beyond2 > 0.0) *
				     crosses_square(cover_point(v_cover), cover_point(v_cover2)));
#endif
#endif
#if LX_FACE_TEST
	// a face turned away from the light is in its own shadow
	shadowed = max(shadowed, float(v_facing <= 0.0));
#endif
#ifdef LX_FACE_AWAY
	shadowed = 1.0;
#endif
#ifdef LX_DECISION
#if LX_FILTER > 0
	/* filtered: R the decision, shadowed where the filtered shadow exceeds one half
	 * (where a NEAREST edge lay); A the visibility the shading uses, 1 - shadowed */
	gl_FragColor = vec4(float(shadowed > 0.5), (u_object_id + 1.25) / 255.0,
			    LX_READS > 0 ? 1.0 : u_served, 1.0 - shadowed);
#else
	gl_FragColor = vec4(shadowed, (u_object_id + 1.25) / 255.0, LX_READS > 0 ? 1.0 : u_served,
			    1.0);
#endif
#else
	float lambert = max(dot(normalize(v_normal), normalize(v_to_light)), 0.0);
#if defined(LX_PROJECTIVE)
	vec3 c = u_color * (LX_AMBIENT + 0.78 * lambert * (1.0 - shadowed) * projected_light());
#elif defined(LX_LIGHT_COLOR)
	vec3 c = u_color * (LX_AMBIENT + 0.78 * lambert * (1.0 - shadowed) * u_light_color);
#else
	vec3 c = u_color * (LX_AMBIENT + 0.78 * lambert * (1.0 - shadowed));
#endif
	gl_FragColor = vec4(c, 1.0);
#endif
}
