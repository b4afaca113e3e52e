#pragma once
/// \file
/// Numbers as a class reads them, for every module that writes one on screen.

#include <string>

namespace collide {

/// "1,234,567": thousands separators, for figures read from the back row.
[[nodiscard]] inline std::string with_separators(long long value) {
    const bool negative = value < 0;
    std::string digits = std::to_string(negative ? -(value + 1) + 1ULL : value + 0ULL);
    std::string out;
    const std::size_t n = digits.size();
    for (std::size_t i = 0; i < n; ++i) {
        out += digits[i];
        if ((n - i - 1) % 3 == 0 && i + 1 < n) out += ',';
    }
    return negative ? "-" + out : out;
}

}  // namespace collide
