#version 100
#ifndef LX_USE_0
#define LX_USE_0 0
#endif
#ifndef LX_USE_1
#define LX_USE_1 0
#endif
#ifndef LX_USE_2
#define LX_USE_2 0
#endif
#ifndef LX_USE_3
#define LX_USE_3 0
#endif
// Main pass. LX_MAPS (0 to 3) shadow maps are looked up; the loader defines it.
uniform mat4 u_view_proj;
uniform vec3 u_offset; // object translation in world space
#if LX_MAPS > 0
uniform mat4 u_shadow_tex[LX_MAPS]; // atlas (s, t, depth, q) <- world
varying vec4 v_shadow[LX_MAPS];
#endif
attribute vec3 a_position;
attribute vec3 a_normal;
attribute vec3 a_face_normal;
varying vec3 v_world;
varying vec3 v_normal;
varying vec3 v_face_normal;

void main()
{
	vec4 world = vec4(a_position + u_offset, 1.0);
	v_world = world.xyz;
	v_normal = a_normal;
	v_face_normal = a_face_normal;
	// only the maps this variant uses (LX_USE_i, see main.frag)
#if LX_USE_0
	v_shadow[0] = u_shadow_tex[0] * world;
#endif
#if LX_USE_1
	v_shadow[1] = u_shadow_tex[1] * world;
#endif
#if LX_USE_2
	v_shadow[2] = u_shadow_tex[2] * world;
#endif
#if LX_USE_3
	v_shadow[3] = u_shadow_tex[3] * world;
#endif
	gl_Position = u_view_proj * world;
}
