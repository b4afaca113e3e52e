#pragma once
/// \file
/// Move-only owners for libav's C handles (std::unique_ptr with the matching free function), and
/// the error helpers every libav call goes through. Internal to collide_video.

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavfilter/avfilter.h>
#include <libavformat/avformat.h>
#include <libavutil/frame.h>
}

#include <sys/resource.h>

#include <memory>
#include <new>
#include <string>
#include <string_view>

#include "collide/error.hpp"

namespace collide::video::detail {

struct FrameFree {
    void operator()(AVFrame* frame) const noexcept { av_frame_free(&frame); }
};
struct PacketFree {
    void operator()(AVPacket* packet) const noexcept { av_packet_free(&packet); }
};
struct CodecContextFree {
    void operator()(AVCodecContext* context) const noexcept { avcodec_free_context(&context); }
};
struct FilterGraphFree {
    void operator()(AVFilterGraph* graph) const noexcept { avfilter_graph_free(&graph); }
};
/// Closes the AVIOContext (if opened and still ours) and frees the muxer context. Closing here
/// is only the abort path: finish() closes explicitly and checks the result.
struct FormatContextFree {
    void operator()(AVFormatContext* context) const noexcept {
        if (context->pb != nullptr && (context->oformat->flags & AVFMT_NOFILE) == 0) {
            avio_closep(&context->pb);
        }
        avformat_free_context(context);
    }
};

using FramePtr = std::unique_ptr<AVFrame, FrameFree>;
using PacketPtr = std::unique_ptr<AVPacket, PacketFree>;
using CodecContextPtr = std::unique_ptr<AVCodecContext, CodecContextFree>;
using FilterGraphPtr = std::unique_ptr<AVFilterGraph, FilterGraphFree>;
using FormatContextPtr = std::unique_ptr<AVFormatContext, FormatContextFree>;

/// True when the process runs under an address-space limit (`ulimit -v`, RLIMIT_AS).
inline bool address_space_limited() {
    rlimit limit{};
    return getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY;
}

/// libav's message for an AVERROR code ("No space left on device").
inline std::string av_error_text(int code) {
    char buffer[AV_ERROR_MAX_STRING_SIZE] = {};
    av_strerror(code, buffer, sizeof buffer);
    return buffer;
}

/// Throws Error(runtime, "<what>: <libav message>") when `code` is negative; returns it otherwise.
inline int check_av(int code, std::string_view what) {
    // Memory is main's to report, as every allocation that fails: "out of memory". x264 reports
    // a malloc that failed as an external library's error; under an address-space limit
    // (`ulimit -v`), with settings that always work, that is the memory too.
    if (code == AVERROR(ENOMEM) || (code == AVERROR_EXTERNAL && address_space_limited()))
        throw std::bad_alloc();
    if (code < 0) throw_runtime_error(std::string(what) + ": " + av_error_text(code));
    return code;
}

/// Throws std::bad_alloc (main's "out of memory") when an allocation returned null.
template <typename T>
T* check_alloc(T* pointer, std::string_view /*what*/) {
    if (pointer == nullptr) throw std::bad_alloc();
    return pointer;
}

}  // namespace collide::video::detail
