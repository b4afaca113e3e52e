// MP4 output, following FFmpeg's doc/examples/mux.c: output context -> stream -> encoder (global
// header) -> parameters to stream -> avio_open -> header -> per frame send/receive until EAGAIN,
// rescale, interleaved write -> flush with a null frame -> trailer -> close.

extern "C" {
#include <libavutil/opt.h>
}

#include <cmath>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "av_handles.hpp"
#include "collide/video/subtitles.hpp"
#include "frame_sink.hpp"
#include "mp4_track_flags.hpp"
#include "rgba_to_yuv.hpp"

namespace collide::video::detail {
namespace {

struct CodecDefaults {
    const char* preset;
    int crf;
};

// Chosen for quality per second of encoding on our flat-coloured, sharp-edged scenes
// (docs/benchmarks.md, section Video): visually lossless at 720p/1080p, a fraction of real time.
CodecDefaults defaults_for(VideoCodec codec) {
    switch (codec) {
        case VideoCodec::h264:
            return {"veryfast", 20};
        case VideoCodec::hevc:
            return {"fast", 24};
        case VideoCodec::av1:
            return {"10", 35};
    }
    return {"", -1};
}

const AVCodec* find_encoder(const VideoOptions& options) {
    const std::string name =
        options.encoder.empty() ? std::string(encoder_name(options.codec)) : options.encoder;
    const AVCodec* codec = avcodec_find_encoder_by_name(name.c_str());
    if (codec == nullptr) {
        throw_runtime_error("video encoder '" + name + "' (for " +
                            std::string(to_string(options.codec)) +
                            ") is not available in this FFmpeg build");
    }
    if (codec->type != AVMEDIA_TYPE_VIDEO) {
        throw_runtime_error("'" + name + "' is not a video encoder");
    }
    return codec;
}

/// The ASS header libavcodec's mov_text encoder parses its one style from (it takes dialog
/// lines in ASS form): white 16 px text at the bottom centre, what players draw by default.
constexpr const char* subtitle_style_header =
    "[Script Info]\r\nScriptType: v4.00+\r\nPlayResX: 384\r\nPlayResY: 288\r\n\r\n"
    "[V4+ Styles]\r\nFormat: Name, Fontname, Fontsize, PrimaryColour, SecondaryColour, "
    "OutlineColour, BackColour, Bold, Italic, Underline, StrikeOut, ScaleX, ScaleY, Spacing, "
    "Angle, BorderStyle, Outline, Shadow, Alignment, MarginL, MarginR, MarginV, Encoding\r\n"
    "Style: Default,Sans,16,&Hffffff,&Hffffff,&H0,&H0,0,0,0,0,100,100,0,0,1,1,0,2,10,10,10,0"
    "\r\n\r\n[Events]\r\nFormat: Layer, Start, End, Style, Name, MarginL, MarginR, MarginV, "
    "Effect, Text\r\n";

/// A cue's plain text as the ASS dialog line the encoder reads. Its parser treats "\n", "\N"
/// and "{\" as markup and nothing else: line breaks become "\N", and an invisible word joiner
/// (U+2060) keeps a literal backslash-n or brace-backslash plain text.
std::string ass_dialog(const std::string& cue_text) {
    const std::string text = plain_cue_text(cue_text);  // the same words as the sidecar files
    std::string out = "0,0,Default,,0,0,0,,";
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        const char next = i + 1 < text.size() ? text[i + 1] : '\0';
        if (c == '\r') continue;
        if (c == '\n') {
            out += "\\N";
            continue;
        }
        out += c;
        if ((c == '\\' && (next == 'n' || next == 'N')) || (c == '{' && next == '\\'))
            out += "\u2060";
    }
    return out;
}

std::int64_t milliseconds(double seconds) {
    return std::llround(seconds * 1000.0);
}

class Mp4Sink final : public FrameSink {
  public:
    Mp4Sink(const VideoOptions& options, const SinkGeometry& geometry,
            const std::filesystem::path& temporary)
        : options_(options), geometry_(geometry), temporary_(temporary) {
        encoder_ = find_encoder(options);
        AVFormatContext* format = nullptr;
        check_av(avformat_alloc_output_context2(&format, nullptr, "mp4", temporary.c_str()),
                 "cannot create an MP4 muxer");
        format_.reset(format);
        packet_.reset(check_alloc(av_packet_alloc(), "AVPacket"));
        frame_.reset(check_alloc(av_frame_alloc(), "AVFrame"));
    }

    // libsvtav1 (1.4.1 in Debian 12) deadlocks when closed without ever receiving a frame; that
    // encoder is therefore only opened by the first frame (see prepare()), and an abandoned
    // SVT-AV1 encoder is also sent its end of stream and drained before it is freed (best effort,
    // errors ignored: this is the abort path). Other encoders are freed at once: draining x264's
    // look-ahead would only delay the exit after Ctrl-C.
    ~Mp4Sink() override {
        if (opened_ && !finished_ && opens_lazily()) {
            if (avcodec_send_frame(codec_.get(), nullptr) >= 0) {
                while (avcodec_receive_packet(codec_.get(), packet_.get()) >= 0) {
                    av_packet_unref(packet_.get());
                }
            }
        }
    }

    /// Opens every encoder but SVT-AV1 at once. Opened by the first frame, x264 (allocating and
    /// touching its buffers) delayed that frame's encoding noticeably; opened here it
    /// overlaps the renderer's start-up on the caller's thread (docs/benchmarks.md, Whole
    /// pipeline).
    void prepare() override {
        if (!opens_lazily()) open();
    }

    void consume(const Image& input) override {
        if (!opened_) open();
        const Image& frame =
            input.width == geometry_.output_width && input.height == geometry_.output_height
                ? input
                : (padded_ = pad_by_edge_replication(input, geometry_.output_width,
                                                     geometry_.output_height));
        // The encoder may still hold a reference to the previous frame's buffers.
        check_av(av_frame_make_writable(frame_.get()), "cannot reuse the video frame buffer");
        const Yuv420View planes{frame_->data[0],     frame_->data[1],     frame_->data[2],
                                frame_->linesize[0], frame_->linesize[1], frame_->linesize[2]};
        rgba_to_yuv420_bt709(frame.rgba.data(), static_cast<std::ptrdiff_t>(frame.stride()),
                             frame.width, frame.height, planes);
        frame_->pts = next_pts_++;
        encode(frame_.get());
    }

    void finish() override {
        if (!opened_) throw_runtime_error("no frames were written to '" + shown() + "'");
        encode(nullptr);  // flush: the encoder holds look-ahead frames
        finished_ = true;
        check_av(av_write_trailer(format_.get()), "cannot finish '" + shown() + "'");
        check_av(avio_closep(&format_->pb), "cannot close '" + shown() + "'");
        // FFmpeg's muxer enables the first subtitle track whatever its disposition.
        if (text_stream_ != nullptr && options_.subtitles_in_picture)
            disable_subtitle_tracks(temporary_);
    }

  private:
    std::string shown() const { return options_.path.string(); }
    bool opens_lazily() const { return std::string_view(encoder_->name) == "libsvtav1"; }

    void configure_encoder() {
        codec_.reset(check_alloc(avcodec_alloc_context3(encoder_), "AVCodecContext"));
        AVCodecContext& c = *codec_;
        c.width = geometry_.output_width;
        c.height = geometry_.output_height;
        c.pix_fmt = AV_PIX_FMT_YUV420P;
        c.time_base = AVRational{1, geometry_.fps};  // constant frame rate: pts = frame index
        c.framerate = AVRational{geometry_.fps, 1};
        c.sample_aspect_ratio = AVRational{1, 1};
        c.color_primaries = AVCOL_PRI_BT709;
        c.color_trc = AVCOL_TRC_BT709;
        c.colorspace = AVCOL_SPC_BT709;
        c.color_range = AVCOL_RANGE_MPEG;
        // rgba_to_yuv420 averages each 2x2 block, so chroma samples sit at the block centres.
        c.chroma_sample_location = AVCHROMA_LOC_CENTER;
        if ((format_->oformat->flags & AVFMT_GLOBALHEADER) != 0) {
            c.flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
        }
        const CodecDefaults defaults = defaults_for(options_.codec);
        const std::string preset = options_.preset.empty() ? defaults.preset : options_.preset;
        const int crf = options_.crf < 0 ? defaults.crf : options_.crf;
        // Options the chosen encoder lacks are ignored (AV_OPT_SEARCH_CHILDREN not needed:
        // priv_data holds them); av_opt_set only fails for unknown names or bad values.
        if (!preset.empty()) set_private_option("preset", preset);
        set_private_option("crf", std::to_string(crf));
        if (options_.codec == VideoCodec::hevc)
            set_private_option("x265-params", "log-level=error");
        // x264's look-ahead thread decides frame types over the frames that have arrived by
        // then, so the bytes followed the renderer's pace (under load, one render in four
        // differed). In the encoding thread it sees the same frames every run, for about 15 % more
        // wall time on 2 cores and the same CPU time (docs/benchmarks.md, Video).
        if (options_.codec == VideoCodec::h264)
            set_private_option("x264-params", "sync-lookahead=0");
    }

    void set_private_option(const char* name, const std::string& value) {
        if (codec_->priv_data == nullptr) return;
        const int result = av_opt_set(codec_->priv_data, name, value.c_str(), 0);
        if (result == AVERROR_OPTION_NOT_FOUND) return;  // e.g. a user-chosen encoder without CRF
        check_av(result, std::string("encoder option ") + name + "=" + value);
    }

    void open() {
        configure_encoder();
        check_av(avcodec_open2(codec_.get(), encoder_, nullptr),
                 std::string("cannot open encoder ") + encoder_->name);
        stream_ = check_alloc(avformat_new_stream(format_.get(), nullptr), "AVStream");
        stream_->time_base = codec_->time_base;  // a hint; the muxer picks its own in the header
        stream_->avg_frame_rate = codec_->framerate;
        check_av(avcodec_parameters_from_context(stream_->codecpar, codec_.get()),
                 "cannot copy encoder parameters");
        if (options_.codec == VideoCodec::hevc) {
            stream_->codecpar->codec_tag = MKTAG('h', 'v', 'c', '1');  // what Apple players want
        }
        if (!options_.subtitles.empty()) add_subtitle_stream();
        add_chapters();
        check_av(avio_open(&format_->pb, temporary_.c_str(), AVIO_FLAG_WRITE),
                 "cannot open '" + shown() + "' for writing");
        AVDictionary* muxer_options = nullptr;
        // Move the index (moov) before the data so players can start before the download ends.
        av_dict_set(&muxer_options, "movflags", "+faststart", 0);
        const int header = avformat_write_header(format_.get(), &muxer_options);
        av_dict_free(&muxer_options);
        check_av(header, "cannot write the header of '" + shown() + "'");
        write_subtitles();

        frame_->format = AV_PIX_FMT_YUV420P;
        frame_->width = geometry_.output_width;
        frame_->height = geometry_.output_height;
        check_av(av_frame_get_buffer(frame_.get(), 0), "cannot allocate a video frame");
        opened_ = true;
    }

    /// The subtitle track: a mov_text encoder (its sample description, the 'tx3g' box, is the
    /// stream's extradata) in milliseconds, tagged with the language.
    void add_subtitle_stream() {
        const AVCodec* text_encoder = avcodec_find_encoder(AV_CODEC_ID_MOV_TEXT);
        if (text_encoder == nullptr)
            throw_runtime_error("this FFmpeg build has no mov_text (MP4 subtitle) encoder");
        text_codec_.reset(check_alloc(avcodec_alloc_context3(text_encoder), "AVCodecContext"));
        text_codec_->time_base = AVRational{1, 1000};
        text_codec_->width = geometry_.output_width;  // the text box spans the picture
        text_codec_->height = geometry_.output_height;
        const std::size_t header_size = std::strlen(subtitle_style_header);
        // Freed by avcodec_free_context: allocated with av_malloc, as libavcodec expects.
        auto* header = static_cast<std::uint8_t*>(av_mallocz(header_size + 1));
        text_codec_->subtitle_header = check_alloc(header, "subtitle header");
        std::memcpy(header, subtitle_style_header, header_size);
        text_codec_->subtitle_header_size = static_cast<int>(header_size);
        check_av(avcodec_open2(text_codec_.get(), text_encoder, nullptr),
                 "cannot open the mov_text subtitle encoder");
        text_stream_ = check_alloc(avformat_new_stream(format_.get(), nullptr), "AVStream");
        text_stream_->time_base = text_codec_->time_base;
        check_av(avcodec_parameters_from_context(text_stream_->codecpar, text_codec_.get()),
                 "cannot copy subtitle encoder parameters");
        av_dict_set(&text_stream_->metadata, "language", options_.subtitle_language.c_str(), 0);
        text_stream_->disposition = options_.subtitles_in_picture ? 0 : AV_DISPOSITION_DEFAULT;
    }

    /// The chapters, in milliseconds, on the format context before the header is written (the
    /// mov muxer reads them there). libavformat has no public function that adds one
    /// (avpriv_new_chapter is internal), so they are made the way avformat_free_context frees
    /// them: the array and each AVChapter from av_malloc, the title in the chapter's metadata,
    /// nb_chapters counting the complete ones (the context frees those and the array).
    void add_chapters() {
        if (options_.chapters.empty()) return;
        AVFormatContext& format = *format_;
        format.chapters = static_cast<AVChapter**>(
            check_alloc(av_calloc(options_.chapters.size(), sizeof(AVChapter*)), "chapters"));
        format.nb_chapters = 0;
        for (const Chapter& source : options_.chapters) {
            auto* chapter =
                static_cast<AVChapter*>(check_alloc(av_mallocz(sizeof(AVChapter)), "AVChapter"));
            chapter->id = static_cast<std::int64_t>(format.nb_chapters) + 1;
            chapter->time_base = AVRational{1, 1000};
            chapter->start = milliseconds(source.start);
            chapter->end = milliseconds(source.end);
            format.chapters[format.nb_chapters++] = chapter;  // owned by the context from here
            check_av(av_dict_set(&chapter->metadata, "title", source.title.c_str(), 0),
                     "cannot set a chapter's title");
        }
    }

    /// Every cue, encoded and handed to the interleaving muxer (which puts them among the
    /// video's packets by time; the muxer fills the gaps between cues with empty samples).
    void write_subtitles() {
        if (text_stream_ == nullptr) return;
        std::vector<std::uint8_t> buffer;
        for (const Cue& cue : options_.subtitles) {
            std::string dialog = ass_dialog(cue.text);
            AVSubtitleRect rect{};
            rect.type = SUBTITLE_ASS;
            rect.ass = dialog.data();
            AVSubtitleRect* rects[] = {&rect};
            AVSubtitle subtitle{};
            subtitle.num_rects = 1;
            subtitle.rects = rects;
            subtitle.end_display_time =
                static_cast<std::uint32_t>(milliseconds(cue.end) - milliseconds(cue.start));
            buffer.resize(1024 + 4 * dialog.size());
            const int size =
                check_av(avcodec_encode_subtitle(text_codec_.get(), buffer.data(),
                                                 static_cast<int>(buffer.size()), &subtitle),
                         "cannot encode a subtitle");
            check_av(av_new_packet(packet_.get(), size), "cannot allocate a subtitle packet");
            std::memcpy(packet_->data, buffer.data(), static_cast<std::size_t>(size));
            packet_->pts = packet_->dts = milliseconds(cue.start);
            packet_->duration = milliseconds(cue.end) - milliseconds(cue.start);
            av_packet_rescale_ts(packet_.get(), text_codec_->time_base, text_stream_->time_base);
            packet_->stream_index = text_stream_->index;
            check_av(av_interleaved_write_frame(format_.get(), packet_.get()),
                     "cannot write '" + shown() + "'");
        }
    }

    /// Sends `frame` (null = flush) and writes every packet the encoder has ready.
    void encode(AVFrame* frame) {
        check_av(avcodec_send_frame(codec_.get(), frame), "encoding failed");
        while (true) {
            const int received = avcodec_receive_packet(codec_.get(), packet_.get());
            if (received == AVERROR(EAGAIN) || received == AVERROR_EOF) return;
            check_av(received, "encoding failed");
            av_packet_rescale_ts(packet_.get(), codec_->time_base, stream_->time_base);
            packet_->stream_index = stream_->index;
            // Takes the packet's reference; fails e.g. with "No space left on device".
            check_av(av_interleaved_write_frame(format_.get(), packet_.get()),
                     "cannot write '" + shown() + "'");
        }
    }

    const VideoOptions& options_;
    SinkGeometry geometry_;
    std::filesystem::path temporary_;
    const AVCodec* encoder_ = nullptr;
    FormatContextPtr format_;
    CodecContextPtr codec_;
    AVStream* stream_ = nullptr;       ///< owned by format_
    CodecContextPtr text_codec_;       ///< the subtitle encoder, when there are cues
    AVStream* text_stream_ = nullptr;  ///< owned by format_
    FramePtr frame_;
    PacketPtr packet_;
    Image padded_;  ///< reused buffer for odd-sized input grown to even size
    std::int64_t next_pts_ = 0;
    bool opened_ = false;
    bool finished_ = false;
};

}  // namespace

std::unique_ptr<FrameSink> make_mp4_sink(const VideoOptions& options, const SinkGeometry& geometry,
                                         const std::filesystem::path& temporary) {
    return std::make_unique<Mp4Sink>(options, geometry, temporary);
}

}  // namespace collide::video::detail
