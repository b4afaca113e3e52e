#pragma once
/// \file
/// Whole-number options parsed strictly. CLI11 converts with strtoull/strtoll in base 0, so
/// `--seed -1` wraps to 2^64 - 1, `--seed 18446744073709551616` saturates to it, and `--seed 010`
/// is octal 8, all without a word. These accept plain decimal digits only, in a stated range, and
/// name the option otherwise (exit 2).

#include <cstdint>
#include <string>
#include <string_view>

#include "cli_fwd.hpp"

namespace collide::app {

/// Decimal digits (an optional leading '+') whose value lies in [min, max]; anything else (a sign,
/// a fraction, an exponent, hex, a value out of range) throws Error(input) naming `option`.
[[nodiscard]] std::uint64_t parse_whole_number(std::string_view text, std::string_view option,
                                               std::uint64_t min, std::uint64_t max);

/// Registers an option whose value is parsed by parse_whole_number into `target`; a bad value
/// throws CLI::ValidationError (a usage error: exit 2 and the hint to --help) with that message.
CLI::Option* add_whole_option(CLI::App& app, const std::string& name, std::uint64_t& target,
                              std::uint64_t min, std::uint64_t max, const std::string& help);
/// The same for an int target, 0 <= min <= max.
CLI::Option* add_whole_option(CLI::App& app, const std::string& name, int& target, int min, int max,
                              const std::string& help);

/// Refuses an empty value (`--at ""`, `--duration=`) for every numeric option of `app` and of its
/// subcommands, at any depth: CLI11 would read it as 0. Whole-number options (above) refuse it
/// themselves; this covers the others, the ones whose type name CLI11 shows as FLOAT, INT, UINT
/// or NUMBER. A usage error (exit 2) naming the option. Call once all options are registered.
void refuse_empty_numbers(CLI::App& app);

}  // namespace collide::app
