/// The `collide` command line: parses arguments, runs one subcommand, and is the only place where
/// errors become messages and exit codes (0 success, 2 bad input or usage, 1 anything else).

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <string>

#include "collide/error.hpp"
#include "commands.hpp"

namespace {

constexpr int exit_usage = 2;
constexpr int exit_failure = 1;

void print_error(const std::string& message) {
    std::fprintf(stderr, "collide: error: %s\n", message.c_str());
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App root{"collide: event-driven vs time-driven hard-disc simulation, rendered to video",
                  "collide"};
    root.set_version_flag("--version", std::string("collide ") + COLLIDE_VERSION);
    root.require_subcommand(0, 1);
    root.footer("Exit codes: 0 success, 2 bad input or usage, 1 other failure.");
    collide::app::add_check_command(root);
    collide::app::add_scenes_command(root);
    collide::app::add_pq_command(root);
    collide::app::add_heap_command(root);
    collide::app::add_render_command(root);
    collide::app::add_thumbnail_command(root);

    collide::app::add_simulate_command(root);
    collide::app::add_bench_command(root);

    try {
        root.parse(argc, argv);
        if (argc == 1) {
            std::fputs(root.help().c_str(), stdout);
        }
        return 0;
    } catch (const CLI::ParseError& e) {
        // --help and --version arrive here as "errors" with exit code 0.
        if (e.get_exit_code() == 0) return root.exit(e);
        // Usage errors read like every other error ("collide: error: ..."), with CLI11's hint.
        print_error(e.what());
        std::fputs("Run with --help for more information.\n", stderr);
        return exit_usage;
    } catch (const collide::Error& e) {
        print_error(e.what());
        return e.exit_code();
    } catch (const std::exception& e) {
        print_error(e.what());
        return exit_failure;
    }
}
