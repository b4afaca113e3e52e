// GIF through libavfilter: all frames go through one graph
//   buffer -> split -> palettegen ---------> paletteuse -> buffersink -> gif encoder -> gif muxer
//                   \-------------------------^
// palettegen emits its palette only at end of stream, so paletteuse holds the frames until then:
// a palette computed from the whole clip (no banding from a generic 256-colour palette), at the
// price of keeping the clip in memory (about width * height * 4 bytes per frame). GIFs are for
// short slide clips, where this is a few hundred MB at most.

extern "C" {
#include <libavfilter/buffersink.h>
#include <libavfilter/buffersrc.h>
}

#include <cstring>
#include <string>

#include "av_handles.hpp"
#include "frame_sink.hpp"

namespace collide::video::detail {
namespace {

class GifSink final : public FrameSink {
public:
    GifSink(const SinkGeometry& geometry, const std::filesystem::path& temporary)
        : geometry_(geometry), temporary_(temporary) {
        // Each kept frame lasts frame_step input frames.
        time_base_ = AVRational{geometry.frame_step, geometry.fps};
        build_graph();
        open_encoder_and_muxer();
        packet_.reset(check_alloc(av_packet_alloc(), "AVPacket"));
        filtered_.reset(check_alloc(av_frame_alloc(), "AVFrame"));
    }

    void consume(const Image& frame) override {
        const std::int64_t index = input_index_++;
        if (index % geometry_.frame_step != 0) return;  // even frame dropping for the rate cap
        FramePtr rgba(check_alloc(av_frame_alloc(), "AVFrame"));
        rgba->format = AV_PIX_FMT_RGBA;
        rgba->width = frame.width;
        rgba->height = frame.height;
        check_av(av_frame_get_buffer(rgba.get(), 0), "cannot allocate a GIF frame");
        for (int row = 0; row < frame.height; ++row) {
            std::memcpy(rgba->data[0] + row * rgba->linesize[0], frame.pixel(0, row),
                        frame.stride());
        }
        rgba->pts = index / geometry_.frame_step;
        check_av(av_buffersrc_add_frame(source_, rgba.get()), "GIF palette filter failed");
        drain_filter();
    }

    void finish() override {
        if (input_index_ == 0) throw_runtime_error("no frames were written to the GIF");
        check_av(av_buffersrc_add_frame(source_, nullptr), "GIF palette filter failed");
        drain_filter();
        encode(nullptr);
        check_av(av_write_trailer(format_.get()), "cannot finish the GIF");
        check_av(avio_closep(&format_->pb), "cannot close the GIF");
    }

private:
    void build_graph() {
        graph_.reset(check_alloc(avfilter_graph_alloc(), "AVFilterGraph"));
        // reserve_transparent=0: our frames are opaque, so all 256 entries hold colours.
        // diff_mode=rectangle: only re-dither the changed part, keeping static areas stable.
        const std::string description =
            "buffer@in=video_size=" + std::to_string(geometry_.input_width) + "x" +
            std::to_string(geometry_.input_height) + ":pix_fmt=" +
            std::to_string(static_cast<int>(AV_PIX_FMT_RGBA)) +
            ":time_base=" + std::to_string(time_base_.num) + "/" + std::to_string(time_base_.den) +
            ":pixel_aspect=1/1,split[a][b];[a]palettegen=reserve_transparent=0:stats_mode=full[p];"
            "[b][p]paletteuse=dither=sierra2_4a:diff_mode=rectangle,buffersink@out";
        AVFilterInOut* inputs = nullptr;
        AVFilterInOut* outputs = nullptr;
        const int parsed =
            avfilter_graph_parse2(graph_.get(), description.c_str(), &inputs, &outputs);
        avfilter_inout_free(&inputs);
        avfilter_inout_free(&outputs);
        check_av(parsed, "cannot build the GIF palette filters");
        check_av(avfilter_graph_config(graph_.get(), nullptr), "cannot configure the GIF filters");
        source_ = avfilter_graph_get_filter(graph_.get(), "buffer@in");
        sink_ = avfilter_graph_get_filter(graph_.get(), "buffersink@out");
        if (source_ == nullptr || sink_ == nullptr) {
            throw_runtime_error("GIF filter graph lacks its source or sink");
        }
    }

    void open_encoder_and_muxer() {
        const AVCodec* gif = avcodec_find_encoder(AV_CODEC_ID_GIF);
        if (gif == nullptr) throw_runtime_error("the GIF encoder is not available in this FFmpeg");
        AVFormatContext* format = nullptr;
        check_av(avformat_alloc_output_context2(&format, nullptr, "gif", temporary_.c_str()),
                 "cannot create a GIF muxer");
        format_.reset(format);
        codec_.reset(check_alloc(avcodec_alloc_context3(gif), "AVCodecContext"));
        codec_->width = geometry_.input_width;
        codec_->height = geometry_.input_height;
        codec_->pix_fmt = AV_PIX_FMT_PAL8;
        codec_->time_base = time_base_;
        check_av(avcodec_open2(codec_.get(), gif, nullptr), "cannot open the GIF encoder");
        stream_ = check_alloc(avformat_new_stream(format_.get(), nullptr), "AVStream");
        stream_->time_base = time_base_;
        check_av(avcodec_parameters_from_context(stream_->codecpar, codec_.get()),
                 "cannot copy GIF parameters");
        check_av(avio_open(&format_->pb, temporary_.c_str(), AVIO_FLAG_WRITE),
                 "cannot open the GIF for writing");
        check_av(avformat_write_header(format_.get(), nullptr), "cannot write the GIF header");
    }

    /// Encodes every frame paletteuse has ready (none until palettegen saw the end of stream).
    void drain_filter() {
        while (true) {
            const int got = av_buffersink_get_frame(sink_, filtered_.get());
            if (got == AVERROR(EAGAIN) || got == AVERROR_EOF) return;
            check_av(got, "GIF palette filter failed");
            filtered_->pict_type = AV_PICTURE_TYPE_NONE;
            const int sent = avcodec_send_frame(codec_.get(), filtered_.get());
            av_frame_unref(filtered_.get());
            check_av(sent, "GIF encoding failed");
            receive_packets();
        }
    }

    void encode(AVFrame* frame) {
        check_av(avcodec_send_frame(codec_.get(), frame), "GIF encoding failed");
        receive_packets();
    }

    void receive_packets() {
        while (true) {
            const int received = avcodec_receive_packet(codec_.get(), packet_.get());
            if (received == AVERROR(EAGAIN) || received == AVERROR_EOF) return;
            check_av(received, "GIF encoding failed");
            av_packet_rescale_ts(packet_.get(), codec_->time_base, stream_->time_base);
            packet_->stream_index = stream_->index;
            check_av(av_interleaved_write_frame(format_.get(), packet_.get()),
                     "cannot write the GIF");
        }
    }

    SinkGeometry geometry_;
    std::filesystem::path temporary_;
    AVRational time_base_{1, 25};
    FilterGraphPtr graph_;
    AVFilterContext* source_ = nullptr;  ///< owned by graph_
    AVFilterContext* sink_ = nullptr;    ///< owned by graph_
    FormatContextPtr format_;
    CodecContextPtr codec_;
    AVStream* stream_ = nullptr;  ///< owned by format_
    PacketPtr packet_;
    FramePtr filtered_;
    std::int64_t input_index_ = 0;
};

}  // namespace

std::unique_ptr<FrameSink> make_gif_sink(const SinkGeometry& geometry,
                                         const std::filesystem::path& temporary) {
    return std::make_unique<GifSink>(geometry, temporary);
}

}  // namespace collide::video::detail
