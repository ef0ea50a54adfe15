#version 430 core
// The marker's disc: red with a "+" for a positive charge, blue with a "-"
// for a negative one, grey for none; a dark rim keeps it readable over a
// flash. Colours are sRGB: it is drawn over the tonemapped frame.
in vec2 v_px;
flat in float v_radius;
flat in float v_sign;
out vec4 o_color;

void main()
{
    float d = length(v_px);
    float inside = clamp(v_radius - d + 0.5, 0.0, 1.0);
    if (inside <= 0.0)
        discard;
    vec3 fill = v_sign > 0.5 ? vec3(0.86, 0.16, 0.12)
              : v_sign < -0.5 ? vec3(0.15, 0.38, 0.92) : vec3(0.6);
    float rim = clamp(d - (v_radius - 2.0) + 0.5, 0.0, 1.0);
    vec3 c = mix(fill, vec3(0.05), rim);
    float bar = 0.55 * v_radius, thick = max(1.0, 0.14 * v_radius);
    float glyph = (abs(v_px.y) < thick && abs(v_px.x) < bar) ? 1.0 : 0.0;
    if (v_sign > 0.5 && abs(v_px.x) < thick && abs(v_px.y) < bar)
        glyph = 1.0;
    c = mix(c, vec3(1.0), glyph);
    o_color = vec4(c, inside);
}
