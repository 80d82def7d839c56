#include "plyimpact/analysis/thresholds/load_drop.hpp"

#include <algorithm>
#include <cstddef>
#include <iterator>

namespace plyimpact {

namespace {

/// The first contact's loading phase: its first sample, and one past its last, the largest impactor
/// displacement (impactor_w: it moves into the plate, SPEC §1) before the force returns to zero.
struct LoadingPhase {
  std::size_t begin = 0, end = 0;
};

LoadingPhase loading_phase(const std::vector<ImpactSample>& history) {
  std::size_t begin = history.size(), deepest = 0;
  for (std::size_t i = 0; i < history.size(); ++i) {
    if (history[i].force > 0.0)
      begin = std::min(begin, i);
    else if (begin < i)
      break; // the first contact has ended
    if (history[i].impactor_w > history[deepest].impactor_w) deepest = i;
  }
  return begin < history.size() ? LoadingPhase{begin, deepest + 1} : LoadingPhase{};
}

/// The force at each sample of [begin, end): the median of the samples of the history within ±window/2 of
/// its time. A median keeps a step (a drop stays a drop) where a mean would spread it over the window, and
/// removes an oscillation whose period the window spans.
std::vector<double> smoothed_force(const std::vector<ImpactSample>& history, LoadingPhase phase,
                                   double window) {
  std::vector<double> smooth, in_window;
  smooth.reserve(phase.end - phase.begin);
  std::size_t lo = 0, hi = 0;
  for (std::size_t i = phase.begin; i < phase.end; ++i) {
    const double t = history[i].t;
    while (history[lo].t < t - 0.5 * window)
      ++lo;
    hi = std::max(hi, i + 1);
    while (hi < history.size() && history[hi].t <= t + 0.5 * window)
      ++hi;
    in_window.clear();
    for (std::size_t k = lo; k < hi; ++k)
      in_window.push_back(history[k].force);
    const auto middle = in_window.begin() + static_cast<std::ptrdiff_t>(in_window.size() / 2);
    std::nth_element(in_window.begin(), middle, in_window.end());
    smooth.push_back(*middle);
  }
  return smooth;
}

} // namespace

std::optional<LoadDrop> first_load_drop(const std::vector<ImpactSample>& history, double fraction) {
  const LoadingPhase phase = loading_phase(history);
  if (phase.end <= phase.begin) return std::nullopt;
  const double window = load_drop_window * (history[phase.end - 1].t - history[phase.begin].t);
  const std::vector<double> smooth = smoothed_force(history, phase, window);
  std::size_t peak = 0; // of the smoothed force so far
  for (std::size_t k = 0; k < smooth.size(); ++k) {
    if (smooth[k] > smooth[peak])
      peak = k;
    else if (smooth[k] < (1.0 - fraction) * smooth[peak]) {
      LoadDrop drop{0.0, 0.0, history[phase.begin + k].t};
      for (std::size_t i = phase.begin; i <= phase.begin + k; ++i)
        if (history[i].force > drop.force) drop = {history[i].force, history[i].t, drop.detected};
      return drop;
    }
  }
  return std::nullopt;
}

std::optional<FirstDelamination> first_delamination(const std::vector<ImpactSample>& history) {
  if (history.empty()) return std::nullopt;
  for (const ImpactSample& s : history)
    if (s.delaminated_area > history.front().delaminated_area) return FirstDelamination{s.t, s.force};
  return std::nullopt;
}

} // namespace plyimpact
