#include "video_job.hpp"

#include <algorithm>
#include <optional>
#include <utility>

#include "collide/error.hpp"
#include "collide/io/file.hpp"
#include "collide/render/preview.hpp"
#include "collide/video/png.hpp"
#include "collide/video/subtitles.hpp"

namespace collide::app {

namespace {

void check_interrupt(const JobHooks& hooks) {
    if (hooks.interrupts != nullptr) hooks.interrupts->throw_if_requested();
}

void frame_done(const JobHooks& hooks, double time) {
    if (hooks.progress != nullptr) hooks.progress->frame_done(time);
}

/// Raw RGBA frames appended to a file (benchmarks only), through io::OutputFile like every
/// output: in place once the video is finished, or a stream ("-", a FIFO, /dev/null).
class RawDump {
  public:
    explicit RawDump(const std::filesystem::path& path) {
        if (!path.empty()) file_.emplace(path, io::OutputOptions{"--dump-rgba", true});
    }

    void write(const Image& image) {
        if (file_) file_->write(image.rgba.data(), image.rgba.size());
    }
    void finish() {
        if (file_) file_->commit();
    }

  private:
    std::optional<io::OutputFile> file_;
};

/// The --preview window: null when not asked for or when there is no display (after a notice).
std::unique_ptr<render::PreviewWindow> open_preview_if_asked(const VideoJob& job,
                                                             const JobHooks& hooks) {
    if (!hooks.preview) return nullptr;
    return render::open_preview(job.width, job.height, job.title.c_str(), hooks.notice);
}

/// The backend that renders the frames. With a preview window open it is GLFW, so that one GL
/// implementation (Mesa's GLX driver) serves both: libOSMesa and the GLX driver share Mesa's
/// per-thread current context (libglapi), while glvnd skips a glXMakeCurrent that its own records
/// say changes nothing; after an OSMesa frame the preview then drew and swapped with OSMesa's
/// context and crashed (issue 22; docs/renderer.md, "Preview").
render::Backend render_backend(const render::PreviewWindow* preview, const JobHooks& hooks) {
    return preview != nullptr ? render::Backend::glfw : hooks.backend;
}

std::unique_ptr<FrameProgram> make(const ProgramFactory& make_program, render::Backend backend) {
    std::unique_ptr<FrameProgram> program = make_program(backend);
    if (!program) throw_runtime_error("no frame program");
    return program;
}

/// --subtitles-file: created (its temporary) before any frame, so an unwritable path fails
/// first; written and put in place with the video, never without it.
class SubtitleSidecar {
  public:
    explicit SubtitleSidecar(const JobOutput& output) {
        if (output.subtitles.file.empty()) return;
        format_ = video::subtitle_format_of(output.subtitles.file, "--subtitles-file");
        io::check_distinct_outputs(
            {{"-o", output.path, output.format == video::VideoFormat::png_sequence},
             {"--subtitles-file", output.subtitles.file, false}});
        file_.emplace(output.subtitles.file, io::OutputOptions{"--subtitles-file", false});
    }
    /// Writes the cues into the temporary (before the video is put in place).
    void write(const Cues& cues) {
        if (!file_) return;
        const std::string text = video::subtitle_file_text(cues, format_);
        file_->write(text.data(), text.size());
    }
    void commit() {
        if (file_) file_->commit();
    }

  private:
    video::SubtitleFormat format_ = video::SubtitleFormat::webvtt;
    std::optional<io::OutputFile> file_;
};

JobResult run_video(const VideoJob& job, const ProgramFactory& make_program,
                    const JobHooks& hooks) {
    SubtitleSidecar sidecar(job.output);
    video::VideoOptions options;
    options.path = job.output.path;
    options.format = job.output.format;
    options.width = job.width;
    options.height = job.height;
    options.fps = job.fps;
    options.cancel = hooks.interrupts != nullptr ? &hooks.interrupts->flag() : nullptr;
    if (job.output.subtitles.embed && job.output.format == video::VideoFormat::mp4) {
        options.subtitles = job.output.cues;
        options.subtitle_language = job.output.subtitles.language;
    }
    video::VideoWriter writer(options);  // validates, checks the path, creates the temporary
    std::unique_ptr<render::PreviewWindow> preview = open_preview_if_asked(job, hooks);
    const std::unique_ptr<FrameProgram> program =
        make(make_program, render_backend(preview.get(), hooks));
    RawDump dump(hooks.dump_rgba);
    check_interrupt(hooks);  // building the renderer (the font atlas) takes a while

    JobResult result;
    for (std::int64_t k = 0; k < job.frames; ++k) {
        check_interrupt(hooks);
        Image image = writer.spare_frame();
        const double time = program->frame(k, FrameUse::output, image);
        check_interrupt(hooks);  // before the encoder gets a frame drawn while a signal came
        // Closing the window stops the preview only: the video is encoded to the end.
        if (preview && !preview->show(image)) preview.reset();
        dump.write(image);
        writer.write(std::move(image));
        result.frames += 1;
        frame_done(hooks, time);
    }
    check_interrupt(hooks);
    program->finish();
    writer.complete();
    sidecar.write(job.output.cues);
    if (hooks.before_commit) hooks.before_commit();
    writer.commit();
    sidecar.commit();
    dump.finish();
    result.notices = writer.notices();
    result.output_width = writer.output_width();
    result.output_height = writer.output_height();
    result.output_fps = writer.output_fps();
    return result;
}

JobResult run_still(const VideoJob& job, const ProgramFactory& make_program,
                    const JobHooks& hooks) {
    // Opened first (it stays hidden until it has the image) so the renderer can share its GL.
    std::unique_ptr<render::PreviewWindow> preview = open_preview_if_asked(job, hooks);
    const std::unique_ptr<FrameProgram> program =
        make(make_program, render_backend(preview.get(), hooks));
    check_interrupt(hooks);  // building the renderer (the font atlas) takes a while
    const std::int64_t first_drawn = std::max<std::int64_t>(0, job.frames - 1 - job.warm_frames);

    JobResult result;
    Image image;
    for (std::int64_t k = 0; k < job.frames; ++k) {
        check_interrupt(hooks);
        const FrameUse use = k + 1 == job.frames ? FrameUse::output
                             : k >= first_drawn  ? FrameUse::warm
                                                 : FrameUse::skip;
        const double time = program->frame(k, use, image);
        result.frames += 1;
        frame_done(hooks, time);
    }
    check_interrupt(hooks);
    program->finish();
    if (preview) preview->show(image);
    result.output_width = image.width;
    result.output_height = image.height;
    check_interrupt(hooks);
    // A large frame takes seconds to compress: encoded where an interrupt can cut it short.
    io::OutputFile png = [&] {
        if (hooks.interrupts == nullptr)
            return video::write_png_uncommitted(image, job.output.path);
        try {
            return video::write_png_uncommitted(std::move(image), job.output.path,
                                                hooks.interrupts->flag());
        } catch (const Error&) {
            check_interrupt(hooks);  // the app's own message naming the signal
            throw;
        }
    }();
    if (hooks.before_commit) hooks.before_commit();
    png.commit();
    return result;
}

}  // namespace

JobResult run_video_job(const VideoJob& job, const ProgramFactory& make_program,
                        const JobHooks& hooks) {
    return job.output.still ? run_still(job, make_program, hooks)
                            : run_video(job, make_program, hooks);
}

}  // namespace collide::app
