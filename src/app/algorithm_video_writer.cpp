// write_algorithm_video (algorithm_video.hpp), apart from the destination checks: it encodes
// (video_job.hpp, libav), and `collide`, which links no encoder, runs the checks.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>

#include "algorithm_video.hpp"
#include "collide/show/chapters.hpp"
#include "interrupt.hpp"
#include "video_job.hpp"

namespace collide::app {

namespace {

/// A drawn lesson as the video job's frame program: frame k of a video shows time k / fps; a
/// still's one frame shows `still_time`.
class AlgorithmFrameProgram final : public FrameProgram {
  public:
    AlgorithmFrameProgram(const AlgorithmFrameDraw& draw, int fps, bool still, double still_time)
        : draw_(draw), fps_(fps), still_(still), still_time_(still_time) {}

    double frame(std::int64_t k, FrameUse use, Image& image) override {
        const double t = still_ ? still_time_ : static_cast<double>(k) / fps_;
        if (use == FrameUse::output) draw_(t, image);
        return t;
    }

  private:
    const AlgorithmFrameDraw& draw_;
    int fps_;
    bool still_;
    double still_time_;
};

}  // namespace

AlgorithmVideoSummary write_algorithm_video(
    const OutputChoice& output, const AlgorithmVideoGeometry& geometry, ProgressMode progress_mode,
    double duration, double still_time, const AlgorithmFrameDraw& draw,
    const SubtitleOutput& subtitles, const Cues& cues, const ChapterOutput& chapters,
    const std::optional<Chapters>& chapter_list, io::OutputFile* commit_with) {
    InterruptGuard interrupts;
    VideoJob job;
    job.output.path = output.path;
    job.output.format = output.format;
    job.output.still = output.still;
    job.width = geometry.width;
    job.height = geometry.height;
    job.fps = geometry.fps;
    job.frames = output.still ? 1
                              : std::max<std::int64_t>(
                                    1, std::llround(duration * static_cast<double>(geometry.fps)));
    if (!output.still) {
        job.output.subtitles = subtitles;
        job.output.cues = cues;
        job.output.cues_in_picture = true;  // the heap's and the puzzle's words are drawn
        job.output.chapter_output = chapters;
        job.output.chapters =
            chapter_list
                ? *chapter_list
                : show::chapters_from_cues(
                      cues, static_cast<double>(job.frames) / static_cast<double>(geometry.fps),
                      geometry.fps);
    }
    Progress progress(progress_mode, job.frames);
    JobHooks hooks;
    hooks.interrupts = &interrupts;
    hooks.progress = &progress;
    hooks.notice = print_notice;
    if (commit_with != nullptr) hooks.commit_with.push_back(commit_with);
    JobResult written;
    try {
        written = run_video_job(
            job,
            [&](render::Backend /*the lessons' renderers are made by their commands*/) {
                return std::make_unique<AlgorithmFrameProgram>(draw, geometry.fps, output.still,
                                                               still_time);
            },
            hooks);
    } catch (...) {
        progress.finish();
        throw;
    }
    progress.finish();
    for (const std::string& line : written.notices) print_notice(line);
    return {written.frames, written.output_width, written.output_height, written.output_fps};
}

}  // namespace collide::app
