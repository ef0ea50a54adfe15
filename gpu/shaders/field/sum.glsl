#version 430
// Second stage of a dot product: one workgroup sums the partial sums.
#define GROUP 256
layout(local_size_x = GROUP) in;
layout(std430, binding = 0) readonly buffer Partials { double partial[]; };
layout(std430, binding = 1) writeonly buffer Result { double result; };
layout(location = 0) uniform int count;

#include "group_sum.inc.glsl"

void main()
{
    uint lid = gl_LocalInvocationID.x;
    double sum = 0.0;
    for (int i = int(lid); i < count; i += GROUP)
        sum += partial[i];
    double summed = group_sum(sum);
    if (lid == 0)
        result = summed;
}
