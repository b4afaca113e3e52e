// `--handout F.pdf` (issue #46): one page per chapter, its still and its words, for `render`,
// `heap` and `puzzle`; read back with poppler's pdfinfo and pdftoppm (every page renders, none is
// blank). Bad input (a still, a name that is no .pdf, an input as the output) exits 2 and writes
// nothing.

#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "../support/files.hpp"
#include "../support/shell.hpp"
#include "../support/skip.hpp"
#include "../support/temp_dir.hpp"
#include "collide/image.hpp"
#include "collide/video/png.hpp"
#include "run_collide.hpp"
#include "subtitle_file.hpp"

using collide::test::capture;
using collide::test::run_collide;
using collide::test::run_command;
using collide::test::TempDir;

namespace {

namespace fs = std::filesystem;

bool have_poppler() {
    return run_command("command -v pdfinfo >/dev/null 2>&1 && command -v pdftoppm >/dev/null 2>&1")
               .exit_code == 0;
}

/// The "Pages:" line of pdfinfo; -1 when pdfinfo cannot read the file.
int pdf_pages(const fs::path& pdf) {
    const auto r = run_command("pdfinfo \"" + pdf.string() + "\" 2>&1");
    if (r.exit_code != 0) return -1;
    const std::size_t at = r.output.find("Pages:");
    if (at == std::string::npos) return -1;
    return std::stoi(r.output.substr(at + 6));
}

/// How many distinct grey levels a page has (a blank page: one).
std::size_t grey_levels(const collide::Image& page) {
    std::vector<bool> seen(256, false);
    for (int y = 0; y < page.height; ++y) {
        for (int x = 0; x < page.width; ++x) {
            const std::uint8_t* p = page.pixel(x, y);
            seen[(p[0] + p[1] + p[2]) / 3] = true;
        }
    }
    return static_cast<std::size_t>(std::count(seen.begin(), seen.end(), true));
}

/// Renders every page of `pdf` with pdftoppm into `dir` and checks each: a PNG, landscape, with
/// a still (many grey levels, not a blank page).
void check_pages(const fs::path& pdf, int pages, const fs::path& dir) {
    const fs::path stem = dir / "page";
    const auto r =
        run_command("pdftoppm -r 40 -png \"" + pdf.string() + "\" \"" + stem.string() + "\" 2>&1");
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    std::vector<fs::path> rendered;
    for (const auto& entry : fs::directory_iterator(dir)) {
        if (entry.path().filename().string().rfind("page-", 0) == 0)
            rendered.push_back(entry.path());
    }
    CHECK(static_cast<int>(rendered.size()) == pages);
    for (const fs::path& png : rendered) {
        CAPTURE(png);
        const collide::Image page = collide::video::read_png(png);
        CHECK(page.width > page.height);  // A4 landscape
        CHECK(grey_levels(page) > 20);
    }
}

/// The number of chapters in a WebVTT chapters file.
int chapters_in(const fs::path& vtt) {
    return static_cast<int>(
        collide::test::parse_subtitles(collide::test::read_all(vtt), true).size());
}

/// Runs `args` with a handout and a chapters file, and checks the handout against the chapters.
void check_handout(const std::string& args, const std::string& name) {
    TempDir dir("handout_" + name);
    const fs::path pdf = dir.path / (name + ".pdf");
    const fs::path vtt = dir.path / (name + ".vtt");
    const auto r = run_collide(args + " --progress none -o \"" + (dir.path / name).string() +
                               ".mp4\" --chapters-file \"" + vtt.string() + "\" --handout \"" +
                               pdf.string() + "\"");
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    const int chapters = chapters_in(vtt);
    CHECK(chapters > 1);
    CHECK(pdf_pages(pdf) == chapters);
    const fs::path pages = dir.path / "pages";
    fs::create_directory(pages);
    check_pages(pdf, chapters, pages);
    // The words are text in the PDF: the chapters' titles are there to search and copy.
    const std::string text = capture("pdftotext \"" + pdf.string() + "\" - 2>/dev/null");
    const std::vector<collide::test::ParsedCue> titles =
        collide::test::parse_subtitles(collide::test::read_all(vtt), true);
    const std::string first_word = titles.back().text.substr(0, titles.back().text.find(' '));
    CHECK_MESSAGE(text.find(first_word) != std::string::npos, first_word);
}

}  // namespace

TEST_CASE("render --handout: a page per chapter of tunnelling, each with its still") {
    if (!have_poppler()) COLLIDE_SKIP_TEST("pdfinfo/pdftoppm (poppler-utils) are not installed");
    check_handout("render tunnelling -q l", "tunnelling");
}

TEST_CASE("heap and puzzle --handout: a page per chapter") {
    if (!have_poppler()) COLLIDE_SKIP_TEST("pdfinfo/pdftoppm (poppler-utils) are not installed");
    check_handout("heap --ops \"P Q E * X\" --size 480x270 --fps 10", "heap");
    check_handout("puzzle \"1 2 3 4 0 6 7 5 8\" --size 854x480 --fps 10", "puzzle");
}

TEST_CASE("--handout: bad input exits 2 and writes nothing") {
    TempDir dir("handout_bad");
    // An input named like a PDF: the font (read by its contents, whatever its name).
    const fs::path font = dir.path / "font.pdf";
    fs::copy_file("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", font);
    const std::string base = "render billiards --size 160x90 --fps 5 --duration 1 --progress none ";
    const std::string mp4 = "-o \"" + (dir.path / "t.mp4").string() + "\" ";
    struct Case {
        std::string args;
        std::string message;
    };
    std::vector<Case> cases = {
        {mp4 + "--handout \"" + (dir.path / "h.txt").string() + "\"", "a PDF file name (.pdf)"},
        {mp4 + "--handout \"" + (dir.path / "missing" / "h.pdf").string() + "\"", "--handout"},
        {"--format mp4 -o \"" + (dir.path / "h.pdf").string() + "\" --handout \"" +
             (dir.path / "h.pdf").string() + "\"",
         "--handout"},
        {"--last-frame -o \"" + (dir.path / "t.png").string() + "\" --handout \"" +
             (dir.path / "h.pdf").string() + "\"",
         "--handout: a still (PNG) has no chapters"},
    };
    for (const Case& c : cases) {
        CAPTURE(c.args);
        const auto r = run_collide(base + c.args);
        CHECK(r.exit_code == 2);
        CHECK_MESSAGE(r.output.find(c.message) != std::string::npos, r.output);
        CHECK(!fs::exists(dir.path / "t.mp4"));
        CHECK(!fs::exists(dir.path / "h.pdf"));
    }
    // The font, an input of the run, as the handout: refused, and the font is kept as it was.
    {
        const std::string before = collide::test::read_all(font);
        const auto r = run_collide(base + mp4 + "--font \"" + font.string() + "\" --handout \"" +
                                   font.string() + "\"");
        CHECK(r.exit_code == 2);
        CHECK_MESSAGE(r.output.find("--handout") != std::string::npos, r.output);
        CHECK(collide::test::read_all(font) == before);
        CHECK(!fs::exists(dir.path / "t.mp4"));
    }
    // A text-only puzzle run takes no handout.
    const auto solve = run_collide("puzzle \"1 2 3 4 0 6 7 5 8\" --solve --handout \"" +
                                   (dir.path / "h.pdf").string() + "\"");
    CHECK(solve.exit_code == 2);
    CHECK(solve.output.find("--handout") != std::string::npos);
}
