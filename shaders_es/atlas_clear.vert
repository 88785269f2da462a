#version 100
// Sets an atlas region and its guard ring to "far" before its shadow pass: a quad over
// the viewport at the far plane. (llvmpipe clears a scissored rectangle by a slow path,
// about a fifth of a millisecond each; this draw costs its fill.)
attribute vec2 a_position; // the viewport's corners, -1 or 1

void main()
{
	gl_Position = vec4(a_position, 1.0, 1.0); // depth 1: the far plane
}
