// `collide-draw`: the drawing commands are registered here (draw_forward.cpp is `collide`'s side).

#include "cli_docs.hpp"
#include "commands.hpp"
#include "puzzle_video.hpp"

namespace collide::app {

void add_drawing_commands(CLI::App& root, int /*argc*/, char** /*argv*/) {
    add_heap_command(root);
    add_puzzle_command(root, drawn_puzzle_video());
    add_render_command(root);
    add_thumbnail_command(root);
    add_docs_generator(root);  // the build's man page and completion (hidden)
}

}  // namespace collide::app
