#version 430 core
// The overlay image's rectangle, in pixels from the top left.
uniform vec4 u_rect;     // x, y, width, height (pixels)
uniform vec2 u_viewport;
out vec2 v_uv;

void main()
{
    int corner = gl_VertexID & 3;
    vec2 c = vec2((corner & 1) == 0 ? 0.0 : 1.0, corner >= 2 ? 1.0 : 0.0);
    v_uv = c;
    vec2 px = u_rect.xy + c * u_rect.zw;
    gl_Position = vec4(2.0 * px.x / u_viewport.x - 1.0, 1.0 - 2.0 * px.y / u_viewport.y, 0.0, 1.0);
}
