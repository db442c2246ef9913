#version 330 core
// A body's soft round shadow: alpha only, blended as dst *= 1 - alpha; uv is m from the foot
// of the body on the ground.
uniform float radius;    // m
uniform float strength;  // darkening at the centre, 0..1
in vec2 f_uv;
in vec3 f_world;
out vec4 colour;
void main() {
    float d = length(f_uv) / radius;
    colour = vec4(0.0, 0.0, 0.0, strength * (1.0 - smoothstep(0.25, 1.0, d)));
}
