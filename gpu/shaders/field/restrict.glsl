#version 430
// Full weighting: the coarse right-hand side from the fine residual, the
// transpose of the trilinear prolongation (weight 1/2 per axis offset, only
// fine nodes inside the box), zero on masked coarse nodes.
layout(local_size_x = 8, local_size_y = 4, local_size_z = 4) in;
layout(r32f, binding = 0) uniform readonly image3D fine;
layout(r8ui, binding = 2) uniform readonly uimage3D coarse_mask;
layout(r32f, binding = 3) uniform writeonly image3D coarse;
layout(location = 0) uniform ivec3 n;      // coarse size
layout(location = 1) uniform ivec3 nf;     // fine size

void main()
{
    ivec3 P = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(P, n)))
        return;
    float s = 0.0;
    if (imageLoad(coarse_mask, P).r == 0u) {
        ivec3 f = 2 * P;
        for (int dk = -1; dk <= 1; dk++) {
            int k = f.z + dk;
            if (k < 0 || k >= nf.z)
                continue;
            float plane = 0.0;
            for (int dj = -1; dj <= 1; dj++) {
                int j = f.y + dj;
                if (j < 0 || j >= nf.y)
                    continue;
                float row = 0.0;
                for (int di = -1; di <= 1; di++) {
                    int i = f.x + di;
                    if (i < 0 || i >= nf.x)
                        continue;
                    row += (di == 0 ? 1.0 : 0.5) * imageLoad(fine, ivec3(i, j, k)).r;
                }
                plane += (dj == 0 ? 1.0 : 0.5) * row;
            }
            s += (dk == 0 ? 1.0 : 0.5) * plane;
        }
    }
    imageStore(coarse, P, vec4(s));
}
