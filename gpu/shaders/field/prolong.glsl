#version 430
// fine += P coarse on free fine nodes: trilinear interpolation of the
// coarse correction (a fine node at an even index sits on a coarse node).
layout(local_size_x = 8, local_size_y = 4, local_size_z = 4) in;
layout(r32f, binding = 0) uniform image3D fine;
layout(r32f, binding = 1) uniform readonly image3D coarse;
layout(r8ui, binding = 2) uniform readonly uimage3D fine_mask;
layout(location = 0) uniform ivec3 n;      // fine size

void main()
{
    ivec3 p = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(p, n)) || imageLoad(fine_mask, p).r != 0u)
        return;
    ivec3 a = p >> 1, b = (p + 1) >> 1;
    float v = imageLoad(coarse, ivec3(a.x, a.y, a.z)).r + imageLoad(coarse, ivec3(b.x, a.y, a.z)).r +
              imageLoad(coarse, ivec3(a.x, b.y, a.z)).r + imageLoad(coarse, ivec3(b.x, b.y, a.z)).r +
              imageLoad(coarse, ivec3(a.x, a.y, b.z)).r + imageLoad(coarse, ivec3(b.x, a.y, b.z)).r +
              imageLoad(coarse, ivec3(a.x, b.y, b.z)).r + imageLoad(coarse, ivec3(b.x, b.y, b.z)).r;
    imageStore(fine, p, vec4(imageLoad(fine, p).r + 0.125 * v));
}
