#pragma once
/// \file
/// The interface every simulation engine offers (event-driven classic and fast, time-driven):
/// advance exactly to a frame time, then hand out a snapshot and measurements.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>

#include "collide/error.hpp"
#include "collide/scene.hpp"
#include "collide/scene3.hpp"
#include "collide/sim/measurements.hpp"
#include "collide/sim/pq/queue_kind.hpp"
#include "collide/snapshot.hpp"
#include "collide/snapshot3.hpp"

namespace collide {

/// What a resolved collision hit, as written in `--events-log` (`pair`, `xwall`, `ywall`; 3D also
/// `zwall`). Narrower than EventKind (collide/event_kind.hpp), what a queued event does: a cell
/// crossing is queued like a collision but never resolves as one, so a record cannot say `cell`.
enum class CollisionKind : std::uint8_t { pair, xwall, ywall, zwall };

/// One resolved collision. For walls b is unused (written empty in the CSV).
struct CollisionRecord {
    double t = 0.0;
    CollisionKind kind = CollisionKind::pair;
    std::uint32_t a = 0;
    std::uint32_t b = 0;
};

using CollisionListener = std::function<void(const CollisionRecord&)>;

/// What every engine offers whatever its dimension: advance to a time, measurements, a collision
/// listener, the stop flag and (event-driven engines) a view of the queue. Engine (discs) and
/// SphereEngine (spheres) add the snapshot of their dimension.
class EngineBase {
  public:
    virtual ~EngineBase() = default;
    EngineBase() = default;
    EngineBase& operator=(const EngineBase&) = delete;

    /// Runs the simulation up to exactly time t (>= time()); throws Error if t < time().
    virtual void advance_to(double t) = 0;
    /// Current simulation time.
    [[nodiscard]] virtual double time() const noexcept = 0;
    /// Observables and cost so far.
    [[nodiscard]] virtual Measurements measurements() const = 0;
    /// Called once per resolved collision, in order (events log, determinism tests).
    virtual void set_collision_listener(CollisionListener listener) = 0;

    /// Asks every later snapshot() to carry a QueueView (Snapshot::queue): the next
    /// limits.next_events collisions, the queue's first slots as far as `limits` says and the
    /// events popped from now on. For teaching videos (`collide render --queue`); an engine never
    /// asked pays nothing measurable. Returns false, and does nothing, for an engine that has no
    /// event queue (time-driven). Throws Error(input) naming the field `queue` (the app maps it
    /// to `--queue`) unless 1 <= limits.next_events <= sim::max_watched_events.
    virtual bool watch_queue(const QueueViewLimits& limits) {
        (void)limits;
        return false;
    }

    /// Makes advance_to() cancellable: the engine polls `stop` (set by another thread or a signal
    /// handler) every few thousand events, or every time step and every few thousand pair tests
    /// within one (the classic engine's initial O(N^2) prediction and the time-driven engine's
    /// all-pairs step), and once it is set throws Error(runtime, "simulation stopped") between
    /// two events or steps. Why: one call can run for minutes (a large --until or --speed, or one
    /// all-pairs step over 10^6 discs), and Ctrl-C must still stop it cleanly. The engine is then
    /// consistent at some time between where it was and t (a time-driven step stopped midway is
    /// undone, up to rounding). nullptr (the default): never stops.
    void set_stop_flag(const std::atomic<bool>* stop) noexcept { stop_ = stop; }

  protected:
    /// For the engines' clone(): a copy keeps the stop flag (the same run stops it) and its own
    /// countdown. Copies go through clone() only, never by slicing an interface.
    EngineBase(const EngineBase&) = default;

    /// For the event loops: call once per event; looks at the flag every stop_poll_events calls,
    /// so the cost per event is a decrement.
    void poll_stop() {
        if (--stop_countdown_ != 0) return;
        stop_countdown_ = stop_poll_events;
        check_stop();
    }
    /// The flag given to set_stop_flag (nullptr: none), for loops inside one long step that poll
    /// it themselves.
    [[nodiscard]] const std::atomic<bool>* stop_flag() const noexcept { return stop_; }
    /// For loops whose every pass is long (a time step over all discs): looks at the flag now.
    void check_stop() const {
        if (stop_ != nullptr && stop_->load(std::memory_order_relaxed)) throw_stopped();
    }
    /// The error of a stop seen by the engine itself or by a loop it called.
    [[noreturn]] static void throw_stopped() { throw_runtime_error("simulation stopped"); }

  private:
    /// Events between two looks at the stop flag: a few milliseconds of the slowest engine (the
    /// classic loop's O(N) events at a few thousand discs).
    static constexpr std::uint32_t stop_poll_events = 1024;
    const std::atomic<bool>* stop_ = nullptr;
    std::uint32_t stop_countdown_ = stop_poll_events;
};

/// An engine of discs (2D): the renderer's source.
class Engine : public EngineBase {
  public:
    /// Every disc at time(), in scene order.
    [[nodiscard]] virtual Snapshot snapshot() const = 0;
    /// An independent copy of the engine as it stands: advanced to the same times in the same
    /// order, it resolves the same collisions bit for bit, and it leaves this engine untouched.
    /// It keeps the stop flag and has no collision listener (a listener may point into whoever
    /// set it). Why: sim::CollisionLookahead runs a copy past a frame to learn what comes next.
    /// O(N + queued events). nullptr from an engine that cannot be copied (time-driven: nothing
    /// needs to run it ahead).
    [[nodiscard]] virtual std::unique_ptr<Engine> clone() const { return nullptr; }

  protected:
    Engine() = default;
    Engine(const Engine&) = default;
};

/// An engine of spheres (3D, `dimension = 3` scenes).
class SphereEngine : public EngineBase {
  public:
    /// Every sphere at time(), in scene order.
    [[nodiscard]] virtual SphereSnapshot snapshot() const = 0;
    /// As Engine::clone.
    [[nodiscard]] virtual std::unique_ptr<SphereEngine> clone() const { return nullptr; }

  protected:
    SphereEngine() = default;
    SphereEngine(const SphereEngine&) = default;
};

/// The engine interface of dimension D (2: Engine, 3: SphereEngine).
template <int D>
using EngineOf = std::conditional_t<D == 2, Engine, SphereEngine>;

/// The simulation engines: two event-driven ones and the naive time-driven baseline.
enum class EngineKind : std::uint8_t {
    fast,     ///< event-driven on a cell grid (sim::FastEngine)
    classic,  ///< the lecture's event-driven loop on any queue of the lecture (sim::ClassicEngine)
    time,     ///< time-driven steps of dt (TimeEngine)
};

/// How the time-driven engine finds overlapping pairs (same outcome, different cost).
enum class OverlapDetection : std::uint8_t {
    all_pairs,  ///< every pair each step: N(N-1)/2 checks, the lecture's naive method
    grid,       ///< pairs in neighbouring cells only
};

/// "fast", "classic" or "time". Throws Error(input) naming `option` and listing the names.
[[nodiscard]] EngineKind parse_engine_kind(std::string_view text,
                                           std::string_view option = "engine");
/// For commands that run an event-driven engine (render's event panel, bench engine): "fast" or
/// "classic"; "time" is refused like an unknown name, naming `option`.
[[nodiscard]] EngineKind parse_event_engine_kind(std::string_view text,
                                                 std::string_view option = "engine");
/// The name parse_engine_kind reads ("fast", "classic", "time").
[[nodiscard]] std::string_view to_string(EngineKind kind) noexcept;

/// "all-pairs" or "grid". Throws Error(input) naming `option` and listing the names.
[[nodiscard]] OverlapDetection parse_overlap_detection(std::string_view text,
                                                       std::string_view option = "td_detect");
/// The name parse_overlap_detection reads ("all-pairs", "grid").
[[nodiscard]] std::string_view to_string(OverlapDetection detection) noexcept;

/// Options shared by the engine factory and the CLI, as values parsed where the user typed them.
struct EngineOptions {
    EngineKind engine = EngineKind::fast;
    pq::QueueKind pq;  ///< classic engine's queue (binary by default)
    double dt = 0.01;  ///< time-driven quantum
    OverlapDetection td_detect = OverlapDetection::all_pairs;  ///< time-driven overlap checks
    /// The stop flag (EngineBase::set_stop_flag), given before the engine is built: building one
    /// can take seconds (the fast engine predicts every sphere's first event; 4 M spheres take
    /// about 10 s), and a signal must end the run within about a second. make_engine looks at it
    /// every few thousand particles while building, throws Error(runtime, "simulation stopped")
    /// once it is set, and hands it to the engine it returns. nullptr (the default): never stops.
    const std::atomic<bool>* stop = nullptr;

    /// Throws Error(input) naming `dt_field` when dt is not finite and > 0 (the names are types
    /// already).
    void validate(std::string_view dt_field = "dt") const;
};

}  // namespace collide

namespace collide {

/// Builds the engine named by options.engine for the scene (validated by the caller).
/// Throws Error(input) naming `dt` for a bad time step (EngineOptions::validate).
[[nodiscard]] std::unique_ptr<Engine> make_engine(const Scene& scene, const EngineOptions& options);
/// The same for spheres (a `dimension = 3` scene): every engine runs in 3D.
[[nodiscard]] std::unique_ptr<SphereEngine> make_engine(const SphereScene& scene,
                                                        const EngineOptions& options);

}  // namespace collide
