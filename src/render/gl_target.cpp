// The GL half of the renderer: one framebuffer, two programs (discs, overlay triangles), a
// handful of draw calls per frame, readback, and text blended on the CPU (glyph_blit.hpp).
#include "gl_target.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "collide/error.hpp"
#include "glyph_blit.hpp"
#include "shaders.hpp"

namespace collide::render {

namespace {
constexpr std::size_t vertices_per_disc = 6;  // a quad's two triangles (disc.vert)
static_assert(sizeof(OverlayVertex) == 12);
}  // namespace

GlTarget::GlTarget(int width, int height, std::unique_ptr<Context> context)
    : width_(width), height_(height), context_(std::move(context)) {
    if (!context_) throw_runtime_error("renderer: no GL context");
    context_->make_current();
    if (gladLoadGLContext(&gl, context_->proc_loader()) == 0) {
        throw_runtime_error("GL: cannot load the GL 3.3 core entry points");
    }
    create_framebuffer();
    create_programs();
    create_vertex_arrays();
    check_gl(gl, "renderer setup");
}

GlTarget::~GlTarget() {
    // The GL objects (destroyed right after this body) need their context current.
    try {
        context_->make_current();
    } catch (...) {  // NOLINT(bugprone-empty-catch): nothing sane to do in a destructor
    }
}

void GlTarget::create_framebuffer() {
    color_texture_ = make_texture(gl);
    gl.BindTexture(GL_TEXTURE_2D, color_texture_.get());
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width_, height_, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                  nullptr);
    gl.BindTexture(GL_TEXTURE_2D, 0);
    framebuffer_ = make_framebuffer(gl);
    gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D,
                            color_texture_.get(), 0);
    if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        check_gl(gl, "the framebuffer");  // a texture the driver had no memory for
        throw_runtime_error("GL: the " + std::to_string(width_) + "x" + std::to_string(height_) +
                            " framebuffer is incomplete");
    }
}

void GlTarget::create_programs() {
    disc_program_ = make_program(gl, shaders::disc_vert, shaders::disc_frag, "disc shader");
    overlay_program_ =
        make_program(gl, shaders::overlay_vert, shaders::overlay_frag, "overlay shader");
    disc_frame_size_ = gl.GetUniformLocation(disc_program_.get(), "frame_size");
    disc_as_points_ = gl.GetUniformLocation(disc_program_.get(), "as_points");
    GLfloat point_range[2] = {0.0F, 0.0F};
    gl.GetFloatv(GL_POINT_SIZE_RANGE, point_range);
    max_point_size_ = point_range[1];
    overlay_frame_size_ = gl.GetUniformLocation(overlay_program_.get(), "frame_size");
}

void GlTarget::create_vertex_arrays() {
    disc_vertex_array_ = make_vertex_array(gl);
    disc_buffer_ = make_buffer(gl);
    gl.BindVertexArray(disc_vertex_array_.get());
    gl.BindBuffer(GL_ARRAY_BUFFER, disc_buffer_.get());
    constexpr auto disc_stride = static_cast<GLsizei>(sizeof(DiscInstance));
    const auto at = [](std::size_t offset) { return reinterpret_cast<const void*>(offset); };
    gl.VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, disc_stride, at(offsetof(DiscInstance, x)));
    gl.VertexAttribPointer(1, 1, GL_FLOAT, GL_FALSE, disc_stride,
                           at(offsetof(DiscInstance, radius)));
    gl.VertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, disc_stride,
                           at(offsetof(DiscInstance, style)));
    gl.VertexAttribPointer(3, 4, GL_UNSIGNED_BYTE, GL_TRUE, disc_stride,
                           at(offsetof(DiscInstance, color)));
    for (GLuint location = 0; location < 4; ++location) gl.EnableVertexAttribArray(location);

    overlay_vertex_array_ = make_vertex_array(gl);
    overlay_buffer_ = make_buffer(gl);
    gl.BindVertexArray(overlay_vertex_array_.get());
    gl.BindBuffer(GL_ARRAY_BUFFER, overlay_buffer_.get());
    constexpr auto stride = static_cast<GLsizei>(sizeof(OverlayVertex));
    gl.VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, stride, at(offsetof(OverlayVertex, x)));
    gl.VertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, stride,
                           at(offsetof(OverlayVertex, color)));
    for (GLuint location = 0; location < 2; ++location) gl.EnableVertexAttribArray(location);
    gl.BindVertexArray(0);
}

void GlTarget::draw(const DrawList& list) {
    context_->make_current();
    gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
    gl.Viewport(0, 0, width_, height_);
    gl.Disable(GL_SCISSOR_TEST);
    gl.Disable(GL_DEPTH_TEST);
    clear_background(list);
    gl.Enable(GL_BLEND);
    gl.BlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // shaders output premultiplied colour
    const auto frame_w = static_cast<float>(width_);
    const auto frame_h = static_cast<float>(height_);

    // Text is blended on the CPU after the readback (read_pixels), over everything GL drew.
    if (!list.under.glyphs().empty() || !list.over.glyphs().empty()) {
        throw_runtime_error("renderer: text can only be drawn over everything else");
    }
    overlay_upload_.assign(list.under.vertices().begin(), list.under.vertices().end());
    overlay_upload_.insert(overlay_upload_.end(), list.over.vertices().begin(),
                           list.over.vertices().end());
    gl.UseProgram(overlay_program_.get());
    gl.Uniform2f(overlay_frame_size_, frame_w, frame_h);
    gl.BindVertexArray(overlay_vertex_array_.get());
    gl.BindBuffer(GL_ARRAY_BUFFER, overlay_buffer_.get());
    gl.BufferData(GL_ARRAY_BUFFER,
                  static_cast<GLsizeiptr>(overlay_upload_.size() * sizeof(OverlayVertex)),
                  overlay_upload_.data(), GL_STREAM_DRAW);
    const auto under_count = static_cast<GLsizei>(list.under.vertices().size());
    if (under_count > 0) gl.DrawArrays(GL_TRIANGLES, 0, under_count);

    submit_spheres(list, frame_w, frame_h);
    submit_discs(list, frame_w, frame_h);

    const auto over_count = static_cast<GLsizei>(list.over.vertices().size());
    if (over_count > 0) {
        gl.UseProgram(overlay_program_.get());
        gl.BindVertexArray(overlay_vertex_array_.get());
        gl.DrawArrays(GL_TRIANGLES, under_count, over_count);
    }
    gl.BindVertexArray(0);
    check_gl(gl, "drawing a frame");
    gl.Finish();
}

// The frame colour, then the whole-pixel fills. Mesa draws a scissored glClear as a quad through
// the rasteriser: ~0.8 ms of llvmpipe CPU per 720p frame for the two boxes. With
// ARB_clear_texture (llvmpipe has it) both clears are plain memory fills of the colour texture
// instead; the previous frame has been read back, so the texture is idle. The pixels are the
// same: a clear writes the colour's bytes exactly.
void GlTarget::clear_background(const DrawList& list) {
    if (gl.ARB_clear_texture != 0) {
        gl.ClearTexImage(color_texture_.get(), 0, GL_RGBA, GL_UNSIGNED_BYTE, &list.background);
        for (const RectF& r : list.fill_clears) {
            const PixelRect p = pixels_covering(r);
            gl.ClearTexSubImage(color_texture_.get(), 0, p.x, p.y, 0, p.width, p.height, 1, GL_RGBA,
                                GL_UNSIGNED_BYTE, &list.fill_color);
        }
        return;
    }
    const auto clear_to = [&](Rgba8 c) {
        gl.ClearColor(c.r / 255.0F, c.g / 255.0F, c.b / 255.0F, 1.0F);
    };
    clear_to(list.background);
    gl.Clear(GL_COLOR_BUFFER_BIT);
    if (list.fill_clears.empty()) return;
    clear_to(list.fill_color);
    gl.Enable(GL_SCISSOR_TEST);
    for (const RectF& r : list.fill_clears) {
        scissor_to(r);
        gl.Clear(GL_COLOR_BUFFER_BIT);
    }
    gl.Disable(GL_SCISSOR_TEST);
}

// Splits each group's discs into point sprites and quads (see disc.vert) in upload order.
void GlTarget::build_disc_vertices(const DrawList& list) {
    disc_vertices_.clear();
    group_draws_.clear();
    std::size_t first = 0;
    for (const DrawList::DiscGroup& group : list.disc_groups) {
        GroupDraws draws;
        draws.first_point = disc_vertices_.size();
        quad_scratch_.clear();
        const std::size_t end = std::min(group.end, list.discs.size());
        for (std::size_t i = first; i < end; ++i) {
            if (fits_point_sprite(list.discs[i])) {
                disc_vertices_.push_back(list.discs[i]);
            } else {
                quad_scratch_.push_back(list.discs[i]);
            }
        }
        draws.point_count = disc_vertices_.size() - draws.first_point;
        draws.first_quad_vertex = disc_vertices_.size();
        for (const DiscInstance& quad : quad_scratch_) {
            disc_vertices_.insert(disc_vertices_.end(), vertices_per_disc, quad);
        }
        draws.quad_vertex_count = disc_vertices_.size() - draws.first_quad_vertex;
        group_draws_.push_back(draws);
        first = std::max(first, end);
    }
}

// Mirrors disc.vert's square: side 2 * (max(radius, min_radius) + aa_margin).
bool GlTarget::fits_point_sprite(const DiscInstance& disc) const noexcept {
    constexpr float min_radius = 0.75F;
    constexpr float aa_margin = 0.5F;
    const float half = std::max(disc.radius, min_radius) + aa_margin;
    return 2.0F * half <= max_point_size_ && disc.x - half >= 0.0F && disc.y - half >= 0.0F &&
           disc.x + half <= static_cast<float>(width_) &&
           disc.y + half <= static_cast<float>(height_);
}

// Per group, scissored: one draw of point sprites, one of quads (each skipped when empty).
void GlTarget::submit_discs(const DrawList& list, float frame_w, float frame_h) {
    if (list.discs.empty()) return;
    build_disc_vertices(list);
    gl.UseProgram(disc_program_.get());
    gl.Uniform2f(disc_frame_size_, frame_w, frame_h);
    gl.BindVertexArray(disc_vertex_array_.get());
    gl.BindBuffer(GL_ARRAY_BUFFER, disc_buffer_.get());
    gl.BufferData(GL_ARRAY_BUFFER,
                  static_cast<GLsizeiptr>(disc_vertices_.size() * sizeof(DiscInstance)),
                  disc_vertices_.data(), GL_STREAM_DRAW);
    gl.Enable(GL_PROGRAM_POINT_SIZE);
    gl.Enable(GL_SCISSOR_TEST);
    for (std::size_t g = 0; g < group_draws_.size(); ++g) {
        const GroupDraws& draws = group_draws_[g];
        scissor_to(list.disc_groups[g].clip);
        if (draws.point_count > 0) {
            gl.Uniform1i(disc_as_points_, 1);
            gl.DrawArrays(GL_POINTS, static_cast<GLint>(draws.first_point),
                          static_cast<GLsizei>(draws.point_count));
        }
        if (draws.quad_vertex_count > 0) {
            gl.Uniform1i(disc_as_points_, 0);
            gl.DrawArrays(GL_TRIANGLES, static_cast<GLint>(draws.first_quad_vertex),
                          static_cast<GLsizei>(draws.quad_vertex_count));
        }
    }
    gl.Disable(GL_SCISSOR_TEST);
}

// The depth buffer and the sphere program, once: only a video with spheres needs them.
void GlTarget::create_depth_buffer() {
    depth_buffer_ = make_renderbuffer(gl);
    gl.BindRenderbuffer(GL_RENDERBUFFER, depth_buffer_.get());
    gl.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width_, height_);
    gl.BindRenderbuffer(GL_RENDERBUFFER, 0);
    gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                               depth_buffer_.get());
    if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        check_gl(gl, "the depth buffer");  // a buffer the driver had no memory for
        throw_runtime_error("GL: the framebuffer with a depth buffer is incomplete");
    }
    sphere_program_ = make_program(gl, shaders::sphere_vert, shaders::sphere_frag, "sphere shader");
    sphere_frame_size_ = gl.GetUniformLocation(sphere_program_.get(), "frame_size");
    sphere_light_dir_ = gl.GetUniformLocation(sphere_program_.get(), "light_dir");
    sphere_ambient_ = gl.GetUniformLocation(sphere_program_.get(), "ambient");
    sphere_depth_cue_ = gl.GetUniformLocation(sphere_program_.get(), "depth_cue");
    sphere_cue_color_ = gl.GetUniformLocation(sphere_program_.get(), "cue_color");
    sphere_eye_ = gl.GetUniformLocation(sphere_program_.get(), "eye");
    sphere_vertex_array_ = make_vertex_array(gl);
    sphere_buffer_ = make_buffer(gl);
    gl.BindVertexArray(sphere_vertex_array_.get());
    gl.BindBuffer(GL_ARRAY_BUFFER, sphere_buffer_.get());
    constexpr auto stride = static_cast<GLsizei>(sizeof(SphereInstance));
    const auto at = [](std::size_t offset) { return reinterpret_cast<const void*>(offset); };
    gl.VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, stride, at(offsetof(SphereInstance, x)));
    gl.VertexAttribPointer(1, 1, GL_FLOAT, GL_FALSE, stride, at(offsetof(SphereInstance, radius)));
    gl.VertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, stride, at(offsetof(SphereInstance, depth)));
    gl.VertexAttribPointer(3, 1, GL_FLOAT, GL_FALSE, stride,
                           at(offsetof(SphereInstance, radius_depth)));
    gl.VertexAttribPointer(4, 4, GL_UNSIGNED_BYTE, GL_TRUE, stride,
                           at(offsetof(SphereInstance, color)));
    gl.VertexAttribPointer(5, 4, GL_FLOAT, GL_FALSE, stride, at(offsetof(SphereInstance, plane_x)));
    for (GLuint location = 0; location < 6; ++location) gl.EnableVertexAttribArray(location);
    gl.BindVertexArray(0);
}

// Per group (a panel), scissored to it, with a depth test: six vertices per sphere (a quad).
void GlTarget::submit_spheres(const DrawList& list, float frame_w, float frame_h) {
    if (list.spheres.empty()) return;
    if (depth_buffer_.get() == 0) create_depth_buffer();
    sphere_vertices_.clear();
    for (const SphereInstance& s : list.spheres)
        sphere_vertices_.insert(sphere_vertices_.end(), vertices_per_disc, s);
    gl.UseProgram(sphere_program_.get());
    gl.Uniform2f(sphere_frame_size_, frame_w, frame_h);
    gl.BindVertexArray(sphere_vertex_array_.get());
    gl.BindBuffer(GL_ARRAY_BUFFER, sphere_buffer_.get());
    gl.BufferData(GL_ARRAY_BUFFER,
                  static_cast<GLsizeiptr>(sphere_vertices_.size() * sizeof(SphereInstance)),
                  sphere_vertices_.data(), GL_STREAM_DRAW);
    gl.DepthMask(GL_TRUE);
    gl.ClearDepth(1.0);
    gl.Clear(GL_DEPTH_BUFFER_BIT);
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(GL_LESS);
    gl.Enable(GL_SCISSOR_TEST);
    std::size_t first = 0;
    for (const DrawList::SphereGroup& group : list.sphere_groups) {
        const std::size_t end = std::min(group.end, list.spheres.size());
        if (end > first) {
            const SphereLight& l = group.light;
            gl.Uniform3f(sphere_light_dir_, l.x, l.y, l.z);
            gl.Uniform1f(sphere_ambient_, l.ambient);
            gl.Uniform1f(sphere_depth_cue_, l.depth_cue);
            gl.Uniform3f(sphere_cue_color_, l.cue_color.r / 255.0F, l.cue_color.g / 255.0F,
                         l.cue_color.b / 255.0F);
            gl.Uniform3f(sphere_eye_, l.eye_x, l.eye_y, l.eye_z);
            scissor_to(group.clip);
            gl.DrawArrays(GL_TRIANGLES, static_cast<GLint>(first * vertices_per_disc),
                          static_cast<GLsizei>((end - first) * vertices_per_disc));
        }
        first = std::max(first, end);
    }
    gl.Disable(GL_SCISSOR_TEST);
    gl.Disable(GL_DEPTH_TEST);
}

// Whole pixels covering r (window coordinates, which are also the colour texture's).
GlTarget::PixelRect GlTarget::pixels_covering(RectF r) {
    const auto x0 = static_cast<GLint>(std::floor(r.x0));
    const auto y0 = static_cast<GLint>(std::floor(r.y0));
    return {x0, y0, static_cast<GLsizei>(std::ceil(r.x1)) - x0,
            static_cast<GLsizei>(std::ceil(r.y1)) - y0};
}

void GlTarget::scissor_to(RectF r) {
    const PixelRect p = pixels_covering(r);
    gl.Scissor(p.x, p.y, p.width, p.height);
}

void GlTarget::read_pixels(const DrawList& list, Image& out) {
    if (out.width != width_ || out.height != height_) out = Image(width_, height_);
    context_->make_current();
    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_.get());
    gl.ReadBuffer(GL_COLOR_ATTACHMENT0);
    gl.PixelStorei(GL_PACK_ALIGNMENT, 4);
    gl.ReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, out.rgba.data());
    check_gl(gl, "reading the frame back");
    for (const TextRun& run : list.text) {
        if (run.font == nullptr || run.glyphs.glyphs().empty()) continue;
        blend_glyphs(out, run.glyphs.glyphs(), run.font->bitmap(), run.font->atlas_size());
    }
}

}  // namespace collide::render
