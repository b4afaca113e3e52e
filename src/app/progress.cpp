#include "progress.hpp"

#include <fmt/core.h>
#include <fmt/format.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "collide/error.hpp"
#include "collide/named_values.hpp"
#include "collide/printable.hpp"
#include "json_output.hpp"

namespace collide::app {

namespace {

constexpr auto bar_interval = std::chrono::milliseconds(100);
constexpr auto json_interval = std::chrono::milliseconds(500);

std::string clock_text(double seconds) {
    // Clamped: an estimate from a first slow frame can be absurd (or inf), and llround of a value
    // beyond long long is unspecified.
    const double shown = seconds > 0.0 ? std::min(seconds, 1e12) : 0.0;  // NaN too
    const auto total = static_cast<long long>(std::llround(shown));
    if (total >= 3600)
        return fmt::format("{}:{:02}:{:02}", total / 3600, total / 60 % 60, total % 60);
    return fmt::format("{}:{:02}", total / 60, total % 60);
}

}  // namespace

ProgressMode parse_progress_mode(std::string_view text, std::string_view option) {
    static constexpr std::array<NamedValue<ProgressMode>, 5> names{
        {{"auto", ProgressMode::automatic},
         {"bar", ProgressMode::bar},
         {"plain", ProgressMode::plain},
         {"json", ProgressMode::json},
         {"none", ProgressMode::none}}};
    return parse_named(text, option, names);
}

double frames_per_second(const ProgressState& state) noexcept {
    return state.elapsed_seconds > 0.0
               ? static_cast<double>(state.frames_done) / state.elapsed_seconds
               : 0.0;
}

double eta_seconds(const ProgressState& state) noexcept {
    const double fps = frames_per_second(state);
    if (fps <= 0.0) return 0.0;
    return static_cast<double>(std::max<std::int64_t>(0, state.frames_total - state.frames_done)) /
           fps;
}

namespace {

double fraction_done(const ProgressState& state) noexcept {
    return state.frames_total > 0 ? std::clamp(static_cast<double>(state.frames_done) /
                                                   static_cast<double>(state.frames_total),
                                               0.0, 1.0)
                                  : 0.0;
}

}  // namespace

std::string format_bar(const ProgressState& state, int columns) {
    constexpr int min_bar = 10;  // narrower, a bar says nothing the percentage does not
    const double fraction = fraction_done(state);
    const std::string percent = fmt::format(" {:>3.0f}%", 100.0 * fraction);
    const std::string frames = fmt::format("  {}/{} frames", state.frames_done, state.frames_total);
    const std::string time = fmt::format("  t = {:.4g}", state.sim_time);
    const std::string fps = fmt::format("  {:.1f} fps", frames_per_second(state));
    const std::string eta = "  ETA " + clock_text(eta_seconds(state));
    const int room = std::max(columns, 1) - 1;  // the last column would wrap the line
    // Figures from the most to the least useful; drop from the end until the bar has room.
    std::array<const std::string*, 5> figures{&percent, &eta, &frames, &fps, &time};
    std::size_t kept = figures.size();
    const auto text_width = [&](std::size_t n) {
        std::size_t w = 0;
        for (std::size_t i = 0; i < n; ++i) w += figures[i]->size();
        return static_cast<int>(w);
    };
    while (kept > 2 && room - 2 - text_width(kept) < min_bar) --kept;
    const int width = std::max(0, room - 2 - text_width(kept));
    const int filled = static_cast<int>(std::lround(fraction * width));
    std::string line = "[" + std::string(filled, '#') + std::string(width - filled, '.') + "]";
    // In the figures' order on screen: percentage, frames, time, fps, ETA.
    for (const std::string* figure : {&percent, &frames, &time, &fps, &eta}) {
        if (std::find(figures.begin(), figures.begin() + static_cast<long>(kept), figure) !=
            figures.begin() + static_cast<long>(kept))
            line += *figure;
    }
    if (static_cast<int>(line.size()) > room) line.resize(static_cast<std::size_t>(room));
    return line;
}

std::string format_plain(const ProgressState& state) {
    return fmt::format("collide: {:.0f}% ({}/{} frames, t = {:.4g}, {:.1f} fps, ETA {})",
                       100.0 * fraction_done(state), state.frames_done, state.frames_total,
                       state.sim_time, frames_per_second(state), clock_text(eta_seconds(state)));
}

int terminal_columns(std::FILE* out) {
    winsize size{};
    if (ioctl(fileno(out), TIOCGWINSZ, &size) == 0 && size.ws_col > 0) return size.ws_col;
    if (const char* env = std::getenv("COLUMNS"); env != nullptr) {
        int columns = 0;
        const char* end = env + std::strlen(env);
        const auto [ptr, ec] = std::from_chars(env, end, columns);
        if (ec == std::errc() && ptr == end && columns > 0) return columns;
    }
    return 80;
}

std::string format_json(const ProgressState& state) {
    // Each figure at the precision it has always had (the time to nine digits, rates and
    // seconds to a thousandth); a figure that is no number (an unknown rate) is null.
    const auto rounded = [](double x, const char* format) -> Json {
        if (!std::isfinite(x)) return nullptr;
        return std::stod(fmt::format(fmt::runtime(format), x));
    };
    Json line;
    line["frame"] = state.frames_done;
    line["frames"] = state.frames_total;
    line["time"] = rounded(state.sim_time, "{:.9g}");
    line["fps"] = rounded(frames_per_second(state), "{:.3f}");
    line["elapsed"] = rounded(state.elapsed_seconds, "{:.3f}");
    line["eta"] = rounded(eta_seconds(state), "{:.3f}");
    return line.dump(-1, ' ', false, Json::error_handler_t::replace);
}

Progress::Progress(ProgressMode mode, std::int64_t frames_total, std::FILE* out)
    : mode_(mode),
      out_(out),
      frames_total_(frames_total),
      started_(std::chrono::steady_clock::now()),
      last_emit_(started_) {
    if (mode_ == ProgressMode::automatic) {
        mode_ = isatty(fileno(out_)) != 0 ? ProgressMode::bar : ProgressMode::none;
    }
}

double Progress::elapsed_seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
}

void Progress::frame_done(double sim_time) {
    ++frames_done_;
    if (mode_ == ProgressMode::none) return;
    const auto now = std::chrono::steady_clock::now();
    const bool last = frames_done_ >= frames_total_;
    if (mode_ == ProgressMode::plain) {
        // A line each time another tenth of the frames is done, and one for the last frame.
        const auto tenths = frames_total_ > 0 ? frames_done_ * 10 / frames_total_ : 0;
        if (!last && tenths <= plain_tenths_) return;
        plain_tenths_ = static_cast<int>(tenths);
        emit({frames_done_, frames_total_, sim_time, elapsed_seconds()});
        return;
    }
    const auto interval = mode_ == ProgressMode::bar ? bar_interval : json_interval;
    if (!last && now - last_emit_ < interval) return;
    last_emit_ = now;
    emit({frames_done_, frames_total_, sim_time,
          std::chrono::duration<double>(now - started_).count()});
}

void Progress::emit(const ProgressState& state) {
    if (mode_ == ProgressMode::bar) {
        std::fprintf(out_, "\r%s", format_bar(state, terminal_columns(out_)).c_str());
        drawn_ = true;
    } else if (mode_ == ProgressMode::plain) {
        std::fprintf(out_, "%s\n", format_plain(state).c_str());
    } else {
        std::fprintf(out_, "%s\n", format_json(state).c_str());
    }
    std::fflush(out_);
}

void Progress::finish() {
    if (drawn_) {
        std::fputc('\n', out_);
        std::fflush(out_);
        drawn_ = false;
    }
}

void print_notice(const std::string& line) {
    std::fprintf(stderr, "collide: %s\n", printable_text(line).c_str());
}

}  // namespace collide::app
