#include "puzzle_options.hpp"

#include <CLI/CLI.hpp>

#include "collide/error.hpp"
#include "progress.hpp"

namespace collide::app {

void add_puzzle_video_options(CLI::App& cmd, PuzzleVideoCli& v) {
    add_algorithm_video_options(cmd, v, "puzzle", "at least 854x480, e.g. 960x540");
    v.code_opt = cmd.add_flag(
        "--code", v.code,
        "Show the search loop's pseudocode beside one search (A* unless --method bfs), the line "
        "under way marked; the first expansions and the goal's walk through the lines slowly");
    v.questions_opt =
        cmd.add_option("--questions", v.questions,
                       "Pause and ponder: early in A*'s search the picture stops and asks "
                       "\"which board does A* expand next?\" between two boards of its queue "
                       "lettered A and B, then reveals the one the search takes: on or none")
            ->type_name("{on,none}")
            ->capture_default_str();
    v.timeline_json_opt =
        cmd.add_option("--timeline-json", v.timeline_json,
                       "Also write the video's timeline as JSON: its segments (run, and with "
                       "--questions on the question and its reveal) with their times and captions")
            ->type_name("PATH");
}

bool puzzle_questions_of(const PuzzleVideoCli& v) {
    if (v.questions != "on" && v.questions != "none")
        throw_option_error("--questions", v.questions, "on or none");
    return v.questions == "on";
}

void refuse_video_options(const PuzzleVideoCli& v, const std::string& mode) {
    (void)parse_progress_mode(v.progress);  // harmless with text, but never a wrong value
    for (const CLI::Option* o :
         {v.output_opt, v.format_opt, v.quality_opt, v.size_opt, v.fps_opt, v.last_frame_opt,
          v.at_opt, v.theme_opt, v.subtitles_opt, v.subtitles_file_opt, v.chapters_opt,
          v.chapters_file_opt, v.slides_opt, v.handout_opt, v.code_opt, v.questions_opt,
          v.timeline_json_opt}) {
        if (given(o)) {
            throw_option_error(o->get_name(), mode + " prints text instead of a video; leave " +
                                                  o->get_name() + " out, or " + mode + " out");
        }
    }
}

}  // namespace collide::app
