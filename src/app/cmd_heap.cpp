/// `collide heap`: animated priority-queue operations for the first half of the lecture (arrays,
/// binary and d-ary heaps, the indexed heap's increase-key, heapsort), several implementations
/// side by side, to MP4, GIF, a PNG sequence or one PNG. Validates everything (operations,
/// options, legibility, destination) before anything is drawn, then renders every frame of the
/// lesson (collide/show/heap_program.hpp, over the record of collide/sim/pq/heap_record.hpp)
/// through HeapRenderer into the same VideoWriter as `collide render`. The command line and its
/// checks, which `collide` runs too, are heap_cli.cpp's.

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>

#include "algorithm_video.hpp"
#include "collide/printable.hpp"
#include "collide/render/heap_view.hpp"
#include "collide/show/chapters.hpp"
#include "collide/show/drawn_timeline.hpp"
#include "collide/show/heap_program.hpp"
#include "collide/show/subtitles.hpp"
#include "collide/video/video_writer.hpp"
#include "commands.hpp"
#include "heap_cli.hpp"
#include "progress.hpp"
#include "render_plan.hpp"

namespace collide::app {

namespace {

void run(const HeapCli& v) {
    // Validation: nothing is drawn, and no file is created, until all of it passes.
    const CheckedHeap checked(v);
    const show::HeapProgram& lesson = checked.lesson;
    const AlgorithmVideoGeometry& geometry = checked.geometry;
    const AlgorithmVideoDestination& destination = checked.destination;
    video::set_libav_verbose(v.video.verbose);
    const OutputChoice& output = destination.output;
    std::optional<io::OutputFile> timeline_file =
        open_timeline_json(v.timeline_json, destination,
                           show::drawn_lesson_timeline(lesson.duration(), geometry.fps,
                                                       show::asked_stretches(lesson)));

    render::HeapRenderer renderer(checked.config, render::Backend::automatic, print_notice);

    const double still_time = destination.still_time;
    const AlgorithmVideoSummary written = write_algorithm_video(
        output, geometry, checked.progress_mode, lesson.duration(), still_time,
        [&](double t, Image& frame) { renderer.render(lesson.frame_at(t), frame); },
        destination.subtitles,
        output.still ? Cues{} : show::heap_subtitle_cues(lesson, geometry.fps),
        destination.chapters,
        // One chapter per operation (or group of short ones), never one per step.
        show::heap_chapters(lesson,
                            static_cast<double>(std::max<std::int64_t>(
                                1, std::llround(lesson.duration() * geometry.fps))) /
                                geometry.fps,
                            geometry.fps),
        timeline_file ? &*timeline_file : nullptr);
    if (output.still) {
        std::printf("%s: %dx%d PNG at %.2f s of a %.2f s video of %s\n",
                    printable_text(output.path.string()).c_str(), geometry.width, geometry.height,
                    still_time, lesson.duration(), lesson.name().c_str());
        return;
    }
    std::printf("%s: %.2f s of video, %lld frames, %dx%d @ %g fps, %s, %zu operations\n",
                printable_text(output.path.string()).c_str(),
                static_cast<double>(written.frames) / geometry.fps,
                static_cast<long long>(written.frames), written.width, written.height, written.fps,
                lesson.name().c_str(), lesson.op_labels().size());
}

}  // namespace

void add_heap_command(CLI::App& root) {
    auto v = std::make_shared<HeapCli>();
    add_heap_options(root, *v)->callback([v] { run(*v); });
}

}  // namespace collide::app
