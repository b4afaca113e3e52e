#pragma once
// Internal: the GL half of the renderer. Owns the context, the framebuffer, the two programs and
// their buffers; draws a DrawList (a picture described on the CPU) and reads it back, blending
// the text in on the CPU. It knows nothing of discs' physics, panels or layouts, so any picture
// made of filled/ringed circles, triangles and text can use it: the simulation frames
// (FrameBuilder), and for example a heap drawn as a tree of labelled nodes (discs with rings),
// edges (OverlayBatch::add_line) and an array of slots (add_rect/add_frame), labels as text runs.
//
//     GlTarget target(1280, 720, make_context(Backend::osmesa, 1280, 720));
//     DrawList list;
//     list.background = {255, 255, 255, 255};
//     list.over.add_line({100, 100}, {200, 200}, 3.0F, {40, 40, 40, 255});
//     list.discs.push_back({200, 200, 30, 0, {90, 175, 245, 255}});   // a filled node
//     list.disc_groups.push_back({list.discs.size(), {0, 0, 1280, 720}});
//     list.text.push_back({&font, {}});
//     font.add_text(list.text.back().glyphs, 190, 210, "42", {0, 0, 0, 255});
//     Image image;
//     target.draw(list);
//     target.read_pixels(list, image);

#include <glad/gl.h>

#include <cstddef>
#include <memory>
#include <vector>

#include "collide/image.hpp"
#include "collide/render/context.hpp"
#include "draw_list.hpp"
#include "gl_objects.hpp"

namespace collide::render {

class GlTarget {
  public:
    /// Makes `context` current, loads GL, creates the framebuffer and programs. Throws
    /// collide::Error (runtime) when any of it fails.
    GlTarget(int width, int height, std::unique_ptr<Context> context);
    ~GlTarget();
    GlTarget(const GlTarget&) = delete;
    GlTarget& operator=(const GlTarget&) = delete;

    /// Issues the GL commands of `list` and waits for them (glFinish).
    void draw(const DrawList& list);
    /// Reads the last drawn frame back (rows top-down) and blends `list.text` over it.
    void read_pixels(const DrawList& list, Image& out);

    [[nodiscard]] Backend backend() const noexcept { return context_->backend(); }
    [[nodiscard]] int width() const noexcept { return width_; }
    [[nodiscard]] int height() const noexcept { return height_; }

  private:
    struct PixelRect {
        GLint x, y;
        GLsizei width, height;
    };
    struct GroupDraws {
        std::size_t first_point = 0;
        std::size_t point_count = 0;
        std::size_t first_quad_vertex = 0;
        std::size_t quad_vertex_count = 0;
    };
    void create_framebuffer();
    void create_programs();
    void create_vertex_arrays();
    void clear_background(const DrawList& list);
    void build_disc_vertices(const DrawList& list);
    [[nodiscard]] bool fits_point_sprite(const DiscInstance& disc) const noexcept;
    void submit_discs(const DrawList& list, float frame_w, float frame_h);
    void create_depth_buffer();
    void submit_spheres(const DrawList& list, float frame_w, float frame_h);
    static PixelRect pixels_covering(RectF r);
    void scissor_to(RectF r);

    // Declaration order matters: the context is destroyed last, after every GL object.
    int width_;
    int height_;
    std::unique_ptr<Context> context_;
    GladGLContext gl{};
    GlObject color_texture_;  // the FBO's colour attachment (a texture: see clear_background)
    GlObject framebuffer_;
    GlObject disc_program_;
    GlObject overlay_program_;
    GlObject disc_vertex_array_;
    GlObject disc_buffer_;
    GlObject overlay_vertex_array_;
    GlObject overlay_buffer_;
    // Spheres (3D panels): their program, vertices and the depth buffer, made at the first frame
    // that has spheres (a 2D video never allocates a depth buffer).
    GlObject sphere_program_;
    GlObject sphere_vertex_array_;
    GlObject sphere_buffer_;
    GlObject depth_buffer_;
    GLint sphere_frame_size_ = -1;
    GLint sphere_light_dir_ = -1;
    GLint sphere_ambient_ = -1;
    GLint sphere_depth_cue_ = -1;
    GLint sphere_cue_color_ = -1;
    GLint sphere_eye_ = -1;
    std::vector<SphereInstance> sphere_vertices_;
    GLint disc_frame_size_ = -1;
    GLint disc_as_points_ = -1;
    GLint overlay_frame_size_ = -1;
    float max_point_size_ = 0.0F;  // largest point sprite the implementation draws (px)
    // Per-frame scratch, kept to avoid allocating every frame. Upload order per group: its
    // point sprites, then its quads (6 vertices each).
    std::vector<DiscInstance> disc_vertices_;
    std::vector<DiscInstance> quad_scratch_;
    std::vector<GroupDraws> group_draws_;
    std::vector<OverlayVertex> overlay_upload_;
};

}  // namespace collide::render
