#version 430 core
// The outdoors behind everything: the ground up to the horizon, a cloud
// deck over it (the storm cell, its base seen from below), a dim night sky
// brighter at the horizon, and the haze: the flashes' light that the air
// scatters towards the eye. The flashes light the ground and the clouds.
// Writes the ground's depth, so that what stands on it hides it.
#include "camera.inc.glsl"
#include "ray.inc.glsl"
#include "light.inc.glsl"
#include "noise.inc.glsl"

in vec2 v_uv;
out vec4 o_color;

uniform vec4 u_ground; // ground z, cloud base z (eye-relative), haze per m, 1: clouds
uniform vec4 u_cell;   // storm cell centre x, y (eye-relative), radius, texture scale (m)
uniform vec3 u_eye;    // the eye (world, for textures that stay put)

const vec3 ZENITH = vec3(0.0012, 0.0016, 0.0035);
const vec3 HORIZON = vec3(0.007, 0.008, 0.013);
const vec3 SOIL = vec3(0.13, 0.12, 0.10);
const float CLOUD_ALBEDO = 0.55;

vec3 sky(vec3 d)
{
    return mix(HORIZON, ZENITH, sqrt(clamp(d.z, 0.0, 1.0)));
}

void main()
{
    vec3 d = ray_dir();
    float scale = u_cell.w;
    float far = 40.0 * scale;
    float t_ground = d.z < 0.0 && u_ground.x < 0.0 ? u_ground.x / d.z : 1e30;
    float t_cloud = 1e30;
    if (u_ground.w > 0.0 && d.z * u_ground.y > 0.0)
        t_cloud = u_ground.y / d.z;
    vec3 colour = sky(d);
    float t_end = far;
    float depth = 1.0;
    if (t_ground < t_cloud && t_ground < far) {
        vec3 p = t_ground * d;
        vec2 w = (u_eye.xy + p.xy) / (0.08 * scale);
        vec3 albedo = SOIL * (0.6 + 0.8 * fbm(vec3(w, 0.5), 3));
        vec3 lit = albedo * (irradiance(p, vec3(0, 0, 1), 0.0) / PI + 0.5 * HORIZON);
        // the far ground fades into the horizon's glow
        colour = mix(HORIZON, lit, exp(-t_ground / (12.0 * scale)));
        t_end = t_ground;
        depth = depth_of(p);
    } else if (t_cloud < far) {
        vec3 p = t_cloud * d;
        vec2 w = (u_eye.xy + p.xy) / (0.5 * scale);
        float cover = smoothstep(0.32, 0.62, fbm(vec3(w, 1.5), 4));
        float r = length(p.xy - u_cell.xy) / u_cell.z;
        cover *= 1.0 - smoothstep(0.55, 1.0, r);
        vec3 n = vec3(0.0, 0.0, -sign(u_ground.y));
        vec3 lit = CLOUD_ALBEDO * (irradiance(p, n, 1.0) / PI + 0.4 * HORIZON) *
                   (0.7 + 0.6 * fbm(vec3(w * 2.7, 3.5), 2));
        colour = mix(colour, lit, cover * exp(-t_cloud / (12.0 * scale)));
        t_end = t_cloud;
    }
    colour += inscatter(d, t_end, u_ground.z);
    o_color = vec4(colour, 1.0);
    gl_FragDepth = depth;
}
