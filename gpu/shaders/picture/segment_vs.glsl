#version 430 core
// One camera-facing quad per segment (instance), four strip vertices each.
// Positions are relative to the flash's origin; the flash state carries
// that origin relative to the eye (computed in double on the CPU), so that
// millimetre sparks and kilometre bolts keep their float precision.

struct segment {
    vec4 a;     // parent xyz (m, from the flash origin), path length there (m)
    vec4 b;     // child xyz, path length there
    vec4 shape; // half-width (m), level brightness, main (0/1), leaf (0/1)
    vec4 slot;  // flash slot, unused x3
};
struct flash_state {
    vec4 origin; // flash origin relative to the eye, world axes (m)
    vec4 gains;  // leader front (m, negative: none), leader gain, all gain, main gain
    vec4 colour; // the halo's linear RGB, the core's tint
};
layout(std430, binding = 0) readonly buffer segments { segment seg[]; };
layout(std430, binding = 1) readonly buffer flashes { flash_state fl[]; };

uniform mat3 u_view;      // world -> view rotation
uniform mat4 u_proj;
uniform float u_focal_px; // pixels per unit of x/z at the image centre
uniform float u_min_px;   // narrowest half-width drawn, pixels
uniform vec2 u_cloud;     // a cloud base's z relative to the eye (1e30: none), fade (m)

out vec2 v_local;        // (along, across) in half-widths
flat out float v_length; // segment length in half-widths
flat out float v_gain;
flat out float v_end_cap;
flat out vec3 v_halo;
flat out float v_core_tint;

void main()
{
    segment s = seg[gl_InstanceID];
    flash_state f = fl[int(s.slot.x)];
    float level = s.shape.y;
    float gain = f.gains.z * level + f.gains.w * s.shape.z * level;
    vec3 p0 = s.a.xyz, p1 = s.b.xyz;
    float end_cap = s.shape.w;
    float front = f.gains.x;
    if (front >= 0.0) {
        // The leader: segments wholly beyond the front are not there yet;
        // the one the front is crossing is drawn up to it.
        if (s.a.w >= front) {
            gain = 0.0;
        } else {
            gain += f.gains.y * level;
            if (s.b.w > front) {
                p1 = mix(p0, p1, (front - s.a.w) / (s.b.w - s.a.w));
                end_cap = 1.0;
            }
        }
    }
    // channel inside a cloud is hidden by it, fading over the first metres
    float above = 0.5 * (p0.z + p1.z) + f.origin.z - u_cloud.x;
    if (above > 0.0)
        gain *= exp(-above / u_cloud.y);
    vec3 q0 = u_view * (f.origin.xyz + p0);
    vec3 q1 = u_view * (f.origin.xyz + p1);
    vec3 d = q1 - q0;
    float len = length(d);
    vec3 dir = len > 0.0 ? d / len : vec3(1.0, 0.0, 0.0);
    vec3 mid = 0.5 * (q0 + q1);
    vec3 side = cross(dir, mid);
    float sl = length(side);
    side = sl > 1e-20 ? side / sl : vec3(-dir.y, dir.x, 0.0);
    // No narrower than u_min_px on screen: widened quads keep their energy.
    float w = s.shape.x;
    float depth = max(-mid.z, 1e-6);
    float min_w = u_min_px * depth / u_focal_px;
    if (w < min_w) {
        gain *= w / min_w;
        w = min_w;
    }
    int corner = gl_VertexID & 3;
    float across = (corner & 1) == 0 ? -1.0 : 1.0;
    bool far_end = corner >= 2;
    float along = far_end ? len / w + end_cap : -1.0;
    vec3 p = q0 + dir * (along * w) + side * (across * w);
    v_local = vec2(along, across);
    v_length = len / w;
    v_gain = gain;
    v_end_cap = end_cap;
    v_halo = f.colour.rgb;
    v_core_tint = f.colour.a;
    gl_Position = gain > 0.0 ? u_proj * vec4(p, 1.0) : vec4(2.0, 2.0, 2.0, 1.0);
}
