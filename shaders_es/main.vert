#version 100
#ifndef LX_SHADOWED
#define LX_SHADOWED 0
#endif
#ifndef LX_READS
#define LX_READS 0
#endif
// Main pass. LX_SHADOWED: the method has shadow maps (the face test); LX_READS (0 to 4):
// how many of them a draw reads, their matrices in the first slots in the maps' order
// (one variant serves every set of that many maps), a varying each and no more: every
// varying costs an interpolation per pixel.
uniform mat4 u_view_proj;
uniform vec3 u_offset; // object translation in world space
uniform vec4 u_light;  // xyz: position (w = 1) or direction of travel (w = 0)
#if LX_READS > 0
uniform mat4 u_shadow_tex[LX_READS]; // atlas (s, t, depth, q) <- world, per map read
#endif
#if LX_SHADOWED
// Which side of its face a point is on, as seen from the light: affine in the position,
// so one interpolated float is exact where the face normal and the light would be three.
varying float v_facing;
#endif
#if LX_READS > 0
varying vec4 v_shadow0;
#endif
#if LX_READS > 1
varying vec4 v_shadow1;
#endif
#if LX_READS > 2
varying vec4 v_shadow2;
#endif
#if LX_READS > 3
varying vec4 v_shadow3;
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

void main()
{
	vec4 world = vec4(a_position + u_offset, 1.0);
	v_to_light = u_light.w > 0.5 ? u_light.xyz - world.xyz : -u_light.xyz;
	v_normal = a_normal;
#ifdef LX_PROJECTIVE
	v_beam = u_beam * world;
#endif
#if LX_SHADOWED
	v_facing = dot(a_face_normal, v_to_light);
#endif
#if LX_READS > 0
	v_shadow0 = u_shadow_tex[0] * world;
#endif
#if LX_READS > 1
	v_shadow1 = u_shadow_tex[1] * world;
#endif
#if LX_READS > 2
	v_shadow2 = u_shadow_tex[2] * world;
#endif
#if LX_READS > 3
	v_shadow3 = u_shadow_tex[3] * world;
#endif
	gl_Position = u_view_proj * world;
}
