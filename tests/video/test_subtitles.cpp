// Subtitles as the encoder writes them: language tags, WebVTT and SubRip text.
#include <doctest/doctest.h>

#include <string>

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
          "\n00:01:01.250 --> 01:02:03.000\na --&gt; b\n");
    CHECK(webvtt_text({}) == "WEBVTT\n");
}

TEST_CASE("SubRip: numbered blocks, comma before the milliseconds, empty cues left out") {
    const Cues cues = {{0.0, 2.0, "Zażółć"}, {2.0, 3.0, "\n"}, {3.0, 4.0, "a --> b\nline 2"}};
    CHECK(srt_text(cues) ==
          "1\n00:00:00,000 --> 00:00:02,000\nZażółć\n"
          "\n2\n00:00:03,000 --> 00:00:04,000\na -> b\nline 2\n");
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
