#version 330 core
// A line's colour, faded over its last pixel across (the anti-aliased fringe).
in vec4 f_colour;
in float f_across;
in float f_half;
out vec4 colour;
void main() {
    // Coverage of this pixel by the line: 1 inside, falling to 0 over the last pixel.
    float cover = clamp(f_half + 0.5 - abs(f_across), 0.0, 1.0);
    colour = vec4(f_colour.rgb, f_colour.a * cover);
}
