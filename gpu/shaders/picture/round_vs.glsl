#version 430 core
// Spheres and rods (capsules), ray-traced in round_fs: here only a quad
// that covers the object's outline. It lies across the view through the
// object's middle, long along the axis' projection, grown by how much
// nearer the object's nearest point is than its middle (perspective); an
// object the eye is in or touching covers the whole view.
#include "camera.inc.glsl"
#include "object.inc.glsl"

flat out vec3 v_a;
flat out vec3 v_b;
flat out float v_radius;
flat out float v_material;
flat out vec3 v_albedo;

void main()
{
    object o = obj[u_first + gl_InstanceID];
    v_a = o.v0.xyz;
    v_b = o.v1.xyz;
    v_radius = o.v0.w;
    v_material = o.v1.w;
    v_albedo = o.v2.rgb;
    int corner = gl_VertexID & 3;
    vec2 c = vec2((corner & 1) == 0 ? -1.0 : 1.0, corner >= 2 ? 1.0 : -1.0);
    vec3 mid = 0.5 * (v_a + v_b);
    float dm = length(mid);
    vec3 m = mid / max(dm, 1e-30);
    float near = min(dot(v_a, m), dot(v_b, m)) - v_radius;
    if (!(near > 1e-3 * dm)) {
        gl_Position = vec4(c, 0.0, 1.0);
        return;
    }
    vec3 axis = (v_b - v_a) - dot(v_b - v_a, m) * m;
    float la = length(axis);
    vec3 along = la > 1e-6 * dm ? axis / la : normalize(cross(m, abs(m.z) < 0.9 ? vec3(0, 0, 1) : vec3(1, 0, 0)));
    vec3 across = cross(m, along);
    float grow = dm / near;
    vec3 p = mid + grow * (c.x * (0.5 * la + v_radius) * along + c.y * v_radius * across);
    gl_Position = u_proj * vec4(u_view * p, 1.0);
}
