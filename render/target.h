// A render target: where one frame is drawn (colour + depth), optionally multisampled, and how
// its pixels come back to memory.
//
//   samples > 1: colour and depth in multisampled renderbuffers (4x at most on llvmpipe);
//                read_rgba resolves them into a single-sample framebuffer with glBlitFramebuffer
//                first (that resolve is most of the cost of anti-aliasing: about 8 ms at 720p).
//   samples <= 1: drawn straight into the single-sample framebuffer.
#pragma once

#include <cstdint>

#include "render/gl.h"

namespace collide::render {

class RenderTarget {
public:
    // Needs a current context; throws std::runtime_error if the framebuffer is incomplete.
    RenderTarget(const Gl& gl, int width, int height, int samples);
    ~RenderTarget();
    RenderTarget(const RenderTarget&) = delete;
    RenderTarget& operator=(const RenderTarget&) = delete;

    int width() const { return width_; }
    int height() const { return height_; }
    int samples() const { return samples_; }  // what the driver gave (0: none)

    // Starts a frame: binds it for drawing (the multisampled buffers, if any), with the
    // viewport covering it.
    void bind();
    // Multisampled: resolves the samples into the single-sample framebuffer, which takes the
    // drawing from here on (the 2D overlays, anti-aliased by their own feathered edges, cost
    // a quarter as much there). Without multisampling: nothing to do.
    void resolve();
    // Only the rectangle x, y, w, h (pixels, OpenGL's bottom-left origin) of the samples.
    void resolve(int x, int y, int w, int h);
    // Binds the single-sample framebuffer for drawing: what resolve() writes into. What is
    // drawn there before a bind() and resolve(rect) stays outside that rectangle.
    void bind_resolved();
    // Resolves and reads the frame as RGBA bytes, top row first (OpenGL's rows run bottom-up;
    // they are flipped here): width * height * 4 bytes into out.
    void read_rgba(std::uint8_t* out);

private:
    const Gl& gl_;
    int width_, height_, samples_ = 0;
    bool resolved_ = false;                                   // since the last bind()
    GLuint msaa_fbo_ = 0, msaa_colour_ = 0, msaa_depth_ = 0;  // when multisampled
    GLuint fbo_ = 0, colour_ = 0, depth_ = 0;                 // single-sample
};

}  // namespace collide::render
