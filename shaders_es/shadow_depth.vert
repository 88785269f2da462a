#version 100
// Shadow pass: casters seen from the light, into one atlas region.
uniform mat4 u_light_clip; // light clip space <- object space
attribute vec3 a_position;
varying vec2 v_zw;

void main()
{
	vec4 p = u_light_clip * vec4(a_position, 1.0);
	// Casters nearer the light than the near plane are flattened onto it rather than
	// clipped ("pancaking"): still nearer than every receiver, they still cast.
	p.z = max(p.z, -p.w);
	v_zw = p.zw;
	gl_Position = p;
}
