// What a filter pass over the viewport triangle (quad_vs.glsl) reads and
// writes: the source texture and its texel, the colour out.
in vec2 v_uv;
uniform sampler2D u_src;
uniform vec2 u_texel; // 1 / source size
out vec4 o_color;
