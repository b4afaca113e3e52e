// The test harness itself (tests/doctest_main.cpp, tests/support/skip.hpp): a test that did not
// run must show as Skipped or Failed in ctest, never as Passed.
#include <doctest/doctest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "../support/skip.hpp"

namespace {

/// Runs this test executable again with `arguments` (and `environment` before it); its exit code.
int run_self(const std::string& environment, const std::string& arguments) {
    const std::string self = std::filesystem::read_symlink("/proc/self/exe").string();
    const std::string command = environment + " '" + self + "' " + arguments + " >/dev/null 2>&1";
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

TEST_CASE("harness: a skipped test exits 77 for ctest's SKIP_RETURN_CODE and no match fails") {
    if (std::getenv("COLLIDE_HARNESS_PROBE") != nullptr)
        COLLIDE_SKIP_TEST("the probe run of the harness test");
    CHECK(run_self("COLLIDE_HARNESS_PROBE=1", "'--test-case=harness: a skipped test*'") ==
          collide::test::skip_exit_code);
    CHECK(run_self("", "'--test-case=no test has this name'") == 1);
    CHECK(run_self("", "--list-test-cases") == 0);
}
