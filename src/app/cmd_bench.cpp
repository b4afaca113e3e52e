/// `collide bench engine`: throughput and memory of an event-driven engine, on a random periodic
/// fluid (N discs at packing fraction eta, melted by the dynamics before timing) or on a scene.
/// Figures for docs/benchmarks.md; not a test.

#include <fmt/core.h>
#include <sys/resource.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <numbers>
#include <string>

#include "cli_numbers.hpp"
#include "cli_types.hpp"
#include "collide/error.hpp"
#include "collide/scene/load.hpp"
#include "collide/sim/engine.hpp"
#include "collide/sim/fast_engine.hpp"
#include "collide/sim/generate.hpp"
#include "collide/sim/generate3.hpp"
#include "collide/sim/scene_check.hpp"
#include "commands.hpp"
#include "measurements_report.hpp"
#include "work_limits.hpp"

namespace collide::app {

namespace {

/// The fast engine's limit (30-bit disc indices), rounded down.
constexpr double max_discs = 1e9;
/// Collision counts are converted to uint64 and counted one by one: 10^15 is exact in both and
/// far beyond any run (years of computing).
constexpr double max_counted = 1e15;

struct BenchOptions {
    std::string scene;  ///< empty: random periodic fluid
    double n = 1e5;     ///< a double, so that --n 1e5 reads like --collisions 5e6
    double eta = 0.5;
    double collisions = 5e6;  ///< collisions timed
    double warmup = -1.0;     ///< collisions before timing; < 0: two per disc
    std::uint64_t seed = 1;
    int dim = 2;                  ///< 2: discs; 3: spheres (an FCC crystal melted at --eta)
    std::string engine = "fast";  ///< as typed; engine_options() parses it
    std::string pq = "binary";
    bool json = false;
    bool no_limits = false;

    /// Checks the counts and parses the engine options into their types. Throws Error(input)
    /// naming the bad option.
    [[nodiscard]] EngineOptions engine_options() const {
        if (dim != 2 && dim != 3)
            throw_option_error("--dim", fmt::format("{}", dim), "2 (discs) or 3 (spheres)");
        if (dim == 3 && !scene.empty())
            throw_option_error("--dim 3",
                               "the 3D benchmark runs its own FCC fluid; leave out --scene");
        if (scene.empty() && dim == 3) {
            if (!(n >= 4.0 && n <= max_discs && n == std::floor(n)))
                throw_option_error(
                    "--n", fmt::format("{:g}", n),
                    fmt::format("a whole number of spheres from 4 to {:g}", max_discs));
            if (!(eta > 0.0 && eta < fcc_close_packing))
                throw_option_error(
                    "--eta", fmt::format("{:g}", eta),
                    fmt::format("a packing fraction in (0, {:.4f})", fcc_close_packing));
        } else if (scene.empty()) {
            if (!(n >= 2.0 && n <= max_discs && n == std::floor(n))) {
                throw_option_error(
                    "--n", fmt::format("{:g}", n),
                    fmt::format("a whole number of discs from 2 to {:g}", max_discs));
            }
            if (!(eta > 0.0 && eta <= 0.85))
                throw_option_error("--eta", fmt::format("{:g}", eta),
                                   "a packing fraction in (0, 0.85]");
        }
        if (!(collisions >= 1.0 && collisions <= max_counted)) {
            throw_option_error("--collisions", fmt::format("{:g}", collisions),
                               fmt::format("a number of collisions from 1 to {:g}", max_counted));
        }
        if (!(warmup <= max_counted) || !std::isfinite(warmup)) {
            throw_option_error("--warmup", fmt::format("{:g}", warmup),
                               fmt::format("a number of collisions up to {:g}", max_counted));
        }
        const double total = collisions + std::max(0.0, warmup);
        if (!no_limits && total > WorkLimits{}.events) {
            throw_option_error(
                "--collisions",
                fmt::format("{:g} collisions (with the warm-up) is over the limit of {:g} (about "
                            "an hour); ask for fewer, or pass {} to run it anyway",
                            total, WorkLimits{}.events, insist_option));
        }
        EngineOptions options;
        options.engine = parse_event_engine_kind(engine, "--engine");
        options.pq = pq::parse_queue_kind(pq, "--pq");
        if (dim == 3 && options.engine != EngineKind::fast)
            throw_option_error("--engine", engine, "fast (the only engine that runs spheres yet)");
        return options;
    }
};

/// CPU seconds used by this process so far (user + system): the machine is shared, so wall time
/// includes time other processes had the core.
double cpu_seconds() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    const auto seconds = [](const timeval& tv) {
        return static_cast<double>(tv.tv_sec) + 1e-6 * static_cast<double>(tv.tv_usec);
    };
    return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

/// Peak resident set size of this process, bytes (Linux reports kilobytes).
std::uint64_t max_rss_bytes() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<std::uint64_t>(usage.ru_maxrss) * 1024U;
}

Scene random_fluid(const BenchOptions& options) {
    Scene scene;
    const auto count = static_cast<std::size_t>(options.n);
    scene.name = fmt::format("fluid-n{}-eta{}", count, options.eta);
    scene.box = Box{1.0, 1.0, Boundary::periodic};
    GenerateSpec spec;
    spec.count = count;
    spec.radius = std::sqrt(options.eta / (std::numbers::pi * options.n));
    spec.temperature = 1.0;
    spec.seed = options.seed;
    spec.validate();
    generate_discs(scene, spec);
    try {
        validate_scene(scene);  // a few discs at a high packing fraction are too big for the box
    } catch (const Error& e) {
        throw_option_error(fmt::format("--n {:g} --eta {:g}", options.n, options.eta),
                           fmt::format("no valid fluid: {}", e.what()));
    }
    return scene;
}

/// N spheres (rounded to 4 k^3, k unit cells per side) on an FCC lattice at packing fraction
/// eta in a periodic unit cube, at kT = 1: a crystal that melts below packing 0.49.
SphereScene fcc_fluid(const BenchOptions& options) {
    SphereScene scene;
    const auto cells =
        static_cast<std::size_t>(std::max(1.0, std::round(std::cbrt(options.n / 4.0))));
    scene.box = Box3{1.0, 1.0, 1.0, Boundary::periodic};
    FccSpec spec;
    spec.cells = {cells, cells, cells};
    spec.packing_fraction = options.eta;
    spec.seed = options.seed;
    generate_fcc(scene, spec);
    scene.name = fmt::format("fcc-n{}-eta{}", scene.spheres.size(), options.eta);
    return scene;
}

/// Advances until `target` more collisions have happened (counted by the listener), in steps
/// sized from the observed collision rate.
void run_collisions(EngineBase& engine, const std::uint64_t& counter, double target) {
    const std::uint64_t goal = counter + static_cast<std::uint64_t>(target);
    double step = 1e-6;
    while (counter < goal) {
        const std::uint64_t before = counter;
        const double t0 = engine.time();
        if (!std::isfinite(t0 + step)) {
            // The step grows eightfold while nothing collides: it only gets here if nothing ever
            // will (discs at rest, or moving in parallel), and then there is nothing to time.
            throw_input_error(
                fmt::format("bench engine: no collision happens in this scene (none "
                            "up to t = {:g}), so there is nothing to time",
                            t0));
        }
        engine.advance_to(t0 + step);
        const double done = static_cast<double>(counter - before);
        const double wanted =
            std::max(1.0, std::min(static_cast<double>(goal - counter), target / 8.0));
        // Aim each step at ~1/8 of the goal; grow fast while nothing happens.
        step = done > 0.0 ? std::min(step * 8.0, step * wanted / done) : step * 8.0;
    }
}

/// Warms the engine up, times `options.collisions` collisions and prints the figures.
void time_engine(const BenchOptions& options, const EngineOptions& engine_options,
                 EngineBase& engine, const std::string& scene_name, double n, bool periodic,
                 std::uint64_t rss_before) {
    std::uint64_t collisions = 0;
    engine.set_collision_listener([&collisions](const CollisionRecord&) { ++collisions; });
    run_collisions(engine, collisions, options.warmup >= 0.0 ? options.warmup : 2.0 * n);
    // Before the first measurements() call, whose temporaries would count as engine memory.
    const std::uint64_t rss_after = max_rss_bytes();
    const Measurements m0 = engine.measurements();
    const double cpu0 = cpu_seconds();
    run_collisions(engine, collisions, options.collisions);
    const double cpu_timed = cpu_seconds() - cpu0;
    const Measurements m1 = engine.measurements();

    const double seconds = m1.wall_seconds - m0.wall_seconds;
    const auto delta = [](std::uint64_t a, std::uint64_t b) { return static_cast<double>(a - b); };
    const double timed_collisions =
        delta(m1.collisions_pair + m1.collisions_wall, m0.collisions_pair + m0.collisions_wall);
    const double timed_events = delta(m1.events, m0.events);
    const double pops = delta(m1.queue.pops, m0.queue.pops);
    const double window = m1.t - m0.t;
    // Z over the timed window only (the tally runs from t = 0, through the melting).
    const double z_window =
        1.0 + ((m1.compressibility - 1.0) * m1.t - (m0.compressibility - 1.0) * m0.t) / window;

    std::vector<ReportField> fields{
        {"scene", scene_name},
        {"engine", std::string(to_string(engine_options.engine))},
        {options.dim == 3 ? "spheres" : "discs", static_cast<std::uint64_t>(n)},
        {"packing_fraction", m1.packing_fraction},
        {"timed_collisions", static_cast<std::uint64_t>(timed_collisions)},
        {"seconds", seconds},
        {"cpu_seconds", cpu_timed},
        {"collisions_per_second", timed_collisions / seconds},
        {"collisions_per_cpu_second", timed_collisions / cpu_timed},
        {"events_per_cpu_second", timed_events / cpu_timed},
        {"stale_fraction", pops > 0 ? delta(m1.queue.stale_pops, m0.queue.stale_pops) / pops : 0.0},
        {"cell_crossings_per_collision",
         delta(m1.cell_crossings, m0.cell_crossings) / timed_collisions},
        {"list_rebuilds_per_collision",
         delta(m1.list_rebuilds, m0.list_rebuilds) / timed_collisions},
        {"pq_max_size", m1.queue.max_size},
        {options.dim == 3 ? "engine_bytes_per_sphere" : "engine_bytes_per_disc",
         static_cast<double>(m1.engine_bytes) / n},
        {options.dim == 3 ? "rss_delta_bytes_per_sphere" : "rss_delta_bytes_per_disc",
         static_cast<double>(rss_after - rss_before) / n},
        {"compressibility_window",
         options.scene.empty() || periodic ? z_window : m1.compressibility},
        {"energy_relative_change", (m1.kinetic_energy - m0.kinetic_energy) / m0.kinetic_energy},
        {"max_overlap", m1.max_overlap},
    };
    if (engine_options.engine == EngineKind::classic)
        fields.insert(fields.begin() + 2, {"pq", pq::to_string(engine_options.pq)});
    const std::string out = options.json ? format_json(fields) : format_text(fields);
    std::fputs(out.c_str(), stdout);
}

void run_bench(const BenchOptions& options) {
    const EngineOptions engine_options = options.engine_options();
    if (options.dim == 3) {
        const SphereScene scene = fcc_fluid(options);
        const std::uint64_t rss_before = max_rss_bytes();
        std::unique_ptr<SphereEngine> engine = make_engine(scene, engine_options);
        time_engine(options, engine_options, *engine, scene.name,
                    static_cast<double>(scene.spheres.size()), true, rss_before);
        return;
    }
    const Scene scene = options.scene.empty() ? random_fluid(options) : load_scene(options.scene);
    const std::uint64_t rss_before = max_rss_bytes();
    std::unique_ptr<Engine> engine = make_engine(scene, engine_options);
    time_engine(options, engine_options, *engine, scene.name,
                static_cast<double>(scene.discs.size()), scene.box.boundary == Boundary::periodic,
                rss_before);
}

}  // namespace

void add_bench_command(CLI::App& root) {
    CLI::App* bench = root.add_subcommand("bench", "Benchmarks (figures for docs/benchmarks.md)");
    bench->require_subcommand(1);
    auto options = std::make_shared<BenchOptions>();
    CLI::App* cmd =
        bench->add_subcommand("engine", "Collisions per second and bytes per disc of an engine");
    cmd->add_option("--scene", options->scene, "Scene to run instead of the random periodic fluid")
        ->type_name("SCENE");
    cmd->add_option("--n", options->n, "Discs in the random fluid (default 100000)");
    cmd->add_option("--eta", options->eta, "Packing fraction of the random fluid (default 0.5)");
    cmd->add_option("--collisions", options->collisions, "Collisions timed (default 5e6)");
    cmd->add_option("--warmup", options->warmup, "Collisions before timing (default: 2 per disc)");
    add_whole_option(*cmd, "--seed", options->seed, 0, UINT64_MAX, "Seed of the random fluid");
    cmd->add_option("--dim", options->dim,
                    "2 (discs, default) or 3: spheres, an FCC crystal of --n spheres (rounded to "
                    "4 k^3) melted at packing --eta");
    cmd->add_option("--engine", options->engine, "fast (default) or classic")
        ->type_name("{fast,classic}");
    cmd->add_option("--pq", options->pq, "Classic engine's queue")->type_name(queue_kind_type);
    cmd->add_flag("--json", options->json, "Print JSON");
    cmd->add_flag(insist_option, options->no_limits,
                  "Time even more than 10^10 collisions (docs/limits.md)");
    cmd->callback([options] { run_bench(*options); });
}

}  // namespace collide::app
