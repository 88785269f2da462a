#version 100
#if defined(GL_FRAGMENT_PRECISION_HIGH) && !defined(LX_FORCE_MEDIUMP)
precision highp float;
#else
precision mediump float;
#endif
// Main pass: shading and the shadow decision. With LX_DECISION defined it writes the
// decision instead of a colour: R = 1 where shadowed, G = (object id + 1) / 255.
// With no maps (method none) nothing is shadowed.
//!include depth_rgba.glsl
uniform vec4 u_light; // xyz: position (w = 1) or direction of travel (w = 0)
uniform vec3 u_color;
uniform float u_object_id;
#if LX_MAPS > 0
uniform sampler2D u_atlas;
uniform vec4 u_region[LX_MAPS]; // the rays a map serves: texture-space bounds (x0, y0, x1, y1),
                                // empty when not rendered
uniform vec3 u_edges[LX_MAPS * 4]; // and inside them a x + b y + c >= 0 (a table top's edges;
                                   // (0, 0, 1) where unused)
uniform float u_bias;           // in depth codes
varying vec4 v_shadow[LX_MAPS];
#endif
varying vec3 v_world;
varying vec3 v_normal;
varying vec3 v_face_normal;

#if LX_MAPS > 0
// 1.0 when map i serves the point and a caster is nearer the light; 0.0 when lit;
// -1.0 when the map does not serve the point.
float lookup(vec4 s, int i)
{
	if (s.w <= 0.0)
		return -1.0;
	vec3 p = s.xyz / s.w;
	vec4 region = u_region[i];
	if (p.x < region.x || p.y < region.y || p.x >= region.z || p.y >= region.w)
		return -1.0;
	for (int k = 0; k < 4; k++) {
		vec3 e = u_edges[i * 4 + k];
		if (e.x * p.x + e.y * p.y + e.z < 0.0)
			return -1.0;
	}
	float stored = lx_decode_code(texture2D(u_atlas, p.xy));
	return lx_depth_code(p.z) > stored + u_bias ? 1.0 : 0.0;
}
#endif

void main()
{
	vec3 to_light = u_light.w > 0.5 ? u_light.xyz - v_world : -u_light.xyz;
	float shadowed = 0.0;
#if LX_MAPS > 0
	if (dot(v_face_normal, to_light) <= 0.0) {
		shadowed = 1.0; // faces away from the light
	} else {
		// the first map that holds the point decides
		for (int i = 0; i < LX_MAPS; i++) {
			float r = lookup(v_shadow[i], i);
			if (r >= 0.0) {
				shadowed = r;
				break;
			}
		}
	}
#endif
#ifdef LX_DECISION
	gl_FragColor = vec4(shadowed, (u_object_id + 1.25) / 255.0, 0.0, 1.0);
#else
	float lambert = max(dot(normalize(v_normal), normalize(to_light)), 0.0);
	vec3 c = u_color * (0.22 + 0.78 * lambert * (1.0 - shadowed));
	gl_FragColor = vec4(c, 1.0);
#endif
}
