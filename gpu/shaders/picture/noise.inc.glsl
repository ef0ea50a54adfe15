// Value noise from an integer hash of the lattice point (the spatial hash
// primes of Teschner et al. 2003, then a multiply-xorshift finaliser), and
// its fractal sum.
float lattice(ivec3 c)
{
    uint h = (uint(c.x) * 73856093u) ^ (uint(c.y) * 19349663u) ^ (uint(c.z) * 83492791u);
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return float(h & 0xffffffu) / 16777215.0;
}

// Smoothly interpolated lattice values, 0..1.
float value_noise(vec3 p)
{
    vec3 i = floor(p), f = p - i;
    vec3 u = f * f * (3.0 - 2.0 * f);
    ivec3 c = ivec3(i);
    float x00 = mix(lattice(c), lattice(c + ivec3(1, 0, 0)), u.x);
    float x10 = mix(lattice(c + ivec3(0, 1, 0)), lattice(c + ivec3(1, 1, 0)), u.x);
    float x01 = mix(lattice(c + ivec3(0, 0, 1)), lattice(c + ivec3(1, 0, 1)), u.x);
    float x11 = mix(lattice(c + ivec3(0, 1, 1)), lattice(c + ivec3(1, 1, 1)), u.x);
    return mix(mix(x00, x10, u.y), mix(x01, x11, u.y), u.z);
}

// octaves of value noise, each twice as fine and half as strong: 0..1.
float fbm(vec3 p, int octaves)
{
    float sum = 0.0, amp = 0.5, norm = 0.0;
    for (int i = 0; i < octaves; i++) {
        sum += amp * value_noise(p);
        norm += amp;
        p = p * 2.03 + vec3(17.1, 5.3, 11.7);
        amp *= 0.5;
    }
    return sum / norm;
}
