// How the objects' materials answer the light (after light.inc.glsl):
// 0 metal, 1 matte, 2 glass. What a mirror sees: indoors a dim room,
// brighter from above, with a lamp high to one side (a polished ball or a
// glass globe shows its highlight); outdoors the night sky above a dark
// ground.
const float GLASS_SCATTER = 0.02; // the share of light the glass sends back diffusely
const vec3 LAMP = vec3(-0.45, -0.55, 0.70); // towards the lamp, about unit

vec3 surroundings(vec3 r)
{
    if (u_outdoor != 0)
        return r.z > 0.0 ? vec3(0.004, 0.005, 0.009) : vec3(0.0015);
    float lamp = pow(max(dot(r, LAMP), 0.0), 40.0);
    return u_ambient * (0.5 + clamp(0.5 + 0.5 * r.z, 0.0, 1.0) + 30.0 * lamp);
}

// Radiance towards the eye (v: unit, from p to the eye) of a surface at p
// with unit normal n.
vec3 shade(vec3 p, vec3 n, vec3 v, float material, vec3 albedo)
{
    float shine = material < 0.5 ? 60.0 : 400.0;
    vec3 diffuse = vec3(0.0), specular = vec3(0.0);
    for (int i = 0; i < u_light_count; i++) {
        vec3 l = u_light_pos[i].xyz - p;
        float s = u_light_pos[i].w;
        float d2 = dot(l, l);
        vec3 ld = l * inversesqrt(max(d2, 1e-30));
        vec3 e = u_light_col[i].rgb / (d2 + s * s);
        float c = dot(n, ld);
        diffuse += e * (material > 1.5 ? abs(c) : max(c, 0.0));
        float spec = pow(max(dot(n, normalize(ld + v)), 0.0), shine) * (shine + 8.0) / (8.0 * PI);
        specular += e * max(c, 0.0) * spec;
    }
    vec3 r = reflect(-v, n);
    float fresnel = pow(1.0 - clamp(dot(n, v), 0.0, 1.0), 5.0);
    if (material < 0.5) { // metal: a coloured mirror, a little diffuse
        vec3 f = albedo + (1.0 - albedo) * fresnel;
        return f * (specular + surroundings(r)) + 0.12 * albedo * (diffuse / PI + u_ambient);
    }
    if (material < 1.5) // matte
        return albedo * (diffuse / PI + u_ambient);
    float f = 0.04 + 0.96 * fresnel; // glass: drawn additively over what lies behind
    return albedo * (f * (specular + surroundings(r)) + GLASS_SCATTER * diffuse / PI);
}
