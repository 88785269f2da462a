#version 100
#ifndef LX_SHADOWED
#define LX_SHADOWED 0
#endif
#ifndef LX_READS
#define LX_READS 0
#endif
#ifndef LX_FACE_TEST
#define LX_FACE_TEST 0 // main.frag's face test
#endif
// Main pass. LX_SHADOWED: the method has shadow maps; LX_FACE_TEST
// (main.frag); LX_READS (0 to 4):
// how many of them a draw reads, their matrices in the first slots in the maps' order
// (one variant serves every set of that many maps), a varying each and no more: every
// varying costs an interpolation per pixel.
uniform mat4 u_view_proj;
uniform vec3 u_offset; // object translation in world space
uniform vec4 u_light;  // xyz: position (w = 1) or direction of travel (w = 0)
#if LX_READS > 0
uniform mat4 u_shadow_tex[LX_READS]; // atlas (s, t, depth, q) <- world, per map read
#ifdef LX_EDGES
uniform vec4 u_region[LX_READS]; // the texture-space bounds each map serves (main.frag)
#endif
#endif
#if LX_FACE_TEST
// Which side of its face a point is on, as seen from the light: affine in the position,
// so one interpolated float is exact where the face normal and the light would be three.
varying float v_facing;
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
#ifdef LX_FACE_PLANE
// Each map's inverse transpose, which takes a plane of the world to the map's homogeneous
// space: there the face (A, B, C, D) holds A s + B t + C depth + D = 0 (s, t and depth
// divided by q), so its depth's slope over (s, t) is -(A, B) / C, one value over the
// triangle (main.frag). Left at 0 where the light grazes the face (lit at under a tenth: a
// half-lixel move runs a long way along it, past the edge of a caster it touches) or the
// face is edge-on to the map.
uniform mat4 u_face_tex[LX_READS];
varying vec4 v_slope01;
#if LX_READS > 2
varying vec4 v_slope23;
#endif

vec2 face_slope(mat4 face_tex, vec4 plane, float lit)
{
	vec4 h = face_tex * plane;
	float ok = lit * float(abs(h.z) > 1e-6 * (abs(h.x) + abs(h.y)));
	return ok > 0.5 ? -h.xy / h.z : vec2(0.0);
}
#endif
#ifdef LX_COVER
// A plane lit on the side its mesh faces casts nothing through the maps (the shadow pass
// draws back faces only); over what lies beyond it the draw tests it exactly:
// u_cover (plane_cover.h) takes a point to h, shadowed by the plane where h.w > 0 and
// 0 <= h.x, h.y <= h.z. Passed on as the four edge functions and h.w, each affine in the
// position (so interpolated exactly) and 0 where the test turns: in fp16 a value near 0
// keeps its sign, where h.x near h.z = 1 would be 1/2048 of the table top off (1 mm).
uniform mat4 u_cover;
varying vec4 v_cover;
varying float v_beyond;
#ifdef LX_COVER2
// a second front over the object (two shelves stacked over the floor), alike
uniform mat4 u_cover2;
varying vec4 v_cover2;
varying float v_beyond2;
#endif
#endif
attribute vec3 a_position;
attribute vec3 a_normal;
attribute vec3 a_face_normal;
varying vec3 v_to_light; // affine in the position: interpolated exactly
varying vec3 v_normal;
#ifdef LX_PROJECTIVE
// A spotlight or projector [Segal]: world -> (s q, t q, d, q) of its image, q = d its depth.
uniform mat4 u_beam;
varying vec4 v_beam;
#endif

#ifdef LX_EDGES
// LX_EDGES (lx_main_defines, both shaders): the test of where a map serves as four edge
// functions of its homogeneous coordinates, interpolated like them (main.frag),
// (s - x0 q, t - y0 q, x1 q - s, y1 q - t): where q > 0, the first two >= 0 and the last
// two > 0 exactly where (s, t) / q lies in [x0, x1) x [y0, y1)
vec4 edges(vec4 c, vec4 region)
{
	return vec4(c.xy - region.xy * c.w, region.zw * c.w - c.xy);
}
#endif

void main()
{
	vec4 world = vec4(a_position + u_offset, 1.0);
	v_to_light = u_light.w > 0.5 ? u_light.xyz - world.xyz : -u_light.xyz;
	v_normal = a_normal;
#ifdef LX_PROJECTIVE
	v_beam = u_beam * world;
#endif
#if LX_FACE_TEST
	v_facing = dot(a_face_normal, v_to_light);
#endif
#if LX_READS > 0
	v_shadow0 = u_shadow_tex[0] * world;
#ifdef LX_EDGES
	v_edges0 = edges(v_shadow0, u_region[0]);
#endif
#endif
#if LX_READS > 1
	v_shadow1 = u_shadow_tex[1] * world;
#ifdef LX_EDGES
	v_edges1 = edges(v_shadow1, u_region[1]);
#endif
#endif
#if LX_READS > 2
	v_shadow2 = u_shadow_tex[2] * world;
#ifdef LX_EDGES
	v_edges2 = edges(v_shadow2, u_region[2]);
#endif
#endif
#if LX_READS > 3
	v_shadow3 = u_shadow_tex[3] * world;
#ifdef LX_EDGES
	v_edges3 = edges(v_shadow3, u_region[3]);
#endif
#endif
#ifdef LX_FACE_PLANE
	vec4 plane = vec4(a_face_normal, -dot(a_face_normal, world.xyz));
	float c = dot(a_face_normal, v_to_light);
	float lit = float(c > 0.0) * float(c * c > 0.01 * dot(a_face_normal, a_face_normal) * dot(v_to_light, v_to_light));
	v_slope01 = vec4(face_slope(u_face_tex[0], plane, lit), 0.0, 0.0);
#if LX_READS > 1
	v_slope01.zw = face_slope(u_face_tex[1], plane, lit);
#endif
#if LX_READS > 2
	v_slope23 = vec4(face_slope(u_face_tex[2], plane, lit), 0.0, 0.0);
#endif
#if LX_READS > 3
	v_slope23.zw = face_slope(u_face_tex[3], plane, lit);
#endif
#endif
#ifdef LX_COVER
	vec4 h = u_cover * world;
	v_cover = vec4(h.xy, h.zz - h.xy);
	v_beyond = h.w;
#ifdef LX_COVER2
	h = u_cover2 * world;
	v_cover2 = vec4(h.xy, h.zz - h.xy);
	v_beyond2 = h.w;
#endif
#endif
	gl_Position = u_view_proj * world;
}
