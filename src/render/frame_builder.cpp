// The one place the overlay level picks how a frame is painted.
#include "frame_builder.hpp"

#include "full_painter.hpp"
#include "lesson_painter.hpp"
#include "minimal_painter.hpp"

namespace collide::render {

std::unique_ptr<Painter> make_painter(const RenderConfig& config) {
    switch (config.overlays) {
        case OverlayLevel::none:
            break;
        case OverlayLevel::full:
            return std::make_unique<FullPainter>(config);
        case OverlayLevel::lesson:
            return std::make_unique<LessonPainter>(config);
    }
    return std::make_unique<MinimalPainter>(config);
}

}  // namespace collide::render
