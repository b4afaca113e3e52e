#pragma once
// JSON on standard output, always valid (RFC 8259): every document the CLI prints is built as a
// value and written by nlohmann::json, never by hand.

#include <nlohmann/json.hpp>
#include <string>

namespace collide::app {

/// A JSON value whose objects keep their keys in insertion order (the order documented).
using Json = nlohmann::ordered_json;

/// `value` as JSON text with a final newline: strings have their control characters, quotes and
/// backslashes escaped and invalid UTF-8 (a file name is any bytes) replaced by U+FFFD; NaN and
/// infinities become null. `indent` < 0: one line.
[[nodiscard]] inline std::string json_text(const Json& value, int indent = 2) {
    return value.dump(indent, ' ', false, Json::error_handler_t::replace) + "\n";
}

}  // namespace collide::app
