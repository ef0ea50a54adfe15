// The sum of v over a GROUP-wide workgroup, in double: halving in shared
// memory, every invocation takes part and gets the sum back.
shared double group_terms[GROUP];

double group_sum(double v)
{
    uint lid = gl_LocalInvocationID.x;
    group_terms[lid] = v;
    barrier();
    for (uint w = GROUP / 2; w > 0; w >>= 1) {
        if (lid < w)
            group_terms[lid] += group_terms[lid + w];
        barrier();
    }
    return group_terms[0];
}
