// The ray through a fragment (after camera.inc.glsl).
// The unit ray through this fragment, eye-relative world axes.
vec3 ray_dir()
{
    vec2 ndc = 2.0 * gl_FragCoord.xy / u_viewport - 1.0;
    return normalize(transpose(u_view) * vec3(ndc / u_lens, -1.0));
}
