#include "collide/sim/pq/queue_kind.hpp"

#include <charconv>
#include <string>
#include <system_error>

#include "collide/error.hpp"
#include "collide/sim/pq/dary_heap.hpp"

namespace collide::pq {

namespace {

constexpr unsigned max_dary_arity = DaryHeap<int, Orientation::min, 0>::max_runtime_arity;

bool is_compiled_indexed_arity(unsigned d) {
    return d == 2 || d == 3 || d == 4 || d == 8;
}

/// What a family's arity may be, for the error message.
std::string expected_arity(std::string_view family) {
    if (family == "dary")
        return "dary:D with D a whole number from 2 to " + std::to_string(max_dary_arity);
    return "indexed:D with D = 2, 3, 4 or 8 (or indexed alone: D = " +
           std::to_string(default_indexed_arity) + ")";
}

/// The arity after "family:"; the whole rest must be a decimal number in the family's range.
unsigned parse_arity(std::string_view family, std::string_view digits, std::string_view option,
                     std::string_view text) {
    unsigned d = 0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), d);
    const bool number =
        !digits.empty() && ec == std::errc{} && end == digits.data() + digits.size();
    const bool in_range =
        family == "dary" ? d >= 2 && d <= max_dary_arity : is_compiled_indexed_arity(d);
    if (!number || !in_range) throw_option_error(option, text, expected_arity(family));
    return d;
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
        throw_option_error(option, text,
                           "a queue: unordered, ordered, binary, dary:D or indexed[:D]");
    }
    const unsigned d = parse_arity(family, text.substr(colon + 1), option, text);
    return {family == "dary" ? QueueFamily::dary : QueueFamily::indexed, d};
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
