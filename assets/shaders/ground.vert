#version 330 core
// The ground plane and the bodies' shadows: a quad of plane coordinates uv (m) about `origin`,
// along the unit vectors axis_u and axis_v (world).
layout(location = 0) in vec2 uv;  // plane coordinates, m
uniform vec3 origin;
uniform vec3 axis_u;
uniform vec3 axis_v;
uniform mat4 view_projection;
out vec2 f_uv;
out vec3 f_world;
void main() {
    f_uv = uv;
    f_world = origin + uv.x * axis_u + uv.y * axis_v;
    gl_Position = view_projection * vec4(f_world, 1.0);
}
