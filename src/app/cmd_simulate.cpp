/// `collide simulate SCENE --until T`: runs one engine without rendering and prints its
/// measurements (text or JSON), optionally logging every collision as CSV `t,kind,a,b`.

#include <fmt/core.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "cli_types.hpp"
#include "collide/error.hpp"
#include "collide/io/file.hpp"
#include "collide/printable.hpp"
#include "collide/scene/load.hpp"
#include "collide/sim/engine.hpp"
#include "collide/sim/fast_engine.hpp"
#include "collide/sim/sphere_check.hpp"
#include "commands.hpp"
#include "interrupt.hpp"
#include "measurements_report.hpp"
#include "work_limits.hpp"

namespace collide::app {

namespace {

struct SimulateOptions {
    std::string scene;
    double until = 0.0;
    std::string engine = "fast";  ///< the engine options as typed; engine_options() parses them
    std::string pq = "binary";
    double dt = EngineOptions{}.dt;
    std::string td_detect = "all-pairs";
    std::string events_log;  ///< empty: no log
    bool json = false;
    bool no_limits = false;  ///< --no-limits: run even beyond the work limits

    /// The engine options parsed into their types. Throws Error(input) naming the bad option.
    [[nodiscard]] EngineOptions engine_options() const {
        if (!(until >= 0.0) || !std::isfinite(until)) {
            throw_option_error("--until", fmt::format("{}", until), "a finite end time >= 0");
        }
        EngineOptions options;
        options.engine = parse_engine_kind(engine, "--engine");
        options.pq = pq::parse_queue_kind(pq, "--pq");
        options.dt = dt;
        options.td_detect = parse_overlap_detection(td_detect, "--td-detect");
        options.validate("--dt");
        return options;
    }
};

/// The events log: lines buffered in memory and written through an io::OutputFile (a temporary
/// beside the destination until finish(); standard output for "-"), so that a run that fails or
/// is interrupted leaves nothing at the destination.
class EventsLog {
  public:
    /// Throws Error(input) naming --events-log when the destination cannot be written.
    explicit EventsLog(const std::string& destination)
        : file_(destination, io::OutputOptions{"--events-log", true}),
          on_standard_output_(file_.is_standard_output()) {
        buffer_.reserve(flush_bytes);
    }

    /// True when the log is written to standard output (which then holds nothing else).
    [[nodiscard]] bool is_standard_output() const noexcept { return on_standard_output_; }

    void write(std::string_view text) {
        buffer_.append(text);
        if (buffer_.size() >= flush_bytes) flush();
    }

    /// Writes what is buffered and moves the file into place. Throws Error(runtime) on failure.
    void finish() {
        flush();
        file_.commit();
    }

  private:
    static constexpr std::size_t flush_bytes = 1 << 16;

    void flush() {
        file_.write(buffer_);
        buffer_.clear();
    }

    io::OutputFile file_;
    bool on_standard_output_ = false;
    std::string buffer_;
};

const char* kind_name(CollisionKind kind) {
    switch (kind) {
        case CollisionKind::pair:
            return "pair";
        case CollisionKind::xwall:
            return "xwall";
        case CollisionKind::ywall:
            return "ywall";
        case CollisionKind::zwall:
            return "zwall";
    }
    return "?";
}

/// `options` with the interrupt flag: building the engine of a large scene takes seconds.
EngineOptions stoppable(EngineOptions options, const InterruptGuard& interrupts) {
    options.stop = &interrupts.flag();
    return options;
}

/// Runs `engine` to --until with the events log and the interrupt flag, and prints its report:
/// `fields` first, then the measurements (`extra` after them).
void run_to_end(const SimulateOptions& options, InterruptGuard& interrupts, EngineBase& engine,
                std::unique_ptr<EventsLog>& log, std::vector<ReportField> fields,
                const std::function<void(const Measurements&, std::vector<ReportField>&)>& extra) {
    if (log) {
        engine.set_collision_listener([&log](const CollisionRecord& r) {
            if (r.kind == CollisionKind::pair) {
                log->write(fmt::format("{},{},{},{}\n", r.t, kind_name(r.kind), r.a, r.b));
            } else {
                log->write(fmt::format("{},{},{},\n", r.t, kind_name(r.kind), r.a));
            }
        });
    }
    engine.set_stop_flag(&interrupts.flag());
    try {
        engine.advance_to(options.until);
    } catch (const Error&) {
        interrupts.throw_if_requested();  // say why the engine stopped
        throw;
    }
    interrupts.throw_if_requested();  // a signal during loading, or too late for a poll
    if (log) log->finish();
    const Measurements m = engine.measurements();
    for (ReportField& f : report_fields(m)) fields.push_back(std::move(f));
    if (extra) extra(m, fields);
    const std::string out = options.json ? format_json(fields) : format_text(fields);
    // Data on standard output (--events-log -) is the only thing there: the report moves aside.
    std::fputs((options.json ? out : printable_text(out)).c_str(),
               log && log->is_standard_output() ? stderr : stdout);
}

/// `simulate` of a 3D scene: any engine on spheres (make_engine); the measurements with three
/// degrees of freedom (temperature), Z from the collision virial, packing fraction and
/// mean-square displacement, plus the z walls and momentum.
void run_simulate_spheres(const SimulateOptions& options, const EngineOptions& engine_options,
                          InterruptGuard& interrupts, const SphereScene& scene) {
    check_simulate_work(scene, engine_options, options.until, options.no_limits);
    std::unique_ptr<EventsLog> log;
    if (!options.events_log.empty()) {
        log = std::make_unique<EventsLog>(options.events_log);
        log->write("t,kind,a,b\n");
    }
    std::unique_ptr<SphereEngine> engine =
        make_engine(scene, stoppable(engine_options, interrupts));
    std::vector<ReportField> fields{{"scene", scene.name},
                                    {"engine", std::string(to_string(engine_options.engine))}};
    if (engine_options.engine == EngineKind::classic)
        fields.push_back({"pq", pq::to_string(engine_options.pq)});
    fields.push_back({"dimension", std::uint64_t{3}});
    fields.push_back({"spheres", static_cast<std::uint64_t>(scene.spheres.size())});
    run_to_end(options, interrupts, *engine, log, std::move(fields),
               [](const Measurements& m, std::vector<ReportField>& out) {
                   out.push_back({"collisions_zwall", m.collisions_zwall});
                   out.push_back({"momentum_z", m.momentum_z});
               });
}

void run_simulate(const SimulateOptions& options) {
    const EngineOptions engine_options = options.engine_options();
    // Ctrl-C stops the run cleanly (the events log's temporary is removed) however long it is.
    InterruptGuard interrupts;
    AnyScene any = [&] {
        const StopAtOnce nothing_written_yet(interrupts);
        return load_any_scene(options.scene);
    }();
    if (const auto* spheres = std::get_if<SphereScene>(&any)) {
        run_simulate_spheres(options, engine_options, interrupts, *spheres);
        return;
    }
    const Scene scene = std::move(std::get<Scene>(any));
    check_simulate_work(scene, engine_options, options.until, options.no_limits);
    // Open the log before simulating: an unwritable path fails fast, with nothing half written.
    std::unique_ptr<EventsLog> log;
    if (!options.events_log.empty()) {
        log = std::make_unique<EventsLog>(options.events_log);
        if (log->is_standard_output() && options.json) {
            throw_option_error("--events-log", "'" + options.events_log +
                                                   "' and --json would both write data to "
                                                   "standard output; give the log a file name");
        }
        log->write("t,kind,a,b\n");
    }
    std::unique_ptr<Engine> engine = make_engine(scene, stoppable(engine_options, interrupts));
    std::vector<ReportField> fields{{"scene", scene.name},
                                    {"engine", std::string(to_string(engine_options.engine))}};
    if (engine_options.engine == EngineKind::classic)
        fields.push_back({"pq", pq::to_string(engine_options.pq)});
    fields.push_back({"discs", static_cast<std::uint64_t>(scene.discs.size())});
    run_to_end(options, interrupts, *engine, log, std::move(fields), {});
}

}  // namespace

void add_simulate_command(CLI::App& root) {
    auto options = std::make_shared<SimulateOptions>();
    CLI::App* cmd =
        root.add_subcommand("simulate", "Run an engine to a time and print its measurements");
    cmd->add_option("scene", options->scene, "Scene: algs4 .txt, .toml, or a built-in name")
        ->required()
        ->type_name("SCENE");
    cmd->add_option("--until", options->until, "Simulation time to stop at")->required();
    cmd->add_option("--engine", options->engine, "fast (default), classic or time")
        ->type_name("{fast,classic,time}");
    cmd->add_option("--pq", options->pq,
                    "Classic engine's queue: unordered|ordered|binary|dary:D|indexed[:D]")
        ->type_name(queue_kind_type);
    cmd->add_option("--dt", options->dt, "Time-driven step");
    cmd->add_option("--td-detect", options->td_detect, "Time-driven overlap checks: all-pairs|grid")
        ->type_name("{all-pairs,grid}");
    cmd->add_option("--events-log", options->events_log,
                    "Write every collision as CSV t,kind,a,b (- for standard output)")
        ->type_name("PATH");
    cmd->add_flag("--json", options->json, "Print the measurements as JSON");
    cmd->add_flag(insist_option, options->no_limits,
                  "Run even when the estimated work (collisions and cell crossings, time-driven "
                  "steps and checks) is beyond the limits of docs/limits.md");
    cmd->callback([options] { run_simulate(*options); });
}

}  // namespace collide::app
