#include "subtitle_options.hpp"

#include "collide/error.hpp"
#include "collide/video/subtitles.hpp"

namespace collide::app {

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
    const bool mp4 = !output.still && output.format == video::VideoFormat::mp4;
    if (given(v.subtitles_opt) && v.subtitles == "embed" && !mp4) {
        throw_option_error("--subtitles",
                           "embed: only an MP4 carries a subtitle track (use --subtitles-file "
                           "F.vtt beside a GIF or PNG frames)");
    }
    out.embed = mp4 && v.subtitles == "embed";
    return out;
}

}  // namespace collide::app
