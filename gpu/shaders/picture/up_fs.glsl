#version 430 core
// Dual-filter (Kawase) upsample: eight taps on a diamond, the result added
// (by blending) onto the finer level.
#include "filter_io.inc.glsl"
void main()
{
    vec3 c = texture(u_src, v_uv + u_texel * vec2(-2.0, 0.0)).rgb;
    c += texture(u_src, v_uv + u_texel * vec2(2.0, 0.0)).rgb;
    c += texture(u_src, v_uv + u_texel * vec2(0.0, -2.0)).rgb;
    c += texture(u_src, v_uv + u_texel * vec2(0.0, 2.0)).rgb;
    c += 2.0 * texture(u_src, v_uv + u_texel * vec2(-1.0, -1.0)).rgb;
    c += 2.0 * texture(u_src, v_uv + u_texel * vec2(1.0, -1.0)).rgb;
    c += 2.0 * texture(u_src, v_uv + u_texel * vec2(-1.0, 1.0)).rgb;
    c += 2.0 * texture(u_src, v_uv + u_texel * vec2(1.0, 1.0)).rgb;
    o_color = vec4(c / 12.0, 1.0);
}
