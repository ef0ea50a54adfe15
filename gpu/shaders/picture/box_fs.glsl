#version 430 core
// A face of a box or plane, shaded by its material (glass additively).
#include "camera.inc.glsl"
#include "light.inc.glsl"
#include "shade.inc.glsl"

in vec3 v_pos;
flat in vec3 v_normal;
flat in vec3 v_albedo;
flat in float v_material;
out vec4 o_color;

void main()
{
    vec3 v = normalize(-v_pos);
    vec3 n = dot(v_normal, v) < 0.0 ? -v_normal : v_normal;
    o_color = vec4(shade(v_pos, n, v, v_material, v_albedo), 1.0);
}
