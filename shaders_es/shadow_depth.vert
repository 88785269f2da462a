#version 100
// Shadow pass: casters seen from the light, into one atlas region.
uniform mat4 u_light_clip; // light clip space <- object space
attribute vec3 a_position;
varying vec2 v_zw;

void main()
{
	vec4 p = u_light_clip * vec4(a_position, 1.0);
	v_zw = p.zw;
	gl_Position = p;
}
