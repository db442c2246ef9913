#include "present/frame_spec.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "present/figures.h"
#include "scenario/input_error.h"
#include "teach/notation.h"

namespace collide {

namespace {

const char* const kCommand = "";  // option errors name the option, not a file

std::string num(double x) { return notation::num_data(x); }

// The named values of an option: the names CLI11 lists, and what each means.
template <class T>
struct Choice {
    const char* name;
    T value;
};

const Choice<Quality> kQualities[] = {
    {"low", Quality::low()}, {"medium", Quality::medium()}, {"high", Quality::high()}};
const Choice<render::ViewKind> kViews[] = {{"2d", render::ViewKind::diagram}, {"3d", render::ViewKind::perspective}};
const Choice<std::optional<render::VideoFormat>> kFormats[] = {
    {"png", std::nullopt}, {"mp4", render::VideoFormat::mp4}, {"gif", render::VideoFormat::gif}};
const char* const kBackends[] = {"osmesa", "egl"};  // render::parse_gl_backend reads them

template <class T, std::size_t N>
const T* find_choice(const Choice<T> (&choices)[N], const std::string& name) {
    for (const Choice<T>& c : choices)
        if (name == c.name) return &c.value;
    return nullptr;
}

template <class T, std::size_t N>
std::vector<std::string> names(const Choice<T> (&choices)[N]) {
    std::vector<std::string> out;
    for (const Choice<T>& c : choices) out.push_back(c.name);
    return out;
}

}  // namespace

Quality Quality::low() { return {0, 0, false, {1, true, false}, 1}; }
Quality Quality::medium() { return {}; }  // the members' defaults
Quality Quality::high() { return {0, 4, true, {6, false, false}, 2}; }

std::string VideoRequest::file_name() const {
    return format == render::VideoFormat::mp4 ? "animation.mp4" : "animation.gif";
}

const RenderChoices& render_choices() {
    static const RenderChoices choices{
        names(kQualities), names(kViews), names(kFormats), {std::begin(kBackends), std::end(kBackends)}};
    return choices;
}

bool parse_render_size(const std::string& text, int* width, int* height) {
    static const std::pair<const char*, std::pair<int, int>> presets[] = {
        {"480p", {854, 480}}, {"720p", {1280, 720}}, {"1080p", {1920, 1080}}, {"1440p", {2560, 1440}}};
    for (const auto& [name, size] : presets)
        if (text == name) {
            *width = size.first;
            *height = size.second;
            return true;
        }
    int w = 0, h = 0;
    char x = 0, extra = 0;
    if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X')) return false;
    if (w < 16 || h < 16 || w > 8192 || h > 8192) return false;
    *width = w;
    *height = h;
    return true;
}

void read_render_size(const std::string& text, int* width, int* height) {
    if (!parse_render_size(text, width, height))
        throw InputError(kCommand, {}, "--size",
                         "expected WxH (16..8192 pixels each) or 480p, 720p, 1080p, 1440p, got '" + text + "'");
}

std::optional<render::ViewKind> read_view(const std::string& text) {
    if (text.empty()) return std::nullopt;
    if (const render::ViewKind* view = find_choice(kViews, text)) return *view;
    throw InputError(kCommand, {}, "--view", "expected 2d or 3d, got '" + text + "'");
}

double read_fps(double fps) {
    if (!(fps > 0 && fps <= 100000))
        throw InputError(kCommand, {}, "--fps", "expected frames per simulated second in (0, 100000], got " + num(fps));
    return fps;
}

FrameSpec read_frame_spec(const std::string& size, double fps, const std::string& quality, const std::string& view) {
    FrameSpec frame;
    read_render_size(size, &frame.width, &frame.height);
    frame.fps = read_fps(fps);
    frame.quality = read_quality(quality);
    frame.view = read_view(view);
    return frame;
}

Quality read_quality(const std::string& name) {
    if (const Quality* q = find_choice(kQualities, name)) return *q;
    throw InputError(kCommand, {}, "--quality", "expected low, medium or high, got '" + name + "'");
}

render::GlBackend read_backend(const std::string& name) {
    render::GlBackend backend;
    if (!render::parse_gl_backend(name, &backend))
        throw InputError(kCommand, {}, "--backend", "expected osmesa or egl (when built), got '" + name + "'");
    return backend;
}

std::optional<VideoRequest> read_format(const std::string& name) {
    const std::optional<render::VideoFormat>* format = find_choice(kFormats, name);
    if (!format) throw InputError(kCommand, {}, "--format", "expected png, mp4 or gif, got '" + name + "'");
    if (!*format) return std::nullopt;
    VideoRequest video{**format, render::find_program("ffmpeg")};
    if (video.ffmpeg.empty())
        throw InputError(kCommand, {}, "--format",
                         name +
                             " is made by ffmpeg, which is not installed (Debian: "
                             "apt-get install ffmpeg); --format png writes the frames alone");
    return video;
}

render::RenderSettings frame_settings(const FrameSpec& frame, const Scene& scene, const SceneView& view,
                                      const render::FormulaText* formula) {
    const render::ViewKind kind =
        frame.view.value_or(scene.dimension == 3 ? render::ViewKind::perspective : render::ViewKind::diagram);
    const bool three_d = kind == render::ViewKind::perspective;
    render::RenderSettings settings;
    settings.width = frame.width;
    settings.height = frame.height;
    settings.samples = three_d ? frame.quality.samples_3d : frame.quality.samples_2d;
    settings.smooth = frame.quality.smooth;
    settings.view = kind;
    // Time with enough decimals to change from frame to frame.
    settings.time_decimals = std::clamp(static_cast<int>(std::ceil(std::log10(std::max(1.0, frame.fps)))), 1, 4);
    if (formula) settings.formula = *formula;
    settings.camera = {view.camera_azimuth, view.camera_elevation, view.camera_target, view.camera_distance};
    settings.points = points_of(view);
    return settings;
}

}  // namespace collide
