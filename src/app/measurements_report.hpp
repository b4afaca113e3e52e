#pragma once
/// \file
/// Measurements as named fields, printed as `key: value` lines or as one JSON object. One list
/// of fields for every engine, so `collide simulate --json` prints the same keys whatever ran.

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "collide/sim/measurements.hpp"

namespace collide::app {

/// One named figure: a count or a real number.
struct ReportField {
    std::string key;
    std::variant<std::uint64_t, double, std::string> value;
};

/// Every field of Measurements (momentum as momentum_x / momentum_y, the queue statistics as
/// pq_pushes, pq_pops, pq_updates, stale_events, pq_max_size), in a stable order.
[[nodiscard]] std::vector<ReportField> report_fields(const Measurements& m);

/// `key: value` lines.
[[nodiscard]] std::string format_text(const std::vector<ReportField>& fields);

/// One JSON object, one key per line, in the fields' order (json_text: always valid JSON,
/// whatever bytes a text field holds); non-finite numbers become null (JSON has no inf/nan).
[[nodiscard]] std::string format_json(const std::vector<ReportField>& fields);

}  // namespace collide::app
