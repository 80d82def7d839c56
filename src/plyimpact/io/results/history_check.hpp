#pragma once
// A history.csv read back for `plyimpact plot` (issue 77; docs/robustness.md, "Plotting a results
// folder"): a results folder is input like a deck, and may be cut short, edited, or not what it seems.
// Before gnuplot sees it, the history is checked —
//   - a regular file (a FIFO blocked the plot, a link to /dev/zero never ended), at most
//     max_history_bytes;
//   - every row as many cells as the header, each a finite number (a row cut mid-line by a full disk or a
//     killed run, "nan" or garbage is named with its line);
// and where it has more than max_plot_rows rows it is thinned for the pictures (a 780 000-row history kept
// gnuplot on its first plot for ten minutes): every k-th row, and in each group of k rows the rows of the
// largest and the smallest contact force, so that the peaks are drawn where they are.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <stdexcept>

namespace plyimpact {

/// A history that cannot be plotted: the message names the file, the line and what is wrong (exit 2).
class HistoryFileError : public std::invalid_argument {
public:
  using std::invalid_argument::invalid_argument;
};

inline constexpr std::uintmax_t max_history_bytes = std::uintmax_t{4} << 30U; ///< 4 GiB
inline constexpr std::size_t max_plot_rows = 20000; ///< rows a picture draws at most (900 px wide)

struct CheckedHistory {
  std::filesystem::path file; ///< what gnuplot reads: the history itself, or its thinned copy
  std::size_t rows = 0;       ///< data rows of the history
  std::size_t plotted = 0;    ///< data rows in `file`
};

/// Checks `history` (above) and returns the file to plot; a thinned copy is written to `thinned` where the
/// history has more than max_plot_rows rows. Throws HistoryFileError.
[[nodiscard]] CheckedHistory check_history_for_plot(const std::filesystem::path& history,
                                                    const std::filesystem::path& thinned);

} // namespace plyimpact
