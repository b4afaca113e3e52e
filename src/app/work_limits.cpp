#include "work_limits.hpp"

#include <fmt/core.h>

#include <cmath>
#include <limits>

#include "collide/error.hpp"
#include "collide/sim/sphere_check.hpp"

namespace collide::app {

namespace {

bool is_array_queue(const pq::QueueKind& kind) {
    return kind.family == pq::QueueFamily::unordered || kind.family == pq::QueueFamily::ordered;
}

/// What a refusal names and how it advises: the option (or scene hint) that sets the span, the
/// one that sets dt, and how to ask for a shorter span.
struct Culprits {
    std::string span;     ///< "--until", "--speed", "demo.toml:5: render.speed", ...
    std::string dt;       ///< "--dt", "demo.toml:6: render.dt", or the span's culprit
    std::string shorter;  ///< advice for a shorter span: "lower --speed or --duration"
    bool span_from_hint = false;
    bool dt_from_hint = false;
};

[[noreturn]] void refuse(const std::string& culprit, const std::string& reason) {
    if (culprit.empty()) throw_input_error(reason);
    throw_option_error(culprit, reason);
}

std::string insist_advice() {
    return fmt::format("or pass {} to run it anyway", insist_option);
}

/// The smallest dt a run to t = span can take at all: a few units in the last place of span,
/// rounded up to a round number.
double smallest_useful_dt(double span) {
    const double ulp = span * std::numeric_limits<double>::epsilon();
    return std::pow(10.0, std::ceil(std::log10(4.0 * ulp)));
}

/// Refusals that --no-limits does not lift: the run could never end.
void check_finishable(const RunShape& run, const WorkEstimate& work, const Culprits& who) {
    if (!std::isfinite(run.span)) {
        refuse(who.span, fmt::format("the run would end at t = {:g}, beyond the range of double "
                                     "precision: {}",
                                     run.span, who.shorter));
    }
    if (run.time_driven && work.dt_below_resolution) {
        refuse(who.dt, fmt::format("dt = {:g} is below the resolution of the clock at t = {:g} "
                                   "(t + dt == t): the time-driven engine could never get there; "
                                   "use a dt of at least {:g}",
                                   run.dt, run.span, smallest_useful_dt(run.span)));
    }
}

// What a refusal says about a scene of either dimension: its particles' count and name, its
// kinetic-theory collision and cell-crossing rates.
std::size_t particle_count(const Scene& scene) {
    return scene.discs.size();
}
std::size_t particle_count(const SphereScene& scene) {
    return scene.spheres.size();
}
const char* particle_word(const Scene&) {
    return "discs";
}
const char* particle_word(const SphereScene&) {
    return "spheres";
}
double collisions_per_time(const Scene& scene) {
    return collision_rate(scene).total();
}
double collisions_per_time(const SphereScene& scene) {
    return collisions_per_time_unit(scene);
}
double crossings_per_time(const Scene& scene) {
    return cell_crossing_rate(scene);
}
double crossings_per_time(const SphereScene& scene) {
    return sphere_crossing_rate(scene);
}

template <class SceneType>
void refuse_excess(const SceneType& scene, const RunShape& run, const WorkExcess& excess,
                   const Culprits& who, const std::string& frames_advice) {
    const std::string limit = fmt::format("over the limit of {}", rough_number(excess.limit));
    const char* particles = particle_word(scene);
    if (excess.what == "events") {
        const std::string crossings =
            run.cell_grid
                ? fmt::format(" and {} cell crossings", rough_number(crossings_per_time(scene)))
                : std::string();
        refuse(who.span,
               fmt::format("simulating t = 0..{:g} would take about {} events (kinetic-theory "
                           "estimate for N = {} {}: {} collisions{} per time unit), {}; "
                           "simulate at most t = {:.3g} ({}), {}",
                           run.span, rough_number(excess.estimate), particle_count(scene),
                           particles, rough_number(collisions_per_time(scene)), crossings, limit,
                           run.span * excess.fitting_fraction(), who.shorter, insist_advice()));
    }
    if (excess.what == "time-driven steps") {
        refuse(who.dt,
               fmt::format("the time-driven engine would take about {} steps of dt = {:g} "
                           "to reach t = {:g}, {}; use a dt of at least {:.3g} or a "
                           "shorter run ({}), {}",
                           rough_number(excess.estimate), run.dt, run.span, limit,
                           run.dt / excess.fitting_fraction(), who.shorter, insist_advice()));
    }
    if (excess.what == "overlap checks") {
        const char* method = run.all_pairs ? "all-pairs" : "grid";
        refuse(who.dt,
               fmt::format("the time-driven engine ({} overlap checks, {} {}) would "
                           "make about {} checks in {} steps of dt = {:g}, {}; use "
                           "--td-detect grid, a larger dt or a shorter run ({}), {}",
                           method, particle_count(scene), particles, rough_number(excess.estimate),
                           rough_number(run.dt > 0 ? run.span / run.dt : 0.0), run.dt, limit,
                           who.shorter, insist_advice()));
    }
    if (excess.what == "pair predictions") {
        refuse(who.span,
               fmt::format("the classic engine predicts each event's two {} against all {} "
                           "{}: simulating t = 0..{:g} would take about {} pair predictions "
                           "(about {} events), {}; use --engine fast (a cell grid: the same "
                           "physics, O(1) per event), simulate at most t = {:.3g} ({}), {}",
                           particles, particle_count(scene), particles, run.span,
                           rough_number(excess.estimate),
                           rough_number(collisions_per_time(scene) * run.span), limit,
                           run.span * excess.fitting_fraction(), who.shorter, insist_advice()));
    }
    if (excess.what == "queue steps") {
        refuse(
            who.span,
            fmt::format("an array queue (--pq unordered or ordered) walks its whole array "
                        "on every removal or insertion: with {} {}, simulating t = 0..{:g} "
                        "would take about {} queue steps, {}; use --pq binary (or any heap), "
                        "fewer {} or a shorter run ({}), {}",
                        particle_count(scene), particles, run.span, rough_number(excess.estimate),
                        limit, particles, who.shorter, insist_advice()));
    }
    refuse(who.span,
           fmt::format("the run would go through about {} frames, {}; {}, {}",
                       rough_number(excess.estimate), limit, frames_advice, insist_advice()));
}

Culprits render_culprits(const RenderPlan& plan, const RenderRequest& request, const Scene& scene) {
    Culprits who;
    const RenderHints& hints = scene.render;
    if (plan.kind == OutputKind::still && request.at) {
        who.span = "--at";
        who.shorter = "give an earlier --at";
    } else {
        who.shorter = "lower --speed or --duration";
        if (request.speed) {
            who.span = "--speed";
        } else if (hints.speed) {
            who.span = hint_option(hints.speed_at, "speed");
            who.span_from_hint = true;
        } else if (request.duration) {
            who.span = "--duration";
        } else if (hints.duration) {
            who.span = hint_option(hints.duration_at, "duration");
            who.span_from_hint = true;
        } else {
            who.span = "scene '" + scene.name + "'";
        }
    }
    // A --dt list's steps are the user's as much as a single --dt (the plan's time engine runs
    // the smallest of them, whose value the messages give).
    if (request.dt || !request.dt_list.empty()) {
        who.dt = "--dt";
    } else if (hints.dt) {
        who.dt = hint_option(hints.dt_at, "dt");
        who.dt_from_hint = true;
    } else {
        who.dt = who.span;
        who.dt_from_hint = who.span_from_hint;
    }
    return who;
}

}  // namespace

RunShape render_run_shape(const RenderPlan& plan) {
    RunShape run;
    run.span = plan.clock.last_time;
    run.event_driven = plan.mode != RenderMode::time;
    run.cell_grid = plan.event_engine.engine == EngineKind::fast;
    run.classic = plan.event_engine.engine == EngineKind::classic;
    run.array_queue = is_array_queue(plan.event_engine.pq);
    run.time_driven = plan.mode != RenderMode::event;
    run.dt = plan.time_engine.dt;
    run.all_pairs = plan.time_engine.td_detect == OverlapDetection::all_pairs;
    run.frames = static_cast<double>(plan.timeline.frame_count());
    return run;
}

void check_render_work(const RenderPlan& plan, const RenderRequest& request, show::SceneView scene,
                       const WorkLimits& limits) {
    const RunShape run = render_run_shape(plan);
    const WorkEstimate work =
        scene.three_d() ? estimate_work(scene.spheres(), run) : estimate_work(scene.discs(), run);
    const Culprits who = render_culprits(plan, request, scene.discs());
    check_finishable(run, work, who);
    if (request.no_limits) return;
    const WorkExcess excess = first_excess(work, limits);
    if (excess.what.empty()) return;
    const std::string instead = fmt::format("give --at <= {:.3g}, or a larger --speed",
                                            run.span * excess.fitting_fraction());
    if (scene.three_d()) {
        refuse_excess(scene.spheres(), run, excess, who, instead);
    } else {
        refuse_excess(scene.discs(), run, excess, who, instead);
    }
}

void check_scene_hints(const Scene& scene, const WorkLimits& limits) {
    RenderRequest request;
    request.scene = scene.name;
    const RenderPlan plan = plan_render(request, scene);  // names a bad hint by file and line
    const RunShape run = render_run_shape(plan);
    const WorkEstimate work = estimate_work(scene, run);
    Culprits who = render_culprits(plan, request, scene);
    who.shorter = "lower the hint, or override it with --speed / --duration";
    if (who.span_from_hint || who.dt_from_hint) check_finishable(run, work, who);
    // Overlap checks depend on --td-detect, which the scene cannot set: render's to refuse.
    WorkEstimate hinted = work;
    hinted.pair_checks = 0.0;
    if (!who.span_from_hint) {
        hinted.collisions = 0.0;
        hinted.crossings = 0.0;
    }
    if (!who.dt_from_hint) hinted.steps = 0.0;
    hinted.frames = 0.0;  // a video's frames are bounded by its duration and fps
    const WorkExcess excess = first_excess(hinted, limits);
    if (excess.what.empty()) return;
    refuse_excess(scene, run, excess, who, "");
}

namespace {

template <class SceneType>
void check_simulate_work_of(const SceneType& scene, const EngineOptions& engine, double until,
                            bool insist, const WorkLimits& limits) {
    RunShape run;
    run.span = until;
    run.time_driven = engine.engine == EngineKind::time;
    run.event_driven = !run.time_driven;
    run.cell_grid = engine.engine == EngineKind::fast;
    run.classic = engine.engine == EngineKind::classic;
    run.array_queue = is_array_queue(engine.pq);
    run.dt = engine.dt;
    run.all_pairs = engine.td_detect == OverlapDetection::all_pairs;
    const WorkEstimate work = estimate_work(scene, run);
    Culprits who;
    who.span = "--until";
    who.dt = "--dt";
    who.shorter = "lower --until";
    check_finishable(run, work, who);
    if (insist) return;
    const WorkExcess excess = first_excess(work, limits);
    if (excess.what.empty()) return;
    refuse_excess(scene, run, excess, who, "");
}

}  // namespace

void check_simulate_work(const Scene& scene, const EngineOptions& engine, double until, bool insist,
                         const WorkLimits& limits) {
    check_simulate_work_of(scene, engine, until, insist, limits);
}

void check_simulate_work(const SphereScene& scene, const EngineOptions& engine, double until,
                         bool insist, const WorkLimits& limits) {
    check_simulate_work_of(scene, engine, until, insist, limits);
}

}  // namespace collide::app
