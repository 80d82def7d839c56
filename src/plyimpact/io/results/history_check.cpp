// A history.csv checked and thinned for plotting (history_check.hpp).
#include "plyimpact/io/results/history_check.hpp"

#include "plyimpact/io/system/atomic_file.hpp"
#include "plyimpact/io/system/regular_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

namespace plyimpact {

namespace {

namespace fs = std::filesystem;

/// The whole history, read without blocking where it is a regular file of at most max_history_bytes.
std::string read_history(const fs::path& file) {
  RegularFileText read = read_regular_file(file, max_history_bytes);
  if (read.text) return std::move(*read.text);
  const std::string advice = read.why_not.starts_with("is not a regular file")
                                 ? ": a results folder's history.csv is a file the impact run wrote"
                             : read.why_not.starts_with("is larger")
                                 ? ": write fewer rows ([output] history_every)"
                                 : "";
  throw HistoryFileError(fmt::format("{}: error: it {}{}", file.string(), read.why_not, advice));
}

/// The cells of a line split at commas.
std::vector<std::string_view> cells(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t at = 0;
  for (;;) {
    const std::size_t comma = line.find(',', at);
    out.push_back(line.substr(at, comma == std::string_view::npos ? std::string_view::npos : comma - at));
    if (comma == std::string_view::npos) return out;
    at = comma + 1;
  }
}

/// A row of a history: its text and its contact force (for the thinning).
struct Row {
  std::string_view text;
  double force = 0.0;
};

/// The data rows, each checked: as many cells as the header, every cell a finite number.
std::vector<Row> checked_rows(const fs::path& file, std::string_view text, std::size_t& columns,
                              std::string_view& header) {
  const std::size_t end_of_header = text.find('\n');
  if (text.empty() || end_of_header == std::string_view::npos)
    throw HistoryFileError(
        fmt::format("{}:1: error: no header line: the history is empty or cut short", file.string()));
  header = text.substr(0, end_of_header);
  const std::vector<std::string_view> names = cells(header);
  columns = names.size();
  const auto force_at = std::find(names.begin(), names.end(), "force_N");
  const std::size_t force = static_cast<std::size_t>(force_at - names.begin());
  if (names.front() != "t_s")
    throw HistoryFileError(
        fmt::format("{}:1: error: the header starts with \"{}\", not t_s: not a history.csv "
                    "of plyimpact impact",
                    file.string(), names.front()));
  std::vector<Row> rows;
  std::size_t at = end_of_header + 1;
  for (std::size_t line = 2; at < text.size(); ++line) {
    const std::size_t eol = text.find('\n', at);
    if (eol == std::string_view::npos)
      throw HistoryFileError(fmt::format("{}:{}: error: the last row has no end of line: the history was cut "
                                         "mid-row (a run killed or a full disk); nothing was plotted",
                                         file.string(), line));
    const std::string_view row = text.substr(at, eol - at);
    const std::vector<std::string_view> c = cells(row);
    if (c.size() != columns)
      throw HistoryFileError(fmt::format("{}:{}: error: {} cells where the header has {}", file.string(),
                                         line, c.size(), columns));
    Row r{row, 0.0};
    for (std::size_t k = 0; k < c.size(); ++k) {
      double value = 0.0;
      const auto [ptr, ec] = std::from_chars(c[k].data(), c[k].data() + c[k].size(), value);
      if (ec != std::errc() || ptr != c[k].data() + c[k].size() || !std::isfinite(value))
        throw HistoryFileError(
            fmt::format("{}:{}: error: column {} (\"{}\") holds \"{}\", not a finite number", file.string(),
                        line, k + 1, names[k], c[k]));
      if (k == force) r.force = value;
    }
    rows.push_back(r);
    at = eol + 1;
  }
  return rows;
}

/// Every k-th row, and in each group of k the rows of the largest and the smallest force, in order.
std::string thinned_rows(std::string_view header, const std::vector<Row>& rows, std::size_t& kept) {
  const std::size_t group = max_plot_rows / 4; // at most four rows kept from each
  const std::size_t k = (rows.size() + group - 1) / group;
  std::string out(header);
  out += '\n';
  kept = 0;
  for (std::size_t first = 0; first < rows.size(); first += k) {
    const std::size_t last = std::min(rows.size(), first + k);
    std::size_t hi = first, lo = first;
    for (std::size_t i = first; i < last; ++i) {
      if (rows[i].force > rows[hi].force) hi = i;
      if (rows[i].force < rows[lo].force) lo = i;
    }
    std::vector<std::size_t> pick{first, hi, lo, last - 1};
    std::sort(pick.begin(), pick.end());
    pick.erase(std::unique(pick.begin(), pick.end()), pick.end());
    for (const std::size_t i : pick) {
      out += rows[i].text;
      out += '\n';
      ++kept;
    }
  }
  return out;
}

} // namespace

CheckedHistory check_history_for_plot(const fs::path& history, const fs::path& thinned) {
  const std::string text = read_history(history);
  std::size_t columns = 0;
  std::string_view header;
  const std::vector<Row> rows = checked_rows(history, text, columns, header);
  if (rows.size() <= max_plot_rows) return {history, rows.size(), rows.size()};
  CheckedHistory c{thinned, rows.size(), 0};
  write_file_atomically(thinned, thinned_rows(header, rows, c.plotted));
  return c;
}

} // namespace plyimpact
