#pragma once
/// \file
/// Which FFmpeg libraries the encoder runs on, for `collide --version`.

#include <string>

namespace collide::video {

/// "libavcodec 59.37.100, libavformat 59.27.100, ..." as loaded at run time (the libraries'
/// own *_version() calls), for every libav library collide_video links.
[[nodiscard]] std::string libav_versions();

}  // namespace collide::video
