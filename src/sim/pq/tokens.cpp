#include "pq/tokens.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <system_error>

#include "collide/error.hpp"

namespace collide::pq::tokens {

void reject(std::string_view option, std::size_t token, std::string_view spelling,
            const std::string& why) {
    throw_input_error(std::string(option) + ": token " + std::to_string(token) + " '" +
                      std::string(spelling) + "': " + why);
}

bool is_word(std::string_view s) noexcept {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
        return std::isalpha(static_cast<unsigned char>(c)) != 0;
    });
}

bool is_integer(std::string_view s) noexcept {
    if (!s.empty() && (s.front() == '+' || s.front() == '-')) s.remove_prefix(1);
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
        return std::isdigit(static_cast<unsigned char>(c)) != 0;
    });
}

std::vector<std::string_view> split(std::string_view text) {
    std::vector<std::string_view> out;
    std::size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i])) != 0) ++i;
        const std::size_t start = i;
        while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i])) == 0) ++i;
        if (i > start) out.push_back(text.substr(start, i - start));
    }
    return out;
}

std::optional<TraceKey> key_of(std::string_view text) {
    TraceKey key;
    if (is_word(text)) {
        key.word = std::string(text);
        return key;
    }
    if (!is_integer(text)) return std::nullopt;
    key.numeric = true;
    if (text.front() == '+') text.remove_prefix(1);  // from_chars takes '-' but not '+'
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), key.number);
    if (ec != std::errc{} || end != text.data() + text.size()) return std::nullopt;
    return key;
}

const char* kind_name(const TraceKey& key) noexcept {
    return key.numeric ? "a number" : "a word";
}

void KeyKindCheck::check(const TraceKey& key, std::size_t token, std::string_view spelling) {
    if (!first_) {
        first_ = key;
        first_spelling_ = std::string(spelling);
        return;
    }
    if (key.numeric != first_->numeric) {
        reject(option_, token, spelling,
               std::string("is ") + kind_name(key) + " but the first key '" + first_spelling_ +
                   "' is " + kind_name(*first_) + "; keys must be all words or all numbers");
    }
}

}  // namespace collide::pq::tokens
