// DrawList's one function, out of gl_target.cpp: code that only lays a picture out (the heap's
// fit check, which `collide` runs without GL) clears a list without linking GL.
#include "draw_list.hpp"

namespace collide::render {

void DrawList::clear() {
    fill_clears.clear();
    under.clear();
    discs.clear();
    disc_groups.clear();
    spheres.clear();
    sphere_groups.clear();
    over.clear();
    for (TextRun& run : text) run.glyphs.clear();
}

}  // namespace collide::render
