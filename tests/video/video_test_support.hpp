#pragma once
// Test support for collide_video_tests: test patterns, PSNR, a libav decoder that reads a file
// back frame by frame, MP4 top-level box listing, and scratch directories.

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "collide/image.hpp"

namespace collide::video::testing {

/// A frame with structure (smooth gradient, hard-edged discs moving with `index`, thin stripes):
/// what the renderer draws, and hard enough that a broken conversion or encoder shows in PSNR.
inline Image test_pattern(int width, int height, int index) {
    Image image(width, height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            std::uint8_t* p = image.pixel(x, y);
            p[0] = static_cast<std::uint8_t>(40 + 150 * x / width);
            p[1] = static_cast<std::uint8_t>(60 + 120 * y / height);
            p[2] = static_cast<std::uint8_t>(200 - 100 * (x + y) / (width + height));
            p[3] = 255;
            if (y < height / 8 && (x / 4) % 2 == 0) p[0] = p[1] = p[2] = 230;  // stripes
            for (int disc = 0; disc < 3; ++disc) {
                const double cx = (width * (0.2 + 0.3 * disc) + 3.0 * index) - width * 0.0;
                const double cy = height * (0.5 + 0.2 * std::sin(0.3 * index + disc));
                const double r = height * (0.12 + 0.03 * disc);
                if ((x - cx) * (x - cx) + (y - cy) * (y - cy) < r * r) {
                    p[0] = static_cast<std::uint8_t>(disc == 0 ? 220 : 30);
                    p[1] = static_cast<std::uint8_t>(disc == 1 ? 200 : 40);
                    p[2] = static_cast<std::uint8_t>(disc == 2 ? 210 : 50);
                }
            }
        }
    }
    return image;
}

/// Peak signal-to-noise ratio over the RGB channels of the common top-left area, in dB.
inline double psnr_rgb(const Image& a, const Image& b) {
    const int width = std::min(a.width, b.width);
    const int height = std::min(a.height, b.height);
    double squared = 0.0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            for (int c = 0; c < 3; ++c) {
                const double d = double(a.pixel(x, y)[c]) - double(b.pixel(x, y)[c]);
                squared += d * d;
            }
        }
    }
    const double mse = squared / (3.0 * width * height);
    return mse == 0.0 ? 99.0 : 10.0 * std::log10(255.0 * 255.0 / mse);
}

/// A yuv420p picture (tight planes).
struct Yuv420 {
    int width = 0;
    int height = 0;
    std::vector<double> y, u, v;
};

/// ITU-R BT.709, 8-bit limited range, in floating point: the reference for the converter tests.
inline double bt709_y(double r, double g, double b) {
    return 16.0 + 219.0 / 255.0 * (0.2126 * r + 0.7152 * g + 0.0722 * b);
}
inline double bt709_u(double r, double g, double b) {
    return 128.0 + 224.0 / 255.0 * (b - (0.2126 * r + 0.7152 * g + 0.0722 * b)) / 1.8556;
}
inline double bt709_v(double r, double g, double b) {
    return 128.0 + 224.0 / 255.0 * (r - (0.2126 * r + 0.7152 * g + 0.0722 * b)) / 1.5748;
}

/// The exact BT.709 yuv420p of an (even-sized) RGBA image, chroma from 2x2 averages.
inline Yuv420 exact_yuv420(const Image& image) {
    Yuv420 out{image.width, image.height, {}, {}, {}};
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* p = image.pixel(x, y);
            out.y.push_back(bt709_y(p[0], p[1], p[2]));
        }
    }
    for (int cy = 0; cy < image.height / 2; ++cy) {
        for (int cx = 0; cx < image.width / 2; ++cx) {
            double r = 0, g = 0, b = 0;
            for (int dy = 0; dy < 2; ++dy) {
                for (int dx = 0; dx < 2; ++dx) {
                    const std::uint8_t* p = image.pixel(2 * cx + dx, 2 * cy + dy);
                    r += p[0] / 4.0;
                    g += p[1] / 4.0;
                    b += p[2] / 4.0;
                }
            }
            out.u.push_back(bt709_u(r, g, b));
            out.v.push_back(bt709_v(r, g, b));
        }
    }
    return out;
}

/// PSNR of one plane against a reference plane of the same size, in dB.
inline double psnr_plane(const std::vector<double>& a, const std::vector<double>& b) {
    double squared = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) squared += (a[i] - b[i]) * (a[i] - b[i]);
    const double mse = squared / double(a.size());
    return mse == 0.0 ? 99.0 : 10.0 * std::log10(255.0 * 255.0 / mse);
}

/// The lowest of the Y, U and V PSNRs: the usual way to state a video codec's fidelity.
inline double psnr_yuv(const Yuv420& reference, const Yuv420& decoded) {
    return std::min({psnr_plane(reference.y, decoded.y), psnr_plane(reference.u, decoded.u),
                     psnr_plane(reference.v, decoded.v)});
}

/// What a file decodes to.
struct Decoded {
    std::string codec;  ///< decoder name, e.g. "h264"
    AVPixelFormat pix_fmt = AV_PIX_FMT_NONE;
    int width = 0;
    int height = 0;
    AVRational avg_frame_rate{0, 1};
    double duration_seconds = 0.0;  ///< container duration
    AVColorPrimaries primaries = AVCOL_PRI_UNSPECIFIED;
    AVColorTransferCharacteristic transfer = AVCOL_TRC_UNSPECIFIED;
    AVColorSpace colorspace = AVCOL_SPC_UNSPECIFIED;
    AVColorRange range = AVCOL_RANGE_UNSPECIFIED;
    std::vector<std::int64_t> pts;  ///< per decoded frame, in stream time base
    AVRational time_base{0, 1};
    std::vector<Image> frames;   ///< decoded frames as RGBA (BT.709 limited -> full RGB)
    std::vector<Yuv420> planes;  ///< decoded frames' planes, when yuv420p
};

/// Decodes every frame of the first video stream of `path` (throws std::runtime_error).
inline Decoded decode_file(const std::filesystem::path& path) {
    Decoded out;
    AVFormatContext* format = nullptr;
    if (avformat_open_input(&format, path.c_str(), nullptr, nullptr) < 0) {
        throw std::runtime_error("cannot open " + path.string());
    }
    std::unique_ptr<AVFormatContext*, void (*)(AVFormatContext**)> format_owner(
        &format, avformat_close_input);
    if (avformat_find_stream_info(format, nullptr) < 0) throw std::runtime_error("no stream info");
    const int index = av_find_best_stream(format, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
    if (index < 0) throw std::runtime_error("no video stream");
    AVStream* stream = format->streams[index];
    const AVCodecParameters* par = stream->codecpar;
    const AVCodec* decoder = avcodec_find_decoder(par->codec_id);
    if (decoder == nullptr) throw std::runtime_error("no decoder");
    out.codec = decoder->name;
    out.width = par->width;
    out.height = par->height;
    out.pix_fmt = static_cast<AVPixelFormat>(par->format);
    out.avg_frame_rate = stream->avg_frame_rate;
    out.time_base = stream->time_base;
    out.duration_seconds = format->duration > 0 ? double(format->duration) / AV_TIME_BASE : 0.0;
    out.primaries = par->color_primaries;
    out.transfer = par->color_trc;
    out.colorspace = par->color_space;
    out.range = par->color_range;

    AVCodecContext* codec = avcodec_alloc_context3(decoder);
    std::unique_ptr<AVCodecContext*, void (*)(AVCodecContext**)> codec_owner(&codec,
                                                                             avcodec_free_context);
    avcodec_parameters_to_context(codec, par);
    if (avcodec_open2(codec, decoder, nullptr) < 0) throw std::runtime_error("cannot open decoder");
    AVPacket* packet = av_packet_alloc();
    std::unique_ptr<AVPacket*, void (*)(AVPacket**)> packet_owner(&packet, av_packet_free);
    AVFrame* frame = av_frame_alloc();
    std::unique_ptr<AVFrame*, void (*)(AVFrame**)> frame_owner(&frame, av_frame_free);

    auto to_rgba = [&](const AVFrame* f) {
        Image image(f->width, f->height);
        SwsContext* sws = sws_getContext(f->width, f->height, static_cast<AVPixelFormat>(f->format),
                                         f->width, f->height, AV_PIX_FMT_RGBA,
                                         SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT,
                                         nullptr, nullptr, nullptr);
        if (f->format == AV_PIX_FMT_YUV420P) {
            int* inv = nullptr;
            int* table = nullptr;
            int src_range = 0, dst_range = 0, b = 0, c = 0, s = 0;
            sws_getColorspaceDetails(sws, &inv, &src_range, &table, &dst_range, &b, &c, &s);
            sws_setColorspaceDetails(sws, sws_getCoefficients(SWS_CS_ITU709), 0, table, 1, b, c, s);
        }
        std::uint8_t* dst[1] = {image.rgba.data()};
        const int dst_stride[1] = {static_cast<int>(image.stride())};
        sws_scale(sws, f->data, f->linesize, 0, f->height, dst, dst_stride);
        sws_freeContext(sws);
        return image;
    };
    auto receive_all = [&] {
        while (avcodec_receive_frame(codec, frame) >= 0) {
            out.pts.push_back(frame->best_effort_timestamp);
            out.frames.push_back(to_rgba(frame));
            if (frame->format == AV_PIX_FMT_YUV420P) {
                Yuv420 planes{frame->width, frame->height, {}, {}, {}};
                for (int y = 0; y < frame->height; ++y) {
                    for (int x = 0; x < frame->width; ++x) {
                        planes.y.push_back(frame->data[0][y * frame->linesize[0] + x]);
                    }
                }
                for (int y = 0; y < frame->height / 2; ++y) {
                    for (int x = 0; x < frame->width / 2; ++x) {
                        planes.u.push_back(frame->data[1][y * frame->linesize[1] + x]);
                        planes.v.push_back(frame->data[2][y * frame->linesize[2] + x]);
                    }
                }
                out.planes.push_back(std::move(planes));
            }
            av_frame_unref(frame);
        }
    };
    while (av_read_frame(format, packet) >= 0) {
        if (packet->stream_index == index) avcodec_send_packet(codec, packet);
        av_packet_unref(packet);
        receive_all();
    }
    avcodec_send_packet(codec, nullptr);
    receive_all();
    return out;
}

/// Four-character types of the top-level boxes of an MP4 file, in file order.
inline std::vector<std::string> mp4_top_level_boxes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::vector<std::string> boxes;
    const auto file_size = static_cast<std::uint64_t>(std::filesystem::file_size(path));
    std::uint64_t offset = 0;
    while (offset + 8 <= file_size) {
        unsigned char header[16];
        in.seekg(static_cast<std::streamoff>(offset));
        in.read(reinterpret_cast<char*>(header), 8);
        std::uint64_t size =
            (std::uint64_t(header[0]) << 24) | (header[1] << 16) | (header[2] << 8) | header[3];
        boxes.emplace_back(reinterpret_cast<char*>(header) + 4, 4);
        if (size == 1) {
            in.read(reinterpret_cast<char*>(header) + 8, 8);
            size = 0;
            for (int i = 8; i < 16; ++i) size = (size << 8) | header[i];
        } else if (size == 0) {
            size = file_size - offset;
        }
        if (size < 8) break;
        offset += size;
    }
    return boxes;
}

/// A fresh directory under the system temp dir, removed (recursively) by the destructor.
class ScratchDirectory {
  public:
    ScratchDirectory() {
        std::string name =
            (std::filesystem::temp_directory_path() / "collide-video-XXXXXX").string();
        if (mkdtemp(name.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
        path_ = name;
    }
    ~ScratchDirectory() {
        std::error_code ignored;
        std::filesystem::permissions(path_, std::filesystem::perms::owner_all,
                                     std::filesystem::perm_options::add, ignored);
        std::filesystem::remove_all(path_, ignored);
    }
    ScratchDirectory(const ScratchDirectory&) = delete;
    ScratchDirectory& operator=(const ScratchDirectory&) = delete;
    const std::filesystem::path& path() const { return path_; }
    std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
    /// Names of the entries (including hidden temporaries), sorted.
    std::vector<std::string> entries() const {
        std::vector<std::string> names;
        for (const auto& entry : std::filesystem::directory_iterator(path_)) {
            names.push_back(entry.path().filename().string());
        }
        std::sort(names.begin(), names.end());
        return names;
    }

  private:
    std::filesystem::path path_;
};

inline std::string read_bytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

inline void write_bytes(const std::filesystem::path& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
}

}  // namespace collide::video::testing
