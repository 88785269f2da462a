/* RGBA8 depth encoding, the CPU mirror of shaders_es/depth_rgba.glsl.
 *
 * ES 2.0 boards may lack depth textures, so light depth d in [0, 1] is stored in an
 * RGBA8 colour texel as a 24-bit integer n = min(floor(d * (2^24 - 1)), 2^24 - 1):
 *   R = n >> 16, G = (n >> 8) & 255, B = n & 255, A = 255 (written here; the shadow
 *   pass writes the drawing object's id there, shadow_depth.frag).
 * - d = 1.0 (the far plane) encodes as 0xFFFFFF, the same as the clear colour
 *   (1, 1, 1, 1): far never wraps to 0. d > 1 and NaN clamp to far, d < 0 to 0.
 * - Each byte b is written as (b + 0.25) / 255, so the driver's float-to-unorm8
 *   conversion yields b whether it rounds (b + 0.25 -> b) or truncates.
 * - Every step is exact in IEEE single precision (integers below 2^24, divisions by
 *   powers of two), so a highp fragment shader and this code agree bit for bit.
 *   Worst-case error of encode/decode is one 24-bit step (2^-24 of the depth range).
 * - The shader compares depths as integers n, never as decoded fractions.
 *
 * A GPU without highp fragment floats (Mali-400: fp16, 11-bit mantissa) cannot hold
 * 2^24 exactly. The shaders' mediump path keeps 11 bits, q = floor(d * 2047), written
 * in the same layout (n = q * 8192: R = q >> 3, G = (q & 7) << 5, B = 255) and compared
 * as q; lx_depth_encode_rgba8_fp16() mirrors it with every step rounded to fp16. */
#ifndef LX_DEPTH_RGBA_H
#define LX_DEPTH_RGBA_H
#include <stdbool.h>
#include <stdint.h>

#define LX_DEPTH_MAX_CODE 16777215u /* 2^24 - 1: the far plane */

enum lx_unorm_conversion { LX_UNORM_ROUND, LX_UNORM_TRUNCATE };

/* The 24-bit code of depth d, computed in single precision as the shader does. */
uint32_t lx_depth_code(double d);
/* Encode as the shader does and convert to bytes as a driver would. */
void lx_depth_encode_rgba8(double d, enum lx_unorm_conversion conv, uint8_t out[4]);
uint32_t lx_depth_decode_code(const uint8_t in[4]);
/* The mediump path with fp16 arithmetic emulated: the 11-bit code q, and the texel. */
uint32_t lx_depth_code_fp16(double d);
void lx_depth_encode_rgba8_fp16(double d, enum lx_unorm_conversion conv, uint8_t out[4]);
/* The 11-bit code the mediump path decodes from a texel. */
uint32_t lx_depth_decode_code_fp16(const uint8_t in[4]);
/* Rounds to the nearest IEEE half-precision value (11 significant bits, ties to even,
 * infinite past 65504, denormals below 2^-14). */
float lx_fp16(float x);
/* a / b as an fp16 shader computes it: a true divide, or (rcp) a * (1 / b), each step
 * rounded to fp16. */
float lx_fp16_div(float a, float b);
float lx_fp16_rcp_mul(float a, float b);
/* The mediump path's code of a projected depth z / w (the texture coordinate's depth
 * over its q, as the main pass divides it), with either divide. */
uint32_t lx_depth_code_fp16_projected(float z, float w, bool rcp);
double lx_depth_decode_rgba8(const uint8_t in[4]);

#endif
