#include "cli_numbers.hpp"

#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <cassert>
#include <charconv>

#include "collide/error.hpp"

namespace collide::app {

namespace {

/// Runs `parse`; a bad value becomes a CLI11 usage error (exit 2 with the hint to --help, like
/// every other bad option value) carrying our message.
template <typename Parse>
std::uint64_t as_usage_error(Parse&& parse) {
    try {
        return parse();
    } catch (const Error& e) {
        throw CLI::ValidationError(e.what());
    }
}

}  // namespace

std::uint64_t parse_whole_number(std::string_view text, std::string_view option, std::uint64_t min,
                                 std::uint64_t max) {
    const auto bad = [&](std::string_view how) {
        throw_option_error(option, text,
                           fmt::format("a whole number{} from {} to {}", how, min, max));
    };
    std::string_view digits = text;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    if (digits.empty() || digits.front() == '-' || digits.front() == '+') bad("");
    std::uint64_t value = 0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (end != digits.data() + digits.size()) bad(" in decimal digits");
    if (error != std::errc{} || value < min || value > max) bad("");
    return value;
}

CLI::Option* add_whole_option(CLI::App& app, const std::string& name, std::uint64_t& target,
                              std::uint64_t min, std::uint64_t max, const std::string& help) {
    const std::string option = name.substr(0, name.find(','));
    CLI::Option* added = app.add_option_function<std::string>(
        name,
        [&target, option, min, max](const std::string& text) {
            target = as_usage_error([&] { return parse_whole_number(text, option, min, max); });
        },
        help);
    return added->type_name("INT");  // in --help, the man page and completion
}

CLI::Option* add_whole_option(CLI::App& app, const std::string& name, int& target, int min, int max,
                              const std::string& help) {
    assert(0 <= min && min <= max);
    const std::string option = name.substr(0, name.find(','));
    CLI::Option* added = app.add_option_function<std::string>(
        name,
        [&target, option, min, max](const std::string& text) {
            target = static_cast<int>(as_usage_error([&] {
                return parse_whole_number(text, option, static_cast<std::uint64_t>(min),
                                          static_cast<std::uint64_t>(max));
            }));
        },
        help);
    return added->type_name("INT");  // in --help, the man page and completion
}

namespace {

/// True for the type names CLI11 gives numbers, alone or as a list ("FLOAT", "INT ...").
bool numeric_type_name(std::string_view name) {
    for (const std::string_view number : {"FLOAT", "INT", "UINT", "NUMBER"}) {
        if (name.substr(0, name.find(' ')) == number) return true;
    }
    return false;
}

}  // namespace

void refuse_empty_numbers(CLI::App& app) {
    // No description: the help shows the option as before.
    const CLI::Validator not_empty(
        [](std::string& text) {
            return text.empty() ? std::string("expected a number, got an empty value")
                                : std::string();
        },
        "");
    for (CLI::Option* option : app.get_options()) {
        if (option->get_expected_max() > 0 && numeric_type_name(option->get_type_name())) {
            option->check(not_empty);
        }
    }
    for (CLI::App* command : app.get_subcommands([](CLI::App*) { return true; })) {
        refuse_empty_numbers(*command);
    }
}

}  // namespace collide::app
