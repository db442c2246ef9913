#version 330 core
// The ground: a grid drawn per pixel (anti-aliased with fwidth), fading with distance into the
// paper. The bodies' soft round shadows are small quads of their own (shadow.frag), darkening it
// (a loop over the shadows in this shader made llvmpipe five times slower).
uniform vec3 paper;
uniform vec3 ground;
uniform vec3 line_colour;
uniform float spacing;     // m between minor lines
uniform float fade;        // m: the grid fades out towards this radius
in vec2 f_uv;
in vec3 f_world;
out vec4 colour;
float grid(vec2 p, float step, float width) {
    vec2 g = abs(fract(p / step - 0.5) - 0.5) / (fwidth(p / step) * width);
    return 1.0 - min(min(g.x, g.y), 1.0);
}
void main() {
    float minor = grid(f_uv, spacing, 1.0);
    float major = grid(f_uv, spacing * 5.0, 1.5);
    vec3 c = ground;
    c = mix(c, line_colour, 0.30 * minor);
    c = mix(c, line_colour, 0.60 * major);
    float r = length(f_uv) / fade;
    c = mix(c, paper, smoothstep(0.55, 1.0, r));
    colour = vec4(c, 1.0);
}
