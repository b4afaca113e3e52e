// The frame pipeline of the renderer: lay out panels and strip, build disc instances and overlay
// triangles on the CPU, then draw them with a handful of GL calls into an FBO and read it back.
#include "collide/render/renderer.hpp"

#include <glad/gl.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <optional>
#include <string>

#include "collide/error.hpp"
#include "font.hpp"
#include "gl_objects.hpp"
#include "glyph_blit.hpp"
#include "layout.hpp"
#include "overlay_geometry.hpp"
#include "plots.hpp"
#include "shaders.hpp"
#include "trails.hpp"

namespace collide::render {

// ---------------------------------------------------------------------------------------------
// Config

std::string_view color_mode_name(ColorMode mode) noexcept {
    switch (mode) {
        case ColorMode::scene:
            return "scene";
        case ColorMode::speed:
            return "speed";
        case ColorMode::mass:
            return "mass";
        case ColorMode::tag:
            return "tag";
    }
    return "scene";
}

ColorMode parse_color_mode(std::string_view text, std::string_view field) {
    if (text == "scene") return ColorMode::scene;
    if (text == "speed") return ColorMode::speed;
    if (text == "mass") return ColorMode::mass;
    if (text == "tag") return ColorMode::tag;
    throw_input_error(std::string(field) + ": unknown colour mode '" + std::string(text) +
                      "' (expected scene, speed, mass or tag)");
}

void RenderConfig::validate() const {
    constexpr int min_size = 64;
    constexpr int max_size = 8192;  // well inside every GL implementation's FBO limit
    const auto fail = [](const char* field, const std::string& reason) {
        throw_input_error(std::string("render.") + field + ": " + reason);
    };
    if (width < min_size || width > max_size) {
        fail("width", "must be in [64, 8192], got " + std::to_string(width));
    }
    if (height < min_size || height > max_size) {
        fail("height", "must be in [64, 8192], got " + std::to_string(height));
    }
    if (!std::isfinite(speed_min) || speed_min < 0.0) fail("speed_min", "must be finite and >= 0");
    if (!std::isfinite(speed_max) || !(speed_max > speed_min)) {
        fail("speed_max", "must be finite and > speed_min");
    }
    if (!std::isfinite(mass_min) || !(mass_min > 0.0)) fail("mass_min", "must be finite and > 0");
    if (!std::isfinite(mass_max) || mass_max < mass_min) {
        fail("mass_max", "must be finite and >= mass_min");
    }
    if (trail_length < 2 || trail_length > 1024) {
        fail("trail_length", "must be in [2, 1024], got " + std::to_string(trail_length));
    }
    if (overlays && font_path.empty()) fail("font_path", "must name a TrueType font");
}

// ---------------------------------------------------------------------------------------------
// Colours and markers

namespace {

constexpr Rgba8 background_color{22, 22, 28, 255};
constexpr Rgba8 box_fill_color{34, 36, 46, 255};
constexpr Rgba8 wall_color{205, 205, 215, 255};
constexpr Rgba8 periodic_edge_color{95, 95, 120, 255};
constexpr Rgba8 title_color{245, 245, 245, 255};
constexpr Rgba8 counter_color{190, 190, 200, 255};
constexpr Rgba8 overlap_halo_color{240, 45, 45, 255};
constexpr Rgba8 missed_flash_color{255, 235, 110, 235};
constexpr Rgba8 escaped_ring_color{255, 70, 70, 255};
constexpr Rgb8 tagged_color{250, 160, 40};
constexpr Rgb8 untagged_color{120, 122, 135};

/// The vertex layout of shaders/disc.vert: one instance per disc or marker (20 bytes).
struct DiscInstance {
    float x, y;    // centre, frame pixels
    float radius;  // pixels
    float style;   // 0 filled, > 0 ring width (px), < 0 glow
    Rgba8 color;
};
static_assert(sizeof(DiscInstance) == 20);
constexpr std::size_t vertices_per_disc = 6;  // a quad's two triangles (disc.vert)
static_assert(sizeof(OverlayVertex) == 12);

Rgb8 disc_color(const DiscState& disc, const RenderConfig& config) noexcept {
    switch (config.color_mode) {
        case ColorMode::scene:
            return disc.color;
        case ColorMode::speed:
            return colormap((norm(disc.velocity) - config.speed_min) /
                            (config.speed_max - config.speed_min));
        case ColorMode::mass: {
            if (!(config.mass_max > config.mass_min)) return colormap(0.5);
            return colormap(std::log(disc.mass / config.mass_min) /
                            std::log(config.mass_max / config.mass_min));
        }
        case ColorMode::tag:
            return disc.tagged ? tagged_color : untagged_color;
    }
    return disc.color;
}

std::string join(const std::vector<std::string>& parts, const char* separator) {
    std::string out;
    for (const std::string& part : parts) {
        if (!out.empty()) out += separator;
        out += part;
    }
    return out;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Renderer::Impl

struct Renderer::Impl {
    // Declaration order matters: the context is destroyed last, after every GL object.
    RenderConfig config;
    std::unique_ptr<Context> context;
    GladGLContext gl{};
    GlObject color_texture;  // the FBO's colour attachment (a texture: see clear_background)
    GlObject framebuffer;
    GlObject disc_program;
    GlObject overlay_program;
    GlObject disc_vertex_array;
    GlObject disc_buffer;
    GlObject overlay_vertex_array;
    GlObject overlay_buffer;
    GLint disc_frame_size = -1;
    GLint disc_as_points = -1;
    GLint overlay_frame_size = -1;
    std::optional<FontAtlas> font;
    std::vector<TrailHistory> trails;

    // Per-frame scratch, kept to avoid allocating every frame.
    std::vector<DiscInstance> instances;
    // Upload order per panel: that panel's point sprites, then its quads (6 vertices each).
    std::vector<DiscInstance> disc_vertices;
    struct PanelDraws {
        std::size_t first_point = 0;
        std::size_t point_count = 0;
        std::size_t first_quad_vertex = 0;
        std::size_t quad_vertex_count = 0;
    };
    std::vector<PanelDraws> panel_draws;
    std::vector<DiscInstance> quad_scratch;
    float max_point_size = 0.0F;  // largest point sprite the implementation draws (px)
    std::vector<std::size_t> panel_instance_end;
    std::vector<RectF> panel_clip;  // scissor of each panel's discs
    OverlayBatch under;             // box fills, walls, trails: drawn before the discs
    OverlayBatch over;              // text, legend, plots: drawn after (text on the CPU)
    // Whole-pixel interiors of the box fills, cleared (clear_background) before anything is
    // drawn; the fractional edges left over go into `under` as thin quads (add_box_fill).
    std::vector<RectF> fill_clears;
    std::vector<Rgb8> colors;
    std::vector<OverlayVertex> overlay_upload;

    Impl(const RenderConfig& cfg, std::unique_ptr<Context> ctx)
        : config(cfg), context(std::move(ctx)) {
        config.validate();
        if (!context) throw_runtime_error("renderer: no GL context");
        context->make_current();
        if (gladLoadGLContext(&gl, context->proc_loader()) == 0) {
            throw_runtime_error("GL: cannot load the GL 3.3 core entry points");
        }
        if (config.overlays) {
            font.emplace(config.font_path, font_pixel_height(config.height));
        }
        create_framebuffer();
        create_programs();
        create_vertex_arrays();
        check_gl(gl, "renderer setup");
    }

    ~Impl() {
        // The GL objects (destroyed right after this body) need their context current.
        try {
            context->make_current();
        } catch (...) {  // NOLINT(bugprone-empty-catch): nothing sane to do in a destructor
        }
    }
    Impl(const Impl&) = delete;
    Impl& operator=(const Impl&) = delete;

    void create_framebuffer() {
        color_texture = make_texture(gl);
        gl.BindTexture(GL_TEXTURE_2D, color_texture.get());
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
        gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, config.width, config.height, 0, GL_RGBA,
                      GL_UNSIGNED_BYTE, nullptr);
        gl.BindTexture(GL_TEXTURE_2D, 0);
        framebuffer = make_framebuffer(gl);
        gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer.get());
        gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D,
                                color_texture.get(), 0);
        if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
            throw_runtime_error("GL: the " + std::to_string(config.width) + "x" +
                                std::to_string(config.height) + " framebuffer is incomplete");
        }
    }

    void create_programs() {
        disc_program = make_program(gl, shaders::disc_vert, shaders::disc_frag, "disc shader");
        overlay_program =
            make_program(gl, shaders::overlay_vert, shaders::overlay_frag, "overlay shader");
        disc_frame_size = gl.GetUniformLocation(disc_program.get(), "frame_size");
        disc_as_points = gl.GetUniformLocation(disc_program.get(), "as_points");
        GLfloat point_range[2] = {0.0F, 0.0F};
        gl.GetFloatv(GL_POINT_SIZE_RANGE, point_range);
        max_point_size = point_range[1];
        overlay_frame_size = gl.GetUniformLocation(overlay_program.get(), "frame_size");
    }

    void create_vertex_arrays() {
        disc_vertex_array = make_vertex_array(gl);
        disc_buffer = make_buffer(gl);
        gl.BindVertexArray(disc_vertex_array.get());
        gl.BindBuffer(GL_ARRAY_BUFFER, disc_buffer.get());
        constexpr auto disc_stride = static_cast<GLsizei>(sizeof(DiscInstance));
        const auto at = [](std::size_t offset) { return reinterpret_cast<const void*>(offset); };
        gl.VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, disc_stride,
                               at(offsetof(DiscInstance, x)));
        gl.VertexAttribPointer(1, 1, GL_FLOAT, GL_FALSE, disc_stride,
                               at(offsetof(DiscInstance, radius)));
        gl.VertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, disc_stride,
                               at(offsetof(DiscInstance, style)));
        gl.VertexAttribPointer(3, 4, GL_UNSIGNED_BYTE, GL_TRUE, disc_stride,
                               at(offsetof(DiscInstance, color)));
        for (GLuint location = 0; location < 4; ++location) gl.EnableVertexAttribArray(location);

        overlay_vertex_array = make_vertex_array(gl);
        overlay_buffer = make_buffer(gl);
        gl.BindVertexArray(overlay_vertex_array.get());
        gl.BindBuffer(GL_ARRAY_BUFFER, overlay_buffer.get());
        constexpr auto stride = static_cast<GLsizei>(sizeof(OverlayVertex));
        gl.VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, stride,
                               reinterpret_cast<const void*>(offsetof(OverlayVertex, x)));
        gl.VertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, stride,
                               reinterpret_cast<const void*>(offsetof(OverlayVertex, color)));
        for (GLuint location = 0; location < 2; ++location) gl.EnableVertexAttribArray(location);
        gl.BindVertexArray(0);
    }

    // ------------------------------------------------------------------ frame building

    static void check_frame(const FrameContent& frame) {
        if (frame.panels.empty() || frame.panels.size() > 2) {
            throw_input_error("render: a frame needs 1 or 2 panels, got " +
                              std::to_string(frame.panels.size()));
        }
        for (const PanelContent& panel : frame.panels) {
            if (panel.snapshot == nullptr) throw_input_error("render: a panel has no snapshot");
        }
    }

    int counter_rows_ = 0;  ///< rows of the counter grid in the frame being built

    void build_frame(const FrameContent& frame) {
        std::vector<Box> boxes;
        for (const PanelContent& panel : frame.panels) boxes.push_back(panel.snapshot->box);
        const int rows = counter_rows(frame);
        counter_rows_ = rows;
        const FrameLayout layout =
            compute_layout(config, boxes, font ? font->line_height() : 0.0F, rows);
        instances.clear();
        panel_instance_end.clear();
        panel_clip.clear();
        under.clear();
        over.clear();
        fill_clears.clear();
        if (trails.size() != frame.panels.size()) {
            trails.assign(frame.panels.size(), TrailHistory(config.trail_length));
        }
        for (std::size_t i = 0; i < frame.panels.size(); ++i) {
            build_panel(frame.panels[i], layout.panels[i], trails[i], frame.panels.size());
            panel_instance_end.push_back(instances.size());
            // Periodic images must not spill past the seam; in a walled box escaped discs must
            // show outside it, so those panels clip to the whole panel instead.
            const bool periodic = frame.panels[i].snapshot->box.boundary == Boundary::periodic;
            panel_clip.push_back(periodic ? layout.panels[i].box : layout.panels[i].area);
        }
        if (font) build_strip(frame, layout);
        current_layout = layout;
    }

    void build_panel(const PanelContent& content, const PanelLayout& panel, TrailHistory& trail,
                     std::size_t panels) {
        const Snapshot& snapshot = *content.snapshot;
        const Box& box = snapshot.box;
        const float wall = font ? std::max(1.0F, std::round(font->pixel_height() / 10.0F)) : 1.0F;
        add_box_fill(panel.box);
        const RectF outline{panel.box.x0 - wall, panel.box.y0 - wall, panel.box.x1 + wall,
                            panel.box.y1 + wall};
        under.add_frame(outline, wall,
                        box.boundary == Boundary::walls ? wall_color : periodic_edge_color);

        colors.resize(snapshot.discs.size());
        for (std::size_t k = 0; k < snapshot.discs.size(); ++k) {
            colors[k] = disc_color(snapshot.discs[k], config);
        }
        if (config.trails) {
            trail.update(snapshot);
            const auto to_pixels = [&](Vec2 p) { return panel.to_pixels(p, box); };
            trail.draw(under, box, to_pixels, colors, std::max(1.0F, wall * 1.5F));
        }
        add_disc_instances(snapshot, panel);
        add_failure_markers(snapshot, panel, wall);
        if (font) add_header(content, panel, panels);
    }

    // The opaque box background, as if drawn with under.add_rect(box, box_fill_color). Shading
    // ~0.7 Mpx of blended quad cost llvmpipe ~1.8 ms CPU per 720p frame; clearing the interior
    // (clear_background) is a memory fill. A quad covers the pixels whose centres lie inside it:
    // every pixel of the integer interior [ceil x0, floor x1) x [ceil y0, floor y1) is at least
    // half a pixel inside, so the clear paints the same pixels there; the strips outside the
    // interior keep the quad's own (possibly fractional) outer edges, so the rasteriser decides
    // those pixels as before. Nothing is drawn before the fills, and an opaque fill over the
    // background gives the fill colour, so the frame is unchanged.
    void add_box_fill(RectF box) {
        const RectF inner{std::ceil(box.x0), std::ceil(box.y0), std::floor(box.x1),
                          std::floor(box.y1)};
        if (!(inner.x0 < inner.x1 && inner.y0 < inner.y1)) {
            under.add_rect(box, box_fill_color);
            return;
        }
        fill_clears.push_back(inner);
        const auto strip = [&](RectF r) {
            if (r.x0 < r.x1 && r.y0 < r.y1) under.add_rect(r, box_fill_color);
        };
        strip({box.x0, box.y0, inner.x0, box.y1});      // left, full height
        strip({inner.x1, box.y0, box.x1, box.y1});      // right, full height
        strip({inner.x0, box.y0, inner.x1, inner.y0});  // top, between the two
        strip({inner.x0, inner.y1, inner.x1, box.y1});  // bottom, between the two
    }

    void add_disc_instances(const Snapshot& snapshot, const PanelLayout& panel) {
        const Box& box = snapshot.box;
        const bool periodic = box.boundary == Boundary::periodic;
        for (std::size_t k = 0; k < snapshot.discs.size(); ++k) {
            const DiscState& disc = snapshot.discs[k];
            const Rgba8 color = with_alpha(colors[k], 255);
            const auto radius = static_cast<float>(disc.radius * panel.scale);
            Vec2 position = disc.position;
            if (disc.escaped) position = clamp_into_panel(position, disc.radius, box, panel);
            const PointF c = panel.to_pixels(position, box);
            instances.push_back({c.x, c.y, radius, 0.0F, color});
            if (periodic) add_periodic_images(disc, panel, box, color);
            if (disc.escaped) {
                instances.push_back(
                    {c.x, c.y, radius + 3.0F, std::max(1.5F, radius * 0.25F), escaped_ring_color});
            }
        }
    }

    // An escaped disc may be far outside; pin it just outside the box, inside its panel, so the
    // viewer sees that it left.
    static Vec2 clamp_into_panel(Vec2 p, double radius, const Box& box, const PanelLayout& panel) {
        const double slack_x = (panel.box.x0 - panel.area.x0) / panel.scale - radius;
        const double slack_y = (panel.box.y0 - panel.area.y0) / panel.scale - radius;
        p.x = std::clamp(p.x, -std::max(0.0, slack_x), box.width + std::max(0.0, slack_x));
        p.y = std::clamp(p.y, -std::max(0.0, slack_y), box.height + std::max(0.0, slack_y));
        return p;
    }

    // A disc straddling an edge of a periodic box shows on both sides (scissored to the box).
    void add_periodic_images(const DiscState& disc, const PanelLayout& panel, const Box& box,
                             Rgba8 color) {
        const double r = disc.radius;
        const Vec2 p = disc.position;
        const int sx = p.x - r < 0.0 ? 1 : (p.x + r > box.width ? -1 : 0);
        const int sy = p.y - r < 0.0 ? 1 : (p.y + r > box.height ? -1 : 0);
        const auto radius = static_cast<float>(r * panel.scale);
        const auto add = [&](int ix, int iy) {
            const PointF c = panel.to_pixels({p.x + ix * box.width, p.y + iy * box.height}, box);
            instances.push_back({c.x, c.y, radius, 0.0F, color});
        };
        if (sx != 0) add(sx, 0);
        if (sy != 0) add(0, sy);
        if (sx != 0 && sy != 0) add(sx, sy);
    }

    void add_failure_markers(const Snapshot& snapshot, const PanelLayout& panel, float wall) {
        const Box& box = snapshot.box;
        const float ring = std::max(1.5F, wall * 1.5F);
        for (const auto& [a, b] : snapshot.overlapping_pairs) {
            for (const std::uint32_t index : {a, b}) {
                if (index >= snapshot.discs.size()) continue;  // defensive: bad marker data
                const DiscState& disc = snapshot.discs[index];
                const PointF c = panel.to_pixels(disc.position, box);
                const auto radius = static_cast<float>(disc.radius * panel.scale);
                instances.push_back({c.x, c.y, radius + 2.0F * ring, ring, overlap_halo_color});
            }
        }
        if (!snapshot.missed_collisions.empty()) {
            double mean_radius = 0.0;
            for (const DiscState& d : snapshot.discs) mean_radius += d.radius;
            mean_radius /= static_cast<double>(std::max<std::size_t>(snapshot.discs.size(), 1));
            const float flash = std::max(8.0F, static_cast<float>(3.0 * mean_radius * panel.scale));
            for (const Vec2 where : snapshot.missed_collisions) {
                const PointF c = panel.to_pixels(where, box);
                instances.push_back({c.x, c.y, flash, -1.0F, missed_flash_color});
            }
        }
    }

    [[nodiscard]] int panel_counter_columns(std::size_t panels) const {
        const float panel_width =
            static_cast<float>(config.width) / static_cast<float>(std::max<std::size_t>(panels, 1));
        return counter_columns(panel_width, font ? font->pixel_height() : 1.0F);
    }

    /// Rows of the counter grid: enough for the panel with the most counters, but the header
    /// never takes more than about 30% of the frame height (small frames keep room for the box;
    /// counters come most important first, so the ones that do not fit are the least important).
    [[nodiscard]] int counter_rows(const FrameContent& frame) const {
        const auto columns = static_cast<std::size_t>(panel_counter_columns(frame.panels.size()));
        std::size_t rows = 0;
        for (const PanelContent& panel : frame.panels) {
            rows = std::max(rows, (panel.counters.size() + columns - 1) / columns);
        }
        const float line = font ? font->line_height() : 1.0F;
        const auto fit = static_cast<std::size_t>(
            std::max(0.0F, std::floor(0.30F * static_cast<float>(config.height) / line) - 1.0F));
        return static_cast<int>(std::min(rows, fit));
    }

    void add_header(const PanelContent& content, const PanelLayout& panel, std::size_t panels) {
        const float baseline = panel.header.y0 + font->ascent();
        font->add_text(over, panel.header.x0, baseline, content.title, title_color);
        const int columns = panel_counter_columns(panels);
        const float column_width =
            (panel.header.x1 - panel.header.x0) / static_cast<float>(columns);
        const std::size_t shown =
            std::min(content.counters.size(),
                     static_cast<std::size_t>(columns) * static_cast<std::size_t>(counter_rows_));
        for (std::size_t k = 0; k < shown; ++k) {
            const auto column = static_cast<float>(k % static_cast<std::size_t>(columns));
            const auto row = static_cast<float>(1 + k / static_cast<std::size_t>(columns));
            font->add_text(over, panel.header.x0 + column * column_width,
                           baseline + row * font->line_height(), content.counters[k],
                           counter_color);
        }
    }

    void build_strip(const FrameContent& frame, const FrameLayout& layout) {
        const RectF strip = layout.strip;
        const float m = layout.margin * 1.5F;
        const float line = font->line_height();
        const RectF columns{strip.x0 + m, strip.y0 + m * 0.5F, strip.x1 - m,
                            strip.y1 - m * 0.5F - line};
        const float info_width = 0.26F * columns.width();
        const float plot_width = 0.5F * (columns.width() - info_width) - m;
        const RectF info{columns.x0, columns.y0, columns.x0 + info_width - m, columns.y1};
        const RectF histogram{info.x1 + m, columns.y0, info.x1 + m + plot_width, columns.y1};
        const RectF drift{histogram.x1 + 2.0F * m, columns.y0, columns.x1, columns.y1};

        font->add_text(over, info.x0, info.y0 + font->ascent(), frame.time_text, title_color);
        add_legend(info);
        std::vector<const Snapshot*> snapshots;
        for (const PanelContent& panel : frame.panels) snapshots.push_back(panel.snapshot);
        draw_speed_plot(over, *font, histogram, snapshots, config.speed_min, config.speed_max);
        draw_drift_plot(over, *font, drift, frame.energy_drift);
        const float notes_baseline = strip.y1 - m * 0.5F - line + font->ascent();
        font->add_text(over, columns.x0, notes_baseline, join(frame.notes, "   \xC2\xB7   "),
                       counter_color);
    }

    // Colour bar with its fixed range (speed or mass modes) or the tag key.
    void add_legend(RectF info) {
        const float line = font->line_height();
        float y = info.y0 + line * 1.3F;
        if (config.color_mode == ColorMode::speed || config.color_mode == ColorMode::mass) {
            const bool speed = config.color_mode == ColorMode::speed;
            const double low = speed ? config.speed_min : config.mass_min;
            const double high = speed ? config.speed_max : config.mass_max;
            const float bar_height = std::max(4.0F, std::round(line * 0.5F));
            constexpr int segments = 32;
            const float bar_width = info.width();
            for (int s = 0; s < segments; ++s) {
                const float x0 = info.x0 + bar_width * static_cast<float>(s) / segments;
                const float x1 = info.x0 + bar_width * static_cast<float>(s + 1) / segments;
                const Rgb8 c = colormap((s + 0.5) / segments);
                over.add_rect({x0, y, x1 + 0.5F, y + bar_height}, with_alpha(c, 255));
            }
            y += bar_height + font->ascent();
            char low_text[32];
            char high_text[32];
            std::snprintf(low_text, sizeof low_text, "%.3g", low);
            std::snprintf(high_text, sizeof high_text, "%.3g", high);
            font->add_text(over, info.x0, y, low_text, counter_color);
            const std::string caption = speed ? "speed" : "mass (log)";
            font->add_text(over, info.x0 + 0.5F * (bar_width - font->text_width(caption)), y,
                           caption, counter_color);
            font->add_text(over, info.x1 - font->text_width(high_text), y, high_text,
                           counter_color);
        } else if (config.color_mode == ColorMode::tag) {
            const float size = std::round(line * 0.6F);
            over.add_rect({info.x0, y, info.x0 + size, y + size}, with_alpha(tagged_color, 255));
            font->add_text(over, info.x0 + size * 1.5F, y + size, "tagged", counter_color);
        }
    }

    // ------------------------------------------------------------------ GL submission

    void submit() {
        gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer.get());
        gl.Viewport(0, 0, config.width, config.height);
        gl.Disable(GL_SCISSOR_TEST);
        gl.Disable(GL_DEPTH_TEST);
        clear_background();
        gl.Enable(GL_BLEND);
        gl.BlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // shaders output premultiplied colour
        const auto frame_w = static_cast<float>(config.width);
        const auto frame_h = static_cast<float>(config.height);

        // Text is blended on the CPU after the readback (read_pixels), over everything GL drew:
        // only `over` may hold glyphs.
        if (!under.glyphs().empty()) {
            throw_runtime_error("renderer: text can only be drawn over everything else");
        }
        overlay_upload.assign(under.vertices().begin(), under.vertices().end());
        overlay_upload.insert(overlay_upload.end(), over.vertices().begin(), over.vertices().end());
        gl.UseProgram(overlay_program.get());
        gl.Uniform2f(overlay_frame_size, frame_w, frame_h);
        gl.BindVertexArray(overlay_vertex_array.get());
        gl.BindBuffer(GL_ARRAY_BUFFER, overlay_buffer.get());
        gl.BufferData(GL_ARRAY_BUFFER,
                      static_cast<GLsizeiptr>(overlay_upload.size() * sizeof(OverlayVertex)),
                      overlay_upload.data(), GL_STREAM_DRAW);
        const auto under_count = static_cast<GLsizei>(under.vertices().size());
        if (under_count > 0) gl.DrawArrays(GL_TRIANGLES, 0, under_count);

        submit_discs(frame_w, frame_h);

        const auto over_count = static_cast<GLsizei>(over.vertices().size());
        if (over_count > 0) {
            gl.UseProgram(overlay_program.get());
            gl.BindVertexArray(overlay_vertex_array.get());
            gl.DrawArrays(GL_TRIANGLES, under_count, over_count);
        }
        gl.BindVertexArray(0);
        check_gl(gl, "drawing a frame");
    }

    // The frame colour, then the whole-pixel interiors of the box fills (add_box_fill). Mesa draws
    // a scissored glClear as a quad through the rasteriser: ~0.8 ms of llvmpipe CPU per 720p
    // frame for the two boxes. With ARB_clear_texture (llvmpipe has it) both clears are plain
    // memory fills of the colour texture instead; the previous frame has been read back, so the
    // texture is idle. The pixels are the same: a clear writes the colour's bytes exactly.
    void clear_background() {
        if (gl.ARB_clear_texture != 0) {
            gl.ClearTexImage(color_texture.get(), 0, GL_RGBA, GL_UNSIGNED_BYTE, &background_color);
            for (const RectF& r : fill_clears) {
                const PixelRect p = pixels_covering(r);
                gl.ClearTexSubImage(color_texture.get(), 0, p.x, p.y, 0, p.width, p.height, 1,
                                    GL_RGBA, GL_UNSIGNED_BYTE, &box_fill_color);
            }
            return;
        }
        gl.ClearColor(background_color.r / 255.0F, background_color.g / 255.0F,
                      background_color.b / 255.0F, 1.0F);
        gl.Clear(GL_COLOR_BUFFER_BIT);
        if (fill_clears.empty()) return;
        gl.ClearColor(box_fill_color.r / 255.0F, box_fill_color.g / 255.0F,
                      box_fill_color.b / 255.0F, 1.0F);
        gl.Enable(GL_SCISSOR_TEST);
        for (const RectF& r : fill_clears) {
            scissor_to(r);
            gl.Clear(GL_COLOR_BUFFER_BIT);
        }
        gl.Disable(GL_SCISSOR_TEST);
    }

    // Splits each panel's discs into point sprites and quads (see disc.vert) in upload order.
    void build_disc_vertices() {
        disc_vertices.clear();
        panel_draws.clear();
        quad_scratch.clear();
        std::size_t first = 0;
        for (const std::size_t end : panel_instance_end) {
            PanelDraws draws;
            draws.first_point = disc_vertices.size();
            quad_scratch.clear();
            for (std::size_t i = first; i < end; ++i) {
                if (fits_point_sprite(instances[i])) {
                    disc_vertices.push_back(instances[i]);
                } else {
                    quad_scratch.push_back(instances[i]);
                }
            }
            draws.point_count = disc_vertices.size() - draws.first_point;
            draws.first_quad_vertex = disc_vertices.size();
            for (const DiscInstance& quad : quad_scratch) {
                disc_vertices.insert(disc_vertices.end(), vertices_per_disc, quad);
            }
            draws.quad_vertex_count = disc_vertices.size() - draws.first_quad_vertex;
            panel_draws.push_back(draws);
            first = end;
        }
    }

    // Mirrors disc.vert's square: side 2 * (max(radius, min_radius) + aa_margin).
    [[nodiscard]] bool fits_point_sprite(const DiscInstance& disc) const noexcept {
        constexpr float min_radius = 0.75F;
        constexpr float aa_margin = 0.5F;
        const float half = std::max(disc.radius, min_radius) + aa_margin;
        return 2.0F * half <= max_point_size && disc.x - half >= 0.0F && disc.y - half >= 0.0F &&
               disc.x + half <= static_cast<float>(config.width) &&
               disc.y + half <= static_cast<float>(config.height);
    }

    // Per panel, scissored: one draw of point sprites, one of quads (each skipped when empty).
    void submit_discs(float frame_w, float frame_h) {
        if (instances.empty()) return;
        build_disc_vertices();
        gl.UseProgram(disc_program.get());
        gl.Uniform2f(disc_frame_size, frame_w, frame_h);
        gl.BindVertexArray(disc_vertex_array.get());
        gl.BindBuffer(GL_ARRAY_BUFFER, disc_buffer.get());
        gl.BufferData(GL_ARRAY_BUFFER,
                      static_cast<GLsizeiptr>(disc_vertices.size() * sizeof(DiscInstance)),
                      disc_vertices.data(), GL_STREAM_DRAW);
        gl.Enable(GL_PROGRAM_POINT_SIZE);
        gl.Enable(GL_SCISSOR_TEST);
        for (std::size_t p = 0; p < panel_draws.size(); ++p) {
            const PanelDraws& draws = panel_draws[p];
            scissor_to(panel_clip[p]);
            if (draws.point_count > 0) {
                gl.Uniform1i(disc_as_points, 1);
                gl.DrawArrays(GL_POINTS, static_cast<GLint>(draws.first_point),
                              static_cast<GLsizei>(draws.point_count));
            }
            if (draws.quad_vertex_count > 0) {
                gl.Uniform1i(disc_as_points, 0);
                gl.DrawArrays(GL_TRIANGLES, static_cast<GLint>(draws.first_quad_vertex),
                              static_cast<GLsizei>(draws.quad_vertex_count));
            }
        }
        gl.Disable(GL_SCISSOR_TEST);
    }

    struct PixelRect {
        GLint x, y;
        GLsizei width, height;
    };

    // Whole pixels covering r (window coordinates, which are also the colour texture's).
    static PixelRect pixels_covering(RectF r) {
        const auto x0 = static_cast<GLint>(std::floor(r.x0));
        const auto y0 = static_cast<GLint>(std::floor(r.y0));
        return {x0, y0, static_cast<GLsizei>(std::ceil(r.x1)) - x0,
                static_cast<GLsizei>(std::ceil(r.y1)) - y0};
    }

    void scissor_to(RectF r) {
        const PixelRect p = pixels_covering(r);
        gl.Scissor(p.x, p.y, p.width, p.height);
    }

    void draw(const FrameContent& frame) {
        check_frame(frame);
        context->make_current();
        build_frame(frame);
        submit();
        gl.Finish();
    }

    void read_pixels(Image& out) {
        if (out.width != config.width || out.height != config.height) {
            out = Image(config.width, config.height);
        }
        context->make_current();
        gl.BindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer.get());
        gl.ReadBuffer(GL_COLOR_ATTACHMENT0);
        gl.PixelStorei(GL_PACK_ALIGNMENT, 4);
        gl.ReadPixels(0, 0, config.width, config.height, GL_RGBA, GL_UNSIGNED_BYTE,
                      out.rgba.data());
        check_gl(gl, "reading the frame back");
        if (font) blend_glyphs(out, over.glyphs(), font->bitmap(), font->atlas_size());
    }

    FrameLayout current_layout;
};

// ---------------------------------------------------------------------------------------------
// Renderer

Renderer::Renderer(const RenderConfig& config, Backend backend, const NoticeSink& notice)
    : Renderer(config, [&] {
          config.validate();  // before creating a context for a config we would reject anyway
          return make_context(backend, config.width, config.height, notice);
      }()) {}

Renderer::Renderer(const RenderConfig& config, std::unique_ptr<Context> context)
    : impl_(std::make_unique<Impl>(config, std::move(context))) {}

Renderer::~Renderer() = default;
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;

Image Renderer::render(const FrameContent& frame) {
    Image image;
    render(frame, image);
    return image;
}

void Renderer::render(const FrameContent& frame, Image& out) {
    impl_->draw(frame);
    impl_->read_pixels(out);
}

void Renderer::draw(const FrameContent& frame) {
    impl_->draw(frame);
}
void Renderer::read_pixels(Image& out) {
    impl_->read_pixels(out);
}

void Renderer::reset_trails() {
    for (TrailHistory& trail : impl_->trails) trail.reset();
}

Backend Renderer::backend() const noexcept {
    return impl_->context->backend();
}
const RenderConfig& Renderer::config() const noexcept {
    return impl_->config;
}

}  // namespace collide::render
