#pragma once
// Internal: the token syntax shared by `collide pq` (trace.cpp) and `collide heap`
// (heap_record.cpp): white-space separated tokens; a key is a word of letters or an integer, and
// one sequence never mixes the two. One definition, so that both commands read the same input the
// same way and say the same thing about it.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "collide/sim/pq/trace.hpp"

namespace collide::pq::tokens {

/// Throws Error(input): "<option>: token <token> '<spelling>': <why>" (tokens count from 1).
[[noreturn]] void reject(std::string_view option, std::size_t token, std::string_view spelling,
                         const std::string& why);

/// A non-empty run of ASCII letters.
[[nodiscard]] bool is_word(std::string_view s) noexcept;
/// An optional sign and a non-empty run of digits (in range or not).
[[nodiscard]] bool is_integer(std::string_view s) noexcept;

/// Splits at ASCII white space.
[[nodiscard]] std::vector<std::string_view> split(std::string_view text);

/// A key from one word or in-range integer; nullopt for anything else.
[[nodiscard]] std::optional<TraceKey> key_of(std::string_view text);

/// "a number" / "a word".
[[nodiscard]] const char* kind_name(const TraceKey& key) noexcept;

/// Words and numbers do not mix: the first key checked decides; check() rejects any later key of
/// the other kind, naming it and the first one.
class KeyKindCheck {
  public:
    explicit KeyKindCheck(std::string_view option) : option_(option) {}
    void check(const TraceKey& key, std::size_t token, std::string_view spelling);

  private:
    std::string_view option_;
    std::optional<TraceKey> first_;
    std::string first_spelling_;
};

}  // namespace collide::pq::tokens
