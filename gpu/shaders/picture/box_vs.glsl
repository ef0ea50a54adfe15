#version 430 core
// Boxes and planes (and a flame's bounding box): 36 vertices an instance,
// six faces of two triangles, counter-clockwise seen from outside.
#include "camera.inc.glsl"
#include "object.inc.glsl"

out vec3 v_pos;            // eye-relative world
flat out vec3 v_normal;    // the face's outward normal
flat out vec3 v_albedo;
flat out float v_material;
flat out int v_instance;

const ivec2 CORNERS[6] = ivec2[6](ivec2(-1, -1), ivec2(1, -1), ivec2(1, 1),
                                  ivec2(-1, -1), ivec2(1, 1), ivec2(-1, 1));

void main()
{
    v_instance = u_first + gl_InstanceID;
    object o = obj[v_instance];
    vec3 ax[3] = vec3[3](o.v1.xyz, o.v2.xyz, o.v3.xyz);
    int face = gl_VertexID / 6, axis = face / 2;
    float s = (face & 1) == 0 ? 1.0 : -1.0;
    ivec2 k = CORNERS[gl_VertexID % 6];
    float su = s * float(k.x), sv = float(k.y); // mirrored on the far face: same winding outside
    int u = (axis + 1) % 3, v = (axis + 2) % 3;
    v_pos = o.v0.xyz + s * ax[axis] + su * ax[u] + sv * ax[v];
    vec3 n = length(ax[axis]) > 0.0 ? ax[axis] : cross(ax[u], ax[v]);
    v_normal = s * normalize(n);
    v_albedo = o.v4.rgb;
    v_material = o.v0.w;
    gl_Position = u_proj * vec4(u_view * v_pos, 1.0);
}
