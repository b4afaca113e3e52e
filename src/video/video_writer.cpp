#include "collide/video/video_writer.hpp"

#include <algorithm>
#include <condition_variable>
#include <cstring>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>
#include <utility>

#ifndef COLLIDE_NO_VIDEO
#include "av_handles.hpp"
#endif
#include "collide/error.hpp"
#include "collide/io/file.hpp"
#include "collide/video/output.hpp"
#include "frame_sink.hpp"

namespace collide::video {

namespace detail {

Image pad_by_edge_replication(const Image& image, int width, int height) {
    Image padded(width, height);
    for (int row = 0; row < height; ++row) {
        const int source_row = std::min(row, image.height - 1);
        std::uint8_t* out = padded.pixel(0, row);
        std::memcpy(out, image.pixel(0, source_row), image.stride());
        const std::uint8_t* last = image.pixel(image.width - 1, source_row);
        for (int x = image.width; x < width; ++x) std::memcpy(padded.pixel(x, row), last, 4);
    }
    return padded;
}

}  // namespace detail

namespace {

/// Where the GIF writer keeps its frames between passes: beside the output (same filesystem as
/// the user chose for it, rather than a possibly small /tmp).
std::filesystem::path scratch_directory(const std::filesystem::path& output) {
    const std::filesystem::path parent = output.parent_path();
    return parent.empty() ? std::filesystem::path(".") : parent;
}

std::string size_text(int width, int height) {
    return std::to_string(width) + "x" + std::to_string(height);
}

// The app replaces this with its own message naming the signal (interrupt.cpp); same wording.
[[noreturn]] void throw_interrupted() {
    throw_runtime_error("interrupted; nothing was written");
}

}  // namespace

/// Owns the sink (all libav handles), the temporary output and the encoder thread with its
/// bounded queue. Member order matters: the thread is joined (in ~Impl) before the sink dies, and
/// the sink (which closes its files) dies before the temporary is removed.
class VideoWriter::Impl {
  public:
    explicit Impl(VideoOptions options) : options_(std::move(options)) {
        options_.validate();
        settle_geometry();
        if (options_.format == VideoFormat::png_sequence) {
            check_sequence_name(options_.path);
            const std::string stem = sequence_stem(options_.path);
            // Sweeps the frames directories that killed runs left here, whatever their stem.
            directory_ = io::OutputDirectory(
                options_.path,
                [stem](std::string_view name) { return is_sequence_frame_name(stem, name); },
                "output", is_any_sequence_frame_name);
        } else {
            io::OutputOptions file_options;
            file_options.stale_directory_entries = is_any_sequence_frame_name;
            file_ = io::OutputFile(options_.path, std::move(file_options));
        }
        sink_ = make_sink();
        worker_ = std::thread([this] { encode_loop(); });
    }

    ~Impl() {
        {
            std::lock_guard lock(mutex_);
            abort_ = true;
        }
        changed_.notify_all();
        if (worker_.joinable()) worker_.join();
        sink_.reset();  // closes files before the temporary is removed
        file_.discard();
        directory_.discard();
    }

    void write(Image frame) {
        if (finished_) throw_runtime_error("VideoWriter::write after finish()");
        if (cancelled()) throw_interrupted();
        if (frame.width != geometry_.input_width || frame.height != geometry_.input_height ||
            frame.rgba.size() != frame.stride() * static_cast<std::size_t>(frame.height)) {
            throw_runtime_error("video frame is " + size_text(frame.width, frame.height) +
                                ", expected " +
                                size_text(geometry_.input_width, geometry_.input_height));
        }
        std::unique_lock lock(mutex_);
        changed_.wait(lock, [&] {
            return failure_ || queue_.size() < static_cast<std::size_t>(options_.queue_frames);
        });
        if (failure_) std::rethrow_exception(failure_);
        queue_.push_back(std::move(frame));
        ++frames_written_;
        lock.unlock();
        changed_.notify_all();
    }

    Image spare_frame() {
        std::lock_guard lock(mutex_);
        if (spares_.empty()) return {};
        Image spare = std::move(spares_.back());
        spares_.pop_back();
        return spare;
    }

    void complete() {
        if (finished_) throw_runtime_error("VideoWriter::finish called twice");
        finished_ = true;  // whatever happens next, no more frames
        {
            std::lock_guard lock(mutex_);
            closing_ = true;
        }
        changed_.notify_all();
        worker_.join();
        if (failure_) std::rethrow_exception(failure_);
        if (cancelled()) throw_interrupted();
        if (frames_written_ == 0) {
            throw_runtime_error("no frames were written to '" + options_.path.string() + "'");
        }
        sink_->finish();
    }

    void prepare_commit() {
        if (!finished_) throw_runtime_error("VideoWriter::commit before complete()");
        if (cancelled()) throw_interrupted();
        if (options_.format == VideoFormat::png_sequence) {
            directory_.prepare_commit();
        } else {
            file_.prepare_commit();
        }
        prepared_ = true;
    }

    void commit() {
        // Prepared already (io::CommitGroup): a stop that came since waits for the renames.
        if (!prepared_) prepare_commit();
        if (options_.format == VideoFormat::png_sequence) {
            directory_.commit();
        } else {
            file_.commit();
        }
    }

    std::filesystem::path finished_file() const {
        if (!finished_ || options_.format == VideoFormat::png_sequence)
            throw_runtime_error("VideoWriter::finished_file: no finished file");
        return file_.reopen_path();
    }

    const std::vector<std::string>& notices() const noexcept { return notices_; }
    const detail::SinkGeometry& geometry() const noexcept { return geometry_; }
    std::int64_t frames_written() const noexcept { return frames_written_; }

  private:
    bool cancelled() const noexcept {
        return options_.cancel != nullptr && options_.cancel->load();
    }

    void settle_geometry() {
        geometry_.input_width = options_.width;
        geometry_.input_height = options_.height;
        geometry_.output_width = options_.width;
        geometry_.output_height = options_.height;
        geometry_.fps = options_.fps;
        if (options_.format == VideoFormat::mp4) {
            // yuv420p stores one chroma sample per 2x2 block: both sizes must be even.
            geometry_.output_width += options_.width % 2;
            geometry_.output_height += options_.height % 2;
            if (geometry_.output_width != options_.width ||
                geometry_.output_height != options_.height) {
                notices_.push_back("video size " + size_text(options_.width, options_.height) +
                                   " rounded up to " +
                                   size_text(geometry_.output_width, geometry_.output_height) +
                                   " (H.264/yuv420p needs even sizes; the last row/column is "
                                   "repeated)");
            }
        }
        if (options_.format == VideoFormat::gif && options_.fps > max_gif_fps) {
            geometry_.frame_step = (options_.fps + max_gif_fps - 1) / max_gif_fps;
            notices_.push_back("GIF frame rate reduced from " + std::to_string(options_.fps) +
                               " to " + std::to_string(options_.fps / geometry_.frame_step) +
                               (options_.fps % geometry_.frame_step != 0 ? ".5" : "") +
                               " fps (keeping 1 frame in " + std::to_string(geometry_.frame_step) +
                               "; GIF viewers do not play faster than " +
                               std::to_string(max_gif_fps) + " fps)");
        }
    }

    std::unique_ptr<detail::FrameSink> make_sink() {
        switch (options_.format) {
            case VideoFormat::mp4:
                return detail::make_mp4_sink(options_, geometry_, file_.reopen_path());
            case VideoFormat::gif:
                return detail::make_gif_sink(geometry_, file_.reopen_path(),
                                             scratch_directory(options_.path));
            case VideoFormat::png_sequence:
                return detail::make_png_sequence_sink(sequence_stem(options_.path), directory_);
        }
        throw_runtime_error("unknown video format");
    }

    /// The encoder thread: pops frames until closed (or aborted), converting and encoding each.
    /// Its first error is kept and rethrown to the caller by write() or finish().
    void encode_loop() {
        try {
            sink_->prepare();
            while (true) {
                Image frame;
                {
                    std::unique_lock lock(mutex_);
                    changed_.wait(lock, [&] { return abort_ || closing_ || !queue_.empty(); });
                    if (abort_ || queue_.empty()) return;  // aborted, or closed and drained
                    frame = std::move(queue_.front());
                    queue_.pop_front();
                }
                changed_.notify_all();
                if (cancelled()) throw_interrupted();
                sink_->consume(frame);
                std::lock_guard lock(mutex_);
                if (spares_.size() < static_cast<std::size_t>(options_.queue_frames))
                    spares_.push_back(std::move(frame));
            }
        } catch (...) {
            {
                std::lock_guard lock(mutex_);
                failure_ = std::current_exception();
                queue_.clear();
            }
            changed_.notify_all();
        }
    }

    VideoOptions options_;
    detail::SinkGeometry geometry_;
    std::vector<std::string> notices_;
    bool prepared_ = false;          ///< prepare_commit() succeeded: only the rename is left
    io::OutputFile file_;            ///< the temporary of an MP4 or GIF
    io::OutputDirectory directory_;  ///< the temporary of a PNG sequence
    std::unique_ptr<detail::FrameSink> sink_;

    std::mutex mutex_;
    std::condition_variable changed_;  ///< queue changed, closing, abort or failure
    std::deque<Image> queue_;          ///< guarded by mutex_
    std::vector<Image> spares_;        ///< guarded by mutex_: consumed frames, for spare_frame()
    bool closing_ = false;             ///< guarded by mutex_: no more frames will come
    bool abort_ = false;               ///< guarded by mutex_: stop without draining
    std::exception_ptr failure_;       ///< guarded by mutex_ (read after join without it)
    std::thread worker_;

    std::int64_t frames_written_ = 0;
    bool finished_ = false;
};

VideoWriter::VideoWriter(VideoOptions options)
    : impl_(std::make_unique<Impl>(std::move(options))) {}
VideoWriter::~VideoWriter() = default;
VideoWriter::VideoWriter(VideoWriter&&) noexcept = default;
VideoWriter& VideoWriter::operator=(VideoWriter&&) noexcept = default;

void VideoWriter::write(Image frame) {
    impl_->write(std::move(frame));
}
Image VideoWriter::spare_frame() {
    return impl_->spare_frame();
}
void VideoWriter::finish() {
    impl_->complete();
    impl_->commit();
}
void VideoWriter::complete() {
    impl_->complete();
}
void VideoWriter::prepare_commit() {
    impl_->prepare_commit();
}
void VideoWriter::commit() {
    impl_->commit();
}
std::filesystem::path VideoWriter::finished_file() const {
    return impl_->finished_file();
}
const std::vector<std::string>& VideoWriter::notices() const noexcept {
    return impl_->notices();
}
int VideoWriter::output_width() const noexcept {
    return impl_->geometry().output_width;
}
int VideoWriter::output_height() const noexcept {
    return impl_->geometry().output_height;
}
double VideoWriter::output_fps() const noexcept {
    const detail::SinkGeometry& geometry = impl_->geometry();
    return static_cast<double>(geometry.fps) / geometry.frame_step;
}
std::int64_t VideoWriter::frames_written() const noexcept {
    return impl_->frames_written();
}

#ifndef COLLIDE_NO_VIDEO  // the lean build's versions: no_video.cpp
bool has_encoder(std::string_view name) {
    return avcodec_find_encoder_by_name(std::string(name).c_str()) != nullptr;
}

void set_libav_verbose(bool verbose) {
    av_log_set_level(verbose ? AV_LOG_INFO : AV_LOG_ERROR);
}
#endif

}  // namespace collide::video
