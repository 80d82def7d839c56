#include "plyimpact/io/run/progress.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <unistd.h>

namespace plyimpact {

ProgressStyle progress_style(const ProgressSettings& settings, std::FILE* stream) {
  if (settings.quiet) return ProgressStyle::quiet;
  return ::isatty(::fileno(stream)) == 1 ? ProgressStyle::bar : ProgressStyle::lines;
}

ProgressClock steady_seconds() {
  return [] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
  };
}

std::string clock_time(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0.0) return "?";
  const auto s = static_cast<long long>(std::llround(seconds));
  if (s >= 3600) return fmt::format("{}:{:02}:{:02}", s / 3600, (s / 60) % 60, s % 60);
  return fmt::format("{}:{:02}", s / 60, s % 60);
}

Progress::Progress(std::string label, double total, ProgressStyle style, double line_interval_s,
                   std::FILE* stream, ProgressClock clock)
    : label_(std::move(label)), total_(total), style_(style), interval_s_(line_interval_s), stream_(stream),
      clock_(std::move(clock)), start_s_(clock_()), last_draw_s_(start_s_) {}

Progress::~Progress() {
  try {
    if (!finished_ && style_ == ProgressStyle::bar && drawn_) finish("");
  } catch (...) { // NOLINT(bugprone-empty-catch): a destructor must not throw; the bar stays drawn
  }
}

double Progress::fraction_of(double done) const {
  return total_ > 0.0 ? std::clamp(done / total_, 0.0, 1.0) : 0.0;
}

double Progress::eta_s(double fraction, double elapsed_s) const {
  double since_s = 0.0, since_fraction = 0.0; // the start, until an update is old enough
  for (const auto& [s, f] : drawn_samples_)
    if (s <= 0.75 * elapsed_s && f < fraction) since_s = s, since_fraction = f;
  if (!(fraction > since_fraction)) return -1.0;
  return (elapsed_s - since_s) * (1.0 - fraction) / (fraction - since_fraction);
}

std::string Progress::line(double done, const std::string& detail, double elapsed_s) const {
  const double fraction = fraction_of(done);
  return fmt::format("{}: {:3.0f} % ({}), {} elapsed, ETA {}", label_, 100.0 * fraction, detail,
                     clock_time(elapsed_s), clock_time(eta_s(fraction, elapsed_s)));
}

double Progress::wait_s() const {
  return style_ == ProgressStyle::bar ? 0.1 : interval_s_;
}

bool Progress::due() {
  if (style_ == ProgressStyle::quiet) return false;
  const std::scoped_lock lock(mutex_);
  return clock_() - last_draw_s_ >= wait_s();
}

void Progress::update(double done, const std::string& detail) {
  if (style_ == ProgressStyle::quiet) return;
  const std::scoped_lock lock(mutex_);
  const double now = clock_();
  if (now - last_draw_s_ < wait_s()) return;
  draw(done, detail, now);
}

void Progress::draw(double done, const std::string& detail, double now) {
  last_draw_s_ = now;
  drawn_ = true;
  const double elapsed_s = now - start_s_;
  const std::string text = line(done, detail, elapsed_s);
  // Keep the samples eta_s may still use: the latest one a quarter of the elapsed time old, and newer.
  while (drawn_samples_.size() > 1 && drawn_samples_[1].first <= 0.75 * elapsed_s)
    drawn_samples_.pop_front();
  drawn_samples_.emplace_back(elapsed_s, fraction_of(done));
  if (style_ == ProgressStyle::lines) {
    fmt::print(stream_, "{}\n", text);
  } else {
    constexpr int cells = 24;
    const double fraction = fraction_of(done);
    const int filled = static_cast<int>(fraction * cells);
    const std::string bar = fmt::format("\r[{:#<{}}{:.<{}}] {}", "", filled, "", cells - filled, text);
    fmt::print(stream_, "{:<{}}", bar, bar_width_ + 1); // blanks over a longer previous bar
    bar_width_ = bar.size() - 1;                        // visible characters, without the \r
  }
  std::fflush(stream_);
}

void Progress::finish(const std::string& summary) {
  if (style_ == ProgressStyle::quiet) return;
  const std::scoped_lock lock(mutex_);
  if (finished_) return;
  finished_ = true;
  if (style_ == ProgressStyle::bar && drawn_) fmt::print(stream_, "\r{:{}}\r", "", bar_width_);
  // A line for logs once the command has shown progress; a short run stays silent.
  if (!summary.empty() && drawn_)
    fmt::print(stream_, "{}: {}, {} elapsed\n", label_, summary, clock_time(clock_() - start_s_));
  std::fflush(stream_);
}

} // namespace plyimpact
