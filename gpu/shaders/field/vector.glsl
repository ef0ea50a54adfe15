#version 430
// Node-wise vector operations on one level, chosen by op:
//   0  a = 0
//   1  a += alpha * b
//   2  a = b + alpha * a
//   3  a = 0 on free nodes (a cold start)
//   4  a = b on masked nodes (new Dirichlet values; free nodes keep a)
layout(local_size_x = 8, local_size_y = 4, local_size_z = 4) in;
layout(r32f, binding = 0) uniform image3D a;
layout(r32f, binding = 1) uniform readonly image3D b;
layout(r8ui, binding = 2) uniform readonly uimage3D mask;
layout(location = 0) uniform ivec3 n;
layout(location = 2) uniform int op;
layout(location = 4) uniform float alpha;

void main()
{
    ivec3 p = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(p, n)))
        return;
    float v = 0.0;
    if (op == 1)
        v = imageLoad(a, p).r + alpha * imageLoad(b, p).r;
    else if (op == 2)
        v = imageLoad(b, p).r + alpha * imageLoad(a, p).r;
    else if (op == 3 || op == 4) {
        if (imageLoad(mask, p).r != 0u)
            v = op == 3 ? imageLoad(a, p).r : imageLoad(b, p).r;
        else
            v = op == 3 ? 0.0 : imageLoad(a, p).r;
    }
    imageStore(a, p, vec4(v));
}
