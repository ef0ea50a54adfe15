#version 430
// First stage of a dot product over a level-0 vector pair: each workgroup
// sums ITEMS * 256 products in double and writes one partial sum.
#define GROUP 256
#define ITEMS 16
layout(local_size_x = GROUP) in;
layout(r32f, binding = 0) uniform readonly image3D a;
layout(r32f, binding = 1) uniform readonly image3D b;
layout(std430, binding = 0) writeonly buffer Partials { double partial[]; };
layout(location = 0) uniform ivec3 n;

#include "group_sum.inc.glsl"

void main()
{
    uint lid = gl_LocalInvocationID.x;
    uint total = uint(n.x) * uint(n.y) * uint(n.z);
    uint base = gl_WorkGroupID.x * uint(GROUP * ITEMS) + lid;
    double sum = 0.0;
    for (int it = 0; it < ITEMS; it++) {
        uint id = base + uint(it * GROUP);
        if (id >= total)
            break;
        uint nxy = uint(n.x) * uint(n.y);
        ivec3 p = ivec3(id % uint(n.x), (id / uint(n.x)) % uint(n.y), id / nxy);
        sum += double(imageLoad(a, p).r) * double(imageLoad(b, p).r);
    }
    double summed = group_sum(sum);
    if (lid == 0)
        partial[gl_WorkGroupID.x] = summed;
}
