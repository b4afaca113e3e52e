#pragma once
// The values of a TOML scene file, each read as the type its field takes and checked, with
// "file:line: field" in every error (the scene reader of toml_scene.cpp reads its tables
// through these).
#include <toml++/toml.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>

#include "collide/disc.hpp"
#include "collide/error.hpp"
#include "collide/vec2.hpp"
#include "toml_text.hpp"

namespace collide::toml_text {

class ValueReader {
  public:
    /// `file`: the name errors give the scene file (its path, or "<text>").
    explicit ValueReader(std::string file) : file_(std::move(file)) {}

  protected:
    std::string where(const toml::node& at, const std::string& field) const;

    [[noreturn]] void fail(const toml::node& at, const std::string& field,
                           const std::string& reason) const;

    /// A generator's error ("generate[1].radius: ...") with the line of the field it names,
    /// where the block `t` (named `prefix`) has that key; the block's own line otherwise (a
    /// count the generator derived from the packing fraction, the block as a whole).
    [[noreturn]] void fail_generated(const toml::table& t, const std::string& prefix,
                                     const Error& e) const;

    void check_keys(const toml::table& table, const std::string& prefix,
                    const keys::Keys& allowed) const;

    const toml::table& table_at(const toml::node& n, const std::string& field) const;

    double number(const toml::node& n, const std::string& field) const;

    double positive(const toml::node& n, const std::string& field) const;

    // Named here rather than in validate_scene, which does not know the box's line.
    double box_side(const toml::node& n, const std::string& field) const;

    std::int64_t integer(const toml::node& n, const std::string& field, std::int64_t min) const;

    std::string text_value(const toml::node& n, const std::string& field) const;

    // Every text a scene carries has a bound, so that no text makes a frame slow to draw.
    std::string bounded_text(const toml::node& n, const std::string& field,
                             std::size_t max_chars) const;

    bool boolean(const toml::node& n, const std::string& field) const;

    Vec2 pair(const toml::node& n, const std::string& field) const;

    Rgb8 rgb(const toml::node& n, const std::string& field) const;

    /// Characters, not bytes: the bounds on texts count what a reader sees.
    static std::size_t utf8_length(const std::string& text);

    std::string file_;
};

}  // namespace collide::toml_text
