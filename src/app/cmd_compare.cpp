/// `collide compare A.png B.png [--tolerance T] [--diff FILE]`: a golden-image check for CI.
/// Exit 0 when the images match (no pixel differs by more than T in any channel), 1 when they do
/// not (a difference image is written and the differences counted), 2 on bad input.

#include <fmt/core.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "cli_numbers.hpp"
#include "collide/error.hpp"
#include "collide/io/file.hpp"
#include "collide/video/png.hpp"
#include "commands.hpp"
#include "image_compare.hpp"

namespace collide::app {

namespace {

struct CompareOptions {
    std::string expected;
    std::string actual;
    int tolerance = 0;
    std::string diff;
    CLI::Option* diff_opt = nullptr;
};

/// Where the difference image goes: --diff, else ACTUAL's stem + ".diff.png" beside it.
std::filesystem::path diff_path(const CompareOptions& o) {
    if (o.diff_opt != nullptr && o.diff_opt->count() > 0) return o.diff;
    const std::filesystem::path actual(o.actual);
    return actual.parent_path() / (actual.stem().string() + ".diff.png");
}

void run_compare(const CompareOptions& o) {
    // The difference image never replaces an image it compares (`--diff EXPECTED`, or EXPECTED
    // named ACTUAL.diff.png): refused before anything is read (exit 2).
    io::check_outputs_not_inputs({{"--diff", diff_path(o), false}},
                                 {{"EXPECTED", o.expected}, {"ACTUAL", o.actual}});
    const Image a = video::read_png(o.expected);  // Error(input) -> exit 2 naming the file
    const Image b = video::read_png(o.actual);
    if (a.width != b.width || a.height != b.height) {
        std::printf("differ: %s is %dx%d, %s is %dx%d\n", o.expected.c_str(), a.width, a.height,
                    o.actual.c_str(), b.width, b.height);
        throw ExitStatus{1};
    }
    const ImageComparison c = compare_images(a, b, o.tolerance);
    if (c.match()) {
        std::printf(
            "match: %lld pixels, none differs by more than %d (largest difference %d, "
            "%lld pixels differ at all)\n",
            static_cast<long long>(c.pixels), o.tolerance, c.largest,
            static_cast<long long>(c.touched));
        return;
    }
    const std::filesystem::path diff = diff_path(o);
    std::string written;
    try {
        video::write_png(difference_image(a, b, o.tolerance), diff);
        written = "; difference image: " + diff.string() + " (red: beyond the tolerance)";
    } catch (const Error& e) {
        written = std::string("; no difference image: ") + e.what();
    }
    std::printf(
        "differ: %lld of %lld pixels (%.3g%%) differ by more than %d: by %.1f on average, "
        "at most %d (of 255)%s\n",
        static_cast<long long>(c.differing), static_cast<long long>(c.pixels),
        100.0 * static_cast<double>(c.differing) / static_cast<double>(c.pixels), o.tolerance,
        c.mean_differing, c.largest, written.c_str());
    throw ExitStatus{1};
}

}  // namespace

void add_compare_command(CLI::App& root) {
    auto o = std::make_shared<CompareOptions>();
    CLI::App* cmd = root.add_subcommand(
        "compare",
        "Compare two PNG images: exit 0 if they match, 1 if not (writing a difference image), 2 "
        "on bad input");
    cmd->add_option("expected", o->expected, "The reference image (PNG), e.g. a golden image")
        ->required();
    cmd->add_option("actual", o->actual, "The image to check (PNG)")->required();
    add_whole_option(*cmd, "--tolerance", o->tolerance, 0, 255,
                     "Largest difference allowed in any channel of a pixel, 0..255 (default 0: "
                     "identical)");
    o->diff_opt = cmd->add_option("--diff", o->diff,
                                  "Where the difference image goes when they differ (default "
                                  "ACTUAL.diff.png beside ACTUAL)");
    cmd->footer(
        "Examples:\n"
        "  collide thumbnail gas --at 2 --size 320x180 -o gas.png\n"
        "  collide compare golden/gas.png gas.png --tolerance 2");
    cmd->callback([o] { run_compare(*o); });
}

}  // namespace collide::app
