#pragma once
// Internal: the ISO 639 language codes a subtitle track may be tagged with.

#include <array>
#include <cstddef>

namespace collide::video::detail {

struct Iso639 {
    const char* terminology;    ///< ISO 639-2/T, three letters: what MP4 stores ("deu")
    const char* two_letter;     ///< ISO 639-1, or "" ("de")
    const char* bibliographic;  ///< ISO 639-2/B where it differs, or "" ("ger")
};

inline constexpr std::size_t iso639_count = 486;
extern const std::array<Iso639, iso639_count> iso639_codes;  ///< sorted by `terminology`

}  // namespace collide::video::detail
