#version 330 core
// Bodies and arrows of the 3D view. position and normal are in the mesh's own frame (m);
// `local` is the point on the mesh before any transform, so that a pattern painted from it turns
// with the body. model: mesh -> world; normal_matrix: its rotation; view_projection: world -> clip.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 local;
uniform mat4 model;
uniform mat3 normal_matrix;
uniform mat4 view_projection;
out vec3 f_normal;
out vec3 f_local;
out vec3 f_world;
void main() {
    vec4 w = model * vec4(position, 1.0);
    f_world = w.xyz;
    f_normal = normal_matrix * normal;
    f_local = local;
    gl_Position = view_projection * w;
}
