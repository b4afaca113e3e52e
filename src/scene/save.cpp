// Writing scenes: TOML (every disc explicit) or algs4 text, through io::OutputFile (an exclusive
// temporary beside the destination, renamed onto it) so that a failure or an interrupt never
// leaves a half-written scene, or anything else, at the destination.

#include "collide/scene/save.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <ostream>
#include <sstream>
#include <string>

#include "collide/error.hpp"
#include "collide/io/file.hpp"
#include "collide/sim/algs4.hpp"

namespace collide {

namespace {

// 17 significant digits: every double reads back as itself.
std::string exact(double v) {
    std::array<char, 40> buf{};
    std::snprintf(buf.data(), buf.size(), "%.17g", v);
    // "1" is a TOML integer, which the reader accepts wherever it wants a number.
    return buf.data();
}

/// The length of the valid UTF-8 sequence at `s[i]`, or 0 when the bytes there are not one.
std::size_t utf8_sequence(const std::string& s, std::size_t i) {
    const auto lead = static_cast<unsigned char>(s[i]);
    const std::size_t length = lead >= 0xC2 && lead <= 0xDF   ? 2
                               : lead >= 0xE0 && lead <= 0xEF ? 3
                               : lead >= 0xF0 && lead <= 0xF4 ? 4
                                                              : 0;
    if (length == 0 || i + length > s.size()) return 0;
    for (std::size_t k = 1; k < length; ++k) {
        if ((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) return 0;
    }
    const auto second = static_cast<unsigned char>(s[i + 1]);
    // Overlong forms, UTF-16 surrogates and code points beyond U+10FFFF are not UTF-8 either.
    if ((lead == 0xE0 && second < 0xA0) || (lead == 0xED && second > 0x9F) ||
        (lead == 0xF0 && second < 0x90) || (lead == 0xF4 && second > 0x8F)) {
        return 0;
    }
    return length;
}

// A TOML basic string: quotes, backslashes and control characters escaped; bytes that are not
// UTF-8 (a title taken from a file name in another encoding) become U+FFFD, since a TOML file
// must be UTF-8 and the export must read back.
std::string quoted(const std::string& s) {
    std::string q = "\"";
    for (std::size_t i = 0; i < s.size();) {
        const char c = s[i];
        const auto u = static_cast<unsigned char>(c);
        if (u >= 0x80) {
            const std::size_t length = utf8_sequence(s, i);
            q += length == 0 ? std::string("\\uFFFD") : s.substr(i, length);
            i += std::max<std::size_t>(length, 1);
            continue;
        }
        if (c == '"' || c == '\\') {
            q += '\\';
            q += c;
        } else if (u < 0x20 || u == 0x7f) {
            std::array<char, 8> buf{};
            std::snprintf(buf.data(), buf.size(), "\\u%04x", u);
            q += buf.data();
        } else {
            q += c;
        }
        ++i;
    }
    return q + "\"";
}

std::string hex_color(Rgb8 c) {
    std::array<char, 8> buf{};
    std::snprintf(buf.data(), buf.size(), "#%02x%02x%02x", c.r, c.g, c.b);
    return buf.data();
}

void write_render(std::ostream& out, const RenderHints& r) {
    if (!r.color_mode && !r.trails && !r.overlays && !r.duration && !r.speed && !r.dt && !r.theme &&
        !r.caption && r.captions.empty() && !r.histogram && !r.replay && !r.replay_tag &&
        r.questions.empty())
        return;
    out << "\n[render]\n";
    if (r.color_mode)
        out << "color_mode = " << quoted(std::string(color_mode_name(*r.color_mode))) << "\n";
    if (r.trails) out << "trails = " << (*r.trails ? "true" : "false") << "\n";
    if (r.overlays)
        out << "overlays = " << quoted(std::string(overlay_level_name(*r.overlays))) << "\n";
    if (r.theme) out << "theme = " << quoted(std::string(theme_name(*r.theme))) << "\n";
    if (r.caption) out << "caption = " << quoted(*r.caption) << "\n";
    if (r.histogram)
        out << "histogram = " << quoted(std::string(plot_size_name(*r.histogram))) << "\n";
    if (r.duration) out << "duration = " << exact(*r.duration) << "\n";
    if (r.speed) out << "speed = " << exact(*r.speed) << "\n";
    if (r.dt) out << "dt = " << exact(*r.dt) << "\n";
    if (r.replay) out << "replay = " << quoted(std::string(replay_choice_name(*r.replay))) << "\n";
    if (r.replay_tag) out << "replay_tag = " << quoted(*r.replay_tag) << "\n";
    for (const CaptionCue& cue : r.captions) {
        out << "\n[[render.captions]]\nat = " << exact(cue.at) << "\ntext = " << quoted(cue.text)
            << "\n";
        if (cue.event_text) out << "event = " << quoted(*cue.event_text) << "\n";
        if (cue.time_text) out << "time = " << quoted(*cue.time_text) << "\n";
        if (cue.hold > 0.0) out << "hold = " << exact(cue.hold) << "\n";
    }
    for (const QuestionCue& cue : r.questions) {
        out << "\n[[render.questions]]\nat = " << exact(cue.at)
            << "\nkind = " << quoted(std::string(question_kind_name(cue.kind)))
            << "\nthink = " << exact(cue.think) << "\n";
        if (!cue.text.empty()) out << "text = " << quoted(cue.text) << "\n";
    }
}

void write_disc(std::ostream& out, const Disc& d) {
    out << "\n[[disc]]\nposition = [" << exact(d.position.x) << ", " << exact(d.position.y)
        << "]\nvelocity = [" << exact(d.velocity.x) << ", " << exact(d.velocity.y)
        << "]\nradius = " << exact(d.radius) << "\nmass = " << exact(d.mass)
        << "\ncolor = " << quoted(hex_color(d.color)) << "\n";
    if (!d.tag.empty()) out << "tag = " << quoted(d.tag) << "\n";
}

}  // namespace

void write_toml_scene(std::ostream& out, const Scene& scene) {
    if (!scene.title.empty()) out << "title = " << quoted(scene.title) << "\n";
    if (!scene.description.empty()) out << "description = " << quoted(scene.description) << "\n";
    out << "\n[box]\nwidth = " << exact(scene.box.width) << "\nheight = " << exact(scene.box.height)
        << "\nboundary = "
        << (scene.box.boundary == Boundary::periodic ? "\"periodic\"" : "\"walls\"") << "\n";
    write_render(out, scene.render);
    for (const Disc& d : scene.discs) write_disc(out, d);
}

void save_scene(const Scene& scene, const std::filesystem::path& path,
                const std::atomic<bool>* cancel) {
    const std::string ext = path.extension().string();
    if (ext != ".toml" && ext != ".txt") {
        throw_scene_error(path.string(), 0, "",
                          "cannot write scenes as '" + ext + "' (use .toml or .txt)");
    }
    if (ext == ".txt" && (scene.box.width != 1.0 || scene.box.height != 1.0 ||
                          scene.box.boundary != Boundary::walls)) {
        throw_scene_error(path.string(), 0, "",
                          "algs4 .txt files describe the unit box with walls only (use .toml)");
    }
    // Everything is formatted before the file is created: an error on the way leaves nothing.
    std::ostringstream text;
    if (ext == ".toml") {
        write_toml_scene(text, scene);
    } else {
        write_algs4(text, scene);
    }
    io::OutputFile file(path, io::OutputOptions{"scene", false});
    file.write(text.view());
    if (cancel != nullptr && cancel->load()) {
        throw_runtime_error("interrupted; nothing was written");  // the destructor removes it
    }
    file.commit();
}

}  // namespace collide
