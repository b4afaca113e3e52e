#pragma once
/// \file
/// The one error type of collide. Library code throws; only `main` turns errors into messages
/// and exit codes (input -> 2, runtime -> 1).

#include <stdexcept>
#include <string>
#include <string_view>

namespace collide {

/// Why an operation failed; decides the process exit code.
enum class ErrorKind {
    input,    ///< bad scene file, CLI argument or path given by the user: exit code 2
    runtime,  ///< anything else (GL context, encoder, disk full): exit code 1
};

/// The single exception type thrown by collide's libraries. `what()` is a one-line message that
/// already names the file, line and field where that is known.
class Error : public std::runtime_error {
  public:
    Error(ErrorKind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
    [[nodiscard]] ErrorKind kind() const noexcept { return kind_; }
    [[nodiscard]] int exit_code() const noexcept { return kind_ == ErrorKind::input ? 2 : 1; }

  private:
    ErrorKind kind_;
};

/// The field-error helper: throws an input error about one field of what the user gave, at a
/// place in a scene file (or another file the user named) when that is known:
/// "file:line: field: reason" (parts left empty/zero are omitted), e.g.
/// "gas.toml:12: generate[0].radius: must be > 0 (got -1)", or "until: the end time must be
/// finite" for a field with no file (a config field, an argument the app maps to its option).
[[noreturn]] inline void throw_scene_error(const std::string& file, int line,
                                           const std::string& field, const std::string& reason) {
    std::string msg = file;
    if (line > 0) msg += ":" + std::to_string(line);
    if (!field.empty()) msg += (msg.empty() ? "" : ": ") + field;
    msg += (msg.empty() ? "" : ": ") + reason;
    throw Error(ErrorKind::input, msg);
}

/// Throws an input error about an option's value: "OPTION: expected EXPECTED, got 'VALUE'", e.g.
/// "--engine: expected fast or classic, got 'warp'". `option` is what the user typed (`--fps`),
/// or a scene key standing in for it ("gas.toml:7: render.dt"); `expected` says what would be
/// accepted, in words a user can act on.
[[noreturn]] inline void throw_option_error(std::string_view option, std::string_view value,
                                            std::string_view expected) {
    std::string msg(option);
    msg += ": expected ";
    msg += expected;
    msg += ", got '";
    msg += value;
    msg += "'";
    throw Error(ErrorKind::input, msg);
}

/// Throws an input error about an option that is wrong as a whole rather than by its value (a
/// conflict with another option, a missing value): "OPTION: REASON".
[[noreturn]] inline void throw_option_error(std::string_view option, std::string_view reason) {
    std::string msg(option);
    msg += ": ";
    msg += reason;
    throw Error(ErrorKind::input, msg);
}

/// Throws an input error with a ready message.
[[noreturn]] inline void throw_input_error(const std::string& message) {
    throw Error(ErrorKind::input, message);
}

/// Throws a runtime (non-input) error.
[[noreturn]] inline void throw_runtime_error(const std::string& message) {
    throw Error(ErrorKind::runtime, message);
}

}  // namespace collide
