#pragma once
// Shared by the test suites: a fresh, uniquely named directory, removed with everything in it.

#include <stdlib.h>  // mkdtemp

#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>

namespace collide::test {

struct TempDir {
    std::filesystem::path path;

    /// Creates $TMPDIR/collide_<name>_XXXXXX (unique, so parallel test processes never share it).
    explicit TempDir(const std::string& name) {
        std::string pattern =
            (std::filesystem::temp_directory_path() / ("collide_" + name + "_XXXXXX")).string();
        if (mkdtemp(pattern.data()) == nullptr)
            throw std::runtime_error("mkdtemp failed for " + pattern);
        path = pattern;
    }
    ~TempDir() {
        std::error_code ignored;
        std::filesystem::remove_all(path, ignored);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
};

}  // namespace collide::test
