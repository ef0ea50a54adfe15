// The finite-volume 7-point Laplacian at node p of an n-node grid whose
// interior edges weigh c (area / length along each axis): the weight of
// the edge to each neighbour p + stencil_step[k], 0 where that lies
// outside the box. Edges on a box face have half the weight (Neumann), as
// in laplace.c.
const ivec3 stencil_step[6] = ivec3[6](ivec3(-1, 0, 0), ivec3(1, 0, 0), ivec3(0, -1, 0),
                                       ivec3(0, 1, 0), ivec3(0, 0, -1), ivec3(0, 0, 1));

float stencil_face(int i, int m)
{
    return (i == 0 || i == m - 1) ? 0.5 : 1.0;
}

void stencil_weights(ivec3 p, ivec3 n, vec3 c, out float w[6])
{
    float fx = stencil_face(p.x, n.x), fy = stencil_face(p.y, n.y), fz = stencil_face(p.z, n.z);
    float cx = c.x * fy * fz, cy = c.y * fx * fz, cz = c.z * fx * fy;
    w[0] = p.x > 0 ? cx : 0.0;
    w[1] = p.x < n.x - 1 ? cx : 0.0;
    w[2] = p.y > 0 ? cy : 0.0;
    w[3] = p.y < n.y - 1 ? cy : 0.0;
    w[4] = p.z > 0 ? cz : 0.0;
    w[5] = p.z < n.z - 1 ? cz : 0.0;
}
