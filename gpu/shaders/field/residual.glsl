#version 430
// out = rhs - A x on free nodes (rhs absent: zero), 0 on masked nodes.
// A x is summed as sum c (x - x_nb): the difference of two nearby floats is
// exact, so the residual of a converged float iterate is not swamped by
// the rounding of d * x - o (which put a floor near 1e-5 on the relative
// residual at 65^3).
// zero_free: read x as 0 on free nodes, so that out is b, the residual of
// phi = 0 that the relative residual is measured against.
layout(local_size_x = 8, local_size_y = 4, local_size_z = 4) in;
layout(r32f, binding = 0) uniform readonly image3D x;
layout(r32f, binding = 1) uniform readonly image3D rhs;
layout(r8ui, binding = 2) uniform readonly uimage3D mask;
layout(r32f, binding = 3) uniform writeonly image3D outv;
layout(location = 0) uniform ivec3 n;
layout(location = 1) uniform vec3 c;
layout(location = 2) uniform int zero_free;
layout(location = 3) uniform int has_rhs;

#include "stencil.inc.glsl"

float value(ivec3 q)
{
    if (zero_free != 0 && imageLoad(mask, q).r == 0u)
        return 0.0;
    return imageLoad(x, q).r;
}

void main()
{
    ivec3 p = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(p, n)))
        return;
    if (imageLoad(mask, p).r != 0u) {
        imageStore(outv, p, vec4(0.0));
        return;
    }
    float w[6];
    stencil_weights(p, n, c, w);
    float xc = value(p), ax = 0.0;
    for (int k = 0; k < 6; k++)
        if (w[k] > 0.0)
            ax += w[k] * (xc - value(p + stencil_step[k]));
    float b = has_rhs != 0 ? imageLoad(rhs, p).r : 0.0;
    imageStore(outv, p, vec4(b - ax));
}
