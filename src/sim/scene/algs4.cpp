// The algs4 text format: line-based parsing that tolerates layout (CRLF, blank lines, leading
// spaces, missing final newline) and rejects content it cannot read, naming file:line:column.

#include "collide/sim/algs4.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <istream>
#include <ostream>
#include <sstream>
#include <string_view>
#include <vector>

#include "collide/error.hpp"

namespace collide {

namespace {

constexpr std::array<const char*, 9> column_names = {"rx",   "ry", "vx", "vy", "radius",
                                                     "mass", "r",  "g",  "b"};

// Never reserve more than this up front: N comes from the file and may be absurd.
constexpr std::size_t max_reserve = std::size_t{1} << 20;

std::vector<std::string_view> split_whitespace(std::string_view line) {
    std::vector<std::string_view> out;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r' ||
                                   line[i] == '\f' || line[i] == '\v'))
            ++i;
        const std::size_t start = i;
        while (i < line.size() && !(line[i] == ' ' || line[i] == '\t' || line[i] == '\r' ||
                                    line[i] == '\f' || line[i] == '\v'))
            ++i;
        if (i > start) out.push_back(line.substr(start, i - start));
    }
    return out;
}

enum class NumberParse { ok, not_a_number, too_large };

// Java's Double.parseDouble forms that matter here: "1.9E-4", ".05", "-0.0", "+3", "1e5".
// NaN and infinities parse (so the message can say "not finite" rather than "not a number").
// A number too small for a double ("1e-400") is 0 with its sign, as Java, strtod and TOML read
// it; one too large ("1e400") is refused as such.
NumberParse parse_double(std::string_view token, double& value) {
    if (!token.empty() && token.front() == '+') {
        token.remove_prefix(1);
        if (!token.empty() && (token.front() == '-' || token.front() == '+'))
            return NumberParse::not_a_number;
    }
    const char* end = token.data() + token.size();
    const auto [ptr, ec] = std::from_chars(token.data(), end, value);
    if (ptr != end) return NumberParse::not_a_number;
    if (ec == std::errc::result_out_of_range) {
        // A well-formed decimal out of range: strtod tells underflow (a tiny result) from
        // overflow (HUGE_VAL).
        const std::string copy(token);
        const double rounded = std::strtod(copy.c_str(), nullptr);
        if (std::isinf(rounded)) return NumberParse::too_large;
        value = rounded;
        return NumberParse::ok;
    }
    return ec == std::errc() ? NumberParse::ok : NumberParse::not_a_number;
}

bool parse_count(std::string_view token, unsigned long long& value) {
    if (!token.empty() && token.front() == '+') token.remove_prefix(1);
    const char* end = token.data() + token.size();
    const auto [ptr, ec] = std::from_chars(token.data(), end, value);
    return ec == std::errc() && ptr == end && !token.empty();
}

std::string quoted(std::string_view s) {
    constexpr std::size_t shown = 40;
    std::string q = "'";
    for (const char c : s.substr(0, shown)) {
        // A binary file must not put control characters or broken UTF-8 on the terminal.
        const auto u = static_cast<unsigned char>(c);
        q += (u < 0x20 || u >= 0x7f) ? '?' : c;
    }
    if (s.size() > shown) q += "...";
    return q + "'";
}

struct Reader {
    const std::string& file;
    ParsedScene parsed;
    std::vector<int> lines;
    unsigned long long expected = 0;
    int count_line = 0;

    void read_count(std::string_view text, int line) {
        const auto tokens = split_whitespace(text);
        if (tokens.size() != 1 || !parse_count(tokens[0], expected)) {
            throw_scene_error(
                file, line, "N",
                "expected the number of discs alone on the first line, got " + quoted(text));
        }
        count_line = line;
        parsed.scene.discs.reserve(
            static_cast<std::size_t>(std::min<unsigned long long>(expected, max_reserve)));
    }

    double number(std::string_view token, int line, std::size_t column) const {
        double v = 0.0;
        const NumberParse result = parse_double(token, v);
        if (result == NumberParse::not_a_number) {
            throw_scene_error(file, line, column_names[column], quoted(token) + " is not a number");
        }
        if (result == NumberParse::too_large) {
            throw_scene_error(file, line, column_names[column],
                              quoted(token) + " is too large for a double (at most 1.8e308)");
        }
        if (!std::isfinite(v))
            throw_scene_error(file, line, column_names[column],
                              "not a finite number (" + std::string(token) + ")");
        return v;
    }

    std::uint8_t channel(std::string_view token, int line, std::size_t column) const {
        const double v = number(token, line, column);
        if (v < 0.0 || v > 255.0 || v != std::floor(v)) {
            throw_scene_error(file, line, column_names[column],
                              "colour must be an integer 0..255, got " + std::string(token));
        }
        return static_cast<std::uint8_t>(v);
    }

    void read_disc(std::string_view text, int line) {
        const auto t = split_whitespace(text);
        if (t.size() != column_names.size()) {
            throw_scene_error(file, line, "",
                              "expected 9 columns (rx ry vx vy radius mass r g b), got " +
                                  std::to_string(t.size()));
        }
        if (parsed.scene.discs.size() >= expected) {
            throw_scene_error(file, line, "N",
                              "more disc lines than N = " + std::to_string(expected) + " (line " +
                                  std::to_string(count_line) + ")");
        }
        Disc d;
        d.position = {number(t[0], line, 0), number(t[1], line, 1)};
        d.velocity = {number(t[2], line, 2), number(t[3], line, 3)};
        d.radius = number(t[4], line, 4);
        d.mass = number(t[5], line, 5);
        d.color = {channel(t[6], line, 6), channel(t[7], line, 7), channel(t[8], line, 8)};
        parsed.scene.discs.push_back(std::move(d));
        lines.push_back(line);
    }

    void finish() {
        if (count_line == 0)
            throw_scene_error(file, 0, "N",
                              "empty file: expected the number of discs on the first line");
        if (parsed.scene.discs.size() != expected) {
            throw_scene_error(file, count_line, "N",
                              "N = " + std::to_string(expected) + " but " +
                                  std::to_string(parsed.scene.discs.size()) + " disc lines follow");
        }
        DiscSource run;
        run.first = 0;
        run.count = parsed.scene.discs.size();
        run.file = file;
        run.lines = std::move(lines);
        run.field = "disc";
        parsed.origin.add(std::move(run));
    }
};

bool blank(std::string_view s) {
    return std::all_of(s.begin(), s.end(), [](char c) {
        return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
    });
}

}  // namespace

ParsedScene parse_algs4(std::string_view text, const std::string& file_label) {
    Reader reader{file_label, {}, {}, 0, 0};
    reader.parsed.scene.box = Box{1.0, 1.0, Boundary::walls};  // algs4's unit box
    // Editors on Windows start UTF-8 files with a byte order mark; TOML files may have one too.
    if (text.starts_with(utf8_bom)) text.remove_prefix(utf8_bom.size());
    int line = 0;
    while (!text.empty()) {
        const std::size_t newline = text.find('\n');
        const std::string_view current = text.substr(0, newline);
        text.remove_prefix(newline == std::string_view::npos ? text.size() : newline + 1);
        ++line;
        if (blank(current)) continue;
        if (reader.count_line == 0) {
            reader.read_count(current, line);
        } else {
            reader.read_disc(current, line);
        }
    }
    reader.finish();
    return std::move(reader.parsed);
}

ParsedScene parse_algs4(std::istream& in, const std::string& file_label) {
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw_scene_error(file_label, 0, "", "read error");
    return parse_algs4(std::string_view(text.view()), file_label);
}

std::string valid_utf8(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        const auto lead = static_cast<unsigned char>(text[i]);
        if (lead < 0x80) {
            out += text[i++];
            continue;
        }
        const std::size_t length = lead >= 0xC2 && lead <= 0xDF   ? 2
                                   : lead >= 0xE0 && lead <= 0xEF ? 3
                                   : lead >= 0xF0 && lead <= 0xF4 ? 4
                                                                  : 0;
        bool ok = length != 0 && i + length <= text.size();
        for (std::size_t k = 1; ok && k < length; ++k)
            ok = (static_cast<unsigned char>(text[i + k]) & 0xC0) == 0x80;
        if (ok) {
            const auto second = static_cast<unsigned char>(text[i + 1]);
            ok = !((lead == 0xE0 && second < 0xA0) || (lead == 0xED && second > 0x9F) ||
                   (lead == 0xF0 && second < 0x90) || (lead == 0xF4 && second > 0x8F));
        }
        if (ok) {
            out.append(text.substr(i, length));
            i += length;
        } else {
            out += "\xEF\xBF\xBD";  // U+FFFD
            ++i;
        }
    }
    return out;
}

ParsedScene read_algs4_text(std::string_view text, const std::filesystem::path& path) {
    ParsedScene parsed = parse_algs4(text, path.string());
    parsed.scene.name = path.stem().string();
    parsed.scene.title = valid_utf8(parsed.scene.name);
    validate_scene(parsed.scene, parsed.origin);
    return parsed;
}

ParsedScene read_algs4_file(const std::filesystem::path& path) {
    // std-only, so the checks come before opening (a FIFO would block in open). The CLI reads
    // through collide::read_scene_file instead, which opens without blocking and checks after.
    std::error_code error;
    const std::filesystem::file_status status = std::filesystem::status(path, error);
    if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
        throw_scene_error(path.string(), 0, "", "not a regular file");
    if (std::filesystem::is_regular_file(status) &&
        std::filesystem::file_size(path, error) > max_scene_file_bytes)
        throw_scene_error(path.string(), 0, "", "larger than the scene file limit");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw_scene_error(path.string(), 0, "", "cannot open the scene file");
    std::ostringstream text;
    text << in.rdbuf();
    return read_algs4_text(text.view(), path);
}

void write_algs4(std::ostream& out, const Scene& scene) {
    out << scene.discs.size() << '\n';
    std::array<char, 512> buf{};
    for (const Disc& d : scene.discs) {
        std::snprintf(buf.data(), buf.size(), "%.17g %.17g %.17g %.17g %.17g %.17g %d %d %d\n",
                      d.position.x, d.position.y, d.velocity.x, d.velocity.y, d.radius, d.mass,
                      d.color.r, d.color.g, d.color.b);
        out << buf.data();
    }
}

}  // namespace collide
