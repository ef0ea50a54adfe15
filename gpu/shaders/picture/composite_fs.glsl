#version 430 core
// The frame: scene + bloom + sky, exposure, the ACES filmic fit
// (Narkowicz 2015), then the sRGB transfer function, into 8 bits.
in vec2 v_uv;
uniform sampler2D u_scene;
uniform sampler2D u_bloom;
uniform float u_bloom_strength;
uniform float u_exposure;
uniform vec3 u_background;
out vec4 o_color;

vec3 aces(vec3 x)
{
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

vec3 srgb(vec3 c)
{
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
}

void main()
{
    vec3 c = texture(u_scene, v_uv).rgb + u_bloom_strength * texture(u_bloom, v_uv).rgb;
    c = u_exposure * (c + u_background);
    o_color = vec4(srgb(aces(c)), 1.0);
}
