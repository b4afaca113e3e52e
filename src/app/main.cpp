/// The `collide` command line: parses arguments, runs one subcommand, and is the only place where
/// errors become messages and exit codes (0 success, 2 bad input or usage, 1 anything else; a run
/// stopped by a signal ends by that signal after its clean stop: the shell's 130 for Ctrl-C).

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <vector>

#include "cli_conventions.hpp"
#include "collide/error.hpp"
#include "collide/printable.hpp"
#include "commands.hpp"
#include "interrupt.hpp"

namespace {

constexpr int exit_usage = 2;
constexpr int exit_failure = 1;

/// Every error message: what it quotes from a scene or the command line reaches the terminal with
/// its control characters escaped (collide/printable.hpp), never as an escape sequence.
void print_error(const std::string& message) {
    std::fprintf(stderr, "collide: error: %s\n", collide::printable_text(message).c_str());
}

/// What to lower when `command` runs out of memory: the sizes that its memory grows with.
std::string memory_advice(const std::string& command) {
    if (command == "render" || command == "thumbnail")
        return "use fewer discs, a smaller frame (-q l or --size), or a shorter --duration";
    if (command == "simulate") return "use fewer discs, or a shorter --until";
    if (command == "bench") return "use a smaller --n";
    if (command == "pq") return "give fewer --ops";
    if (command == "puzzle") return "lower --max-nodes, or show A* alone (--method astar)";
    return "use fewer discs (the scene's N, or [[generate]] count)";
}

/// "out of memory while running `collide render`": std::bad_alloc says neither what ran out nor
/// what to do.
std::string out_of_memory_message(const CLI::App& root) {
    const std::vector<CLI::App*> commands = root.get_subcommands();
    const std::string command = commands.empty() ? std::string() : commands.front()->get_name();
    std::string message = "out of memory";
    if (!command.empty()) message += " in `collide " + command + "`";
    // Name the scene the advice is about (`check big.toml`): the user may not know its size.
    if (!commands.empty()) {
        const CLI::Option* scene = commands.front()->get_option_no_throw("scene");
        if (scene != nullptr && scene->count() > 0 && !scene->results().empty()) {
            message += " with the scene '" + scene->results().front() + "'";
        }
    }
    message += ": the run needs more memory than the system would give; " + memory_advice(command);
    return message;
}

}  // namespace

namespace {

/// A run that a signal stopped ends the same way whatever error the stop surfaced as (a write
/// that gave up, a loop that polled the flag): one message, then the signal (interrupt.hpp).
void end_if_interrupted() {
    if (const int signal_number = collide::app::interrupt_received(); signal_number != 0) {
        collide::app::end_by_signal(signal_number, collide::app::interrupt_message(signal_number));
    }
}

}  // namespace

int main(int argc, char** argv) {
    collide::app::ignore_file_size_signal();
    CLI::App root{"collide: event-driven vs time-driven hard-disc simulation, rendered to video",
                  "collide"};
    root.set_version_flag("--version", collide::app::version_text);
    root.require_subcommand(0, 1);
    root.footer(
        "Exit codes: 0 success, 2 bad input or usage, 1 other failure; stopped by a signal "
        "(Ctrl-C): ended by that signal after cleaning up (the shell shows 130).");
    collide::app::add_check_command(root);
    collide::app::add_scenes_command(root);
    collide::app::add_pq_command(root);
    // heap, puzzle, render, thumbnail, compare: here in collide-draw; in collide, an exec of
    // collide-draw when one of them is the command.
    collide::app::add_drawing_commands(root, argc, argv);

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
        print_error(e.what() + collide::app::typo_hint(root, e));
        std::fputs("Run with --help for more information.\n", stderr);
        return exit_usage;
    } catch (const collide::app::ExitStatus& status) {
        return status.code;
    } catch (const collide::Error& e) {
        end_if_interrupted();
        print_error(e.what());
        return e.exit_code();
    } catch (const std::bad_alloc&) {
        end_if_interrupted();
        print_error(out_of_memory_message(root));
        return exit_failure;
    } catch (const std::exception& e) {
        end_if_interrupted();
        print_error(e.what());
        return exit_failure;
    }
}
