// The frame's lights: the discharges lit now (points along their channels)
// and the flames. Intensity is irradiance times m^2, softened within each
// light's radius: E = I cos / (d^2 + s^2).
const float PI = 3.14159265;
uniform int u_light_count;
uniform vec4 u_light_pos[32]; // eye-relative world xyz, softening radius (m)
uniform vec4 u_light_col[32]; // linear RGB intensity
uniform vec3 u_ambient;       // radiance of the room around, lighting every surface
uniform int u_outdoor;        // 1: under the night sky

// Irradiance at p facing n. wrap 0: Lambert; wrap 1: light from any side
// counts half (a cloud, frosted glass).
vec3 irradiance(vec3 p, vec3 n, float wrap)
{
    vec3 e = vec3(0.0);
    for (int i = 0; i < u_light_count; i++) {
        vec3 l = u_light_pos[i].xyz - p;
        float s = u_light_pos[i].w;
        float d2 = dot(l, l);
        float c = dot(n, l) * inversesqrt(max(d2, 1e-30));
        c = (c + wrap) / (1.0 + wrap);
        e += u_light_col[i].rgb * max(c, 0.0) / (d2 + s * s);
    }
    return e;
}

// What the air between the eye and t_max along the unit ray d scatters
// towards the eye, sigma per metre (isotropic): the integral of
// I / ((t - t0)^2 + h^2) over t is atan((t - t0) / h) / h.
vec3 inscatter(vec3 d, float t_max, float sigma)
{
    vec3 sum = vec3(0.0);
    for (int i = 0; i < u_light_count; i++) {
        vec3 l = u_light_pos[i].xyz;
        float s = u_light_pos[i].w;
        float t0 = dot(l, d);
        float h = sqrt(max(dot(l, l) - t0 * t0, 0.0) + s * s);
        sum += u_light_col[i].rgb * (atan((t_max - t0) / h) + atan(t0 / h)) / h;
    }
    return sum * sigma / (4.0 * PI);
}
