// The GL side of the 3D view: its programs (assets/shaders/), the meshes uploaded once, and
// the draw calls for lists of what a pass produced (mesh instances, lines, the ground). It
// decides nothing about what is drawn: render/scene3d_passes.h does.
//
// Conventions: world coordinates in metres, y up; colours are 0xAABBGGRR (render/style.h); line
// widths in pixels of the frame.
#pragma once

#include <vector>

#include "engine/math.h"
#include "render/camera.h"
#include "render/gl.h"
#include "render/mesh.h"
#include "render/style.h"

namespace collide::render {

// One mesh placed in the world.
struct MeshDraw {
    int mesh;             // an id from Batch3d::add
    Mat4f model;          // mesh frame -> world
    Mat3f normal_matrix;  // the model's rotation, for the normals
    Colour colour;        // alpha ignored
    int pattern;          // 0: plain; 1: a sphere's wedges (mesh.frag)
};

// A line of constant width on the screen between two world points.
struct Segment {
    Vec3 a, b;  // m
    Colour colour;
    float width;  // pixels
};

// The ground plane: a square of half side `extent` about `origin` in the plane of the unit
// vectors u, v, with a grid of `spacing` (every fifth line stronger) fading into the paper.
struct GroundDraw {
    Vec3 origin, u, v;  // m; unit vectors
    float extent;       // m
    float spacing;      // m between minor grid lines
    Colour paper, ground, grid;
};

// A body's soft round shadow on the ground, centred on the foot of its centre.
struct Shadow {
    Vec3 foot;       // m
    float radius;    // m
    float strength;  // darkening at the centre, 0..1
};

// How a list of meshes meets the depth buffer.
enum class MeshDepth {
    behind_lines,  // depth-tested, pushed back a little (polygon offset) so that outlines win
    tested,
    over,  // no depth test: drawn over everything, in list order
};

class Batch3d {
public:
    explicit Batch3d(const Gl& gl);
    ~Batch3d();
    Batch3d(const Batch3d&) = delete;
    Batch3d& operator=(const Batch3d&) = delete;

    // Uploads a mesh; its id for MeshDraw (ids count from 0 in the order of the calls). An
    // empty mesh gets an id too and must not be drawn.
    int add(const Mesh& mesh);
    // The camera to draw with (call again when it changes): the frame's projection, the eye,
    // and the lights, fixed in the viewer's frame (the key from the upper left, the fill from
    // the right).
    void set_camera(const Camera& camera);

    // Starts a pass on the whole frame: depth test on (less or equal), no blending.
    void begin();
    // The ground, its grid and the shadows (which darken it, and write no depth).
    void ground(const GroundDraw& ground, const std::vector<Shadow>& shadows);
    void meshes(const std::vector<MeshDraw>& draws, MeshDepth depth);
    // Lines are blended and write no depth (their faded fringes would punch holes in what is
    // drawn later). depth_bias (normalised depth) pulls them towards the eye.
    void lines(const std::vector<Segment>& segments, bool depth_test, float depth_bias);
    // Ends a pass: depth test off; throws std::runtime_error on a GL error, naming `what`.
    void end(const char* what);
    // Forgets the depth of everything drawn so far: what is drawn next is depth-tested only
    // against itself (arrows over the bodies, yet each arrow shaded as a solid).
    void clear_depth();

private:
    struct GpuMesh {
        GLuint vao = 0, vbo = 0;
        GLsizei count = 0;
    };
    void use_mesh_program();

    const Gl& gl_;
    GLuint mesh_program_ = 0, line_program_ = 0, ground_program_ = 0, shadow_program_ = 0;
    std::vector<GpuMesh> meshes_;
    GLuint line_vao_ = 0, line_vbo_ = 0, ground_vao_ = 0, ground_vbo_ = 0;
    // From the camera.
    Mat4f frame_projection_ = Mat4f::Identity();
    Vec3f eye_ = Vec3f::Zero(), key_light_ = Vec3f::UnitY(), fill_light_ = Vec3f::UnitY();
    int frame_w_ = 1, frame_h_ = 1;
};

}  // namespace collide::render
