// The frame's camera, as the scene passes share it. Positions are relative
// to the eye, along the world's axes; u_view turns them into view space.
uniform mat3 u_view;     // world -> view rotation
uniform mat4 u_proj;
uniform vec2 u_lens;     // focal / aspect, focal: view x/z, y/z to NDC
uniform vec2 u_viewport; // pixels

// The depth buffer's value of an eye-relative point.
float depth_of(vec3 q)
{
    vec4 c = u_proj * vec4(u_view * q, 1.0);
    return clamp(0.5 * c.z / c.w + 0.5, 0.0, 1.0);
}
