#include "subtitle_options.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>

#include "collide/error.hpp"
#include "collide/io/file.hpp"
#include "collide/video/subtitles.hpp"

namespace collide::app {

// Declared in video_job.hpp, defined here: `collide` checks --slides (chapter_output_of) before
// it execs collide-draw, without linking the job and its encoder.
bool is_slide_file_name(std::string_view name) {
    if (name == "index.html" || name == "video.mp4" || name == "subtitles.vtt" ||
        name == "chapters.vtt")
        return true;
    constexpr std::string_view prefix = "chapter-";
    constexpr std::string_view suffix = ".png";
    if (name.size() <= prefix.size() + suffix.size() || name.substr(0, prefix.size()) != prefix ||
        name.substr(name.size() - suffix.size()) != suffix)
        return false;
    const std::string_view digits =
        name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
    return std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
}

SubtitleOutput subtitle_output_of(const VideoCli& v, const OutputChoice& output) {
    SubtitleOutput out;
    if (v.subtitles != "embed" && v.subtitles != "none")
        throw_option_error("--subtitles", v.subtitles, "embed or none");
    out.language = video::subtitle_language(v.lang, "--lang");
    if (given(v.subtitles_file_opt)) {
        if (output.still) throw_option_error("--subtitles-file", "a still (PNG) has no subtitles");
        out.file = v.subtitles_file;
        (void)video::subtitle_format_of(out.file, "--subtitles-file");
    }
    const bool mp4 = output.mp4_video();
    if (given(v.subtitles_opt) && v.subtitles == "embed" && !mp4) {
        throw_option_error("--subtitles",
                           "embed: only an MP4 carries a subtitle track (use --subtitles-file "
                           "F.vtt beside a GIF or PNG frames)");
    }
    out.embed = mp4 && v.subtitles == "embed";
    return out;
}

ChapterOutput chapter_output_of(const VideoCli& v, const OutputChoice& output, std::string title) {
    ChapterOutput out;
    if (v.chapters != "embed" && v.chapters != "none")
        throw_option_error("--chapters", v.chapters, "embed or none");
    const bool mp4 = output.mp4_video();
    if (given(v.chapters_opt) && v.chapters == "embed" && !mp4) {
        throw_option_error("--chapters",
                           "embed: only an MP4 carries chapters (use --chapters-file F.vtt "
                           "beside a GIF or PNG frames)");
    }
    out.embed = mp4 && v.chapters == "embed";
    if (given(v.chapters_file_opt)) {
        if (output.still) throw_option_error("--chapters-file", "a still (PNG) has no chapters");
        out.file = v.chapters_file;
        if (video::subtitle_format_of(out.file, "--chapters-file") != video::SubtitleFormat::webvtt)
            throw_option_error("--chapters-file", v.chapters_file, "a WebVTT file name (.vtt)");
    }
    if (given(v.slides_opt)) {
        if (!mp4) {
            throw_option_error("--slides",
                               output.still ? "a still (PNG) has no chapters to step through"
                                            : "the slide player plays an MP4; write one (-o "
                                              "F.mp4, the default) instead of a GIF or PNG frames");
        }
        if (v.slides.empty()) throw_option_error("--slides", "expected a folder name");
        out.slides = v.slides;
        // An existing slide folder is replaced as a whole: only one holding nothing but a slide
        // folder's files (an earlier one), so nothing the user did not name is ever deleted.
        io::check_output_directory(out.slides, is_slide_file_name, "--slides");
    }
    if (given(v.handout_opt)) {
        if (output.still) throw_option_error("--handout", "a still (PNG) has no chapters");
        if (v.handout.empty()) throw_option_error("--handout", "expected a file name (F.pdf)");
        out.handout = v.handout;
        std::string extension = out.handout.extension().string();
        for (char& c : extension)
            c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        if (extension != ".pdf")
            throw_option_error("--handout", v.handout, "a PDF file name (.pdf)");
    }
    out.language = v.lang;
    out.title = std::move(title);
    return out;
}

}  // namespace collide::app
