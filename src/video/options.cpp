#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <string>

#include "collide/error.hpp"
#include "collide/named_values.hpp"
#include "collide/video/subtitles.hpp"
#include "collide/video/video_writer.hpp"

namespace collide::video {
namespace {

constexpr int max_dimension = 8192;
constexpr int max_fps = 240;
constexpr int max_queue_frames = 64;
constexpr std::array<NamedValue<VideoFormat>, 4> format_names{
    {{"mp4", VideoFormat::mp4},
     {"gif", VideoFormat::gif},
     {"png", VideoFormat::png_sequence},
     {"png_sequence", VideoFormat::png_sequence}}};
/// Own names first; the encoders' and the other standards' names are accepted as aliases.
constexpr std::array<NamedValue<VideoCodec>, 7> codec_names{{{"h264", VideoCodec::h264},
                                                             {"hevc", VideoCodec::hevc},
                                                             {"av1", VideoCodec::av1},
                                                             {"avc", VideoCodec::h264},
                                                             {"x264", VideoCodec::h264},
                                                             {"h265", VideoCodec::hevc},
                                                             {"x265", VideoCodec::hevc}}};
constexpr std::array<std::string_view, 10> x26x_presets = {
    "ultrafast", "superfast", "veryfast", "faster",   "fast",
    "medium",    "slow",      "slower",   "veryslow", "placebo"};

void require_range(std::string_view field, int value, int low, int high) {
    if (value < low || value > high) {
        throw_scene_error("", 0, std::string(field),
                          "must be " + std::to_string(low) + ".." + std::to_string(high) +
                              ", got " + std::to_string(value));
    }
}

void validate_preset(const VideoOptions& options) {
    if (options.preset.empty() || options.format != VideoFormat::mp4) return;
    if (options.codec == VideoCodec::av1) {
        const bool digits = std::all_of(options.preset.begin(), options.preset.end(),
                                        [](unsigned char c) { return std::isdigit(c) != 0; });
        if (!digits || options.preset.size() > 2 || std::stoi(options.preset) > 13) {
            throw_scene_error(
                "", 0, "video.preset",
                "AV1 (SVT-AV1) presets are numbers 0..13, got '" + options.preset + "'");
        }
        return;
    }
    if (std::find(x26x_presets.begin(), x26x_presets.end(), options.preset) == x26x_presets.end()) {
        throw_scene_error("", 0, "video.preset",
                          "expected one of ultrafast superfast veryfast faster fast medium slow "
                          "slower veryslow placebo, got '" +
                              options.preset + "'");
    }
}

/// Cues in order, each within [0, inf) and after the previous one's end: one subtitle at a time,
/// what an MP4 text track can hold.
void validate_cues(const Cues& cues) {
    double previous_end = 0.0;
    for (std::size_t i = 0; i < cues.size(); ++i) {
        const Cue& cue = cues[i];
        const std::string field = "video.subtitles[" + std::to_string(i) + "]";
        if (!(cue.start >= previous_end) || !(cue.end > cue.start) || !std::isfinite(cue.end)) {
            throw_scene_error("", 0, field,
                              "must start at or after the previous cue's end and end after it "
                              "starts, got " +
                                  std::to_string(cue.start) + ".." + std::to_string(cue.end) +
                                  " s");
        }
        previous_end = cue.end;
    }
}

/// Chapters in order, each non-empty, with a title, and none starting before the previous end.
void validate_chapters(const Chapters& chapters) {
    double previous_end = 0.0;
    for (std::size_t i = 0; i < chapters.size(); ++i) {
        const Chapter& chapter = chapters[i];
        const std::string field = "video.chapters[" + std::to_string(i) + "]";
        if (!(chapter.start >= previous_end) || !(chapter.end > chapter.start) ||
            !std::isfinite(chapter.end)) {
            throw_scene_error("", 0, field,
                              "must start at or after the previous chapter's end and end after "
                              "it starts, got " +
                                  std::to_string(chapter.start) + ".." +
                                  std::to_string(chapter.end) + " s");
        }
        if (chapter.title.empty()) throw_scene_error("", 0, field + ".title", "is empty");
        previous_end = chapter.end;
    }
}

}  // namespace

void VideoOptions::validate() const {
    if (path.empty()) throw_scene_error("", 0, "video.path", "is empty");
    require_range("video.width", width, 1, max_dimension);
    require_range("video.height", height, 1, max_dimension);
    require_range("video.fps", fps, 1, max_fps);
    require_range("video.queue_frames", queue_frames, 1, max_queue_frames);
    if (crf != -1) {
        require_range("video.crf", crf, 0, codec == VideoCodec::av1 ? 63 : 51);
    }
    validate_preset(*this);
    if (!format_built(format))
        throw_scene_error("", 0, "video.format",
                          "this build has no video (" + std::string(to_string(format)) +
                              "): built with -DCOLLIDE_VIDEO=OFF, it writes PNG frames only");
    validate_cues(subtitles);
    validate_chapters(chapters);
    if (video::subtitle_language(subtitle_language, "video.subtitle_language") !=
        subtitle_language) {
        throw_scene_error(
            "", 0, "video.subtitle_language",
            "must be an ISO 639-2/T code such as eng or pol, got '" + subtitle_language + "'");
    }
}

bool format_built(VideoFormat format) noexcept {
#ifdef COLLIDE_NO_VIDEO
    return format == VideoFormat::png_sequence;
#else
    (void)format;
    return true;
#endif
}

void require_format_built(VideoFormat format, std::string_view option) {
    if (format_built(format)) return;
    throw_option_error(std::string(option),
                       "this build has no video (" + std::string(to_string(format)) +
                           "): it was built without libav (-DCOLLIDE_VIDEO=OFF) and writes PNG "
                           "only: --format png for frames, --last-frame or `thumbnail` for one");
}

VideoFormat parse_video_format(std::string_view text, std::string_view field) {
    return parse_named(text, field, format_names, "", NameCase::ignore);
}

VideoCodec parse_video_codec(std::string_view text, std::string_view field) {
    return parse_named(text, field, codec_names, "", NameCase::ignore);
}

std::string_view to_string(VideoFormat format) noexcept {
    return name_of(format, format_names);
}

std::string_view to_string(VideoCodec codec) noexcept {
    return name_of(codec, codec_names);
}

std::string_view encoder_name(VideoCodec codec) noexcept {
    switch (codec) {
        case VideoCodec::h264:
            return "libx264";
        case VideoCodec::hevc:
            return "libx265";
        case VideoCodec::av1:
            return "libsvtav1";
    }
    return "?";
}

}  // namespace collide::video
