// End-to-end: `collide scenes` lists the built-in library with descriptions.

#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>

#include "../support/temp_dir.hpp"
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

TEST_CASE("a built-in scene whose file is a broken or looping link is said to be one") {
    namespace fs = std::filesystem;
    const collide::test::TempDir dir("scenes_links");
    fs::create_directories(dir.path / "scenes");
    const fs::path scenes = dir.path / "scenes";
    fs::create_symlink("loop.toml", scenes / "loop.toml");  // itself
    fs::create_symlink("pong.toml", scenes / "ping.toml");  // two that lead to each other
    fs::create_symlink("ping.toml", scenes / "pong.toml");
    fs::create_symlink("removed.toml", scenes / "broken.toml");
    const std::string env = "COLLIDE_DATA_DIR='" + dir.path.string() + "'";
    struct Case {
        const char* args;
        const char* says;
    };
    for (const Case& c :
         {Case{"check loop", "is a symbolic link in a loop"},
          Case{"simulate ping --until 1", "is a symbolic link in a loop"},
          Case{"render pong -o never.mp4", "is a symbolic link in a loop"},
          Case{"thumbnail broken -o never.png", "is a broken symbolic link (to 'removed.toml')"},
          Case{"check broken", "is a broken symbolic link"}}) {
        CAPTURE(c.args);
        const auto r = collide::test::run_collide_env(env, c.args);
        CHECK(r.exit_code == 2);
        CHECK(r.output.find(c.says) != std::string::npos);
        CHECK(r.output.find("not a built-in scene") == std::string::npos);
        CHECK(r.output.find("did you mean") == std::string::npos);
    }
    // A name that is not there at all is still an unknown name.
    const auto unknown = collide::test::run_collide_env(env, "check lop");
    CHECK(unknown.exit_code == 2);
    CHECK(unknown.output.find("not a built-in scene") != std::string::npos);
}
