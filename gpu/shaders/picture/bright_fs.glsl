#version 430 core
// Bright pass at half resolution: a 4-tap box down, then what lies above
// the threshold, with a soft knee so the cut leaves no edge.
#include "filter_io.inc.glsl"
uniform float u_threshold;
uniform float u_knee;
void main()
{
    vec3 c = 0.25 * (texture(u_src, v_uv + u_texel * vec2(-0.5, -0.5)).rgb +
                     texture(u_src, v_uv + u_texel * vec2(0.5, -0.5)).rgb +
                     texture(u_src, v_uv + u_texel * vec2(-0.5, 0.5)).rgb +
                     texture(u_src, v_uv + u_texel * vec2(0.5, 0.5)).rgb);
    float l = max(c.r, max(c.g, c.b));
    float soft = clamp(l - u_threshold + u_knee, 0.0, 2.0 * u_knee);
    soft = soft * soft / (4.0 * u_knee + 1e-5);
    float keep = max(soft, l - u_threshold) / max(l, 1e-5);
    o_color = vec4(c * keep, 1.0);
}
