#version 430 core
// A charge's marker: a disc of a fixed size in pixels at the charge's
// place, over the finished frame. Behind the eye: not drawn.
#include "camera.inc.glsl"
#include "object.inc.glsl"

out vec2 v_px;           // from the centre, pixels
flat out float v_radius; // pixels
flat out float v_sign;

void main()
{
    object o = obj[u_first + gl_InstanceID];
    v_radius = o.v0.w;
    v_sign = o.v1.x;
    int corner = gl_VertexID & 3;
    vec2 c = vec2((corner & 1) == 0 ? -1.0 : 1.0, corner >= 2 ? 1.0 : -1.0);
    vec4 clip = u_proj * vec4(u_view * o.v0.xyz, 1.0);
    float reach = v_radius + 1.5;
    v_px = c * reach;
    if (clip.w <= 0.0) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        return;
    }
    vec2 ndc = clip.xy / clip.w + 2.0 * v_px / u_viewport;
    gl_Position = vec4(ndc, 0.0, 1.0);
}
