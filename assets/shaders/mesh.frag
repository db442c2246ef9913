#version 330 core
// Bodies and arrows, lit as a textbook figure: mostly their flat colour, a key light, a fill
// light and a small highlight. eye is a point (m, world); key_light and fill_light are unit
// vectors towards the lights (world). pattern 1: a sphere's wedges.
uniform vec3 base;
uniform int pattern;
uniform vec3 eye;
uniform vec3 key_light;
uniform vec3 fill_light;
in vec3 f_normal;
in vec3 f_local;
in vec3 f_world;
out vec4 colour;
void main() {
    vec3 n = normalize(f_normal);
    vec3 v = normalize(eye - f_world);
    if (dot(n, v) < 0.0) n = -n;
    vec3 c = base;
    // A sphere's wedges (like a beach ball) make its spin visible.
    if (pattern == 1 && f_local.x * f_local.z > 0.0) c *= 0.80;
    float key = max(dot(n, key_light), 0.0);
    float fill = max(dot(n, fill_light), 0.0);
    float sky = 0.5 + 0.5 * n.y;
    // Bright and soft, as in a textbook figure: the outlines carry the shape.
    vec3 lit = c * (0.78 + 0.25 * key + 0.05 * fill);
    vec3 h = normalize(key_light + v);
    lit += vec3(0.12) * pow(max(dot(n, h), 0.0), 40.0);
    colour = vec4(min(lit, vec3(1.0)), 1.0);
}
