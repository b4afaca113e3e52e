// MP4 output decoded back with libavformat/libavcodec: codec, pixel format, size, frame count,
// timing, faststart, colour tags and fidelity.

#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include "../support/skip.hpp"
#include "collide/error.hpp"
#include "collide/video/video_writer.hpp"
#include "frame_sink.hpp"
#include "video_test_support.hpp"

using namespace collide::video;
using namespace collide::video::testing;

// libx265 3.5 (Debian 12) leaks a few kB per encoder inside x265::FrameFilter::init, whatever the
// caller does; LeakSanitizer (sanitizer builds) reads this hook and ignores leaks from that
// library.
extern "C" const char* __lsan_default_suppressions() {
    return "leak:libx265.so\n";
}

namespace {

constexpr int frames = 12;

VideoOptions mp4_options(const std::filesystem::path& path, int width, int height, int fps = 24) {
    set_libav_verbose(false);
    VideoOptions options;
    options.path = path;
    options.width = width;
    options.height = height;
    options.fps = fps;
    return options;
}

void encode_pattern(const VideoOptions& options, int count) {
    VideoWriter writer(options);
    for (int i = 0; i < count; ++i) writer.write(test_pattern(options.width, options.height, i));
    writer.finish();
}

std::ptrdiff_t index_of(const std::vector<std::string>& boxes, const std::string& type) {
    const auto found = std::find(boxes.begin(), boxes.end(), type);
    return found == boxes.end() ? -1 : found - boxes.begin();
}

/// Position `u` folded back into [0, size], as a disc bouncing between two walls.
double fold(double u, double size) {
    u = std::fmod(u, 2 * size);
    return u < size ? u : 2 * size - u;
}

/// What a render looks like to the encoder: a flat dark box with 20 small discs drifting across
/// it, slowly. Its frame types depend on how many frames the look-ahead sees (test_pattern's
/// fast motion does not show the difference).
collide::Image drifting_discs(int width, int height, int index) {
    collide::Image image(width, height);
    for (std::size_t p = 0; p < image.rgba.size(); p += 4) {
        image.rgba[p] = 30;
        image.rgba[p + 1] = 32;
        image.rgba[p + 2] = 44;
        image.rgba[p + 3] = 255;
    }
    const double r = height * 0.04;
    for (int disc = 0; disc < 20; ++disc) {
        const double cx = fold(width * 0.05 * disc + (0.7 + 0.13 * disc) * index, width);
        const double cy = fold(height * 0.37 * disc + (0.9 - 0.08 * disc) * index, height);
        for (int y = std::max(0, int(cy - r)); y <= std::min(height - 1, int(cy + r)); ++y) {
            for (int x = std::max(0, int(cx - r)); x <= std::min(width - 1, int(cx + r)); ++x) {
                if ((x - cx) * (x - cx) + (y - cy) * (y - cy) >= r * r) continue;
                std::uint8_t* pixel = image.pixel(x, y);
                pixel[0] = 230;
                pixel[1] = 160;
                pixel[2] = 50;
            }
        }
    }
    return image;
}

}  // namespace

TEST_CASE("H.264 MP4 decodes back with the promised stream properties and quality") {
    ScratchDirectory dir;
    const auto path = dir / "clip.mp4";
    const VideoOptions options = mp4_options(path, 320, 180, 24);
    encode_pattern(options, frames);

    const Decoded decoded = decode_file(path);
    CHECK(decoded.codec == "h264");
    CHECK(decoded.pix_fmt == AV_PIX_FMT_YUV420P);
    CHECK(decoded.width == 320);
    CHECK(decoded.height == 180);
    REQUIRE(decoded.frames.size() == static_cast<std::size_t>(frames));
    CHECK(av_cmp_q(decoded.avg_frame_rate, AVRational{24, 1}) == 0);
    CHECK(decoded.duration_seconds == doctest::Approx(frames / 24.0).epsilon(0.02));
    // Constant frame rate: consecutive timestamps one frame apart.
    for (std::size_t i = 1; i < decoded.pts.size(); ++i) {
        const double step = double(decoded.pts[i] - decoded.pts[i - 1]) * av_q2d(decoded.time_base);
        CHECK(step == doctest::Approx(1.0 / 24.0).epsilon(0.001));
    }
    CHECK(decoded.primaries == AVCOL_PRI_BT709);
    CHECK(decoded.transfer == AVCOL_TRC_BT709);
    CHECK(decoded.colorspace == AVCOL_SPC_BT709);
    CHECK(decoded.range == AVCOL_RANGE_MPEG);

    // Fidelity of the encode, as video PSNR: decoded Y, U, V planes against the exact BT.709
    // conversion of the source (a wrong matrix or range would fail this too).
    REQUIRE(decoded.planes.size() == static_cast<std::size_t>(frames));
    double worst = 99.0;
    double worst_rgb = 99.0;
    for (int i = 0; i < frames; ++i) {
        const collide::Image source = test_pattern(320, 180, i);
        worst = std::min(worst, psnr_yuv(exact_yuv420(source), decoded.planes[i]));
        worst_rgb = std::min(worst_rgb, psnr_rgb(source, decoded.frames[i]));
    }
    MESSAGE("worst PSNR " << worst << " dB (YUV planes), " << worst_rgb << " dB (RGB)");
    CHECK(worst >= 35.0);
    // In RGB, 4:2:0 chroma subsampling of the pattern's saturated hard edges alone caps PSNR near
    // 33 dB even losslessly (crf 0); still, a BT.601/full-range mix-up would fall far below 30.
    CHECK(worst_rgb >= 30.0);
    CHECK(dir.entries() == std::vector<std::string>{"clip.mp4"});  // no temporary left behind
}

TEST_CASE("MP4 is faststart: the moov box comes before mdat") {
    ScratchDirectory dir;
    const auto path = dir / "fast.mp4";
    encode_pattern(mp4_options(path, 160, 90), 5);
    const auto boxes = mp4_top_level_boxes(path);
    REQUIRE(index_of(boxes, "moov") >= 0);
    REQUIRE(index_of(boxes, "mdat") >= 0);
    CHECK(index_of(boxes, "ftyp") == 0);
    CHECK(index_of(boxes, "moov") < index_of(boxes, "mdat"));
}

TEST_CASE("odd sizes are rounded up to even, with a notice, and keep their content") {
    ScratchDirectory dir;
    const auto path = dir / "odd.mp4";
    const VideoOptions options = mp4_options(path, 161, 91);
    VideoWriter writer(options);
    CHECK(writer.output_width() == 162);
    CHECK(writer.output_height() == 92);
    REQUIRE(writer.notices().size() == 1);
    CHECK(writer.notices()[0].find("161x91 rounded up to 162x92") != std::string::npos);
    for (int i = 0; i < 4; ++i) writer.write(test_pattern(161, 91, i));
    writer.finish();

    const Decoded decoded = decode_file(path);
    CHECK(decoded.width == 162);
    CHECK(decoded.height == 92);
    REQUIRE(decoded.frames.size() == 4);
    // The added column/row repeat the last ones: compare with the source grown the same way.
    REQUIRE(decoded.planes.size() == 4);
    const collide::Image grown =
        collide::video::detail::pad_by_edge_replication(test_pattern(161, 91, 0), 162, 92);
    CHECK(psnr_yuv(exact_yuv420(grown), decoded.planes[0]) >= 35.0);
}

TEST_CASE("even sizes produce no notice") {
    ScratchDirectory dir;
    VideoWriter writer(mp4_options(dir / "even.mp4", 160, 90));
    CHECK(writer.notices().empty());
}

TEST_CASE("spare frames: consumed frames come back for reuse and the output is unchanged") {
    ScratchDirectory dir;
    const VideoOptions fresh = mp4_options(dir / "fresh.mp4", 64, 48);
    encode_pattern(fresh, frames);

    // The same frames, each drawn into a recycled buffer when one is available (stale pixels are
    // overwritten, as the renderer does).
    const VideoOptions recycled = mp4_options(dir / "recycled.mp4", 64, 48);
    VideoWriter writer(recycled);
    for (int i = 0; i < frames; ++i) {
        collide::Image frame = writer.spare_frame();
        const collide::Image pattern = test_pattern(64, 48, i);
        if (frame.rgba.empty()) {
            frame = pattern;
        } else {
            REQUIRE(frame.rgba.size() == pattern.rgba.size());
            std::copy(pattern.rgba.begin(), pattern.rgba.end(), frame.rgba.begin());
        }
        writer.write(std::move(frame));
    }
    writer.finish();
    const collide::Image spare =
        writer.spare_frame();  // the encoder has consumed every frame by now
    CHECK(spare.width == 64);
    CHECK(spare.height == 48);
    CHECK(spare.rgba.size() == 64u * 48u * 4u);
    CHECK(read_bytes(dir / "recycled.mp4") == read_bytes(dir / "fresh.mp4"));
}

TEST_CASE("preset and CRF change the encoding: lower CRF gives a bigger, better file") {
    ScratchDirectory dir;
    VideoOptions fine = mp4_options(dir / "fine.mp4", 160, 90);
    fine.crf = 12;
    fine.preset = "ultrafast";
    VideoOptions coarse = fine;
    coarse.path = dir / "coarse.mp4";
    coarse.crf = 40;
    encode_pattern(fine, 6);
    encode_pattern(coarse, 6);
    CHECK(std::filesystem::file_size(fine.path) > std::filesystem::file_size(coarse.path));
    const Decoded a = decode_file(fine.path);
    const Decoded b = decode_file(coarse.path);
    REQUIRE(a.frames.size() == 6);
    REQUIRE(b.frames.size() == 6);
    const Yuv420 reference = exact_yuv420(test_pattern(160, 90, 3));
    CHECK(psnr_yuv(reference, a.planes.at(3)) > psnr_yuv(reference, b.planes.at(3)));
}

TEST_CASE("HEVC MP4 round trip when libx265 is available") {
    if (!has_encoder("libx265")) {
        COLLIDE_SKIP_TEST("this FFmpeg has no libx265");
    }
    ScratchDirectory dir;
    VideoOptions options = mp4_options(dir / "clip.mp4", 160, 90);
    options.codec = VideoCodec::hevc;
    options.preset = "ultrafast";
    encode_pattern(options, 4);
    const Decoded decoded = decode_file(options.path);
    CHECK(decoded.codec == "hevc");
    CHECK(decoded.frames.size() == 4);
    CHECK(decoded.primaries == AVCOL_PRI_BT709);
}

TEST_CASE("AV1 MP4 round trip when libsvtav1 is available") {
    if (!has_encoder("libsvtav1")) {
        COLLIDE_SKIP_TEST("this FFmpeg has no libsvtav1");
    }
    ScratchDirectory dir;
    VideoOptions options = mp4_options(dir / "clip.mp4", 160, 96);
    options.codec = VideoCodec::av1;
    options.preset = "12";
    encode_pattern(options, 4);
    const Decoded decoded = decode_file(options.path);
    CHECK(decoded.frames.size() == 4);
    CHECK(decoded.width == 160);

    // The guarded paths: a writer destroyed before any frame, or after frames without finish(),
    // must neither hang (SVT-AV1 1.4.1 deadlocks when closed without frames) nor leave files.
    VideoOptions aborted = options;
    aborted.path = dir / "aborted.mp4";
    { VideoWriter unused(aborted); }
    {
        VideoWriter partial(aborted);
        partial.write(test_pattern(160, 96, 0));
    }
    {
        VideoWriter empty(aborted);
        CHECK_THROWS_AS(empty.finish(), collide::Error);
    }
    CHECK(dir.entries() == std::vector<std::string>{"clip.mp4"});
}

TEST_CASE("chapters: the MP4 lists them back with their titles and times, the video unchanged") {
    ScratchDirectory dir;
    VideoOptions options = mp4_options(dir / "chapters.mp4", 64, 48, 10);
    options.chapters = {
        {0.0, 0.4, "Zderzenia: Δt ≈ 0.01 s"}, {0.4, 0.9, "Kule"}, {0.9, 1.2, "End"}};
    encode_pattern(options, 12);

    AVFormatContext* format = nullptr;
    REQUIRE(avformat_open_input(&format, options.path.c_str(), nullptr, nullptr) >= 0);
    std::unique_ptr<AVFormatContext*, void (*)(AVFormatContext**)> owner(&format,
                                                                         avformat_close_input);
    REQUIRE(avformat_find_stream_info(format, nullptr) >= 0);
    REQUIRE(format->nb_chapters == 3);
    for (unsigned int i = 0; i < format->nb_chapters; ++i) {
        CAPTURE(i);
        const AVChapter* chapter = format->chapters[i];
        const AVDictionaryEntry* title = av_dict_get(chapter->metadata, "title", nullptr, 0);
        REQUIRE(title != nullptr);
        CHECK(std::string(title->value) == options.chapters[i].title);
        CHECK(static_cast<double>(chapter->start) * av_q2d(chapter->time_base) ==
              doctest::Approx(options.chapters[i].start).epsilon(0.002));
        CHECK(static_cast<double>(chapter->end) * av_q2d(chapter->time_base) ==
              doctest::Approx(options.chapters[i].end).epsilon(0.002));
    }
    const Decoded decoded = decode_file(options.path);
    CHECK(decoded.frames.size() == 12);
}

TEST_CASE("chapters: out of order, empty or untitled ones are refused, naming the field") {
    ScratchDirectory dir;
    VideoOptions options = mp4_options(dir / "bad.mp4", 64, 48, 10);
    options.chapters = {{0.0, 1.0, "a"}, {0.5, 2.0, "b"}};
    CHECK_THROWS_WITH_AS(options.validate(), doctest::Contains("video.chapters[1]"),
                         collide::Error);
    options.chapters = {{0.0, 0.0, "a"}};
    CHECK_THROWS_WITH_AS(options.validate(), doctest::Contains("video.chapters[0]"),
                         collide::Error);
    options.chapters = {{0.0, 1.0, ""}};
    CHECK_THROWS_WITH_AS(options.validate(), doctest::Contains("video.chapters[0].title"),
                         collide::Error);
}

TEST_CASE("the same frames give the same bytes whether they come in a burst or one at a time") {
    // x264's threaded look-ahead decided frame types over whatever frames had arrived, so its
    // choices followed the renderer's pace: under load the same render gave different bytes.
    // Encoded in step with the caller, the output depends on the frames alone.
    ScratchDirectory dir;
    constexpr int width = 320;
    constexpr int height = 180;
    constexpr int count = 450;  // 30 s at 15 fps: past x264's 250-frame key interval
    const VideoOptions burst = mp4_options(dir / "burst.mp4", width, height);
    {
        VideoWriter writer(burst);
        for (int i = 0; i < count; ++i) writer.write(drifting_discs(width, height, i));
        writer.finish();
    }
    const VideoOptions paced = mp4_options(dir / "paced.mp4", width, height);
    {
        VideoWriter writer(paced);
        for (int i = 0; i < count; ++i) {
            writer.write(drifting_discs(width, height, i));
            // Uneven pauses: the encoder catches up on some frames and not on others.
            if (i % 5 == 0) std::this_thread::sleep_for(std::chrono::milliseconds(2));
        }
        writer.finish();
    }
    CHECK(read_bytes(burst.path) == read_bytes(paced.path));
}
