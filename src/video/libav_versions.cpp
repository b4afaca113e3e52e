#include "collide/video/libav_versions.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavfilter/avfilter.h>
#include <libavformat/avformat.h>
#include <libavutil/avutil.h>
#include <libswscale/swscale.h>
}

#include <string>

namespace collide::video {

namespace {

std::string version_text(const char* library, unsigned version) {
    return std::string(library) + " " + std::to_string(AV_VERSION_MAJOR(version)) + "." +
           std::to_string(AV_VERSION_MINOR(version)) + "." +
           std::to_string(AV_VERSION_MICRO(version));
}

}  // namespace

std::string libav_versions() {
    return version_text("libavcodec", avcodec_version()) + ", " +
           version_text("libavformat", avformat_version()) + ", " +
           version_text("libavutil", avutil_version()) + ", " +
           version_text("libswscale", swscale_version()) + ", " +
           version_text("libavfilter", avfilter_version());
}

}  // namespace collide::video
