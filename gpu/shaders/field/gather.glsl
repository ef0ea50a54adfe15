#version 430
// phi at candidate points, trilinear, in double from the float nodes, in
// exactly fg_field_sample's order of operations. The host computes each
// point's cell and fractions (GLSL's double division need not be correctly
// rounded); `precise` forbids fused multiply-adds and reassociation, so
// equal node values give samples equal to the bit.
layout(local_size_x = 64) in;
layout(r32f, binding = 0) uniform readonly image3D phi;
layout(std430, binding = 0) readonly buffer Cells { int cell[]; };
layout(std430, binding = 1) readonly buffer Fractions { double frac[]; };
layout(std430, binding = 2) writeonly buffer Samples { double sample_out[]; };
layout(location = 0) uniform int count;

double node(ivec3 c, int dx, int dy, int dz)
{
    return double(imageLoad(phi, c + ivec3(dx, dy, dz)).r);
}

void main()
{
    int id = int(gl_GlobalInvocationID.x);
    if (id >= count)
        return;
    ivec3 c = ivec3(cell[3 * id], cell[3 * id + 1], cell[3 * id + 2]);
    double tx = frac[3 * id], ty = frac[3 * id + 1], tz = frac[3 * id + 2];
    precise double x00 = node(c, 0, 0, 0) + tx * (node(c, 1, 0, 0) - node(c, 0, 0, 0));
    precise double x10 = node(c, 0, 1, 0) + tx * (node(c, 1, 1, 0) - node(c, 0, 1, 0));
    precise double x01 = node(c, 0, 0, 1) + tx * (node(c, 1, 0, 1) - node(c, 0, 0, 1));
    precise double x11 = node(c, 0, 1, 1) + tx * (node(c, 1, 1, 1) - node(c, 0, 1, 1));
    precise double y0 = x00 + ty * (x10 - x00);
    precise double y1 = x01 + ty * (x11 - x01);
    precise double v = y0 + tz * (y1 - y0);
    sample_out[id] = v;
}
