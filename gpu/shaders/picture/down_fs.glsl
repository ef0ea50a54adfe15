#version 430 core
// Dual-filter (Kawase) downsample: the centre and four diagonal taps.
#include "filter_io.inc.glsl"
void main()
{
    vec3 c = 4.0 * texture(u_src, v_uv).rgb;
    c += texture(u_src, v_uv + u_texel * vec2(-1.0, -1.0)).rgb;
    c += texture(u_src, v_uv + u_texel * vec2(1.0, -1.0)).rgb;
    c += texture(u_src, v_uv + u_texel * vec2(-1.0, 1.0)).rgb;
    c += texture(u_src, v_uv + u_texel * vec2(1.0, 1.0)).rgb;
    o_color = vec4(c / 8.0, 1.0);
}
