#pragma once
// A test that cannot run (reference data absent, no display, an optional encoder missing) must
// show as "Skipped" in ctest's summary, never as "Passed". COLLIDE_SKIP_TEST(why) prints
// "SKIP: why", records the skip and returns from the test case. When every test case a process
// ran was skipped (ctest runs one per process) and none failed, doctest_main.cpp exits with
// skip_exit_code, which tests/CMakeLists.txt declares as every test's SKIP_RETURN_CODE.
//
// Not doctest's `skip` decorator: it is decided when the executable starts, and a decorated test
// is left out of --list-test-cases, so a test skipped while ctest discovered the tests would
// vanish from ctest instead of showing as skipped, and one run by name would exit 0 (Passed).

#include <doctest/doctest.h>

namespace collide::test {

/// The exit code of a test process whose test cases were all skipped (automake's convention).
inline constexpr int skip_exit_code = 77;

/// Marks the running test case as skipped (defined in tests/doctest_main.cpp).
void note_skipped();

}  // namespace collide::test

/// Skips the running test case, saying why, and returns from the enclosing function (the test
/// case, or a void helper: the test case then still counts as skipped).
#define COLLIDE_SKIP_TEST(why)           \
    do {                                 \
        ::collide::test::note_skipped(); \
        MESSAGE("SKIP: " << why);        \
        return;                          \
    } while (false)
