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
#if defined(GL_FRAGMENT_PRECISION_HIGH) && !defined(LX_FORCE_MEDIUMP)
precision highp float;
#else
precision mediump float;
#endif
// Main pass: shading and the shadow decision. With LX_DECISION defined it writes the
// decision instead of a colour: R = 1 where shadowed, G = (object id + 1) / 255, B = 1
// where the pixel ran a lookup (the variant reads a map).
// The loader compiles one variant per set of maps a frame uses: LX_USE_i is 1 for each
// map i that a draw reads.
// With no maps (method none) nothing is shadowed.
//!include depth_rgba.glsl
uniform vec3 u_color;
uniform float u_object_id;
#if LX_MAPS > 0
uniform sampler2D u_atlas;
uniform vec4 u_region[LX_MAPS]; // the rays a map serves: texture-space bounds (x0, y0, x1, y1),
                                // empty when not rendered
uniform float u_bias;           // in depth codes
varying float v_facing;         // > 0 where the face is turned towards the light
#endif
#if LX_USE_0
varying vec4 v_shadow0;
#endif
#if LX_USE_1
varying vec4 v_shadow1;
#endif
#if LX_USE_2
varying vec4 v_shadow2;
#endif
#if LX_USE_3
varying vec4 v_shadow3;
#endif
varying vec3 v_to_light; // towards the light, not normalised
varying vec3 v_normal;

#if LX_MAPS > 0
// Whether a map serves the point: in front of its light and inside its bounds.
// Written without branches, and called with constant indices only: indexing uniform
// arrays with a variable is slow or unsupported on small GPUs.
bool serves(vec3 p, float w, vec4 region)
{
	return w > 0.0 && all(greaterThanEqual(p.xy, region.xy)) && all(lessThan(p.xy, region.zw));
}
#endif

void main()
{
	float shadowed = 0.0;
#if LX_MAPS > 0
	if (v_facing <= 0.0) {
		shadowed = 1.0; // faces away from the light
	} else {
		// The first map, in order, that serves the point wins; later maps are only
		// looked at where the earlier ones fail (coherent regions skip them), then one
		// fetch. (GLSL ES 1.00 has no token pasting, so each is written out.)
		vec3 p = vec3(0.0);
		bool found = false;
#if LX_USE_0
		p = v_shadow0.xyz / v_shadow0.w;
		found = serves(p, v_shadow0.w, u_region[0]);
#endif
#if LX_USE_1
		if (!found) {
			p = v_shadow1.xyz / v_shadow1.w;
			found = serves(p, v_shadow1.w, u_region[1]);
		}
#endif
#if LX_USE_2
		if (!found) {
			p = v_shadow2.xyz / v_shadow2.w;
			found = serves(p, v_shadow2.w, u_region[2]);
		}
#endif
#if LX_USE_3
		if (!found) {
			p = v_shadow3.xyz / v_shadow3.w;
			found = serves(p, v_shadow3.w, u_region[3]);
		}
#endif
		if (found) {
			float stored = lx_decode_code(texture2D(u_atlas, p.xy));
			shadowed = lx_depth_code(p.z) > stored + u_bias ? 1.0 : 0.0;
		}
	}
#endif
#ifdef LX_DECISION
	gl_FragColor = vec4(shadowed, (u_object_id + 1.25) / 255.0, LX_USE_0 + LX_USE_1 + LX_USE_2 + LX_USE_3 > 0 ? 1.0 : 0.0,
			    1.0);
#else
	float lambert = max(dot(normalize(v_normal), normalize(v_to_light)), 0.0);
	vec3 c = u_color * (0.22 + 0.78 * lambert * (1.0 - shadowed));
	gl_FragColor = vec4(c, 1.0);
#endif
}
