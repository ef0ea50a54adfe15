// The objects' instances (picture_objects.c), eye-relative world axes:
//   sphere, rod: v0 (a, radius), v1 (b, material), v2 (albedo)
//   box, plane:  v0 (centre, material), v1..v3 (half-axes), v4 (albedo)
//   volume:      as a box (the third axis up, half the height), v0.w seed,
//                v4 (hottest colour, intensity)
//   marker:      v0 (position, radius px), v1.x sign
struct object {
    vec4 v0, v1, v2, v3, v4;
};
layout(std430, binding = 2) readonly buffer objects { object obj[]; };
uniform int u_first; // the kind's first instance
