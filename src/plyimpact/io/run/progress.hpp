#pragma once
// Progress of a long command on stderr, with the time left (ETA): a bar redrawn in place when stderr
// is a terminal; plain lines every few seconds when it is not (CI logs, cluster job logs), so a log
// shows where a run is; nothing with --quiet. Thread-safe: sweep threads report into one display.
#include <chrono>
#include <cstdio>
#include <deque>
#include <functional>
#include <mutex>
#include <string>
#include <utility>

namespace plyimpact {

enum class ProgressStyle { bar, lines, quiet };

/// What the user asked for: `--quiet`, and how often plain lines are written (`--progress-every`).
struct ProgressSettings {
  bool quiet = false;
  double line_interval_s = 10.0;
};

/// bar when `stream` is a terminal, lines otherwise, quiet when asked.
[[nodiscard]] ProgressStyle progress_style(const ProgressSettings& settings, std::FILE* stream);

/// Seconds since some fixed instant; replaceable so that tests can drive the clock.
using ProgressClock = std::function<double()>;
[[nodiscard]] ProgressClock steady_seconds();

/// "0:07", "12:05", "1:02:03" (h:mm:ss), or "?" for a negative or non-finite time.
[[nodiscard]] std::string clock_time(double seconds);

class Progress {
public:
  /// `label` starts every line ("impact", "sweep"); `total` is the amount of work (any unit).
  Progress(std::string label, double total, ProgressStyle style, double line_interval_s = 10.0,
           std::FILE* stream = stderr, ProgressClock clock = steady_seconds());
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  Progress(Progress&&) = delete;
  Progress& operator=(Progress&&) = delete;

  /// `done` of `total` finished; `detail` says it in the command's terms ("t = 1.2 of 4.3 ms").
  /// Drawn at most 10 times a second (bar) or once per line interval (lines).
  void update(double done, const std::string& detail);
  /// Whether an update now would be drawn (callers skip building `detail` when not).
  [[nodiscard]] bool due();
  /// The last line: `summary` with the elapsed time; clears the bar. Called by the destructor if not
  /// called before (a run that ends by an exception leaves no half-drawn bar).
  void finish(const std::string& summary);

  /// The text of one update: "label: 45 % (detail), 0:03 elapsed, ETA 0:04".
  [[nodiscard]] std::string line(double done, const std::string& detail, double elapsed_s) const;
  /// Seconds left at `fraction` done after `elapsed_s`: the work left at the recent rate, measured since
  /// the latest drawn update at least a quarter of the elapsed time ago (from the start before there is
  /// one), so that a run whose steps grow dearer (damage spreading) is not promised the early rate.
  /// Negative (shown "?") before any work is done.
  [[nodiscard]] double eta_s(double fraction, double elapsed_s) const;

private:
  void draw(double done, const std::string& detail, double now);
  [[nodiscard]] double wait_s() const;
  [[nodiscard]] double fraction_of(double done) const;

  std::string label_;
  double total_;
  ProgressStyle style_;
  double interval_s_;
  std::FILE* stream_;
  ProgressClock clock_;
  double start_s_, last_draw_s_;
  bool drawn_ = false, finished_ = false;
  std::size_t bar_width_ = 0; ///< characters of the last bar, cleared by finish
  /// (elapsed [s], fraction) of the drawn updates still needed by eta_s, oldest first.
  std::deque<std::pair<double, double>> drawn_samples_;
  std::mutex mutex_;
};

} // namespace plyimpact
