#pragma once
/// \file
/// Progress of a render on stderr: a one-line bar redrawn in place (frames, simulation time,
/// frames per second, ETA) that fits the terminal's width when stderr is a terminal, plain lines
/// for CI logs, JSON lines for scripts, or nothing.
/// Progress never goes to stdout, which holds only the final summary.

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace collide::app {

enum class ProgressMode {
    automatic,  ///< bar when stderr is a terminal (isatty), otherwise none
    bar,        ///< "\r[#####.....]  45/300 frames  t = 3.20  12.3 fps  ETA 0:21"
    json,       ///< one JSON object per line: {"frame":45,"frames":300,"time":3.2,...}
    plain,      ///< a line at every tenth of the frames, no "\r" (CI logs): "collide: 40% ..."
    none,
};

/// "auto" / "bar" / "plain" / "json" / "none"; throws Error(input) naming `option` otherwise.
[[nodiscard]] ProgressMode parse_progress_mode(std::string_view text,
                                               std::string_view option = "--progress");

/// The numbers shown at one moment.
struct ProgressState {
    std::int64_t frames_done = 0;
    std::int64_t frames_total = 0;
    double sim_time = 0.0;         ///< simulation time of the last finished frame
    double elapsed_seconds = 0.0;  ///< wall time since the start
};

/// Frames per second so far and the estimated seconds left (0 when unknown).
[[nodiscard]] double frames_per_second(const ProgressState& state) noexcept;
[[nodiscard]] double eta_seconds(const ProgressState& state) noexcept;
/// The bar line (without the leading "\r"), at most `columns` - 1 characters (the last column
/// of a terminal would wrap): the bar gets what the figures leave, and the least useful figures
/// (simulation time, then frames per second, then the frame count) go first when it is narrow.
[[nodiscard]] std::string format_bar(const ProgressState& state, int columns = 80);
/// The plain line (without the newline): "collide: 40% (120/300 frames, t = 3.2, 12.3 fps,
/// ETA 0:21)".
[[nodiscard]] std::string format_plain(const ProgressState& state);
/// The width of the terminal `out` is (TIOCGWINSZ), else $COLUMNS when it is a positive number,
/// else 80.
[[nodiscard]] int terminal_columns(std::FILE* out);
/// The JSON line (without the newline).
[[nodiscard]] std::string format_json(const ProgressState& state);

/// Reports a render's progress to a FILE (stderr). Redraws at most every 0.1 s (bar) or 0.5 s
/// (json) plus the final frame, so reporting costs nothing measurable. Not thread-safe.
class Progress {
  public:
    Progress(ProgressMode mode, std::int64_t frames_total, std::FILE* out = stderr);
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    /// One more frame finished at simulation time `sim_time`.
    void frame_done(double sim_time);
    /// Ends the bar line (a newline after the last redraw); safe to call more than once.
    void finish();

    /// The mode in effect after resolving `automatic`.
    [[nodiscard]] ProgressMode mode() const noexcept { return mode_; }
    [[nodiscard]] double elapsed_seconds() const;

  private:
    void emit(const ProgressState& state);

    ProgressMode mode_;
    std::FILE* out_;
    std::int64_t frames_total_;
    std::int64_t frames_done_ = 0;
    std::chrono::steady_clock::time_point started_;
    std::chrono::steady_clock::time_point last_emit_;
    bool drawn_ = false;    ///< a bar line is on screen without its newline
    int plain_tenths_ = 0;  ///< tenths of the frames reported so far (plain mode)
};

/// A notice for the user on stderr, as "collide: LINE" (the writer's and renderer's notices).
void print_notice(const std::string& line);

}  // namespace collide::app
