#include "progress.hpp"

#include <fmt/core.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "collide/error.hpp"
#include "collide/named_values.hpp"

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
    static constexpr std::array<NamedValue<ProgressMode>, 4> names{
        {{"auto", ProgressMode::automatic},
         {"bar", ProgressMode::bar},
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

std::string format_bar(const ProgressState& state, int width) {
    const double fraction = state.frames_total > 0
                                ? std::clamp(static_cast<double>(state.frames_done) /
                                                 static_cast<double>(state.frames_total),
                                             0.0, 1.0)
                                : 0.0;
    const int filled = static_cast<int>(std::lround(fraction * width));
    return fmt::format("[{}{}] {:>3.0f}%  {}/{} frames  t = {:.4g}  {:.1f} fps  ETA {}",
                       std::string(filled, '#'), std::string(width - filled, '.'), 100.0 * fraction,
                       state.frames_done, state.frames_total, state.sim_time,
                       frames_per_second(state), clock_text(eta_seconds(state)));
}

std::string format_json(const ProgressState& state) {
    return fmt::format(
        R"({{"frame":{},"frames":{},"time":{:.9g},"fps":{:.3f},"elapsed":{:.3f},"eta":{:.3f}}})",
        state.frames_done, state.frames_total, state.sim_time, frames_per_second(state),
        state.elapsed_seconds, eta_seconds(state));
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
    const auto interval = mode_ == ProgressMode::bar ? bar_interval : json_interval;
    const bool last = frames_done_ >= frames_total_;
    if (!last && now - last_emit_ < interval) return;
    last_emit_ = now;
    emit({frames_done_, frames_total_, sim_time,
          std::chrono::duration<double>(now - started_).count()});
}

void Progress::emit(const ProgressState& state) {
    if (mode_ == ProgressMode::bar) {
        std::fprintf(out_, "\r%s", format_bar(state).c_str());
        drawn_ = true;
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
    std::fprintf(stderr, "collide: %s\n", line.c_str());
}

}  // namespace collide::app
