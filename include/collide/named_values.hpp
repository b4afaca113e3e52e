#pragma once
/// \file
/// Enum values a user chooses by name (`--engine classic`, `--theme light`, `theme = "light"` in a
/// scene): one table per enum gives both the parse, whose error names the option and lists the
/// valid names, and the name printed back. Std-only, for every module.

#include <algorithm>
#include <array>
#include <cctype>
#include <cstddef>
#include <string>
#include <string_view>

#include "collide/error.hpp"

namespace collide {

/// One name of an enum value. A value may have several (aliases: `h265` for `hevc`); the first
/// listed is its own name, the one printed and the one error messages list.
template <class E>
struct NamedValue {
    std::string_view name;
    E value;
};

/// How parse_named compares the text typed with the names.
enum class NameCase : unsigned char {
    exact,   ///< `Light` is not `light` (command-line and scene names)
    ignore,  ///< `MP4` is `mp4` (formats and codecs, as file extensions are written)
};

/// The own name of `value` in `table` (its first listed name); `fallback` when it has none.
template <class E, std::size_t N>
[[nodiscard]] constexpr std::string_view name_of(E value, const std::array<NamedValue<E>, N>& table,
                                                 std::string_view fallback = "?") noexcept {
    for (const NamedValue<E>& entry : table) {
        if (entry.value == value) return entry.name;
    }
    return fallback;
}

/// The own names of `table`, in order, as a user reads them: "a, b or c" (aliases left out).
template <class E, std::size_t N>
[[nodiscard]] std::string list_names(const std::array<NamedValue<E>, N>& table) {
    std::array<std::string_view, N> own{};
    std::size_t count = 0;
    for (const NamedValue<E>& entry : table) {
        if (name_of(entry.value, table) == entry.name) own[count++] = entry.name;
    }
    std::string out;
    for (std::size_t i = 0; i < count; ++i) {
        if (i > 0) out += i + 1 == count ? " or " : ", ";
        out += own[i];
    }
    return out;
}

/// The value named `text` in `table`. Throws Error(input) through throw_option_error:
/// "OPTION: expected a, b or c, got 'text'", or with `kind` ("an event-driven engine"):
/// "OPTION: expected an event-driven engine (a or b), got 'text'". O(N).
template <class E, std::size_t N>
[[nodiscard]] E parse_named(std::string_view text, std::string_view option,
                            const std::array<NamedValue<E>, N>& table, std::string_view kind = "",
                            NameCase name_case = NameCase::exact) {
    const auto lower = [](char c) {
        return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    };
    const auto same = [&](std::string_view name) {
        if (name_case == NameCase::exact) return name == text;
        return std::equal(name.begin(), name.end(), text.begin(), text.end(),
                          [&](char a, char b) { return lower(a) == lower(b); });
    };
    for (const NamedValue<E>& entry : table) {
        if (same(entry.name)) return entry.value;
    }
    const std::string names = list_names(table);
    throw_option_error(option, text, kind.empty() ? names : std::string(kind) + " (" + names + ")");
}

}  // namespace collide
