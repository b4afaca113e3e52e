#pragma once
// What a TOML scene may cost before toml++ sees it: a lexical pass over the text that refuses
// nesting the parser would recurse into without bound (dotted keys and table headers are not
// covered by its own limit on nested arrays and inline tables: `a.a.a...(50,000 times) = 1`
// overflows the stack) and more values than a scene could sensibly hold (the parsed document
// costs about 100 bytes per value, so a small file of `{},{},...` would take gigabytes).

#include <cstddef>
#include <string>
#include <string_view>

namespace collide {

/// The deepest nesting a TOML scene may have, counting every table-header and dotted-key part,
/// every array and every inline table on the way to a value. A scene needs four or five.
inline constexpr std::size_t max_toml_depth = 64;

/// The most values (keys, array elements, tables) a TOML scene may hold: room for 200,000
/// explicit [[disc]] tables; larger scenes belong in algs4 files or [[generate]] blocks.
inline constexpr std::size_t max_toml_values = 2'000'000;

/// Throws Error(input) "FILE:LINE: ..." when `text` nests deeper than max_toml_depth or holds
/// more than max_toml_values values. Linear in the text; never recurses. Syntax errors are left
/// to the parser (a malformed file passes or is refused here by the same rules).
void check_toml_limits(std::string_view text, const std::string& file);

}  // namespace collide
