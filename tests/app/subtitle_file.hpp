#pragma once
// A strict reader of the subtitle and chapter files collide writes (WebVTT and SubRip), for the
// end-to-end tests: it fails the running test case on anything malformed.

#include <doctest/doctest.h>

#include <cstdio>
#include <string>
#include <vector>

namespace collide::test {

/// One cue of a parsed subtitle file.
struct ParsedCue {
    double start = 0.0;
    double end = 0.0;
    std::string text;
};

/// "HH:MM:SS.mmm" (or ',' before the milliseconds) in seconds; -1 when malformed.
inline double parse_time(const std::string& t) {
    int h = 0, m = 0, s = 0, ms = 0;
    char sep = 0;
    if (t.size() != 12 || std::sscanf(t.c_str(), "%2d:%2d:%2d%c%3d", &h, &m, &s, &sep, &ms) != 5)
        return -1.0;
    if (m > 59 || s > 59) return -1.0;
    return h * 3600.0 + m * 60.0 + s + ms / 1000.0;
}

/// A strict reader of the two formats as we write them: WebVTT (the "WEBVTT" line, then blocks
/// "start --> end" + text lines) or SubRip (numbered blocks 1, 2, ... with ',' in the times).
/// Blocks are separated by one empty line; times increase and never overlap. Fails the test
/// case (REQUIRE) on anything else.
inline std::vector<ParsedCue> parse_subtitles(const std::string& file_text, bool webvtt) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (start < file_text.size()) {
        const std::size_t end = file_text.find('\n', start);
        REQUIRE(end != std::string::npos);  // every line ends with a newline
        lines.push_back(file_text.substr(start, end - start));
        start = end + 1;
    }
    std::size_t i = 0;
    if (webvtt) {
        REQUIRE(!lines.empty());
        REQUIRE(lines[0] == "WEBVTT");
        i = 1;
    }
    std::vector<ParsedCue> cues;
    while (i < lines.size()) {
        if (webvtt || !cues.empty()) {
            REQUIRE(lines[i].empty());  // the blank line between blocks
            ++i;
        }
        REQUIRE(i < lines.size());
        if (!webvtt) {
            REQUIRE(lines[i] == std::to_string(cues.size() + 1));
            ++i;
        }
        REQUIRE(i < lines.size());
        const std::string& timing = lines[i++];
        REQUIRE(timing.size() == 29);
        REQUIRE(timing.substr(12, 5) == " --> ");
        const char sep = webvtt ? '.' : ',';
        CHECK(timing[8] == sep);
        ParsedCue cue{parse_time(timing.substr(0, 12)), parse_time(timing.substr(17)), ""};
        REQUIRE(cue.start >= 0.0);
        REQUIRE(cue.end > cue.start);
        if (!cues.empty()) CHECK(cue.start >= cues.back().end);
        while (i < lines.size() && !lines[i].empty()) {
            if (!cue.text.empty()) cue.text += '\n';
            cue.text += lines[i++];
        }
        REQUIRE(!cue.text.empty());
        cues.push_back(cue);
    }
    return cues;
}

/// `text` without carriage returns, without <...> tags and with one newline at the end.
inline std::string without_markup(const std::string& text) {
    std::string out;
    bool in_tag = false;
    for (const char c : text) {
        if (c == '<') in_tag = true;
        if (!in_tag && c != '\r') out += c;
        if (c == '>') in_tag = false;
    }
    while (!out.empty() && out.back() == '\n') out.pop_back();
    return out + '\n';
}

}  // namespace collide::test
