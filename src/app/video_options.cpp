// The video options' registration: no GL and no encoder, so that `collide` (which draws nothing)
// links it too (collide_app_options); what checks them against the encoder is elsewhere
// (subtitle_options.cpp).

#include "video_options.hpp"

#include <fmt/core.h>

#include <CLI/CLI.hpp>

#include "cli_numbers.hpp"
#include "font_search.hpp"

namespace collide::app {

bool given(const CLI::Option* option) {
    return option != nullptr && option->count() > 0;
}

void add_video_options(CLI::App& cmd, VideoCli& v, const VideoOptionSet& set) {
    v.output_opt =
        cmd.add_option("-o,--output", v.output,
                       set.video
                           ? fmt::format("Output file (default out/{}.mp4, .gif, _frames/ or .png)",
                                         set.stem)
                           : fmt::format("Output file (default out/{}.png)", set.stem))
            ->type_name("PATH");
    if (set.video) {
        v.format_opt = cmd.add_option("--format", v.format,
                                      "mp4 (default), gif, or png (a directory of frames)")
                           ->type_name("{mp4,gif,png}");
    }
    v.quality_opt =
        cmd.add_option("-q,--quality", v.quality,
                       "l 854x480@15, m 1280x720@30 (default), h 1920x1080@60, k 3840x2160@60")
            ->type_name("{l,m,h,k}");
    v.size_opt = cmd.add_option("--size", v.size,
                                fmt::format("Frame size WxH, overrides -q ({})", set.size_example))
                     ->type_name("WxH");
    v.fps_opt =
        add_whole_option(cmd, "--fps", v.fps, 1, max_fps, "Frames per second, overrides -q");
    if (set.video) {
        v.last_frame_opt = cmd.add_flag(
            "--last-frame", v.last_frame,
            fmt::format("Write only the final frame, as a PNG (-o FILE.png, default out/{}.png)",
                        set.stem));
    }
    if (!set.at_help.empty()) v.at_opt = cmd.add_option("--at", v.at, std::string(set.at_help));
    if (set.theme) {
        v.theme_opt =
            cmd.add_option("--theme", v.theme,
                           fmt::format("Colours: dark (screens) or light (projectors, print); {}",
                                       set.theme_help))
                ->type_name("{dark,light}");
    }
    if (set.preview) {
        v.preview_opt = cmd.add_flag("--preview", v.preview,
                                     "Show the frames live in a window when a display exists");
    }
    cmd.add_option("--progress", v.progress,
                   "Progress on stderr: auto (bar on a terminal), bar, plain (a line per tenth, "
                   "for CI logs), json or none")
        ->capture_default_str()
        ->type_name("{auto,bar,plain,json,none}");
    if (set.video && set.subtitles) {
        v.subtitles_opt = cmd.add_option("--subtitles", v.subtitles,
                                         "embed (default: an MP4 carries the title, description "
                                         "and captions as a subtitle "
                                         "track) or none")
                              ->type_name("{embed,none}");
        cmd.add_option(
               "--lang", v.lang,
               "The subtitles' language, ISO 639: en, pl, cs, de, el, ru, ... (default und: "
               "undetermined)")
            ->type_name("LANG");
        v.subtitles_file_opt =
            cmd.add_option(
                   "--subtitles-file", v.subtitles_file,
                   "Also write the subtitles beside the video: F.vtt (WebVTT) or F.srt (SubRip)")
                ->type_name("PATH");
        v.chapters_opt = cmd.add_option("--chapters", v.chapters,
                                        "embed (default: an MP4 carries chapters at the title "
                                        "card, each caption, the replay "
                                        "and the epilogue) or none")
                             ->type_name("{embed,none}");
        v.chapters_file_opt = cmd.add_option("--chapters-file", v.chapters_file,
                                             "Also write the chapters beside the video: F.vtt")
                                  ->type_name("PATH");
        v.slides_opt =
            cmd.add_option(
                   "--slides", v.slides,
                   "Also write a slide player: DIR/index.html plays the video and stops at each "
                   "chapter's end (right arrow, space: go on; left: back; F: full screen), with a "
                   "PNG "
                   "per chapter; works offline. DIR must be new, empty or an earlier slide folder")
                ->type_name("DIR");
        v.handout_opt = cmd.add_option("--handout", v.handout,
                                       "Also write a handout: F.pdf, one page per chapter with its "
                                       "still and its words, to print or read beside the video")
                            ->type_name("PATH");
    }
    cmd.add_flag("--verbose", v.verbose, "Show the encoder's own log");
    cmd.add_option("--font", v.font, font_option_help)->type_name("FILE");
}

}  // namespace collide::app
