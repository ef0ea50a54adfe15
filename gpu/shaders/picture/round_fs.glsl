#version 430 core
// A sphere or a rod (a capsule: a cylinder with round ends) hit by this
// fragment's ray, shaded by its material, at its true depth. Glass is
// drawn additively after the segments; from inside a glass sphere the far
// side is what the ray meets.
#include "camera.inc.glsl"
#include "ray.inc.glsl"
#include "light.inc.glsl"
#include "shade.inc.glsl"

flat in vec3 v_a;
flat in vec3 v_b;
flat in float v_radius;
flat in float v_material;
flat in vec3 v_albedo;
out vec4 o_color;

// The ray t d (t > 0) against the sphere at c: the nearer hit, or the far
// one from inside. Keeps the smaller of it and *t.
void sphere(vec3 c, float r, vec3 d, inout float t, inout vec3 n)
{
    float b = dot(c, d);
    float h = b * b - (dot(c, c) - r * r);
    if (h < 0.0)
        return;
    float s = sqrt(h);
    float hit = b - s > 0.0 ? b - s : b + s;
    if (hit > 0.0 && hit < t) {
        t = hit;
        n = (hit * d - c) / r;
    }
}

// The ray against the rod's side: a point whose projection on the axis
// falls between the ends, at distance r from it (a quadratic in t).
void side(vec3 a, vec3 b, float r, vec3 d, inout float t, inout vec3 n)
{
    vec3 ba = b - a, oa = -a;
    float baba = dot(ba, ba);
    if (baba < 1e-12 * r * r)
        return;
    float bard = dot(ba, d), baoa = dot(ba, oa);
    float qa = baba - bard * bard;
    float qb = baba * dot(oa, d) - baoa * bard;
    float qc = baba * dot(oa, oa) - baoa * baoa - r * r * baba;
    float h = qb * qb - qa * qc;
    if (h < 0.0 || qa <= 0.0)
        return;
    float hit = (-qb - sqrt(h)) / qa;
    float y = baoa + hit * bard;
    if (hit > 0.0 && hit < t && y > 0.0 && y < baba) {
        t = hit;
        n = (oa + hit * d - ba * (y / baba)) / r;
    }
}

void main()
{
    vec3 d = ray_dir();
    float t = 1e30;
    vec3 n = vec3(0.0, 0.0, 1.0);
    side(v_a, v_b, v_radius, d, t, n);
    sphere(v_a, v_radius, d, t, n);
    sphere(v_b, v_radius, d, t, n);
    if (t >= 1e30)
        discard;
    vec3 q = t * d;
    n = normalize(n);
    if (dot(n, d) > 0.0)
        n = -n; // seen from inside
    o_color = vec4(shade(q, n, -d, v_material, v_albedo), 1.0);
    gl_FragDepth = depth_of(q);
}
