#pragma once
/// \file
/// Runs that cannot finish are refused before they start. Each command turns its options into a
/// RunShape, estimates the work (collide/sim/work_estimate.hpp) and, when a WorkLimits limit is
/// exceeded, throws Error(input) naming the option that asks for it, the estimate, and what would
/// fit; `--no-limits` runs it anyway. Two things are refused even then: a run whose end time is
/// not a finite number, and a dt below the resolution of the clock (span + dt == span), which
/// could never finish however long one waits. Pure (no files): unit-tested in tests/app_core.

#include <string>

#include "collide/scene.hpp"
#include "collide/scene3.hpp"
#include "collide/show/scene_view.hpp"
#include "collide/sim/engine.hpp"
#include "collide/sim/work_estimate.hpp"
#include "render_plan.hpp"

namespace collide::app {

/// The option that lets a run exceed WorkLimits.
inline constexpr const char* insist_option = "--no-limits";

/// What `plan` asks of the engines: the span up to its last frame, the engines its mode runs.
[[nodiscard]] RunShape render_run_shape(const RenderPlan& plan);

/// Refuses a render / thumbnail whose work exceeds the limits (unless request.no_limits) or can
/// never finish (always). Messages name the command-line option or the scene hint
/// ("file:line: render.speed") responsible. Throws Error(input).
/// A 3D `scene`'s work is the spheres' (3D collision rates) and messages name spheres.
void check_render_work(const RenderPlan& plan, const RenderRequest& request, show::SceneView scene,
                       const WorkLimits& limits = {});

/// `collide check`: refuses a scene whose [render] hints make `collide render SCENE` (no options)
/// refuse, naming the hint, so that check and render agree. Limits that only CLI options can
/// change (the time-driven overlap checks of a big scene: --td-detect grid) are left to render.
void check_scene_hints(const Scene& scene, const WorkLimits& limits = {});

/// `collide simulate --until T`: refuses a run whose work exceeds the limits (unless insist), or
/// can never finish (always), naming --until or --dt. Throws Error(input).
void check_simulate_work(const Scene& scene, const EngineOptions& engine, double until, bool insist,
                         const WorkLimits& limits = {});
/// The same for a 3D scene (every engine runs spheres), naming spheres.
void check_simulate_work(const SphereScene& scene, const EngineOptions& engine, double until,
                         bool insist, const WorkLimits& limits = {});

}  // namespace collide::app
