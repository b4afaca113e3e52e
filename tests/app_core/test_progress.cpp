// The progress line: fits the terminal, plain lines for CI logs.

#include <doctest/doctest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "progress.hpp"

using namespace collide::app;

TEST_CASE("the progress bar fits the terminal's width, dropping the least useful figures first") {
    const ProgressState state{120, 300, 3.25, 10.0};
    const std::string wide = format_bar(state, 200);
    CHECK(wide.size() == 199);  // the bar takes what the figures leave
    CHECK(wide.find("120/300 frames") != std::string::npos);
    CHECK(wide.find("t = 3.25") != std::string::npos);
    CHECK(wide.find("ETA 0:15") != std::string::npos);
    for (const int columns : {120, 80, 60, 40, 30, 20, 5, 1}) {
        CAPTURE(columns);
        const std::string line = format_bar(state, columns);
        CHECK(static_cast<int>(line.size()) <= columns - 1);
        if (columns >= 30) {
            CHECK(line.find(" 40%") != std::string::npos);
            CHECK(line.find("ETA") != std::string::npos);
            CHECK(line.find("[####") == 0);  // still a bar
        }
    }
    // At 60 columns the simulation time goes before the frame count.
    const std::string sixty = format_bar(state, 60);
    CHECK(sixty.find("t = ") == std::string::npos);
    CHECK(sixty.find("ETA 0:15") != std::string::npos);
}

TEST_CASE("the terminal width comes from $COLUMNS when the stream is no terminal") {
    std::FILE* file = std::tmpfile();
    REQUIRE(file != nullptr);
    ::setenv("COLUMNS", "57", 1);
    CHECK(terminal_columns(file) == 57);
    ::setenv("COLUMNS", "wide", 1);
    CHECK(terminal_columns(file) == 80);
    ::unsetenv("COLUMNS");
    CHECK(terminal_columns(file) == 80);
    std::fclose(file);
}

TEST_CASE("--progress plain: a line per tenth of the frames, and none of them rewritten") {
    CHECK(parse_progress_mode("plain") == ProgressMode::plain);
    std::FILE* file = std::tmpfile();
    REQUIRE(file != nullptr);
    {
        Progress progress(ProgressMode::plain, 50, file);
        for (int i = 0; i < 50; ++i) progress.frame_done(0.1 * i);
        progress.finish();
    }
    std::rewind(file);
    std::string text;
    for (int c = std::fgetc(file); c != EOF; c = std::fgetc(file)) text += static_cast<char>(c);
    std::fclose(file);
    INFO(text);
    CHECK(text.find('\r') == std::string::npos);
    int lines = 0;
    for (const char c : text) lines += c == '\n' ? 1 : 0;
    CHECK(lines == 10);
    CHECK(text.find("collide: 10% (5/50 frames") == 0);
    CHECK(text.find("collide: 100% (50/50 frames") != std::string::npos);
}
