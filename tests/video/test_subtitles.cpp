// Subtitles as the encoder writes them: language tags, WebVTT and SubRip text.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "collide/error.hpp"
#include "collide/video/subtitles.hpp"

namespace collide::video {
namespace {

TEST_CASE("language tags: ISO 639-1 and both ISO 639-2 forms become the MP4's code") {
    CHECK(subtitle_language("pl") == "pol");
    CHECK(subtitle_language("PL") == "pol");
    CHECK(subtitle_language("cs") == "ces");
    CHECK(subtitle_language("cze") == "ces");  // bibliographic form
    CHECK(subtitle_language("ger") == "deu");
    CHECK(subtitle_language("el") == "ell");
    CHECK(subtitle_language("ru") == "rus");
    CHECK(subtitle_language("en") == "eng");
    CHECK(subtitle_language("und") == "und");
    for (const char* bad : {"xx", "", "e", "english", "pl-PL", "qqq", "p1"}) {
        CAPTURE(bad);
        CHECK_THROWS_WITH_AS((void)subtitle_language(bad, "--lang"), doctest::Contains("--lang: '"),
                             Error);
    }
}

TEST_CASE("sidecar formats come from the extension") {
    CHECK(subtitle_format_of("a/b.vtt") == SubtitleFormat::webvtt);
    CHECK(subtitle_format_of("b.SRT") == SubtitleFormat::srt);
    CHECK_THROWS_WITH_AS((void)subtitle_format_of("b.txt", "--subtitles-file"),
                         doctest::Contains("--subtitles-file: 'b.txt' must end in .vtt"), Error);
    CHECK_THROWS_AS((void)subtitle_format_of("vtt"), Error);
}

TEST_CASE("WebVTT: header, millisecond times, escaped markup, no blank line inside a cue") {
    const Cues cues = {{0.0, 1.5, "Δt ≈ 0.01 s\n\nσ <η> & more"}, {61.25, 3723.0, "a --> b"}};
    CHECK(webvtt_text(cues) ==
          "WEBVTT\n"
          "\n00:00:00.000 --> 00:00:01.500\nΔt ≈ 0.01 s\nσ &lt;η&gt; &amp; more\n"
          "\n00:01:01.250 --> 01:02:03.000\na -&gt; b\n");
    CHECK(webvtt_text({}) == "WEBVTT\n");
}

TEST_CASE("SubRip: numbered blocks, comma before the milliseconds, empty cues left out") {
    const Cues cues = {{0.0, 2.0, "Zażółć"}, {2.0, 3.0, "\n"}, {3.0, 4.0, "a --> b\nline 2"}};
    CHECK(srt_text(cues) ==
          "1\n00:00:00,000 --> 00:00:02,000\nZażółć\n"
          "\n2\n00:00:03,000 --> 00:00:04,000\na -> b\nline 2\n");
}

namespace {

/// How many lines of `file` a reader takes for the start of a cue: any line with the arrow of a
/// timing line (FFmpeg's SubRip reader takes "H:M:S,ms --> H:M:S,ms" anywhere, WebVTT's any
/// line holding "-->").
std::size_t timing_lines(const std::string& file) {
    std::size_t count = 0;
    for (std::size_t at = file.find("-->"); at != std::string::npos; at = file.find("-->", at + 1))
        ++count;
    return count;
}

}  // namespace

TEST_CASE("cue text: no arrow, control character or blank line survives, letters do") {
    CHECK(plain_cue_text("a --> b") == "a -> b");
    CHECK(plain_cue_text("a ---> b") == "a -> b");  // one pass left "-->"
    CHECK(plain_cue_text("a ----> b -----> c") == "a -> b -> c");
    CHECK(plain_cue_text("<!-- x -->") == "<!-- x ->");
    CHECK(plain_cue_text("a -- > b") == "a -- > b");  // no reader takes this for an arrow
    CHECK(plain_cue_text("a\r\rb") == "a\nb");        // a lone CR ends a line for FFmpeg
    CHECK(plain_cue_text("a\r\n\r\nb") == "a\nb");
    CHECK(plain_cue_text("a\n \t \nb\n\x0b\x0c\n") == "a\nb");  // lines of white space end cues too
    CHECK(plain_cue_text("a\x1b[2Jb\x07\x7f") == "a[2Jb");
    CHECK(plain_cue_text("a\xc2\x9b"
                         "2Jb\xc2\x85"
                         "c") == "a2Jbc");  // C1: CSI, NEL
    CHECK(plain_cue_text("a\tb") == "a b");
    CHECK(plain_cue_text("Zażółć ≈ σ → η ½") == "Zażółć ≈ σ → η ½");
    CHECK(plain_cue_text("a-->") == "a->");
    CHECK(plain_cue_text("-->-->") == "->->");
}

TEST_CASE("forged cues: scene text never adds a cue to a SubRip or WebVTT file") {
    // Text written to look like the end of its cue and the start of another, in every spelling.
    const std::vector<std::string> forgeries = {
        "ok\n\n2\n00:00:00,500 ---> 00:00:09,000\nforged",
        "ok\n\n2\n00:00:00,500 ----> 00:00:09,000\nforged",
        "ok\r\r2\r00:00:00,500 ---> 00:00:09,000\rforged",
        "ok\n \n2\n00:00:00.500 -->> 00:00:09.000\nforged",
        "ok\n\x0c\n2\n00:00:00,500 -\x1b-> 00:00:09,000\nforged",
        "ok\n\n2\n00:00:00,500 -\xc2\x85-> 00:00:09,000\nforged",
        "ok\n\n2\n00:00:00,500 --\t> 00:00:09,000\nforged",
        "12\n00:00:01,000-->00:00:02,000",
    };
    for (const std::string& text : forgeries) {
        CAPTURE(text);
        const Cues cues = {{0.0, 1.0, "first"}, {1.0, 2.0, text}, {2.0, 3.0, "last"}};
        CHECK(timing_lines(srt_text(cues)) == 3);
        CHECK(timing_lines(webvtt_text(cues)) == 3);
        CHECK(srt_text(cues).find("\n\n3\n00:00:02,000 --> 00:00:03,000\nlast\n") !=
              std::string::npos);
        const std::string shown = plain_cue_text(text);
        CHECK(shown.find("\n\n") == std::string::npos);
        CHECK(shown.find('\r') == std::string::npos);
    }
}

TEST_CASE("WebVTT chapters: one cue per chapter, its title as the text") {
    const Chapters chapters = {{0.0, 2.0, "Title <card>"}, {2.0, 61.5, "Kule się zderzają"}};
    CHECK(webvtt_chapters_text(chapters) ==
          "WEBVTT\n"
          "\n00:00:00.000 --> 00:00:02.000\nTitle &lt;card&gt;\n"
          "\n00:00:02.000 --> 00:01:01.500\nKule się zderzają\n");
}

}  // namespace
}  // namespace collide::video
