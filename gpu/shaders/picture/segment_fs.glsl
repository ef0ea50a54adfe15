#version 430 core
// The glow across one segment: a white-hot core, tinted by the halo's
// colour (a glow discharge's more than a spark's), inside the coloured halo (the flash's: nitrogen's violet-blue by
// default), functions of the distance to the segment in half-widths.
in vec2 v_local;
flat in float v_length;
flat in float v_gain;
flat in float v_end_cap;
flat in vec3 v_halo;
flat in float v_core_tint; // how much of the halo's colour the core keeps
out vec4 o_color;


void main()
{
    float beyond = max(-v_local.x, v_end_cap > 0.5 ? v_local.x - v_length : 0.0);
    float d = length(vec2(max(beyond, 0.0), v_local.y));
    if (d >= 1.0)
        discard;
    float core = exp(-d * d / (2.0 * 0.18 * 0.18));
    float halo = 0.35 * (1.0 - d) * (1.0 - d);
    o_color = vec4(v_gain * (core * mix(vec3(1.0), v_halo, v_core_tint) + halo * v_halo), 1.0);
}
