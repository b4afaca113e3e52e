// The typed values of a TOML scene file (toml_values.hpp).
#include "toml_values.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "collide/scene/load.hpp"
#include "collide/sim/scene_check.hpp"

namespace collide::toml_text {

std::string ValueReader::where(const toml::node& at, const std::string& field) const {
    return file_ + ":" + std::to_string(at.source().begin.line) + ": " + field;
}

void ValueReader::fail(const toml::node& at, const std::string& field,
                       const std::string& reason) const {
    throw_scene_error(file_, static_cast<int>(at.source().begin.line), field, reason);
}

/// A generator's error ("generate[1].radius: ...") with the line of the field it names,
/// where the block `t` (named `prefix`) has that key; the block's own line otherwise (a
/// count the generator derived from the packing fraction, the block as a whole).
void ValueReader::fail_generated(const toml::table& t, const std::string& prefix,
                                 const Error& e) const {
    const std::string_view message = e.what();
    int line = static_cast<int>(t.source().begin.line);
    if (message.substr(0, prefix.size() + 1) == prefix + ".") {
        const std::string_view rest = message.substr(prefix.size() + 1);
        const std::string key(rest.substr(0, rest.find_first_of(":[")));
        if (const toml::node* field = t.get(key)) {
            line = static_cast<int>(field->source().begin.line);
        }
    }
    throw_scene_error(file_, line, "", e.what());  // the generator names the field
}

void ValueReader::check_keys(const toml::table& table, const std::string& prefix,
                             const keys::Keys& allowed) const {
    for (auto&& [key, value] : table) {
        const std::string name(key.str());
        if (std::find(allowed.begin(), allowed.end(), name) != allowed.end()) continue;
        std::string reason = "unknown key '" + clipped(name) + "'";
        const std::string guess = nearest_name(name, allowed);
        reason += guess.empty() ? " (valid keys: " + joined(allowed) + ")"
                                : " (did you mean '" + guess + "'?)";
        throw_scene_error(file_, static_cast<int>(key.source().begin.line), prefix, reason);
    }
}

const toml::table& ValueReader::table_at(const toml::node& n, const std::string& field) const {
    const toml::table* t = n.as_table();
    if (t == nullptr) fail(n, field, "expected a table");
    return *t;
}

double ValueReader::number(const toml::node& n, const std::string& field) const {
    double v = 0.0;
    if (const auto* i = n.as_integer()) {
        v = static_cast<double>(i->get());
    } else if (const auto* f = n.as_floating_point()) {
        v = f->get();
    } else {
        fail(n, field, "expected a number");
    }
    if (!std::isfinite(v)) fail(n, field, "not a finite number (" + num(v) + ")");
    return v;
}

double ValueReader::positive(const toml::node& n, const std::string& field) const {
    const double v = number(n, field);
    if (!(v > 0.0)) fail(n, field, "must be > 0 (got " + num(v) + ")");
    return v;
}

// Named here rather than in validate_scene, which does not know the box's line.
double ValueReader::box_side(const toml::node& n, const std::string& field) const {
    const double v = positive(n, field);
    if (v > max_scene_magnitude)
        fail(n, field, "must be at most " + num(max_scene_magnitude) + " (got " + num(v) + ")");
    return v;
}

std::int64_t ValueReader::integer(const toml::node& n, const std::string& field,
                                  std::int64_t min) const {
    const auto* i = n.as_integer();
    if (i == nullptr) fail(n, field, "expected an integer");
    if (i->get() < min)
        fail(n, field,
             "must be >= " + std::to_string(min) + " (got " + std::to_string(i->get()) + ")");
    return i->get();
}

std::string ValueReader::text_value(const toml::node& n, const std::string& field) const {
    const auto* s = n.as_string();
    if (s == nullptr) fail(n, field, "expected a string");
    return s->get();
}

// Every text a scene carries has a bound, so that no text makes a frame slow to draw.
std::string ValueReader::bounded_text(const toml::node& n, const std::string& field,
                                      std::size_t max_chars) const {
    std::string text = text_value(n, field);
    const std::size_t chars = utf8_length(text);
    if (chars > max_chars) {
        fail(n, field,
             "too long: at most " + std::to_string(max_chars) + " characters, got " +
                 std::to_string(chars) + " (docs/scenes.md, \"Limits\")");
    }
    return text;
}

bool ValueReader::boolean(const toml::node& n, const std::string& field) const {
    const auto* b = n.as_boolean();
    if (b == nullptr) fail(n, field, "expected true or false");
    return b->get();
}

Vec2 ValueReader::pair(const toml::node& n, const std::string& field) const {
    const toml::array* a = n.as_array();
    if (a == nullptr || a->size() != 2) fail(n, field, "expected [x, y]");
    return {number(*a->get(0), field + "[0]"), number(*a->get(1), field + "[1]")};
}

Rgb8 ValueReader::rgb(const toml::node& n, const std::string& field) const {
    if (const toml::array* a = n.as_array()) {
        if (a->size() != 3)
            fail(n, field, "expected \"#rrggbb\" or [r, g, b] with integers 0..255");
        const auto channel = [&](std::size_t k) {
            const std::int64_t c = integer(*a->get(k), field + "[" + std::to_string(k) + "]", 0);
            if (c > 255)
                fail(*a->get(k), field,
                     "colour channels are 0..255 (got " + std::to_string(c) + ")");
            return static_cast<std::uint8_t>(c);
        };
        return {channel(0), channel(1), channel(2)};
    }
    const auto* s = n.as_string();
    const std::string hex = s ? s->get() : std::string();
    const bool ok =
        hex.size() == 7 && hex[0] == '#' && std::all_of(hex.begin() + 1, hex.end(), [](char c) {
            return std::isxdigit(static_cast<unsigned char>(c)) != 0;
        });
    if (!ok) fail(n, field, "expected \"#rrggbb\" or [r, g, b] with integers 0..255");
    const auto byte = [&](std::size_t at) {
        return static_cast<std::uint8_t>(std::stoi(hex.substr(at, 2), nullptr, 16));
    };
    return {byte(1), byte(3), byte(5)};
}

std::size_t ValueReader::utf8_length(const std::string& text) {
    return static_cast<std::size_t>(std::count_if(text.begin(), text.end(), [](char c) {
        return (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    }));
}

}  // namespace collide::toml_text
