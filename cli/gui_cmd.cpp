#include "cli/gui_cmd.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "present/gui_model.h"
#include "scenario/input_error.h"
#include "scenario/lesson.h"
#include "present/figures.h"
#include "present/frame_spec.h"
#include "present/render_job.h"
#include "render/png.h"
#include "render/renderer.h"
#include "render/window.h"

#ifdef COLLIDE_HAVE_GLFW
#include <imgui.h>

#include "render/window_controls.h"
#endif

namespace collide {

namespace {

const char* const kCommand = "";  // option errors name the option

// The options, the script and the scene, read before any window: bad input is exit code 2
// (file, line and word named) with or without a display, with or without GLFW. The frames
// are as collide render draws them at its default quality.
bool read_gui_input(const GuiOptions& o, std::ostream& err, FrameSpec* frame, std::vector<GuiAction>* script) {
    try {
        read_render_size(o.size, &frame->width, &frame->height);
        if (!(o.fps > 0 && o.fps <= 1000))
            throw InputError(kCommand, {}, "--fps", "expected frames per simulated second in (0, 1000]");
        frame->fps = o.fps;
        frame->view = read_view(o.view);
        if (!o.script.empty()) *script = parse_gui_script(o.script);
        load_scenario(o.scenario);
    } catch (const InputError& e) {
        err << "collide: error: " << e.what() << "\n";
        return false;
    }
    return true;
}

}  // namespace

#ifndef COLLIDE_HAVE_GLFW

int run_gui(const GuiOptions& o, std::ostream&, std::ostream& err) {
    FrameSpec frame;
    std::vector<GuiAction> script;
    if (!read_gui_input(o, err, &frame, &script)) return 2;
    err << "collide gui: " << render::window_support() << "\n";
    return 1;
}

#else

namespace {

constexpr int kPanelWidth = 390;  // px, the controls beside the frame
constexpr int kMinHeight = 720;   // px: room for every control beside a small frame

// The UI font's glyphs: Latin-1, Greek (e, mu, omega), sub- and superscripts, arrows, math.
const ImWchar kUiGlyphs[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2070, 0x209F, 0x2190, 0x21FF, 0x2200, 0x22FF, 0};

const char* kSpeeds[] = {"1 (real time)", "0.5", "0.25", "0.1", "0.05"};
const double kSpeedValues[] = {1.0, 0.5, 0.25, 0.1, 0.05};
const char* kModels[] = {"frictionless", "coulomb", "matrix", "stick", "page-listing", "routh"};  // Model order
const char* kPolicies[] = {"sequential", "simultaneous"};

std::string fixed(double x, int decimals) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, x);
    return buf;
}

// Everything the window shows for one scene: the model, the renderer drawing its frames, the
// texture the frame is shown from.
class Session {
public:
    Session(render::Window& window, const FrameSpec& frame, const std::string& scenario)
        : window_(window), frame_(frame) {
        scene_source_ = load_scenario(scenario, &view_, &lesson_);
        id_ = lesson_ ? lesson_->id : scenario;
        if (const auto slash = id_.find_last_of('/'); slash != std::string::npos) id_ = id_.substr(slash + 1);
        if (const auto dot = id_.rfind(".toml"); dot != std::string::npos) id_ = id_.substr(0, dot);
        model_ = std::make_unique<GuiModel>(scene_source_, frame.fps, Rerun::background);
        rebuild_renderer();
    }

    GuiModel& model() { return *model_; }
    GuiToggles& toggles() { return toggles_; }
    const std::string& id() const { return id_; }
    const std::string& title() const { return scene_source_.title; }
    const std::optional<Lesson>& lesson() const { return lesson_; }
    const render::RenderSettings& settings() const { return settings_; }
    const std::vector<std::uint8_t>& rgba() const { return rgba_; }
    // The frame as the window shows it, behind the controls.
    void draw_frame_behind() const { image_.draw_behind(settings_.width, settings_.height); }

    // Takes a re-run that has finished (the edits run on the model's worker), its frames or its
    // error; true when there was one (the renderer then follows the run shown).
    bool poll() {
        if (!model_->poll()) return false;
        rebuild_renderer();
        return true;
    }

    // After a new run or a change of the panels shown: the settings, the formula and the
    // framing follow the scene of the run shown (the edited scene once its run has finished).
    void rebuild_renderer() {
        const Scene& scene = model_->shown_scene();
        const std::optional<render::FormulaText> formula = first_collision_formula(scene, model_->run());
        settings_ = frame_settings(frame_, scene, view_, formula ? &*formula : nullptr);
        settings_.header = toggles_.header;
        settings_.table = toggles_.table;
        settings_.plots = toggles_.plots;
        settings_.timeline = toggles_.timeline;
        if (!camera_) {  // the scenario's camera, or the renderer's default angles, to orbit from
            camera_ = settings_.camera;
            const int d = scene.dimension;
            if (!camera_->azimuth) camera_->azimuth = render::default_azimuth(d);
            if (!camera_->elevation) camera_->elevation = render::default_elevation(d);
        }
        settings_.camera = *camera_;
        renderer_ = std::make_unique<render::Renderer>(window_, scene, settings_);
        renderer_->prepare(model_->frames(), model_->impacts());
        dirty_ = true;
    }

    void mark_dirty() { dirty_ = true; }

    bool perspective() const { return settings_.view == render::ViewKind::perspective; }
    // The 3D view's camera: dragged by (dx, dy) pixels, zoomed by wheel steps.
    void orbit(float dx, float dy, float wheel) { turn(-0.4 * dx, 0.4 * dy, std::pow(1.1, wheel)); }
    // Turned right and up by degrees, the distance divided by `zoom` (the script's orbit, zoom).
    void turn(double right, double up, double zoom) {
        if (!perspective() || (right == 0 && up == 0 && zoom == 1)) return;
        camera_->azimuth = std::fmod(*camera_->azimuth + right, 360.0);
        camera_->elevation = std::clamp(*camera_->elevation + up, -89.0, 89.0);
        camera_->zoom = std::clamp(camera_->zoom * zoom, 0.2, 8.0);
        settings_.camera = *camera_;  // the figure's panels too
        renderer_->set_camera(*camera_);
        renderer_->prepare(model_->frames(), model_->impacts());
        dirty_ = true;
    }

    // Draws the frame at the playback time when something changed, into the texture.
    void update_frame() {
        if (!dirty_ && shown_index_ == model_->index()) return;
        rgba_.resize(static_cast<std::size_t>(settings_.width) * settings_.height * 4);
        renderer_->render(model_->display_frame(), toggles_.decor, rgba_.data());
        image_.upload(settings_.width, settings_.height, rgba_.data());
        shown_index_ = model_->index();
        dirty_ = false;
    }

    std::string save_frame(const std::string& path) {
        update_frame();
        render::write_png_atomic(path, settings_.width, settings_.height, rgba_.data());
        return path;
    }

    // False when the run has no collision.
    bool save_figure(const std::string& path) {
        const std::optional<render::Image> figure =
            first_collision_figure(window_, model_->shown_scene(), view_, settings_, model_->run());
        window_.use_default_framebuffer();
        if (!figure) return false;
        render::write_png_atomic(path, figure->width, figure->height, figure->rgba.data());
        return true;
    }

private:
    render::Window& window_;
    FrameSpec frame_;
    Scene scene_source_;
    SceneView view_;
    std::optional<Lesson> lesson_;
    std::string id_;
    std::unique_ptr<GuiModel> model_;
    GuiToggles toggles_;
    std::optional<render::CameraRequest> camera_;  // kept across rebuilds
    render::RenderSettings settings_;
    std::unique_ptr<render::Renderer> renderer_;
    std::vector<std::uint8_t> rgba_;
    render::WindowImage image_{window_};
    bool dirty_ = true;
    std::size_t shown_index_ = static_cast<std::size_t>(-1);
};

struct Ui {
    bool help = false;
    int speed = 0;
    std::string status;  // the last thing done ("saved ...")
    int saved = 0;       // frames saved, for their names
};

// Under a frame shorter than the window: the keys, and what was done last.
void draw_keys(const Ui& ui, bool perspective, int y, int width, int height) {
    ImGui::SetNextWindowPos(ImVec2(0, static_cast<float>(y)));
    ImGui::SetNextWindowSize(ImVec2(static_cast<float>(width), static_cast<float>(height)));
    ImGui::Begin("keys", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings);
    ImGui::TextWrapped("Space play / pause    → ← one frame    N next collision    Home the start    S slower");
    ImGui::TextWrapped("R reset    F save the frame    G save the figure    H help    Q quit");
    if (perspective) ImGui::TextWrapped("Drag over the frame to turn the camera; the wheel zooms.");
    ImGui::TextWrapped(
        "Every change re-runs the scene from t = 0, in the background (the frame stays the last complete "
        "run's until then): the frame is the one collide render draws.");
    if (!ui.status.empty() && ui.status != "save-frame" && ui.status != "save-figure")
        ImGui::TextWrapped("%s", ui.status.c_str());
    ImGui::End();
}

// The controls beside the frame. An edit starts a re-run on the model's worker (the renderer
// follows when it has finished: Session::poll). Returns true when the panels shown changed so
// that the renderer must be rebuilt.
bool draw_panel(Session& s, Ui& ui, int x, int height, const std::vector<std::string>& lesson_ids,
                std::string* switch_to, bool* quit) {
    GuiModel& m = s.model();
    bool rebuild = false;
    ImGui::SetNextWindowPos(ImVec2(static_cast<float>(x), 0));
    ImGui::SetNextWindowSize(ImVec2(static_cast<float>(kPanelWidth), static_cast<float>(height)));
    ImGui::Begin("Collide", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
    ImGui::TextWrapped("%s", s.title().c_str());
    // Scene picker: the bundled lessons.
    if (!lesson_ids.empty()) {
        int current = -1;
        for (std::size_t k = 0; k < lesson_ids.size(); ++k)
            if (lesson_ids[k] == s.id()) current = static_cast<int>(k);
        // Scenario files show as scenes/NAME.
        const auto label = [](const std::string& id) {
            const auto slash = id.find_last_of('/');
            return slash == std::string::npos ? id : "scenes/" + id.substr(slash + 1, id.size() - slash - 6);
        };
        const std::string preview = current >= 0 ? label(lesson_ids[static_cast<std::size_t>(current)]) : s.id();
        if (ImGui::BeginCombo("scene", preview.c_str())) {
            for (std::size_t k = 0; k < lesson_ids.size(); ++k)
                if (ImGui::Selectable(label(lesson_ids[k]).c_str(), static_cast<int>(k) == current))
                    *switch_to = lesson_ids[k];
            ImGui::EndCombo();
        }
    }
    ImGui::Separator();

    // Playback.
    const double duration = m.frames().back().t;
    ImGui::Text("t = %s s of %s s", fixed(m.time(), 3).c_str(), fixed(duration, 3).c_str());
    if (ImGui::Button(m.playing ? "Pause" : "Play")) m.playing = !m.playing;
    ImGui::SameLine();
    if (ImGui::Button("|<")) m.seek_index(0);
    ImGui::SameLine();
    if (ImGui::Button("< back")) m.step(-1);
    ImGui::SameLine();
    if (ImGui::Button("step >")) m.step(1);
    ImGui::SameLine();
    if (ImGui::Button("next collision")) {
        if (!m.next_collision()) ui.status = "no collision after this frame";
    }
    float t = static_cast<float>(m.time());
    if (ImGui::SliderFloat("time (s)", &t, 0.0f, static_cast<float>(duration), "%.3f")) m.seek_time(t);
    if (ImGui::Combo("speed", &ui.speed, kSpeeds, IM_ARRAYSIZE(kSpeeds))) m.speed = kSpeedValues[ui.speed];
    // The run shown, or while a change re-runs the scene (on the worker), how far that run got:
    // one line either way, so that the controls below stay where they are.
    if (m.running()) {
        const double length = m.scene().duration, reached = m.run_progress() * length;
        const std::string text = fixed(reached, 3) + " s of " + fixed(length, 3) + " s";
        // A bar as tall as a line of text, its label beside it on the same baseline.
        ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(ImGui::GetStyle().FramePadding.x, 0.0f));
        ImGui::ProgressBar(static_cast<float>(m.run_progress()),
                           ImVec2(ImGui::CalcItemWidth(), ImGui::GetTextLineHeight()), text.c_str());
        ImGui::PopStyleVar();
        ImGui::SameLine(0.0f, ImGui::GetStyle().ItemInnerSpacing.x);
        ImGui::TextUnformatted("re-running");
    } else {
        ImGui::Text("%zu collision%s in the run", m.impacts().size(), m.impacts().size() == 1 ? "" : "s");
    }
    ImGui::Separator();

    // Physics: scene-wide.
    const Scene& sc = m.scene();
    float e = static_cast<float>(sc.restitution);
    if (ImGui::SliderFloat("e (restitution)", &e, 0.0f, 1.0f, "%.2f")) {
        m.set_restitution(e);
    }
    float mu = static_cast<float>(sc.friction);
    if (ImGui::SliderFloat("\u03bc (friction)", &mu, 0.0f, 1.5f, "%.2f")) {
        m.set_friction(mu);
    }
    int model = static_cast<int>(sc.model);
    if (ImGui::Combo("model", &model, kModels, IM_ARRAYSIZE(kModels))) {
        m.set_model(static_cast<Model>(model));
    }
    int policy = static_cast<int>(sc.policy);
    if (ImGui::Combo("contacts", &policy, kPolicies, IM_ARRAYSIZE(kPolicies))) {
        m.set_policy(static_cast<Policy>(policy));
    }

    // Bodies.
    for (std::size_t i = 0; i < sc.bodies.size(); ++i) {
        const SceneBody& b = sc.bodies[i];
        if (b.is_static()) continue;
        ImGui::PushID(static_cast<int>(i));
        if (ImGui::CollapsingHeader(b.name.c_str())) {
            double mass = render::body_mass(sc, i);
            if (ImGui::InputDouble("mass (kg)", &mass, 0.0, 0.0, "%.4g", ImGuiInputTextFlags_EnterReturnsTrue) &&
                mass > 0) {
                m.set_mass(i, mass);
            }
            // Size: the shape scaled about its centre (mass kept).
            for (const double k : {0.8, 1.25}) {
                if (ImGui::Button(k < 1 ? "smaller (\u00d70.8)" : "bigger (\u00d71.25)")) {
                    m.scale_size(i, k);
                }
                ImGui::SameLine();
            }
            ImGui::Text("size");
            const int d = sc.dimension;
            double v[3] = {d == 1   ? b.body1.v
                           : d == 2 ? b.body2.v.x()
                                    : b.body3.v.x(),
                           d == 2   ? b.body2.v.y()
                           : d == 3 ? b.body3.v.y()
                                    : 0.0,
                           d == 3 ? b.body3.v.z() : 0.0};
            if (ImGui::InputScalarN("v (m/s)", ImGuiDataType_Double, v, d, nullptr, nullptr, "%.4g",
                                    ImGuiInputTextFlags_EnterReturnsTrue)) {
                m.set_velocity(i, Vec3(v[0], v[1], v[2]));
            }
            if (d == 2) {
                double w = b.body2.w;
                if (ImGui::InputDouble("\u03c9 (rad/s)", &w, 0.0, 0.0, "%.4g", ImGuiInputTextFlags_EnterReturnsTrue)) {
                    m.set_spin(i, Vec3(0, 0, w));
                }
            } else if (d == 3) {
                double w[3] = {b.body3.w.x(), b.body3.w.y(), b.body3.w.z()};
                if (ImGui::InputScalarN("\u03c9 (rad/s)", ImGuiDataType_Double, w, 3, nullptr, nullptr, "%.4g",
                                        ImGuiInputTextFlags_EnterReturnsTrue)) {
                    m.set_spin(i, Vec3(w[0], w[1], w[2]));
                }
            }
        }
        ImGui::PopID();
    }
    if (ImGui::Button("Reset the scene")) {
        m.reset();
    }
    if (!m.error().empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.8f, 0.1f, 0.1f, 1.0f));
        ImGui::TextWrapped("The world refuses this change: %s", m.error().c_str());
        ImGui::PopStyleColor();
    }
    ImGui::Separator();

    // What the frame shows.
    GuiToggles& tg = s.toggles();
    bool decor_changed = false;
    decor_changed |= ImGui::Checkbox("velocities", &tg.decor.velocities);
    ImGui::SameLine();
    decor_changed |= ImGui::Checkbox("impulses", &tg.decor.impacts);
    ImGui::SameLine();
    decor_changed |= ImGui::Checkbox("trails", &tg.decor.trails);
    decor_changed |= ImGui::Checkbox("labels", &tg.decor.labels);
    ImGui::SameLine();
    decor_changed |= ImGui::Checkbox("centres", &tg.decor.com);
    ImGui::SameLine();
    decor_changed |= ImGui::Checkbox("+ directions", &tg.decor.directions);
    rebuild |= ImGui::Checkbox("header", &tg.header);
    ImGui::SameLine();
    rebuild |= ImGui::Checkbox("table", &tg.table);
    ImGui::SameLine();
    rebuild |= ImGui::Checkbox("plots", &tg.plots);
    ImGui::SameLine();
    rebuild |= ImGui::Checkbox("time line", &tg.timeline);
    if (decor_changed) s.mark_dirty();
    ImGui::Separator();

    if (ImGui::Button("Save frame (F)")) ui.status = "save-frame";
    ImGui::SameLine();
    if (ImGui::Button("Save figure (G)")) ui.status = "save-figure";
    ImGui::SameLine();
    if (ImGui::Button("Help (H)")) ui.help = !ui.help;
    ImGui::SameLine();
    if (ImGui::Button("Quit")) *quit = true;
    if (!ui.status.empty() && ui.status != "save-frame" && ui.status != "save-figure")
        ImGui::TextWrapped("%s", ui.status.c_str());
    if (ui.help) {
        ImGui::Separator();
        ImGui::TextWrapped(
            "Keys: Space play / pause; Right, Left one frame; N next collision; Home the start; "
            "S slower (cycles the speeds); R reset the scene; F save the frame; G save the before / at / "
            "after figure; H this help; Q or Esc quit.\n"
            "Every change re-runs the scene from t = 0, in the background (a newer change cancels it); "
            "until it has finished the frame is the last complete run's. The frame is the one collide "
            "render draws.");
    }
    ImGui::End();
    return rebuild;
}

}  // namespace

int run_gui(const GuiOptions& o, std::ostream& out, std::ostream& err) {
    FrameSpec frame;
    std::vector<GuiAction> script;
    if (!read_gui_input(o, err, &frame, &script)) return 2;
    const int frame_w = frame.width, frame_h = frame.height;

    std::unique_ptr<render::Window> window;
    const int window_h = std::max(frame_h, kMinHeight);
    try {
        window = render::Window::open(frame_w + kPanelWidth, window_h, "Collide");
    } catch (const std::exception& e) {
        err << "collide gui: " << e.what() << "\n";
        return 1;
    }
    // The picker: the bundled lessons by id, then the bundled scenarios by file.
    std::vector<std::string> lesson_ids;
    try {
        for (const Lesson& L : load_lessons(lessons_dir())) lesson_ids.push_back(L.id);
        std::vector<std::string> scenes;
        for (const auto& e : std::filesystem::directory_iterator(lessons_dir() + "/scenes"))
            if (e.path().extension() == ".toml") scenes.push_back(e.path().string());
        std::sort(scenes.begin(), scenes.end());
        lesson_ids.insert(lesson_ids.end(), scenes.begin(), scenes.end());
    } catch (const std::exception&) {
        // A broken lesson elsewhere: no picker, the scene given still opens.
    }

    try {
        render::WindowControls controls(*window, 15.0f, kUiGlyphs);
        auto session = std::make_unique<Session>(*window, frame, o.scenario);
        controls.make_current();
        Ui ui;
        std::size_t next_action = 0;
        long wait_frames = 0;
        std::string screenshot;  // taken at the end of this window frame
        bool quit = false;
        auto last = std::chrono::steady_clock::now();
        while (!quit && !window->should_close()) {
            controls.make_current();
            const bool scripted = next_action < script.size();
            // Waiting for events, the progress bar of a re-run still moves.
            controls.poll_events(scripted || session->model().playing ? 0.0
                                 : session->model().running()         ? 1.0 / 30
                                                                      : 0.1);
            session->poll();  // a re-run that has finished replaces the frames
            const auto now = std::chrono::steady_clock::now();
            session->model().advance(std::chrono::duration<double>(now - last).count());
            last = now;

            // The script: one action a window frame (a wait: that many frames).
            if (wait_frames > 0) {
                --wait_frames;
            } else if (next_action < script.size()) {
                const GuiAction& a = script[next_action++];
                if (!run_script_action(a, o.script, &session->model(), &session->toggles())) {
                    if (a.verb == "quit") quit = true;
                    else if (a.verb == "wait") wait_frames = a.args.empty() ? 1 : std::stol(a.args[0]);
                    else if (a.verb == "screenshot") screenshot = a.args[0];
                    else if (a.verb == "open") {
                        try {
                            session = std::make_unique<Session>(*window, frame, a.args[0]);
                        } catch (const InputError& e) {
                            throw InputError(o.script, {a.line, 1}, a.verb, e.what());
                        }
                    } else if (a.verb == "orbit") session->turn(std::stod(a.args[0]), std::stod(a.args[1]), 1.0);
                    else if (a.verb == "zoom") session->turn(0.0, 0.0, std::stod(a.args[0]));
                    else if (a.verb == "save-frame") out << "saved " << session->save_frame(a.args[0]) << "\n";
                    else if (a.verb == "save-figure") {
                        if (!session->save_figure(a.args[0]))
                            throw InputError(o.script, {a.line, 1}, a.verb, "the run has no collision to draw");
                        out << "saved " << a.args[0] << "\n";
                    }
                } else if (a.verb == "set" || a.verb == "reset" || a.verb == "toggle") {
                    session->rebuild_renderer();
                }
            }

            // Keys (when no text field has them).
            controls.make_current();
            controls.begin_frame();
            GuiModel& m = session->model();
            if (!ImGui::GetIO().WantCaptureKeyboard) {
                if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Space))) m.playing = !m.playing;
                if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_RightArrow))) m.step(1);
                if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_LeftArrow))) m.step(-1);
                if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Home))) m.seek_index(0);
                if (controls.letter_pressed('N') && !m.next_collision()) ui.status = "no collision after this frame";
                if (controls.letter_pressed('S')) {
                    ui.speed = (ui.speed + 1) % IM_ARRAYSIZE(kSpeedValues);
                    m.speed = kSpeedValues[ui.speed];
                }
                if (controls.letter_pressed('R')) m.reset();
                if (controls.letter_pressed('F')) ui.status = "save-frame";
                if (controls.letter_pressed('G')) ui.status = "save-figure";
                if (controls.letter_pressed('H')) ui.help = !ui.help;
                if (controls.letter_pressed('Q') || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape)))
                    quit = true;
            }

            // The 3D view's camera: drag to orbit, wheel to zoom, over the frame.
            const ImGuiIO& io = ImGui::GetIO();
            const bool over_frame =
                io.MousePos.x >= 0 && io.MousePos.x < frame_w && io.MousePos.y >= 0 && io.MousePos.y < frame_h;
            if (!io.WantCaptureMouse && over_frame)
                session->orbit(ImGui::IsMouseDragging(ImGuiMouseButton_Left) ? io.MouseDelta.x : 0.0f,
                               ImGui::IsMouseDragging(ImGuiMouseButton_Left) ? io.MouseDelta.y : 0.0f, io.MouseWheel);

            // The frame, drawn by the renderer (its own ImGui context), shown pixel for pixel.
            session->update_frame();
            controls.make_current();
            session->draw_frame_behind();
            if (window_h > frame_h) draw_keys(ui, session->perspective(), frame_h, frame_w, window_h - frame_h);
            std::string switch_to;
            if (draw_panel(*session, ui, frame_w, window_h, lesson_ids, &switch_to, &quit)) session->rebuild_renderer();
            const float background[4] = {0.93f, 0.93f, 0.91f, 1.0f};
            controls.end_frame(background);
            if (!screenshot.empty()) {
                int fb_w = 0, fb_h = 0;
                window->framebuffer_size(&fb_w, &fb_h);
                std::vector<std::uint8_t> pixels(static_cast<std::size_t>(fb_w) * fb_h * 4);
                window->read_back_buffer(fb_w, fb_h, pixels.data());
                render::write_png_atomic(screenshot, fb_w, fb_h, pixels.data());
                out << "saved " << screenshot << "\n";
                screenshot.clear();
            }
            window->swap();

            // Saving from the buttons and keys, after the frame.
            if (ui.status == "save-frame") {
                const std::string path = o.out_dir + "/" + session->id() + "-t" + fixed(m.time(), 3) + ".png";
                ui.status = "saved " + session->save_frame(path);
            } else if (ui.status == "save-figure") {
                const std::string path = o.out_dir + "/" + session->id() + "-figure.png";
                ui.status = session->save_figure(path) ? "saved " + path : "the run has no collision to draw";
            }
            if (!switch_to.empty()) {
                session = std::make_unique<Session>(*window, frame, switch_to);
                ui.status.clear();
            }
        }
    } catch (const InputError& e) {
        err << "collide: error: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        err << "collide gui: " << e.what() << "\n";
        return 1;
    }
    return 0;
}

#endif

}  // namespace collide
