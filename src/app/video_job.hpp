#pragma once
/// \file
/// The one video job of `render`, `thumbnail`, `heap` and `puzzle`: a frame program (frame k ->
/// image) run through one loop that feeds the preview window, the video writer (MP4, GIF, PNG
/// sequence) or one PNG, with progress and interrupts.
///
///   video:  for k in 0..frames-1: program.frame(k, output) -> preview -> writer  (then finish)
///   still:  for k in 0..frames-1: program.frame(k, skip | warm | output) -> the last one is
///           the PNG (--at, --last-frame, thumbnail: the frames before it are the warm-up that
///           brings simulations and trails to the same state as the video's frame)
///
/// The loop knows nothing of what is drawn: each command hands in its program.

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "collide/cue.hpp"
#include "collide/image.hpp"
#include "collide/io/file.hpp"
#include "collide/render/context.hpp"
#include "collide/render/renderer.hpp"
#include "collide/video/video_writer.hpp"
#include "interrupt.hpp"
#include "progress.hpp"

namespace collide::app {

/// What the job needs frame k for.
enum class FrameUse {
    skip,    ///< a still's frame far before the last: only advance the state
    warm,    ///< a still's frame whose drawing the last one depends on (trails): draw, no pixels
    output,  ///< draw into the image
};

/// The pictures of one video. The job calls frame(k) for k = 0, 1, ..., frames - 1, each once.
class FrameProgram {
  public:
    virtual ~FrameProgram() = default;
    /// Brings the program to frame k and, for FrameUse::output, draws it into `image` (any
    /// size: the program sizes it). Returns the time frame k shows (for the progress line).
    virtual double frame(std::int64_t k, FrameUse use, Image& image) = 0;
    /// After the last frame, before the output is finished: throws when the frames were not
    /// all produced as they should have been.
    virtual void finish() {}
};

/// Makes the program once the preview window (if any) is open: `backend` is the GL backend its
/// renderer must use (GLFW with a preview window, so one GL implementation serves both).
using ProgramFactory = std::function<std::unique_ptr<FrameProgram>(render::Backend backend)>;

/// A video's subtitles as outputs (--subtitles, --lang, --subtitles-file, checked).
struct SubtitleOutput {
    bool embed = false;            ///< an MP4 gets a subtitle track (other formats have none)
    std::string language = "und";  ///< ISO 639-2/T, the track's language tag
    std::filesystem::path file;    ///< a WebVTT (.vtt) or SubRip (.srt) file too; empty: none
};

/// A video's chapters as outputs (--chapters, --chapters-file, --slides, --handout, checked).
struct ChapterOutput {
    bool embed = false;             ///< an MP4 carries chapters (other formats have none)
    std::filesystem::path file;     ///< a WebVTT chapters file too; empty: none
    std::filesystem::path slides;   ///< the slide player's folder (MP4 only); empty: none
    std::filesystem::path handout;  ///< a PDF, a page per chapter (videos); empty: none
    std::string language = "und";   ///< the slide page's subtitle language (--lang as given)
    std::string title;              ///< the slide page's title (the lesson's)
};

/// The files of a slide folder, by name: the names a folder written by --slides holds.
[[nodiscard]] bool is_slide_file_name(std::string_view name);

/// Where the job's output goes and as what.
struct JobOutput {
    std::filesystem::path path;
    video::VideoFormat format = video::VideoFormat::mp4;  ///< videos only
    bool still = false;  ///< one PNG: the last frame (the frames before it are warm-up)
    /// Videos: the words on screen as timed text (collide_show makes them), written as
    /// `subtitles` says; the sidecar file is all or nothing with the video.
    Cues cues;
    /// The cues are drawn into the frames (the lesson level's caption, the heap's and the
    /// puzzle's words): the MP4 track is then not "default", and the slide player hides it.
    bool cues_in_picture = false;
    SubtitleOutput subtitles;
    /// Videos: the chapters (collide_show makes them), written as `chapter_output` says; the
    /// chapters file and the slide folder are put in place with the video.
    Chapters chapters;
    ChapterOutput chapter_output;
};

/// One run: the output, the frame geometry and how many frames.
struct VideoJob {
    JobOutput output;
    int width = 1280;
    int height = 720;
    int fps = 30;
    std::int64_t frames = 1;        ///< >= 1
    std::int64_t warm_frames = 0;   ///< still: how many frames before the last are drawn
    std::string title = "collide";  ///< the preview window's title
};

/// Outside-world connections of a run. All optional.
struct JobHooks {
    const InterruptGuard* interrupts = nullptr;  ///< polled between frames; cancels encoding
    Progress* progress = nullptr;
    bool preview = false;  ///< show frames in a window when a display exists
    /// GL backend for the frames; with a preview window open they go through GLFW instead.
    render::Backend backend = render::Backend::automatic;
    render::NoticeSink notice;  ///< one-line notices (empty = stderr)
    /// Benchmarks only: also append every frame as raw RGBA to this file (for timing libx264
    /// alone on exactly the same frames with the ffmpeg command line).
    std::filesystem::path dump_rgba;
    /// The run's other outputs (--layout-json): called once every frame is written and the
    /// output is complete in its temporary, before it is put in place, so that a failure here
    /// leaves the destination untouched.
    std::function<void()> before_commit;
    /// The run's other outputs, whole in their temporaries by the time before_commit returns:
    /// put in place together with the job's own (io::CommitGroup: all or none).
    std::vector<io::OutputFile*> commit_with;
};

/// What was written, for the summary line.
struct JobResult {
    std::int64_t frames = 0;
    std::vector<std::string> notices;  ///< from the encoder (size rounded, GIF rate reduced)
    int output_width = 0;
    int output_height = 0;
    double output_fps = 0.0;
};

/// Runs the job: creates the writer (which checks the destination and creates its temporary),
/// opens the preview, makes the program, then feeds it every frame in order. Nothing appears at
/// job.output.path unless every frame was produced and the file finished (temporary + rename).
/// Throws Error: input for bad options, runtime for GL/encoder failures or an interrupt.
JobResult run_video_job(const VideoJob& job, const ProgramFactory& make_program,
                        const JobHooks& hooks);

}  // namespace collide::app
