#version 430 core
// The glow across one segment: a white-hot core inside a bluish halo,
// functions of the distance to the segment in half-widths.
in vec2 v_local;
flat in float v_length;
flat in float v_gain;
flat in float v_end_cap;
out vec4 o_color;

const vec3 CORE = vec3(1.0, 1.0, 1.0);
const vec3 HALO = vec3(0.55, 0.65, 1.0);

void main()
{
    float beyond = max(-v_local.x, v_end_cap > 0.5 ? v_local.x - v_length : 0.0);
    float d = length(vec2(max(beyond, 0.0), v_local.y));
    if (d >= 1.0)
        discard;
    float core = exp(-d * d / (2.0 * 0.18 * 0.18));
    float halo = 0.35 * (1.0 - d) * (1.0 - d);
    o_color = vec4(v_gain * (core * CORE + halo * HALO), 1.0);
}
