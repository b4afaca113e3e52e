// `collide heap`'s command line and its checks (heap_cli.hpp), shared by both programs.
#include "heap_cli.hpp"

#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "cli_numbers.hpp"
#include "cli_types.hpp"
#include "collide/error.hpp"
#include "collide/render_options.hpp"
#include "collide/show/heap_code.hpp"
#include "collide/sim/pq/heap_record.hpp"
#include "font_search.hpp"

namespace collide::app {

namespace {

/// --pace, checked: (0, 60] seconds per step.
show::HeapPacing pacing_of(double pace) {
    if (!std::isfinite(pace) || pace <= 0.0 || pace > 60.0)
        throw_option_error("--pace", fmt::format("{}", pace), "(0, 60] seconds per step");
    return show::heap_pacing(pace);
}

/// The record of the operations (or of the heapsort); the options it reads were checked.
pq::HeapRecord record_of(const HeapCli& v) {
    const auto orientation = v.min ? pq::Orientation::min : pq::Orientation::max;
    if (given(v.sort_opt)) {
        if (given(v.impl_opt))
            throw_option_error("--impl", "--sort is heapsort on a binary heap; leave --impl out");
        const std::vector<pq::TraceKey> keys = pq::parse_sort_keys(v.sort, "--sort");
        return pq::HeapRecord::heapsort(keys, orientation);
    }
    const std::vector<pq::HeapOp> ops = pq::parse_heap_ops(v.ops, "--ops");
    std::vector<pq::QueueKind> kinds;
    for (const std::string& impl : v.impls) kinds.push_back(pq::parse_queue_kind(impl, "--impl"));
    if (kinds.empty()) kinds.push_back({pq::QueueFamily::binary, 2});
    if (kinds.size() > render::max_heap_panels) {
        throw_option_error("--impl", fmt::format("at most {} implementations side by side, got {}",
                                                 render::max_heap_panels, kinds.size()));
    }
    return pq::HeapRecord::operations(ops, kinds, orientation, "--ops", "--impl");
}

show::HeapProgram lesson_of(const HeapCli& v) {
    if (given(v.ops_opt) == given(v.sort_opt))
        throw_option_error("--ops", "give either --ops \"P Q E * ...\" or --sort \"S O R T ...\"");
    if (v.index_base != 0 && v.index_base != 1)
        throw_option_error("--index-base", std::to_string(v.index_base), "0 or 1");
    const show::HeapPacing pacing = pacing_of(v.pace);
    show::HeapProgram lesson(record_of(v), pacing, v.index_base);
    if (v.code) {
        if (!show::heap_code_fits(lesson.record())) {
            throw_option_error("--code",
                               "shows the code of one heap beside it; give a single "
                               "heap (--impl binary, dary:D or indexed), or --sort");
        }
        lesson.show_code(true);
    }
    if (v.questions != "on" && v.questions != "none")
        throw_option_error("--questions", v.questions, "on or none");
    lesson.ask_questions(v.questions == "on");
    return lesson;
}

/// Refuses a lesson whose queue holds more keys than the frame can show legibly.
void check_legible(const pq::HeapRecord& record, const HeapCli& v) {
    const std::size_t panels = record.panels().size();
    const std::size_t limit = render::max_legible_keys(panels, v.code);
    if (record.capacity() <= limit) return;
    throw_option_error(
        given(v.sort_opt) ? "--sort" : "--ops",
        fmt::format("the queue holds up to {} keys at once, but at most {} can be drawn "
                    "legibly with {} panel{} side by side (keys over ~14 px tall at "
                    "854x480){}; use fewer keys{}",
                    record.capacity(), limit, panels, panels == 1 ? "" : "s",
                    v.code ? " beside the code" : "",
                    panels > 1 ? " or fewer implementations"
                    : v.code   ? " or leave out --code"
                               : ""));
}

/// The least frame height whose heap lessons are checked to fit (check_fits): -q l's.
constexpr int lesson_check_height = 480;

/// The lesson's frames checked for fit (HeapProgram::fit_check_times), each panel cut to at
/// most `keys` keys.
std::vector<view::HeapFrameView> layouts_of(const show::HeapProgram& lesson, std::size_t keys) {
    std::vector<view::HeapFrameView> frames;
    for (const double t : lesson.fit_check_times()) {
        view::HeapFrameView frame = lesson.frame_at(t);
        for (view::HeapPanelView& panel : frame.panels) {
            panel.capacity = std::min(panel.capacity, keys);
            if (panel.slots.size() > keys) panel.slots.resize(keys);
        }
        frames.push_back(std::move(frame));
    }
    return frames;
}

/// Refuses a lesson whose trees, maps and keys do not all fit `config`'s frame with every
/// label at the lesson size (HeapRenderer::fits: no node on a node, every key inside its
/// node), naming the most keys at once that would fit these panels; rather than draw a
/// squashed picture.
void check_fits(const show::HeapProgram& lesson, const render::HeapViewConfig& config,
                const HeapCli& v) {
    // Below -q l's 480 lines (previews, thumbnails) the text stands at its least size, larger
    // than 2.8 % of the frame, and the picture is a sketch: the check is for lesson sizes.
    if (config.height < lesson_check_height) return;
    const std::size_t capacity = lesson.record().capacity();
    const auto fit = [&](std::size_t keys) {
        const std::vector<view::HeapFrameView> frames = layouts_of(lesson, keys);
        return std::all_of(frames.begin(), frames.end(), [&](const view::HeapFrameView& f) {
            return render::HeapRenderer::fits(config, f);
        });
    };
    if (fit(capacity)) return;
    std::size_t most = capacity - 1;
    while (most > 0 && !fit(most)) --most;
    const std::size_t panels = lesson.record().panels().size();
    const bool words = lesson.widest_key().size() > 2;
    std::string impls;
    for (const std::string& impl : v.impls) impls += (impls.empty() ? "" : ",") + impl;
    throw_option_error(
        given(v.sort_opt) ? "--sort" : "--ops",
        fmt::format("the queue holds up to {} keys at once, but {} fit{} a {}x{} frame with {} "
                    "(every node apart and every key inside its node at the lesson size){}; "
                    "use fewer keys{}{}",
                    capacity, most == 0 ? std::string("none") : "at most " + std::to_string(most),
                    most == 1 ? "s" : "", config.width, config.height,
                    "--impl " + (impls.empty() ? std::string("binary") : impls),
                    v.code ? " beside the code" : "", words ? ", shorter keys" : "",
                    panels > 1 ? " or fewer implementations" : ""));
}

/// The lesson, checked, and legible at any frame size (check_legible).
show::HeapProgram checked_lesson(const HeapCli& v) {
    show::HeapProgram lesson = lesson_of(v);
    check_legible(lesson.record(), v);
    return lesson;
}

/// The renderer's configuration for `lesson` in `geometry`'s frame, checked to fit (check_fits).
render::HeapViewConfig fitted_config(const show::HeapProgram& lesson,
                                     const AlgorithmVideoGeometry& geometry, Theme theme,
                                     const HeapCli& v) {
    render::HeapViewConfig config;
    config.font_path = find_drawing_font(v.video.font);
    config.width = geometry.width;
    config.height = geometry.height;
    config.widest_key = lesson.widest_key();
    config.keys = lesson.keys();
    config.captions = lesson.captions();
    if (lesson.shows_code()) config.code_lines = lesson.code_lines();
    config.theme = theme;
    check_fits(lesson, config, v);
    return config;
}

}  // namespace

CheckedHeap::CheckedHeap(const HeapCli& v)
    : progress_mode(parse_progress_mode(v.video.progress)),
      theme(parse_theme(v.video.theme, "--theme")),
      lesson(checked_lesson(v)),
      geometry(algorithm_video_geometry_of(v.video)),
      config(fitted_config(lesson, geometry, theme, v)),
      destination(
          algorithm_video_destination_of(v.video, "heap", lesson.duration(), lesson.name())) {
    check_timeline_json(v.timeline_json, destination);
}

CLI::App* add_heap_options(CLI::App& root, HeapCli& values) {
    CLI::App* cmd = root.add_subcommand(
        "heap",
        "Animate priority-queue operations: heaps as trees over their arrays, step by step");
    values.ops_opt =
        cmd->add_option("--ops", values.ops,
                        "Operations separated by spaces, as in `collide pq`: a key (word "
                        "or integer) inserts, '*' removes the max (min), KEY^NEW raises "
                        "KEY to NEW (increase-key, --impl indexed only)")
            ->type_name(operations_type);
    values.sort_opt =
        cmd->add_option("--sort", values.sort,
                        "Heapsort these keys instead: heap construction, then sortdown")
            ->type_name(keys_type);
    values.impl_opt =
        cmd->add_option("--impl", values.impls,
                        "Implementations, one panel each, repeatable or comma-separated: "
                        "unordered|ordered|binary|dary:D|indexed[:D] (default binary)")
            ->delimiter(',')
            ->type_name(queue_kind_type);
    cmd->add_flag("--min", values.min,
                  "A min-queue ('*' removes the smallest; --sort: descending)");
    // Digits only (never octal or hex); 0 or 1 is checked with the other options.
    add_whole_option(*cmd, "--index-base", values.index_base, 0, std::numeric_limits<int>::max(),
                     "Index of the first slot: 1 as in the lecture's code, 0 as in its pseudo-code")
        ->capture_default_str();
    cmd->add_option("--pace", values.pace, "Seconds per step (a compare, an exchange, ...)")
        ->capture_default_str();
    cmd->add_flag("--code", values.code,
                  "Show the operation's pseudocode beside the heap, the line under way marked "
                  "(one heap panel: binary, dary:D, indexed, or --sort)");
    cmd->add_option("--questions", values.questions,
                    "Pause and ponder: before each swim or sink the picture stops and asks "
                    "\"where does K end up?\", candidate slots lettered A, B, C, then reveals "
                    "the slot the operation reaches: on or none")
        ->type_name("{on,none}")
        ->capture_default_str();
    cmd->add_option("--timeline-json", values.timeline_json,
                    "Also write the video's timeline as JSON: its segments (run, and with "
                    "--questions on each question and reveal) with their times and captions")
        ->type_name("PATH");
    add_algorithm_video_options(*cmd, values.video, "heap", "e.g. 640x360");
    cmd->footer(
        "Examples:\n"
        "  collide heap --ops \"P Q E * X A M * P L E *\" -o heap.mp4   # the lecture's trace\n"
        "  collide heap --ops \"P Q E * X A M *\" --impl dary:3 --min\n"
        "  collide heap --ops \"P Q E * X A M *\" --impl unordered,ordered,binary\n"
        "  collide heap --ops \"5 9 3 7 * 3^12\" --impl indexed       # increase-key\n"
        "  collide heap --sort \"S O R T E X A M P L E\" -o heapsort.mp4\n"
        "  collide heap --ops \"P Q E * X A M *\" --code           # swim and sink as code\n"
        "  collide heap --ops \"P Q E * X A M *\" --questions on   # where does K end up?\n"
        "See docs/heap.md for a whole lesson.");
    return cmd;
}

}  // namespace collide::app
