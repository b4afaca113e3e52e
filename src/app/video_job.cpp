#include "video_job.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

#include "collide/error.hpp"
#include "collide/io/file.hpp"
#include "collide/render/preview.hpp"
#include "collide/show/chapters.hpp"
#include "collide/show/slide_player.hpp"
#include "collide/video/handout.hpp"
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
    void add_to(io::CommitGroup& outputs) { outputs.add(file_ ? &*file_ : nullptr); }

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
    void add_to(io::CommitGroup& outputs) { outputs.add(file_ ? &*file_ : nullptr); }

  private:
    video::SubtitleFormat format_ = video::SubtitleFormat::webvtt;
    std::optional<io::OutputFile> file_;
};

/// --chapters-file: like the subtitle sidecar, a WebVTT chapters file put in place with the video.
class ChapterSidecar {
  public:
    explicit ChapterSidecar(const JobOutput& output) {
        if (output.chapter_output.file.empty()) return;
        file_.emplace(output.chapter_output.file, io::OutputOptions{"--chapters-file", false});
    }
    void write(const Chapters& chapters) {
        if (!file_) return;
        const std::string text = video::webvtt_chapters_text(chapters);
        file_->write(text.data(), text.size());
    }
    void add_to(io::CommitGroup& outputs) { outputs.add(file_ ? &*file_ : nullptr); }

  private:
    std::optional<io::OutputFile> file_;
};

constexpr const char* slide_page = "index.html";
constexpr const char* slide_video = "video.mp4";
constexpr const char* slide_subtitles = "subtitles.vtt";
constexpr const char* slide_chapters = "chapters.vtt";

/// "chapter-01.png", ... (at least two digits).
std::string still_name(std::size_t chapter) {
    char name[40];
    std::snprintf(name, sizeof name, "chapter-%02zu.png", chapter + 1);
    return name;
}

/// --slides DIR: a hidden folder beside DIR, made before any frame (so an unusable DIR fails
/// first), that gets a still of each chapter's last frame as the frames pass, then the page,
/// the subtitles, the chapters and a copy of the finished video (from its temporary), and goes
/// in DIR's place with the run's other outputs (io::CommitGroup).
class SlideFolder {
  public:
    explicit SlideFolder(const VideoJob& job) {
        const ChapterOutput& out = job.output.chapter_output;
        if (out.slides.empty()) return;
        if (job.output.chapters.empty())
            throw_option_error("--slides", "this video has no chapters to stop at");
        folder_.emplace(out.slides, is_slide_file_name, "--slides");
        const auto fps = static_cast<double>(job.fps);
        for (std::size_t i = 0; i < job.output.chapters.size(); ++i) {
            const std::int64_t still = std::llround(job.output.chapters[i].still * fps);
            stills_.push_back({std::clamp<std::int64_t>(still, 0, job.frames - 1), i});
        }
    }

    /// Video frame k: written as the still of every chapter that ends with it.
    void offer(std::int64_t k, const Image& image) {
        while (folder_ && next_ < stills_.size() && stills_[next_].frame <= k) {
            write(still_name(stills_[next_].chapter), video::png_bytes(image, "--slides still"));
            ++next_;
        }
    }

    /// The page, the subtitles, the chapters and a copy of the finished video, read from
    /// `video` (its temporary: nothing is in place yet).
    void complete(const VideoJob& job, const video::VideoWriter& writer) {
        if (!folder_) return;
        copy_video(writer.finished_file());
        show::SlidePage page;
        page.title = job.output.chapter_output.title;
        page.video = slide_video;
        page.language = job.output.chapter_output.language;
        page.cues = job.output.cues;
        page.cues_in_picture = job.output.cues_in_picture;
        page.chapters = job.output.chapters;
        page.fps = job.fps;
        if (!job.output.cues.empty()) {
            page.subtitles = slide_subtitles;
            write(slide_subtitles, video::webvtt_text(job.output.cues));
        }
        write(slide_chapters, video::webvtt_chapters_text(job.output.chapters));
        write(slide_page, show::slide_page_html(page));
    }

    void add_to(io::CommitGroup& outputs) { outputs.add(folder_ ? &*folder_ : nullptr); }

  private:
    struct Still {
        std::int64_t frame;
        std::size_t chapter;
    };

    void copy_video(const std::filesystem::path& video_path) {
        std::ifstream in(video_path, std::ios::binary);
        if (!in)
            throw_runtime_error("--slides: cannot read the video '" + video_path.string() + "'");
        const io::File file = folder_->create_file(slide_video);
        std::vector<char> buffer(1 << 20);
        while (in) {
            in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
            const auto got = static_cast<std::size_t>(in.gcount());
            if (got > 0) file.write_all(buffer.data(), got, slide_video);
        }
        if (in.bad())
            throw_runtime_error("--slides: cannot read the video '" + video_path.string() + "'");
    }

    template <typename Bytes>
    void write(const std::string& name, const Bytes& bytes) {
        io::File file = folder_->create_file(name);
        file.write_all(bytes.data(), bytes.size(), name);
        file.close(name);
    }

    std::optional<io::OutputDirectory> folder_;
    std::vector<Still> stills_;  ///< by frame (chapters are in order)
    std::size_t next_ = 0;
};

/// The frame of each chapter's still (chapters.still, in video frames, within the video).
std::vector<std::int64_t> still_frames(const VideoJob& job) {
    std::vector<std::int64_t> frames;
    const auto fps = static_cast<double>(job.fps);
    for (const Chapter& chapter : job.output.chapters) {
        const std::int64_t still = std::llround(chapter.still * fps);
        frames.push_back(std::clamp<std::int64_t>(still, 0, job.frames - 1));
    }
    return frames;
}

/// The words on screen at `time` (the cues showing then), a line each, leaving out the lines
/// the chapter's title already says (a caption is the title of its chapter).
std::string words_at(const Cues& cues, double time, const std::string& title) {
    std::string words;
    for (const Cue& cue : cues) {
        if (cue.start > time || time >= cue.end) continue;
        std::istringstream lines(cue.text);
        for (std::string line; std::getline(lines, line);) {
            const std::string said = show::one_line(line);
            if (said.empty() || title.find(said) != std::string::npos) continue;
            if (!words.empty()) words += '\n';
            words += said;
        }
    }
    return words;
}

/// --handout F.pdf: its temporary made before any frame (an unwritable path fails first); each
/// chapter's still kept as the frames pass, the PDF written once the video is complete and put
/// in place with it (io::CommitGroup).
class HandoutFile {
  public:
    explicit HandoutFile(const VideoJob& job) {
        const ChapterOutput& out = job.output.chapter_output;
        if (out.handout.empty()) return;
        if (job.output.chapters.empty())
            throw_option_error("--handout", "this video has no chapters to make pages of");
        file_.emplace(out.handout, io::OutputOptions{"--handout", false});
        frames_ = still_frames(job);
    }

    /// Video frame k: kept as the still of every chapter that it stands for.
    void offer(std::int64_t k, const Image& image) {
        while (file_ && pages_.size() < frames_.size() && frames_[pages_.size()] <= k)
            pages_.push_back({{}, video::handout_still(image), {}});
    }

    /// The PDF into the temporary: each page's title and words from the chapters and cues.
    void complete(const VideoJob& job) {
        if (!file_) return;
        const Chapters& chapters = job.output.chapters;
        for (std::size_t i = 0; i < pages_.size(); ++i) {
            pages_[i].title = chapters[i].title;
            pages_[i].caption = words_at(job.output.cues, chapters[i].still, chapters[i].title);
        }
        const std::string title = job.output.chapter_output.title.empty()
                                      ? std::string("collide")
                                      : job.output.chapter_output.title;
        const std::string pdf = video::handout_pdf(pages_, title);
        file_->write(pdf.data(), pdf.size());
    }

    void add_to(io::CommitGroup& outputs) { outputs.add(file_ ? &*file_ : nullptr); }

  private:
    std::optional<io::OutputFile> file_;
    std::vector<std::int64_t> frames_;
    std::vector<video::HandoutPage> pages_;  ///< one per chapter seen so far
};

/// The job's outputs are files of their own, none inside the slide folder.
void check_distinct(const JobOutput& output) {
    std::vector<io::NamedOutput> outputs{
        {"-o", output.path, output.format == video::VideoFormat::png_sequence}};
    if (!output.subtitles.file.empty())
        outputs.push_back({"--subtitles-file", output.subtitles.file, false});
    if (!output.chapter_output.file.empty())
        outputs.push_back({"--chapters-file", output.chapter_output.file, false});
    if (!output.chapter_output.slides.empty())
        outputs.push_back({"--slides", output.chapter_output.slides, true});
    if (!output.chapter_output.handout.empty())
        outputs.push_back({"--handout", output.chapter_output.handout, false});
    if (outputs.size() > 1) io::check_distinct_outputs(outputs);
}

JobResult run_video(const VideoJob& job, const ProgramFactory& make_program,
                    const JobHooks& hooks) {
    check_distinct(job.output);
    SubtitleSidecar sidecar(job.output);
    ChapterSidecar chapter_file(job.output);
    SlideFolder slides(job);
    HandoutFile handout(job);
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
        options.subtitles_in_picture = job.output.cues_in_picture;
    }
    if (job.output.chapter_output.embed && job.output.format == video::VideoFormat::mp4)
        options.chapters = job.output.chapters;
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
        slides.offer(k, image);
        handout.offer(k, image);
        writer.write(std::move(image));
        result.frames += 1;
        frame_done(hooks, time);
    }
    check_interrupt(hooks);
    program->finish();
    writer.complete();
    sidecar.write(job.output.cues);
    chapter_file.write(job.output.chapters);
    slides.complete(job, writer);
    handout.complete(job);
    if (hooks.before_commit) hooks.before_commit();
    // Every output is whole in its temporary: now all of them go in place, or none.
    // The slide folder first: its rename checks the folder once more, the others cannot fail
    // but for a system that refuses a rename it has just allowed.
    io::CommitGroup outputs;
    slides.add_to(outputs);
    outputs.add([&] { writer.prepare_commit(); }, [&] { writer.commit(); });
    sidecar.add_to(outputs);
    chapter_file.add_to(outputs);
    handout.add_to(outputs);
    dump.add_to(outputs);
    for (io::OutputFile* file : hooks.commit_with) outputs.add(file);
    outputs.commit();
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
    io::CommitGroup outputs;
    outputs.add(&png);
    for (io::OutputFile* file : hooks.commit_with) outputs.add(file);
    outputs.commit();
    return result;
}

}  // namespace

JobResult run_video_job(const VideoJob& job, const ProgramFactory& make_program,
                        const JobHooks& hooks) {
    return job.output.still ? run_still(job, make_program, hooks)
                            : run_video(job, make_program, hooks);
}

}  // namespace collide::app
