#pragma once
/// \file
/// The one set of video options of `render`, `thumbnail`, `heap` and `puzzle` (-o, --format, -q,
/// --size, --fps, --at, --last-frame, --progress, --preview, --verbose, --theme, --font),
/// registered by one function: a command says which of them it takes and how its help names its
/// defaults. Registration only (collide_app_options: no GL, no encoder, so that `collide` links it
/// too); subtitle_options.hpp checks the subtitle options against the output.

#include <string>
#include <string_view>

#include "cli_fwd.hpp"

namespace collide::app {

/// The highest --fps accepted.
inline constexpr int max_fps = 240;

/// The video options, raw as CLI11 stores them; an option's pointer tells whether it was given.
struct VideoCli {
    std::string output;
    std::string format;
    std::string quality = "m";
    std::string size;
    int fps = 30;
    double at = 0.0;
    bool last_frame = false;
    std::string progress = "auto";
    bool preview = false;
    bool verbose = false;
    std::string theme = "dark";
    std::string font;                 ///< --font FILE (empty: find_font's search)
    std::string subtitles = "embed";  ///< --subtitles embed|none
    std::string lang = "und";         ///< --lang: the subtitles' language
    std::string subtitles_file;       ///< --subtitles-file F.vtt|F.srt
    std::string chapters = "embed";   ///< --chapters embed|none
    std::string chapters_file;        ///< --chapters-file F.vtt
    std::string slides;               ///< --slides DIR
    std::string handout;              ///< --handout F.pdf

    CLI::Option* output_opt = nullptr;
    CLI::Option* format_opt = nullptr;
    CLI::Option* quality_opt = nullptr;
    CLI::Option* size_opt = nullptr;
    CLI::Option* fps_opt = nullptr;
    CLI::Option* at_opt = nullptr;
    CLI::Option* last_frame_opt = nullptr;
    CLI::Option* preview_opt = nullptr;
    CLI::Option* theme_opt = nullptr;
    CLI::Option* subtitles_opt = nullptr;
    CLI::Option* subtitles_file_opt = nullptr;
    CLI::Option* chapters_opt = nullptr;
    CLI::Option* chapters_file_opt = nullptr;
    CLI::Option* slides_opt = nullptr;
    CLI::Option* handout_opt = nullptr;
};

/// What differs between the commands: which options they take and how their help reads.
struct VideoOptionSet {
    std::string_view stem;          ///< default outputs: out/STEM.mp4, ... ("<scene>", "heap")
    std::string_view size_example;  ///< in --size's help, e.g. "e.g. 640x360"
    bool video = true;            ///< false: one PNG only (thumbnail): no --format, no --last-frame
    std::string_view at_help;     ///< --at's meaning; empty: no --at
    bool preview = false;         ///< --preview
    bool theme = true;            ///< --theme
    std::string_view theme_help;  ///< --theme's default, in words
    /// --subtitles, --lang, --subtitles-file, --chapters, --chapters-file, --slides, --handout
    /// (videos only)
    bool subtitles = false;
};

/// True when the user gave `option` on the command line.
[[nodiscard]] bool given(const CLI::Option* option);

/// Registers the options `set` names on `cmd`, into `v`.
void add_video_options(CLI::App& cmd, VideoCli& v, const VideoOptionSet& set);

}  // namespace collide::app
