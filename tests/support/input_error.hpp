#pragma once
// Shared by the test suites: the message of the input error an operation throws.

#include <doctest/doctest.h>

#include <string>
#include <utility>

#include "collide/error.hpp"

namespace collide::test {

/// Runs f; returns the message of the collide::Error it throws (and checks that the error is an
/// input error, exit code 2), or "" when it throws nothing.
template <class F>
std::string input_error_message(F&& f) {
    try {
        std::forward<F>(f)();
    } catch (const Error& e) {
        CHECK(e.kind() == ErrorKind::input);
        return e.what();
    }
    return "";
}

inline bool contains(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

}  // namespace collide::test
