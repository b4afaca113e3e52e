#pragma once
/// \file
/// `collide heap`'s bridge between the animation model (collide/sim/pq/heap_lesson.hpp) and the
/// drawing (collide/render/heap_view.hpp): what each panel shows at one moment, as plain values.
/// Pure functions: unit-tested in collide_app_core_tests.

#include <cstddef>
#include <string>

#include "collide/render/heap_view.hpp"
#include "collide/sim/pq/heap_lesson.hpp"

namespace collide::app {

/// How the lesson is shown, fixed for a video.
struct HeapShow {
    bool min = false;    ///< a min-queue (titles say "min")
    bool sort = false;   ///< heapsort: the sorted part is set apart
    int index_base = 1;  ///< index of slot 0 on screen (1 as in the lecture's code)
};

/// Smooth start and stop of a slide: 0 at 0, 1 at 1, flat at both ends.
[[nodiscard]] float ease(double x) noexcept;

/// The frame at `seconds` of the lesson.
[[nodiscard]] render::HeapFrameView heap_frame_at(const pq::LessonTimeline& timeline,
                                                  const HeapShow& show, double seconds);

/// The widest key label of the lesson (for sizing node text once per video).
[[nodiscard]] std::string widest_key(const pq::LessonTimeline& timeline);

}  // namespace collide::app
