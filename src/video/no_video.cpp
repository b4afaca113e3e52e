// The lean build (-DCOLLIDE_VIDEO=OFF): collide_video without libav. PNG files and PNG frames are
// written as in the full build; MP4 and GIF are refused before anything is made
// (VideoOptions::validate, require_format_built), so these stand-ins are never reached by a
// checked output.

#include <string>

#include "collide/error.hpp"
#include "collide/video/video_writer.hpp"
#include "frame_sink.hpp"

namespace collide::video {

namespace detail {

std::unique_ptr<FrameSink> make_mp4_sink(const VideoOptions& /*options*/,
                                         const SinkGeometry& /*geometry*/,
                                         const std::filesystem::path& /*temporary*/) {
    throw_runtime_error("this build has no video: MP4 needs libav (-DCOLLIDE_VIDEO=ON)");
}

std::unique_ptr<FrameSink> make_gif_sink(const SinkGeometry& /*geometry*/,
                                         const std::filesystem::path& /*temporary*/,
                                         const std::filesystem::path& /*scratch_directory*/) {
    throw_runtime_error("this build has no video: GIF needs libav (-DCOLLIDE_VIDEO=ON)");
}

}  // namespace detail

bool has_encoder(std::string_view /*name*/) {
    return false;
}

void set_libav_verbose(bool /*verbose*/) {}

}  // namespace collide::video
