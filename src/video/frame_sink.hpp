#pragma once
/// \file
/// The format-specific back ends behind VideoWriter (MP4 through libavcodec, GIF through
/// libavfilter's palette filters, PNG sequences through stb). Internal to collide_video.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "collide/image.hpp"
#include "collide/io/file.hpp"
#include "collide/video/video_writer.hpp"

namespace collide::video::detail {

/// Receives frames on the writer's encoder thread and writes them to a temporary path.
class FrameSink {
  public:
    virtual ~FrameSink() = default;
    /// Called once on the encoder thread before the first frame: sinks with a costly start (x264
    /// allocates its look-ahead and tables) do it here, while the caller is still setting up its
    /// renderer, instead of stalling the first frame. Throws Error(runtime).
    virtual void prepare() {}
    /// Encodes one frame of exactly the writer's input size. Throws Error(runtime).
    virtual void consume(const Image& frame) = 0;
    /// Flushes everything and closes the output; the caller then renames it. Throws Error.
    virtual void finish() = 0;
};

/// Sizes and rates the writer settles on before creating a sink.
struct SinkGeometry {
    int input_width = 0;  ///< size of the frames given to write()
    int input_height = 0;
    int output_width = 0;  ///< encoded size (even for yuv420p)
    int output_height = 0;
    int fps = 0;         ///< requested frames per second
    int frame_step = 1;  ///< keep every frame_step-th frame (GIF rate cap)
};

/// MP4 via libavformat + the codec's encoder. Throws Error(runtime) naming a missing encoder.
std::unique_ptr<FrameSink> make_mp4_sink(const VideoOptions& options, const SinkGeometry& geometry,
                                         const std::filesystem::path& temporary);
/// GIF with a palette generated from all frames (palettegen + paletteuse); frames wait between
/// the passes in an unnamed scratch file in `scratch_directory`.
std::unique_ptr<FrameSink> make_gif_sink(const SinkGeometry& geometry,
                                         const std::filesystem::path& temporary,
                                         const std::filesystem::path& scratch_directory);
/// PNG files `<stem>_00000.png`... inside the output directory's temporary (which must outlive
/// the sink).
std::unique_ptr<FrameSink> make_png_sequence_sink(const std::string& stem,
                                                  const io::OutputDirectory& directory);

/// `image` encoded as PNG. Throws Error(runtime) naming `shown_as`.
std::vector<unsigned char> encode_png(const Image& image, const std::filesystem::path& shown_as);

/// `image` grown to `width` x `height` (>= its size) by repeating the last column and row.
Image pad_by_edge_replication(const Image& image, int width, int height);

}  // namespace collide::video::detail
