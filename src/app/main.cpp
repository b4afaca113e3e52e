/// The `collide` command line: parses arguments, runs one subcommand, and is the only place where
/// errors become messages and exit codes (0 success, 2 bad input or usage, 1 anything else; a run
/// stopped by a signal ends by that signal after its clean stop: the shell's 130 for Ctrl-C).

#include <malloc.h>
#include <sys/resource.h>

#include <CLI/CLI.hpp>
#include <csignal>
#include <cstdio>
#include <exception>
#include <new>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include "cli_conventions.hpp"
#include "cli_help.hpp"
#include "cli_numbers.hpp"
#include "collide/error.hpp"
#include "collide/printable.hpp"
#include "commands.hpp"
#include "interrupt.hpp"
#include "progress.hpp"
#include "standard_streams.hpp"

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
    if (command == "heap") return "give fewer --ops, or a smaller frame (-q l or --size)";
    if (command == "compare") return "compare smaller images";
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

/// The command line's exit code, with every error turned into its message.
int run(CLI::App& root, int argc, char** argv, const std::vector<char*>& help_args);

/// `code`, unless something printed on standard output was lost: then the message and 1 (or
/// the quiet end by SIGPIPE of any program whose reader left, as `collide scenes | head -c1`).
int with_standard_output_checked(int code) {
    bool broken_pipe = false;
    const std::optional<std::string> failure = collide::app::standard_output_failure(broken_pipe);
    if (!failure) return code;
    if (broken_pipe) {
        std::signal(SIGPIPE, SIG_DFL);
        std::raise(SIGPIPE);
    }
    print_error(*failure);
    return code == 0 ? exit_failure : code;
}

/// Under an address-space limit (`ulimit -v`), one malloc arena for all threads: each thread's
/// own arena reserves 64 MiB of address space (128 MiB while it is made), which took half a
/// render's (and, by the number of threads, more on more cores), and made the libraries that do
/// not survive a failed allocation (LLVM, in the software GL's shader compiler) crash at limits
/// the run fits in. Measured: a 640x360 render peaks at 0.57 GiB of address space instead of
/// 1.0 (docs/limits.md, "Memory").
void one_malloc_arena_under_address_limit() noexcept {
#ifdef __GLIBC__
    rlimit limit{};
    if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
        mallopt(M_ARENA_MAX, 1);
#endif
}

}  // namespace

int main(int argc, char** argv) {
    one_malloc_arena_under_address_limit();
    // Before anything opens a file: a closed standard output must stay closed for writes.
    collide::app::reserve_standard_descriptors();
    collide::app::ignore_file_size_signal();
    std::vector<char*> help_args;  // `collide help [COMMAND]`: `collide [COMMAND] --help`
    collide::app::help_as_flag(argc, argv, help_args);
    CLI::App root{"collide: event-driven vs time-driven hard-disc simulation, rendered to video",
                  "collide"};
    collide::app::use_wrapping_help(root, collide::app::terminal_columns(stdout));
    root.set_version_flag("-V,--version", collide::app::version_text);
    root.require_subcommand(0, 1);
    root.footer(
        "Exit codes: 0 success, 2 bad input or usage, 1 other failure; stopped by a signal "
        "(Ctrl-C): ended by that signal after cleaning up (the shell shows 130).");
    collide::app::add_check_command(root);
    collide::app::add_scenes_command(root);
    collide::app::add_pq_command(root);
    // heap, puzzle, render, thumbnail: here in collide-draw; in collide, an exec of collide-draw
    // when one of them is the command.
    collide::app::add_drawing_commands(root, argc, argv);
    collide::app::add_compare_command(root);  // PNG files only: runs in both programs

    collide::app::add_simulate_command(root);
    collide::app::add_bench_command(root);
    collide::app::add_help_command(root);
    collide::app::refuse_empty_numbers(root);
    return with_standard_output_checked(run(root, argc, argv, help_args));
}

namespace {

int run(CLI::App& root, int argc, char** argv, const std::vector<char*>& help_args) {
    try {
        root.parse(argc, argv);
        if (argc == 1) {
            std::fputs(root.help().c_str(), stdout);
        }
        return 0;
    } catch (const CLI::ParseError& e) {
        // --help and --version arrive here as "errors" with exit code 0, but `collide help NAME`
        // for a NAME that is no command is a usage error: the word left over.
        const bool unknown_topic = !help_args.empty() && !root.remaining().empty();
        if (e.get_exit_code() == 0 && !unknown_topic) return root.exit(e);
        const CLI::ExtrasError topic(root.remaining());
        const CLI::ParseError& error = e.get_exit_code() == 0 ? topic : e;
        // Usage errors read like every other error ("collide: error: ..."), with CLI11's hint.
        print_error(error.what() + collide::app::typo_hint(root, error));
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
    } catch (const std::system_error& e) {
        end_if_interrupted();
        // A thread the system could not start (EAGAIN: no memory for its stack under
        // `ulimit -v`) is memory too, not "Resource temporarily unavailable".
        const bool memory = e.code() == std::errc::resource_unavailable_try_again ||
                            e.code() == std::errc::not_enough_memory;
        print_error(memory ? out_of_memory_message(root) : std::string(e.what()));
        return exit_failure;
    } catch (const std::exception& e) {
        end_if_interrupted();
        print_error(e.what());
        return exit_failure;
    }
}

}  // namespace
