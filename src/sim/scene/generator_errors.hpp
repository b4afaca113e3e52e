#pragma once
// What the disc and sphere generators say when a [[generate]] or [[fcc]] entry cannot be built:
// the entry's field named as the scene file spells it, numbers as a reader would write them.

#include <sstream>
#include <string>

#include "collide/error.hpp"

namespace collide::detail {

/// A number in at most six significant digits ("0.3", "1e+06").
inline std::string num(double v) {
    std::ostringstream s;
    s.precision(6);
    s << v;
    return s.str();
}

/// Throws Error(input) naming `prefix.field` ("generate[2].count"), or `prefix` alone when
/// `field` is empty; the scene loader adds the file and line.
[[noreturn]] inline void fail(const std::string& prefix, const std::string& field,
                              const std::string& reason) {
    throw_scene_error("", 0, prefix + (field.empty() ? "" : "." + field), reason);
}

}  // namespace collide::detail
