// End-to-end: `collide scenes` lists the built-in library with descriptions.

#include <doctest/doctest.h>

#include <cstdlib>
#include <sstream>
#include <string>

#include "run_collide.hpp"

using collide::test::run_collide;

TEST_CASE("collide scenes: one line per built-in scene, name then description") {
    const auto r = run_collide("scenes");
    CHECK(r.exit_code == 0);
    std::istringstream lines(r.output);
    std::string line;
    int count = 0;
    bool tunnelling = false;
    while (std::getline(lines, line)) {
        ++count;
        const auto space = line.find("  ");
        CHECK(space != std::string::npos);  // a description follows the name
        if (line.rfind("tunnelling ", 0) == 0) tunnelling = true;
    }
    CHECK(count >= 8);
    CHECK(tunnelling);
}

TEST_CASE("collide scenes: an assets directory without scenes is a clear error") {
    const char* saved = std::getenv("COLLIDE_ASSETS_DIR");
    const std::string previous = saved ? saved : "";
    ::setenv("COLLIDE_ASSETS_DIR", "/nonexistent", 1);  // the child process inherits it
    const auto r = run_collide("scenes");
    if (saved) {
        ::setenv("COLLIDE_ASSETS_DIR", previous.c_str(), 1);
    } else {
        ::unsetenv("COLLIDE_ASSETS_DIR");
    }
    CHECK(r.exit_code == 2);
    CHECK(r.output.find("no built-in scenes found in /nonexistent/scenes") != std::string::npos);
}
