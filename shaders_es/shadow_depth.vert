#version 100
// Shadow pass: casters seen from the light, into one atlas region.
uniform mat4 u_light_clip; // light clip space <- object space
uniform float u_pancake;   // 1: flatten casters nearer than the near plane; 0: clip them
attribute vec3 a_position;
varying vec2 v_zw;

void main()
{
	vec4 p = u_light_clip * vec4(a_position, 1.0);
	// Casters nearer the light than the near plane are flattened onto it rather than
	// clipped ("pancaking"): still nearer than every receiver, they still cast. Only in
	// front of the light (w > 0): a vertex behind it (a plane map's w = 0 plane cuts
	// through the scene) moved to z = -w would drag its edges' depth beyond the far
	// plane, and the far clip would cut away the part in front.
	// Exact only when all of a triangle is in front of the near plane, so only for the
	// maps whose near plane can cut casters (u_pancake).
	if (p.w > 0.0)
		p.z = mix(p.z, max(p.z, -p.w), u_pancake);
	v_zw = p.zw;
	gl_Position = p;
}
