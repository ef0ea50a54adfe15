#version 430 core
// A flame, marched through its bounding box (drawn with its back faces, so
// that it shows from inside too) and added to the frame: a plume that
// narrows to a flickering tip, its outline and density stirred by noise
// rising with time, white-yellow where hottest and redder as it rises and
// cools, with a blue foot where the fuel meets the air.
#include "camera.inc.glsl"
#include "ray.inc.glsl"
#include "object.inc.glsl"
#include "noise.inc.glsl"

in vec3 v_pos;
flat in int v_instance;
out vec4 o_color;

uniform float u_time;

const int STEPS = 28;
const float BOUND = 1.25;   // the box's half width over the base radius
const float GLOW = 1.6;     // emission per base radius at intensity 1

void main()
{
    object o = obj[v_instance];
    vec3 c = o.v0.xyz, up = o.v3.xyz;
    float half_h = length(up);
    up /= half_h;
    vec3 ex = normalize(o.v1.xyz), ey = normalize(o.v2.xyz);
    float radius = length(o.v1.xyz) / BOUND, height = 2.0 * half_h;
    vec3 base = c - half_h * up;
    vec3 d = ray_dir();
    // the ray's span inside the box (slabs along its three axes)
    float t0 = 0.0, t1 = 1e30;
    vec3 axes[3] = vec3[3](ex, ey, up);
    vec3 half_ext = vec3(BOUND * radius, BOUND * radius, half_h);
    for (int k = 0; k < 3; k++) {
        float dc = dot(c, axes[k]), dd = dot(d, axes[k]);
        if (abs(dd) < 1e-12) {
            if (abs(dc) > half_ext[k])
                discard;
            continue;
        }
        float a = (dc - half_ext[k]) / dd, b = (dc + half_ext[k]) / dd;
        t0 = max(t0, min(a, b));
        t1 = min(t1, max(a, b));
    }
    if (t1 <= t0)
        discard;
    float dt = (t1 - t0) / float(STEPS);
    vec3 hot = o.v4.rgb; // Planck's colour of the hottest part (picture_timeline.c)
    vec3 sum = vec3(0.0);
    float seed = o.v0.w * 7.31;
    for (int i = 0; i < STEPS; i++) {
        vec3 p = (t0 + (float(i) + 0.5) * dt) * d - base;
        float h = dot(p, up) / height;
        vec2 r2 = vec2(dot(p, ex), dot(p, ey)) / radius;
        if (h <= 0.0 || h >= 1.0)
            continue;
        vec3 q = vec3(r2 * 1.7, h * 3.0 - u_time * 2.2) + seed;
        float n = fbm(q, 3);
        // the outline: full at the foot, narrowing to a tip, stirred
        float width = (0.55 + 0.55 * sqrt(h) * (1.0 - h) * 2.0) * pow(1.0 - h, 0.6) * (0.75 + 0.5 * n);
        float rr = length(r2 + 0.25 * h * vec2(n - 0.5, 0.0));
        float dens = smoothstep(width, 0.45 * width, rr) * (1.0 - h);
        vec3 colour = mix(hot, hot * vec3(1.0, 0.42, 0.12), smoothstep(0.1, 0.9, h));
        colour += vec3(0.15, 0.3, 1.0) * (1.0 - smoothstep(0.0, 0.12, h)) * 0.6;
        sum += colour * dens;
    }
    o_color = vec4(o.v4.a * GLOW * sum * dt / radius, 1.0);
}
