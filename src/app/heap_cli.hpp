#pragma once
/// \file
/// The command line of `collide heap` and every check of it (the operations, the options, the
/// legibility and fit of the lesson at its frame size, the destinations), none of which needs GL
/// or an encoder. Both programs register the command from here: `collide` checks a line before
/// it becomes collide-draw (so a bad one is refused without starting the drawing program: the
/// same message, exit 2), and collide-draw checks it again and draws (cmd_heap.cpp).

#include <string>
#include <vector>

#include "algorithm_video.hpp"
#include "cli_fwd.hpp"
#include "collide/render/heap_view.hpp"
#include "collide/show/heap_program.hpp"
#include "progress.hpp"
#include "video_options.hpp"

namespace collide::app {

/// Raw option values as CLI11 stores them.
struct HeapCli {
    std::string ops;
    std::string sort;
    std::vector<std::string> impls;
    bool min = false;
    int index_base = 1;
    double pace = 0.8;
    bool code = false;
    std::string questions = "none";
    std::string timeline_json;
    AlgorithmVideoCli video;

    CLI::Option* ops_opt = nullptr;
    CLI::Option* sort_opt = nullptr;
    CLI::Option* impl_opt = nullptr;
};

/// Registers `heap` on `root` with its options stored in `values` (which must outlive `root`'s
/// parse); the caller sets its callback.
CLI::App* add_heap_options(CLI::App& root, HeapCli& values);

/// Everything `collide heap` needs to draw, checked in collide-draw's order before any frame is
/// drawn or file created (but the default output's folder): --progress, --theme, the lesson
/// (--ops or --sort, --impl, --index-base, --pace, --code, --questions), that its keys are
/// legible and fit the frame (HeapRenderer::fits), -q/--size/--fps, --font, the destination
/// (--at, -o, --format, subtitles, chapters) and --timeline-json. Throws Error(input) naming
/// the option.
struct CheckedHeap {
    ProgressMode progress_mode;
    Theme theme;
    show::HeapProgram lesson;
    AlgorithmVideoGeometry geometry;
    render::HeapViewConfig config;
    AlgorithmVideoDestination destination;

    explicit CheckedHeap(const HeapCli& values);
};

}  // namespace collide::app
