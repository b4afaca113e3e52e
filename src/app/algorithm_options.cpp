#include "algorithm_options.hpp"

#include <fmt/core.h>

#include <string>

namespace collide::app {

void add_algorithm_video_options(CLI::App& cmd, AlgorithmVideoCli& v, std::string_view stem,
                                 std::string_view size_example) {
    const std::string at_help = fmt::format(
        "Write only the frame at this many seconds of video, as a PNG (a still for "
        "slides; -o FILE.png, default out/{}.png)",
        stem);
    VideoOptionSet set;
    set.stem = stem;
    set.size_example = size_example;
    set.at_help = at_help;
    set.theme = true;
    set.theme_help = "as in `collide render` (default dark)";
    set.subtitles = true;
    add_video_options(cmd, v, set);
}

}  // namespace collide::app
