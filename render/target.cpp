#include "render/target.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace collide::render {

namespace {

void require_complete(const Gl& gl, const char* what) {
    const GLenum status = gl.CheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error(std::string(what) + " framebuffer incomplete (status " + std::to_string(status) + ")");
}

}  // namespace

RenderTarget::RenderTarget(const Gl& gl, int width, int height, int samples) : gl_(gl), width_(width), height_(height) {
    GLint max_size = 0, max_samples = 0;
    gl_.GetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
    if (width < 1 || height < 1 || width > max_size || height > max_size)
        throw std::runtime_error("frame size " + std::to_string(width) + "x" + std::to_string(height) +
                                 " is outside 1.." + std::to_string(max_size) + " pixels");
    gl_.GetIntegerv(GL_MAX_SAMPLES, &max_samples);
    samples_ = samples > 1 ? std::min(samples, static_cast<int>(max_samples)) : 0;
    if (samples_ < 2) samples_ = 0;

    // The single-sample framebuffer: the resolve target, or the drawing target without MSAA.
    gl_.GenRenderbuffers(1, &colour_);
    gl_.BindRenderbuffer(GL_RENDERBUFFER, colour_);
    gl_.RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    gl_.GenFramebuffers(1, &fbo_);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, fbo_);
    gl_.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_);
    if (samples_ == 0) {
        gl_.GenRenderbuffers(1, &depth_);
        gl_.BindRenderbuffer(GL_RENDERBUFFER, depth_);
        gl_.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
        gl_.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depth_);
    }
    require_complete(gl_, "the frame's");

    if (samples_ > 0) {
        gl_.GenRenderbuffers(1, &msaa_colour_);
        gl_.BindRenderbuffer(GL_RENDERBUFFER, msaa_colour_);
        gl_.RenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_RGBA8, width, height);
        gl_.GenRenderbuffers(1, &msaa_depth_);
        gl_.BindRenderbuffer(GL_RENDERBUFFER, msaa_depth_);
        gl_.RenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_DEPTH24_STENCIL8, width, height);
        gl_.GenFramebuffers(1, &msaa_fbo_);
        gl_.BindFramebuffer(GL_FRAMEBUFFER, msaa_fbo_);
        gl_.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, msaa_colour_);
        gl_.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, msaa_depth_);
        require_complete(gl_, "the multisampled");
    }
    check_gl(gl_, "creating the render target");
}

RenderTarget::~RenderTarget() {
    const GLuint fbos[] = {msaa_fbo_, fbo_};
    const GLuint rbs[] = {msaa_colour_, msaa_depth_, colour_, depth_};
    gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl_.DeleteFramebuffers(2, fbos);
    gl_.DeleteRenderbuffers(4, rbs);
}

void RenderTarget::bind() {
    resolved_ = false;
    gl_.BindFramebuffer(GL_FRAMEBUFFER, samples_ > 0 ? msaa_fbo_ : fbo_);
    gl_.Viewport(0, 0, width_, height_);
}

void RenderTarget::resolve() { resolve(0, 0, width_, height_); }

void RenderTarget::resolve(int x, int y, int w, int h) {
    if (samples_ > 0 && !resolved_) {
        gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, msaa_fbo_);
        gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo_);
        gl_.BlitFramebuffer(x, y, x + w, y + h, x, y, x + w, y + h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    }
    bind_resolved();
}

void RenderTarget::bind_resolved() {
    resolved_ = true;
    gl_.BindFramebuffer(GL_FRAMEBUFFER, fbo_);
    gl_.Viewport(0, 0, width_, height_);
}

void RenderTarget::read_rgba(std::uint8_t* out) {
    resolve();
    gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
    gl_.ReadBuffer(GL_COLOR_ATTACHMENT0);
    gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl_.ReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, out);
    check_gl(gl_, "reading the frame back");
    // Bottom-up to top-down.
    const std::size_t row = static_cast<std::size_t>(width_) * 4;
    std::vector<std::uint8_t> tmp(row);
    for (int y = 0; y < height_ / 2; ++y) {
        std::uint8_t* a = out + static_cast<std::size_t>(y) * row;
        std::uint8_t* b = out + static_cast<std::size_t>(height_ - 1 - y) * row;
        std::memcpy(tmp.data(), a, row);
        std::memcpy(a, b, row);
        std::memcpy(b, tmp.data(), row);
    }
}

}  // namespace collide::render
