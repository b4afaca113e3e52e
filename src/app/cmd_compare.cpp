/// `collide compare EXPECTED ACTUAL [--tolerance T] [--max-diff-pixels N] [--max-diff-percent P]
/// [--diff FILE] [--json]`: a golden-image check for CI. A pixel differs when one of its channels
/// differs by more than T; the images match when no more pixels differ than the allowances let
/// pass (none by default). Exit 0 on a match, 1 when they differ (a difference image is written
/// and the differences counted), 2 on bad input. It runs in `collide` itself: it needs a PNG
/// reader and writer, no GL and no encoder, so it starts in milliseconds.

#include <fmt/core.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <system_error>

#include "cli_numbers.hpp"
#include "collide/error.hpp"
#include "collide/io/file.hpp"
#include "collide/video/png.hpp"
#include "commands.hpp"
#include "image_compare.hpp"
#include "json_output.hpp"

namespace collide::app {

namespace {

struct CompareOptions {
    std::string expected;
    std::string actual;
    int tolerance = 0;
    std::uint64_t max_diff_pixels = 0;
    double max_diff_percent = 100.0;
    std::string diff;
    bool json = false;
    CLI::Option* diff_opt = nullptr;
    CLI::Option* pixels_opt = nullptr;
    CLI::Option* percent_opt = nullptr;
};

/// Where the difference image goes: --diff, else ACTUAL's stem + ".diff.png" beside it.
std::filesystem::path diff_path(const CompareOptions& o) {
    if (o.diff_opt != nullptr && o.diff_opt->count() > 0) return o.diff;
    const std::filesystem::path actual(o.actual);
    return actual.parent_path() / (actual.stem().string() + ".diff.png");
}

/// What lets the comparison pass: the tolerance, and the allowances given (none: no pixel may
/// differ; one or both: every one given must hold).
CompareAllowance allowance_of(const CompareOptions& o) {
    CompareAllowance a;
    a.tolerance = o.tolerance;
    const bool pixels_given = o.pixels_opt->count() > 0;
    const bool percent_given = o.percent_opt->count() > 0;
    a.max_pixels = pixels_given    ? static_cast<std::int64_t>(o.max_diff_pixels)
                   : percent_given ? std::numeric_limits<std::int64_t>::max()
                                   : 0;
    a.max_percent = percent_given ? o.max_diff_percent : 100.0;
    return a;
}

Json size_json(const Image& image) {
    return Json{{"width", image.width}, {"height", image.height}};
}

/// The --json document: what was compared, against what allowance, and how they differ.
Json report_json(const CompareOptions& o, const Image& a, const Image& b, bool match,
                 const std::optional<ImageComparison>& c, const std::string& diff_written,
                 const std::string& diff_error) {
    Json j;
    j["result"] = match ? "match" : (c ? "differ" : "size");
    j["expected"] = o.expected;
    j["actual"] = o.actual;
    j["expected_size"] = size_json(a);
    j["actual_size"] = size_json(b);
    j["tolerance"] = o.tolerance;
    j["max_diff_pixels"] = o.pixels_opt->count() > 0 ? Json(o.max_diff_pixels) : Json(nullptr);
    j["max_diff_percent"] = o.percent_opt->count() > 0 ? Json(o.max_diff_percent) : Json(nullptr);
    if (c) {
        j["pixels"] = c->pixels;
        j["differing"] = c->differing;
        j["differing_percent"] = c->differing_percent();
        j["touched"] = c->touched;
        j["largest_difference"] = c->largest;
        j["mean_difference"] = c->mean_differing;
        const PixelBox& box = c->differing_box;
        j["bounding_box"] = box.empty() ? Json(nullptr)
                                        : Json{{"x", box.x0},
                                               {"y", box.y0},
                                               {"width", box.width()},
                                               {"height", box.height()}};
    }
    j["diff_image"] = diff_written.empty() ? Json(nullptr) : Json(diff_written);
    if (!diff_error.empty()) j["diff_error"] = diff_error;
    return j;
}

/// " (within --max-diff-pixels 20)" and the like: what let differing pixels pass.
std::string allowance_text(const CompareOptions& o) {
    std::string text;
    if (o.pixels_opt->count() > 0) text += fmt::format("--max-diff-pixels {}", o.max_diff_pixels);
    if (o.percent_opt->count() > 0) {
        text +=
            (text.empty() ? "" : ", ") + fmt::format("--max-diff-percent {}", o.max_diff_percent);
    }
    return text;
}

void run_compare(const CompareOptions& o) {
    const std::filesystem::path diff = diff_path(o);
    // The difference image never replaces an image it compares (`--diff EXPECTED`, or EXPECTED
    // named ACTUAL.diff.png): refused before anything is read (exit 2).
    io::check_outputs_not_inputs({{"--diff", diff, false}},
                                 {{"EXPECTED", o.expected}, {"ACTUAL", o.actual}});
    const Image a = video::read_png(o.expected);  // Error(input) -> exit 2 naming the file
    const Image b = video::read_png(o.actual);
    if (a.width != b.width || a.height != b.height) {
        if (o.json) {
            std::fputs(json_text(report_json(o, a, b, false, std::nullopt, "", "")).c_str(),
                       stdout);
        } else {
            std::printf("differ: %s is %dx%d, %s is %dx%d\n", o.expected.c_str(), a.width, a.height,
                        o.actual.c_str(), b.width, b.height);
        }
        throw ExitStatus{1};
    }
    const ImageComparison c = compare_images(a, b, o.tolerance);
    const bool match = within(c, allowance_of(o));
    std::string written;
    std::string diff_error;
    if (!match) {
        try {
            video::write_png(difference_image(a, b, o.tolerance), diff);
            written = diff.string();
        } catch (const Error& e) {
            diff_error = e.what();
        }
    }
    if (o.json) {
        std::fputs(json_text(report_json(o, a, b, match, c, written, diff_error)).c_str(), stdout);
    } else if (match) {
        std::string allowed;
        if (c.differing > 0) allowed = " (within " + allowance_text(o) + ")";
        std::printf(
            "match: %lld pixels, %lld differ by more than %d%s (largest difference %d, "
            "%lld pixels differ at all)\n",
            static_cast<long long>(c.pixels), static_cast<long long>(c.differing), o.tolerance,
            allowed.c_str(), c.largest, static_cast<long long>(c.touched));
    } else {
        const PixelBox& box = c.differing_box;
        const std::string where =
            fmt::format(", within {}x{} at ({}, {})", box.width(), box.height(), box.x0, box.y0);
        const std::string picture =
            !written.empty() ? "; difference image: " + written + " (red: beyond the tolerance)"
                             : "; no difference image: " + diff_error;
        const std::string beyond =
            allowance_text(o).empty() ? "" : " (more than " + allowance_text(o) + " allow)";
        std::printf(
            "differ: %lld of %lld pixels (%.3g%%) differ by more than %d%s: by %.1f on average, "
            "at most %d (of 255)%s%s\n",
            static_cast<long long>(c.differing), static_cast<long long>(c.pixels),
            c.differing_percent(), o.tolerance, beyond.c_str(), c.mean_differing, c.largest,
            where.c_str(), picture.c_str());
    }
    if (!match) throw ExitStatus{1};
}

}  // namespace

void add_compare_command(CLI::App& root) {
    auto o = std::make_shared<CompareOptions>();
    CLI::App* cmd = root.add_subcommand(
        "compare",
        "Compare two PNG images: exit 0 if they match, 1 if not (writing a difference image), 2 "
        "on bad input");
    cmd->add_option("expected", o->expected, "The reference image (PNG), e.g. a golden image")
        ->required()
        ->type_name("PATH");
    cmd->add_option("actual", o->actual, "The image to check (PNG)")->required()->type_name("PATH");
    add_whole_option(*cmd, "--tolerance", o->tolerance, 0, 255,
                     "Largest difference allowed in any channel of a pixel, 0..255 (default 0: "
                     "identical)");
    o->pixels_opt = add_whole_option(
        *cmd, "--max-diff-pixels", o->max_diff_pixels, 0,
        static_cast<std::uint64_t>(video::max_png_side) * video::max_png_side,
        "How many pixels may differ by more than the tolerance and the images still match "
        "(default 0)");
    o->percent_opt =
        cmd->add_option("--max-diff-percent", o->max_diff_percent,
                        "What share of the pixels, in percent (0..100), may differ by more than "
                        "the tolerance and the images still match; with --max-diff-pixels, both "
                        "must hold")
            ->type_name("FLOAT")
            ->check(CLI::Validator(
                [](const std::string& text) -> std::string {
                    try {
                        std::size_t used = 0;
                        const double p = std::stod(text, &used);
                        if (used == text.size() && std::isfinite(p) && p >= 0.0 && p <= 100.0)
                            return {};
                    } catch (const std::exception&) {
                    }
                    return "--max-diff-percent: expected a percentage 0..100, got '" + text + "'";
                },
                "", "percentage"));
    o->diff_opt = cmd->add_option("--diff", o->diff,
                                  "Where the difference image goes when they differ (default "
                                  "ACTUAL.diff.png beside ACTUAL); never one of the inputs")
                      ->type_name("PATH");
    cmd->add_flag("--json", o->json,
                  "Print the result as JSON: sizes, pixels compared and differing, the largest "
                  "channel difference, the bounding box of the differences, the difference image");
    cmd->footer(
        "Examples:\n"
        "  collide thumbnail gas --at 2 --size 320x180 -o gas.png\n"
        "  collide compare golden/gas.png gas.png --tolerance 2 --max-diff-pixels 50");
    cmd->callback([o] { run_compare(*o); });
}

}  // namespace collide::app
