#pragma once
/// \file
/// Numbers as a class reads them, for every module that writes one on screen.

#include <cmath>
#include <cstdio>
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

/// A count or a rate as every card, panel and plot writes it: whole, with thousands separators
/// ("57,213", "221,190,000"); below 1 (a rate) and beyond 10^15 in three significant digits
/// ("0.25", "1.2e+16"). One rule, so that no "57.2k" stands beside a "4,404".
[[nodiscard]] inline std::string count_text(double value) {
    const double magnitude = std::abs(value);
    if (!std::isfinite(value) || magnitude >= 1e15 || (magnitude > 0.0 && magnitude < 0.5)) {
        char text[32];
        std::snprintf(text, sizeof text, "%.3g", value);
        return text;
    }
    return with_separators(std::llround(value));
}

}  // namespace collide
