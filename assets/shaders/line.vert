#version 330 core
// Lines of constant pixel width: each segment a quad expanded in screen space (6 vertices a
// segment, all with the same a and b). viewport: the frame's size in pixels; depth_bias: in
// normalised depth, pulls lines in front of the faces they outline.
layout(location = 0) in vec3 a;
layout(location = 1) in vec3 b;
layout(location = 2) in vec2 corner;  // x: 0 at a, 1 at b; y: -1 or +1 across
layout(location = 3) in vec4 colour;
layout(location = 4) in float width;  // pixels
uniform mat4 view_projection;
uniform vec2 viewport;
uniform float depth_bias;
out vec4 f_colour;
out float f_across;  // pixels from the centre line
out float f_half;    // half the width, pixels
void main() {
    vec4 ca = view_projection * vec4(a, 1.0);
    vec4 cb = view_projection * vec4(b, 1.0);
    vec2 sa = ca.xy / ca.w * viewport * 0.5;
    vec2 sb = cb.xy / cb.w * viewport * 0.5;
    vec2 d = sb - sa;
    float len = length(d);
    d = len > 1e-6 ? d / len : vec2(1.0, 0.0);
    vec2 n = vec2(-d.y, d.x);
    vec4 c = corner.x < 0.5 ? ca : cb;
    // Half the width across plus a pixel of fringe (faded in the fragment shader: the edges
    // are anti-aliased without multisampling), and half the width beyond each end (square caps
    // close the corners).
    f_half = 0.5 * width;
    f_across = corner.y * (f_half + 1.0);
    vec2 offset = n * f_across + d * (corner.x < 0.5 ? -0.5 : 0.5) * width;
    c.xy += offset / (viewport * 0.5) * c.w;
    c.z -= depth_bias * c.w;
    f_colour = colour;
    gl_Position = c;
}
