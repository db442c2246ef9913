// A scene built in code, run with Collide's engine and drawn with its headless renderer: a
// ball dropped on the ground, the frame of its first bounce (the impulse, the normal, the
// velocity just after), written as a PNG.
// Usage: drop-frame OUT.png
#include <cstdio>
#include <exception>
#include <memory>
#include <vector>

#include "engine/mass.h"
#include "engine/record.h"
#include "render/context.h"
#include "render/frame_state.h"
#include "render/png.h"
#include "render/renderer.h"

int main(int argc, char** argv) {
    using namespace collide;
    if (argc != 2) {
        std::fprintf(stderr, "usage: drop-frame OUT.png\n");
        return 2;
    }
    Scene scene;
    scene.title = "A ball dropped on the ground";
    scene.dimension = 2;
    scene.gravity = Vec3(0.0, -9.81, 0.0);
    scene.duration = 1.0;
    scene.restitution = 0.8;
    SceneBody ground;
    ground.name = "ground";
    ground.shape = "plane";
    ground.shape2 = Shape2::half_plane(Vec2(0.0, 1.0), 0.0);
    ground.body2.is_static = true;
    SceneBody ball;
    ball.name = "ball";
    ball.shape = "disc";
    ball.shape2 = Shape2::disc(0.1);
    ball.body2.mass = 1.0;
    ball.body2.inertia = disc_inertia_2d(1.0, 0.1);
    ball.body2.position = Vec2(0.0, 1.0);
    scene.bodies = {ground, ball};

    try {
        // One run, recorded (engine/record.h): the states at t = 0 and 1 s, every collision,
        // and every body at the first collision instants.
        const Recording<2> run = record<2>(scene, {0.0, scene.duration});
        if (run.events.empty() || run.instants.empty()) {
            std::fprintf(stderr, "drop-frame: the ball never landed\n");
            return 1;
        }
        const Event<2>& bounce = run.events.front();
        std::printf("the ball lands at t = %.4f s with v = %.4f m/s and leaves with %.4f m/s\n", bounce.t,
                    bounce.before_b.v.y(), bounce.after_b.v.y());

        // The frame at the bounce, with its impulse drawn; framed on the whole run.
        render::FrameState frame = render::frame_state(scene, bounce.t, run.instants.front().bodies);
        frame.impacts.push_back(render::impact_mark(scene, bounce));
        const std::vector<render::FrameState> samples = {render::frame_state(scene, 0.0, run.states.front()), frame,
                                                         render::frame_state(scene, scene.duration, run.states.back())};
        std::unique_ptr<render::GlContext> context = render::create_gl_context();
        render::RenderSettings settings;
        settings.width = 640;
        settings.height = 360;
        settings.plots = false;  // (three samples make no plot of energy against time)
        render::Renderer renderer(*context, scene, settings);
        renderer.prepare(samples, frame.impacts);
        const render::Image image = renderer.render(frame, render::Decor{});
        render::write_png_atomic(argv[1], image.width, image.height, image.rgba.data());
        std::printf("wrote %s (%dx%d)\n", argv[1], image.width, image.height);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "drop-frame: %s\n", e.what());
        return 1;
    }
    return 0;
}
