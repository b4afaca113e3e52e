#pragma once
/// \file
/// Images in, video files out: MP4 (H.264 by default, optionally HEVC or AV1), GIF for slides,
/// and PNG sequences, through FFmpeg's libraries (libavcodec/format/filter, libswscale).
///
/// Typical use (the app's `render` command):
/// \code
///   collide::video::VideoOptions options;
///   options.path = "out.mp4";                      // options.format: mp4 by default
///   options.width = 1280; options.height = 720; options.fps = 30;
///   options.cancel = &interrupts.flag();           // set by the SIGINT/SIGTERM handler
///   collide::video::check_output_writable(options.path);   // before rendering anything
///   collide::video::VideoWriter writer(options);   // may throw Error (bad option, no encoder)
///   for (...) writer.write(std::move(frame));      // queued; encoding runs on its own thread
///   writer.finish();                               // flush, trailer, rename onto options.path
/// \endcode
/// Destroying a writer without a successful `finish()` (exception, interrupt) deletes the
/// temporary output and leaves whatever was at `options.path` before untouched.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "collide/cue.hpp"
#include "collide/image.hpp"
#include "collide/video/output.hpp"

namespace collide::video {

/// Container / kind of output.
enum class VideoFormat {
    mp4,           ///< MP4 with `codec`, yuv420p, BT.709 tags, constant frame rate, +faststart
    gif,           ///< animated GIF, two-pass generated palette, at most `max_gif_fps`
    png_sequence,  ///< a directory `path` holding `<stem>_00000.png`, `<stem>_00001.png`, ...
};

/// Video codec for MP4 output (ignored for GIF and PNG).
enum class VideoCodec {
    h264,  ///< libx264: plays everywhere (browsers, phones, PowerPoint, VLC). The default.
    hevc,  ///< libx265: smaller files at equal quality, slower; not every player has it
    av1,   ///< libsvtav1: smallest files, slowest, newest players only
};

/// GIF frame rates above this are reduced by dropping frames evenly (GIF delays are counted in
/// 1/100 s and most viewers clamp short delays, so 25 fps (4/100 s) is the practical maximum).
inline constexpr int max_gif_fps = 25;

/// What to write and how. Defaults produce a 720p30 H.264 MP4 that plays everywhere.
struct VideoOptions {
    std::filesystem::path path;  ///< destination file (mp4/gif) or directory (png)
    VideoFormat format = VideoFormat::mp4;
    int width = 1280;  ///< pixels, 1..8192; frames must have this size.
                       ///< Odd sizes are rounded up for yuv420p (see notices)
    int height = 720;  ///< pixels, 1..8192, as `width`
    int fps = 30;      ///< frames per second, 1..240 (constant frame rate)
    VideoCodec codec = VideoCodec::h264;
    /// libav encoder name overriding encoder_name(codec) (e.g. "libopenh264"); empty = default.
    /// Must encode `codec`'s format family into MP4; a name this FFmpeg lacks is an Error.
    std::string encoder;
    /// Encoder speed/size trade-off; empty = the codec's default below. x264/x265 names
    /// (ultrafast superfast veryfast faster fast medium slow slower veryslow) or, for AV1,
    /// an SVT-AV1 preset number "0".."13". Default per codec: h264 "veryfast" (1.6-2x the
    /// frames per second of "medium" for ~5% more bytes at CRF 20 on disc scenes; "ultrafast"
    /// is faster still but 4x bigger; docs/benchmarks.md), hevc "fast", av1 "10".
    std::string preset;
    /// Constant rate factor (quality; lower = better and bigger); -1 = the codec's default below.
    /// h264/hevc 0..51 (default h264 20, hevc 24), av1 0..63 (default 35).
    int crf = -1;
    /// Frames queued between `write()` and the encoder thread (bounded: `write` blocks when the
    /// encoder falls behind, so memory stays at about queue_frames * width * height * 4 bytes).
    int queue_frames = 4;
    /// MP4 only: a subtitle track (mov_text, what MP4 players and ffmpeg read) carrying these
    /// cues, in order, not overlapping, within the video; empty = no track. GIF and PNG have
    /// no subtitle track (write a sidecar with subtitle_file_text instead).
    Cues subtitles;
    /// The track's language tag, ISO 639-2/T ("eng", "pol"; subtitle_language() makes one).
    std::string subtitle_language = "und";
    /// The cues are drawn into the picture already: the track is written but not enabled (not
    /// "default"), so that players show it only when asked, never on top of the same words.
    bool subtitles_in_picture = false;
    /// MP4 only: chapters (what players list for navigation; FFmpeg's mov muxer writes them as a
    /// chapter text track and a Nero 'chpl' box), in order, back to back, within the video;
    /// empty = none. Ignored for GIF and PNG.
    Chapters chapters;
    /// Cancellation hook: when it points to a flag that becomes true (the app's SIGINT/SIGTERM
    /// handler sets it), `write`/`finish` throw Error(runtime, "interrupted") and the temporary
    /// output is deleted. Must outlive the writer. Lock-free, so a signal handler may set it.
    const std::atomic<bool>* cancel = nullptr;

    /// Throws Error(input) naming the first bad field ("video.width: must be 1..8192, got 0").
    void validate() const;
};

/// "mp4" / "gif" / "png" -> format; throws Error(input) naming `field` and the accepted values.
[[nodiscard]] VideoFormat parse_video_format(std::string_view text,
                                             std::string_view field = "format");
/// "h264" / "hevc" (or "h265") / "av1" -> codec; throws Error(input) naming `field`.
[[nodiscard]] VideoCodec parse_video_codec(std::string_view text, std::string_view field = "codec");
[[nodiscard]] std::string_view to_string(VideoFormat format) noexcept;
[[nodiscard]] std::string_view to_string(VideoCodec codec) noexcept;
/// The libav encoder name used for `codec` ("libx264", "libx265", "libsvtav1").
[[nodiscard]] std::string_view encoder_name(VideoCodec codec) noexcept;
/// Whether this build writes `format`: PNG frames always; MP4 and GIF only when it was built
/// with libav (-DCOLLIDE_VIDEO=ON, the default; OFF is the lean build for CI thumbnails).
[[nodiscard]] bool format_built(VideoFormat format) noexcept;
/// Throws Error(input) naming `option` when this build does not write `format` (the lean build
/// asked for an MP4 or a GIF), saying what it writes instead.
void require_format_built(VideoFormat format, std::string_view option);
/// True when this FFmpeg build has the encoder `name` (e.g. to skip AV1 where it is missing).
[[nodiscard]] bool has_encoder(std::string_view name);
/// libav logs to stderr (x264 prints statistics at "info"); the app calls this once to show only
/// errors (`verbose` = false) or everything. It sets libav's own process-wide log level.
void set_libav_verbose(bool verbose);

/// Encodes a stream of equally sized RGBA images into `options.path`.
///
/// Threads: `write` only queues; conversion (RGBA -> yuv420p, BT.709) and encoding run on the
/// writer's own thread (libx264 adds its own worker threads), so the caller can simulate and
/// render the next frame meanwhile. Use a writer from one thread at a time. Move-only.
class VideoWriter {
  public:
    /// Validates the options, checks the destination is writable, finds the encoder and creates
    /// the temporary output. Throws Error(input) for bad options or an unwritable path,
    /// Error(runtime) naming the encoder when it is not available in this FFmpeg build.
    explicit VideoWriter(VideoOptions options);
    /// Without a successful finish(): stops the encoder thread and deletes the temporary output.
    ~VideoWriter();
    VideoWriter(VideoWriter&&) noexcept;
    VideoWriter& operator=(VideoWriter&&) noexcept;
    VideoWriter(const VideoWriter&) = delete;
    VideoWriter& operator=(const VideoWriter&) = delete;

    /// Queues one frame (must be options.width x options.height); blocks while the queue is full.
    /// Throws Error(runtime) if the frame size is wrong, the cancel flag is set, or the encoder
    /// thread failed earlier (its error, e.g. "No space left on device", is rethrown here).
    void write(Image frame);

    /// A frame the encoder has finished with, to render the next one into and write() back (its
    /// pixels are stale), or an empty Image while none is free. Recycling keeps the steady state
    /// free of 3.7 MB (720p) allocations, each paid again in page faults and zeroing. Keeps at
    /// most options.queue_frames spares. Thread-safe with respect to the encoder thread.
    [[nodiscard]] Image spare_frame();

    /// Drains the queue, flushes the encoder, writes the trailer and renames the temporary onto
    /// `options.path`. Throws Error(runtime) on any failure (then nothing is renamed), including
    /// when no frame was written. Calling it twice throws.
    void finish();
    /// finish() in steps, for a run with several outputs that puts none in place before all
    /// are written (io::CommitGroup): complete() writes all (same throws), prepare_commit() does
    /// all that can still fail but the rename (io::OutputFile::prepare_commit), commit() the
    /// rename (and prepare_commit() first, if it was not called).
    void complete();
    void prepare_commit();
    void commit();
    /// After complete(): a path that reads the finished MP4 or GIF while it waits in its
    /// temporary (/proc/self/fd/N), for a copy that must be ready before anything is put in
    /// place (the slide folder's video). Throws Error(runtime) for a PNG sequence.
    [[nodiscard]] std::filesystem::path finished_file() const;

    /// Human-readable remarks about adjustments made to the request (odd size rounded up, GIF
    /// frame rate reduced, ...), for the app to print; the library itself never prints.
    [[nodiscard]] const std::vector<std::string>& notices() const noexcept;
    /// Encoded frame size (even for yuv420p formats) and frame rate actually written.
    [[nodiscard]] int output_width() const noexcept;
    [[nodiscard]] int output_height() const noexcept;
    [[nodiscard]] double output_fps() const noexcept;
    /// Frames accepted by write() so far.
    [[nodiscard]] std::int64_t frames_written() const noexcept;

    class Impl;  ///< the format-specific machinery (src/video)

  private:
    std::unique_ptr<Impl> impl_;
};

}  // namespace collide::video
