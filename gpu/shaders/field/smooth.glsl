#version 430
// One Gauss-Seidel half-sweep of the finite-volume 7-point Laplacian over
// the nodes of one colour ((i + j + k) % 2 == color), in place: a node of
// one colour reads only neighbours of the other, so the dispatch has no
// races. x = (rhs + sum c x_nb) / sum c on free nodes; masked nodes keep x.
layout(local_size_x = 8, local_size_y = 4, local_size_z = 4) in;
layout(r32f, binding = 0) uniform image3D x;
layout(r32f, binding = 1) uniform readonly image3D rhs;
layout(r8ui, binding = 2) uniform readonly uimage3D mask;
layout(location = 0) uniform ivec3 n;
layout(location = 1) uniform vec3 c;
layout(location = 2) uniform int color;
layout(location = 3) uniform int has_rhs;

#include "stencil.inc.glsl"

void main()
{
    ivec3 g = ivec3(gl_GlobalInvocationID);
    ivec3 p = ivec3(2 * g.x + ((color + g.y + g.z) & 1), g.y, g.z);
    if (any(greaterThanEqual(p, n)) || imageLoad(mask, p).r != 0u)
        return;
    float w[6];
    stencil_weights(p, n, c, w);
    float d = 0.0, o = 0.0;
    for (int k = 0; k < 6; k++) {
        if (w[k] > 0.0) {
            d += w[k];
            o += w[k] * imageLoad(x, p + stencil_step[k]).r;
        }
    }
    float b = has_rhs != 0 ? imageLoad(rhs, p).r : 0.0;
    imageStore(x, p, vec4((b + o) / d));
}
