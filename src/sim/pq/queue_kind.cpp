#include "collide/sim/pq/queue_kind.hpp"

#include <charconv>
#include <string>
#include <system_error>

#include "collide/error.hpp"

namespace collide::pq {

namespace {

constexpr std::string_view expected_kinds = "unordered|ordered|binary|dary:D|indexed";

[[noreturn]] void reject(std::string_view option, std::string_view text, std::string_view why) {
    throw_input_error(std::string(option) + ": " + std::string(why) + " '" + std::string(text) +
                      "' (expected " + std::string(expected_kinds) + ")");
}

/// The arity after "family:"; the whole rest must be a decimal number.
unsigned parse_arity(std::string_view digits, std::string_view option, std::string_view text) {
    unsigned d = 0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), d);
    if (digits.empty() || ec != std::errc{} || end != digits.data() + digits.size()) {
        reject(option, text, "bad arity in queue");
    }
    return d;
}

bool is_compiled_indexed_arity(unsigned d) {
    return d == 2 || d == 3 || d == 4 || d == 8;
}

}  // namespace

QueueKind parse_queue_kind(std::string_view text, std::string_view option) {
    if (text == "unordered") return {QueueFamily::unordered, 0};
    if (text == "ordered") return {QueueFamily::ordered, 0};
    if (text == "binary") return {QueueFamily::binary, 2};
    if (text == "indexed") return {QueueFamily::indexed, default_indexed_arity};

    const std::size_t colon = text.find(':');
    const std::string_view family = text.substr(0, colon);
    if (colon == std::string_view::npos || (family != "dary" && family != "indexed")) {
        reject(option, text, "unknown queue");
    }
    const unsigned d = parse_arity(text.substr(colon + 1), option, text);
    if (family == "dary") {
        if (d < 2 || d > DaryHeap<int, Orientation::min, 0>::max_runtime_arity) {
            reject(option, text, "arity must be 2..64 in queue");
        }
        return {QueueFamily::dary, d};
    }
    if (!is_compiled_indexed_arity(d)) reject(option, text, "arity must be 2, 3, 4 or 8 in queue");
    return {QueueFamily::indexed, d};
}

std::string to_string(const QueueKind& kind) {
    switch (kind.family) {
        case QueueFamily::unordered:
            return "unordered";
        case QueueFamily::ordered:
            return "ordered";
        case QueueFamily::binary:
            return "binary";
        case QueueFamily::dary:
            return "dary:" + std::to_string(kind.d);
        case QueueFamily::indexed:
            return "indexed:" + std::to_string(kind.d);
    }
    return "unknown";
}

}  // namespace collide::pq
