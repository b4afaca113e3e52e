// The words of scene messages (toml_text.hpp) and nearest_name, the "did you mean" of every
// unknown key or name (collide/scene/load.hpp).

#include "toml_text.hpp"

#include <algorithm>
#include <sstream>
#include <string_view>

#include "collide/scene/load.hpp"

namespace collide {

namespace toml_text {

std::string num(double v) {
    std::ostringstream s;
    s.precision(6);
    s << v;
    return s.str();
}

/// A value as echoed in a message: whole when short, else its start and its length (a 10 MB key
/// is not worth printing).
std::string clipped(const std::string& text) {
    constexpr std::size_t shown = 40;
    if (text.size() <= shown + 3) return text;
    std::size_t cut = shown;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;  // UTF-8
    return text.substr(0, cut) + "... (" + std::to_string(text.size()) + " bytes)";
}

std::string joined(const std::vector<std::string>& keys) {
    std::string s;
    for (const std::string& k : keys) s += (s.empty() ? "" : ", ") + k;
    return s;
}

}  // namespace toml_text

namespace {

// Optimal string alignment distance: insertions, deletions, substitutions and swaps of two
// neighbouring letters ("titel" -> "title") each cost 1.
std::size_t edit_distance(std::string_view a, std::string_view b) {
    const std::size_t w = b.size() + 1;
    std::vector<std::size_t> d((a.size() + 1) * w);
    for (std::size_t i = 0; i <= a.size(); ++i) d[i * w] = i;
    for (std::size_t j = 0; j <= b.size(); ++j) d[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            std::size_t best = std::min(
                {d[(i - 1) * w + j] + 1, d[i * w + j - 1] + 1, d[(i - 1) * w + j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                best = std::min(best, d[(i - 2) * w + j - 2] + 1);
            d[i * w + j] = best;
        }
    }
    return d[a.size() * w + b.size()];
}

}  // namespace

std::string nearest_name(std::string_view word, const std::vector<std::string>& candidates) {
    std::string best;
    std::size_t best_distance = 0;
    for (const std::string& c : candidates) {
        // The distance is at least the difference in length: a candidate that far off can never
        // be suggested, and measuring it would cost a table of word x candidate (a 10 MB key:
        // seconds and a gigabyte).
        const std::size_t longer = std::max(word.size(), c.size());
        const std::size_t shorter = std::min(word.size(), c.size());
        if (longer - shorter > std::max<std::size_t>(1, longer / 3)) continue;
        const std::size_t d = edit_distance(word, c);
        if (best.empty() || d < best_distance) {
            best = c;
            best_distance = d;
        }
    }
    // A typo changes a few letters; beyond a third of the word it is a different word.
    const std::size_t allowed = std::max<std::size_t>(1, std::max(word.size(), best.size()) / 3);
    return best_distance <= allowed ? best : std::string();
}

}  // namespace collide
