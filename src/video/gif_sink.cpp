// GIF through libavfilter, two passes so that one palette fits the whole clip:
//   pass 1 (while frames arrive): buffer -> palettegen -> buffersink   (a 16x16 palette at EOF)
//   pass 2 (in finish):           buffer (frames re-read) + buffer (palette) -> paletteuse
//                                 -> buffersink -> gif encoder -> gif muxer
// Between the passes the kept frames wait in an unnamed spill file beside the output (raw RGBA,
// io::open_scratch_file: never named, or unlinked at once, so nothing is left behind even after a
// crash), not in memory: a 720p GIF
// of 10 s would otherwise hold ~1 GB.

extern "C" {
#include <libavfilter/buffersink.h>
#include <libavfilter/buffersrc.h>
#include <libavutil/pixdesc.h>
}

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "av_handles.hpp"
#include "frame_sink.hpp"

namespace collide::video::detail {
namespace {

/// Raw frames of one size appended to an unlinked temporary file and read back by index.
class SpillFile {
  public:
    SpillFile(const std::filesystem::path& directory, std::size_t frame_bytes)
        : file_(io::open_scratch_file(directory)), fd_(file_.get()), frame_bytes_(frame_bytes) {}
    SpillFile(const SpillFile&) = delete;
    SpillFile& operator=(const SpillFile&) = delete;

    void append(const std::uint8_t* data) {
        const auto offset = static_cast<off_t>(frames_ * frame_bytes_);
        transfer(data, offset, ::pwrite, "write");
        ++frames_;
    }
    void read(std::size_t index, std::uint8_t* data) {
        transfer(data, static_cast<off_t>(index * frame_bytes_), ::pread, "read");
    }
    [[nodiscard]] std::size_t frames() const noexcept { return frames_; }

  private:
    static std::string errno_text() { return std::strerror(errno); }

    /// Moves one frame between memory and the file at `offset`, retrying short transfers.
    template <typename Buffer, typename Io>
    void transfer(Buffer* data, off_t offset, Io io, const char* what) {
        std::size_t done = 0;
        while (done < frame_bytes_) {
            const ssize_t n =
                io(fd_, data + done, frame_bytes_ - done, offset + static_cast<off_t>(done));
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) {
                throw_runtime_error(std::string("GIF frame store: cannot ") + what + ": " +
                                    (n < 0 ? errno_text() : std::string("unexpected end")));
            }
            done += static_cast<std::size_t>(n);
        }
    }

    io::File file_;
    int fd_ = -1;  ///< file_'s descriptor
    std::size_t frame_bytes_ = 0;
    std::size_t frames_ = 0;
};

/// A configured filter graph with its named source(s) and sink.
struct FilterChain {
    FilterGraphPtr graph;
    AVFilterContext* source = nullptr;   ///< "buffer@in", owned by graph
    AVFilterContext* palette = nullptr;  ///< "buffer@palette" (pass 2 only), owned by graph
    AVFilterContext* sink = nullptr;     ///< "buffersink@out", owned by graph
};

FilterChain build_chain(const std::string& description) {
    FilterChain chain;
    chain.graph.reset(check_alloc(avfilter_graph_alloc(), "AVFilterGraph"));
    chain.graph->nb_threads = 1;  // palette filters are cheap; leave the cores to x264 & co.
    AVFilterInOut* inputs = nullptr;
    AVFilterInOut* outputs = nullptr;
    const int parsed =
        avfilter_graph_parse2(chain.graph.get(), description.c_str(), &inputs, &outputs);
    avfilter_inout_free(&inputs);
    avfilter_inout_free(&outputs);
    check_av(parsed, "cannot build the GIF palette filters");
    check_av(avfilter_graph_config(chain.graph.get(), nullptr), "cannot configure the GIF filters");
    chain.source = avfilter_graph_get_filter(chain.graph.get(), "buffer@in");
    chain.palette = avfilter_graph_get_filter(chain.graph.get(), "buffer@palette");
    chain.sink = avfilter_graph_get_filter(chain.graph.get(), "buffersink@out");
    if (chain.source == nullptr || chain.sink == nullptr) {
        throw_runtime_error("GIF filter graph lacks its source or sink");
    }
    return chain;
}

std::string buffer_arguments(int width, int height, int pix_fmt, AVRational time_base) {
    return "video_size=" + std::to_string(width) + "x" + std::to_string(height) +
           ":pix_fmt=" + std::to_string(pix_fmt) + ":time_base=" + std::to_string(time_base.num) +
           "/" + std::to_string(time_base.den) + ":pixel_aspect=1/1";
}

class GifSink final : public FrameSink {
  public:
    GifSink(const SinkGeometry& geometry, const std::filesystem::path& temporary,
            const std::filesystem::path& scratch_directory)
        : geometry_(geometry),
          temporary_(temporary),
          spill_(scratch_directory, static_cast<std::size_t>(geometry.input_width) *
                                        static_cast<std::size_t>(geometry.input_height) * 4) {
        // Each kept frame lasts frame_step input frames.
        time_base_ = AVRational{geometry.frame_step, geometry.fps};
        // reserve_transparent=0: our frames are opaque, so all 256 entries hold colours.
        statistics_ = build_chain("buffer@in=" + input_arguments() +
                                  ",palettegen=reserve_transparent=0:stats_mode=full"
                                  ",buffersink@out");
        packet_.reset(check_alloc(av_packet_alloc(), "AVPacket"));
        filtered_.reset(check_alloc(av_frame_alloc(), "AVFrame"));
    }

    void consume(const Image& frame) override {
        const std::int64_t index = input_index_++;
        if (index % geometry_.frame_step != 0) return;  // even frame dropping for the rate cap
        spill_.append(frame.rgba.data());
        add_frame(statistics_.source, frame.rgba.data(),
                  static_cast<std::int64_t>(spill_.frames() - 1));
    }

    void finish() override {
        if (spill_.frames() == 0) throw_runtime_error("no frames were written to the GIF");
        FramePtr palette = compute_palette();
        dither_ = build_chain(
            "buffer@in=" + input_arguments() + "[main];buffer@palette=" +
            buffer_arguments(palette->width, palette->height, palette->format, time_base_) +
            "[palette];[main][palette]paletteuse=dither=sierra2_4a:diff_mode=rectangle"
            ",buffersink@out");
        // diff_mode=rectangle: only re-dither the changed part, keeping static areas stable.
        palette->pts = 0;
        check_av(av_buffersrc_add_frame(dither_.palette, palette.get()), "GIF palette failed");
        check_av(av_buffersrc_add_frame(dither_.palette, nullptr), "GIF palette failed");
        open_encoder_and_muxer();
        std::vector<std::uint8_t> pixels(static_cast<std::size_t>(geometry_.input_width) *
                                         static_cast<std::size_t>(geometry_.input_height) * 4);
        for (std::size_t i = 0; i < spill_.frames(); ++i) {
            spill_.read(i, pixels.data());
            add_frame(dither_.source, pixels.data(), static_cast<std::int64_t>(i));
            encode_filtered();
        }
        check_av(av_buffersrc_add_frame(dither_.source, nullptr), "GIF dithering failed");
        encode_filtered();
        encode(nullptr);
        check_av(av_write_trailer(format_.get()), "cannot finish the GIF");
        check_av(avio_closep(&format_->pb), "cannot close the GIF");
    }

  private:
    std::string input_arguments() const {
        return buffer_arguments(geometry_.input_width, geometry_.input_height, AV_PIX_FMT_RGBA,
                                time_base_);
    }

    /// Copies RGBA pixels into a new frame with timestamp `pts` and hands it to `source`, then
    /// runs the graph until every filter has taken what it can. Without that push, pass 1 would
    /// keep every frame queued in memory until finish(): palettegen outputs nothing before the
    /// end, so nothing downstream ever pulls, and a filter graph only runs when something pulls.
    /// Pushed, palettegen adds each frame to its colour histogram and frees it at once.
    void add_frame(AVFilterContext* source, const std::uint8_t* rgba, std::int64_t pts) {
        FramePtr frame(check_alloc(av_frame_alloc(), "AVFrame"));
        frame->format = AV_PIX_FMT_RGBA;
        frame->width = geometry_.input_width;
        frame->height = geometry_.input_height;
        check_av(av_frame_get_buffer(frame.get(), 0), "cannot allocate a GIF frame");
        const std::size_t row_bytes = static_cast<std::size_t>(geometry_.input_width) * 4;
        for (int row = 0; row < geometry_.input_height; ++row) {
            std::memcpy(frame->data[0] + row * frame->linesize[0], rgba + row * row_bytes,
                        row_bytes);
        }
        frame->pts = pts;
        check_av(av_buffersrc_add_frame_flags(source, frame.get(), AV_BUFFERSRC_FLAG_PUSH),
                 "GIF palette filter failed");
    }

    /// Ends pass 1 and returns palettegen's single output frame.
    FramePtr compute_palette() {
        check_av(av_buffersrc_add_frame(statistics_.source, nullptr), "GIF palette failed");
        FramePtr palette(check_alloc(av_frame_alloc(), "AVFrame"));
        check_av(av_buffersink_get_frame(statistics_.sink, palette.get()),
                 "GIF palette generation failed");
        statistics_ = FilterChain{};  // pass 1 done: free its graph
        return palette;
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

    /// Encodes every frame paletteuse has ready.
    void encode_filtered() {
        while (true) {
            const int got = av_buffersink_get_frame(dither_.sink, filtered_.get());
            if (got == AVERROR(EAGAIN) || got == AVERROR_EOF) return;
            check_av(got, "GIF dithering failed");
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
    SpillFile spill_;
    AVRational time_base_{1, 25};
    FilterChain statistics_;  ///< pass 1: palettegen
    FilterChain dither_;      ///< pass 2: paletteuse
    FormatContextPtr format_;
    CodecContextPtr codec_;
    AVStream* stream_ = nullptr;  ///< owned by format_
    PacketPtr packet_;
    FramePtr filtered_;
    std::int64_t input_index_ = 0;
};

}  // namespace

std::unique_ptr<FrameSink> make_gif_sink(const SinkGeometry& geometry,
                                         const std::filesystem::path& temporary,
                                         const std::filesystem::path& scratch_directory) {
    return std::make_unique<GifSink>(geometry, temporary, scratch_directory);
}

}  // namespace collide::video::detail
