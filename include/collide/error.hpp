#pragma once
/// \file
/// The one error type of collide. Library code throws; only `main` turns errors into messages
/// and exit codes (input -> 2, runtime -> 1).

#include <stdexcept>
#include <string>

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

/// Throws an input error "file:line: field: reason" (parts left empty/zero are omitted).
[[noreturn]] inline void throw_input_error(const std::string& file, int line,
                                           const std::string& field, const std::string& reason) {
    std::string msg = file;
    if (line > 0) msg += ":" + std::to_string(line);
    if (!field.empty()) msg += (msg.empty() ? "" : ": ") + field;
    msg += (msg.empty() ? "" : ": ") + reason;
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
