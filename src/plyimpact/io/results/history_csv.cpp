#include "plyimpact/io/results/history_csv.hpp"

#include <fmt/format.h>

#include <iterator>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <stdexcept>
#include <unistd.h>

namespace plyimpact {

namespace {

/// Rows are written in blocks of about this many bytes (a few hundred rows).
constexpr std::size_t block_bytes = 64 * 1024;
/// ... and at least this often while the run goes, so a slow run shows its history.
constexpr auto flush_interval = std::chrono::seconds(1);

} // namespace

HistoryLayout history_layout(const ImpactResult& result) {
  HistoryLayout layout;
  if (!result.history.empty())
    layout.damaged_plies = static_cast<int>(result.history.front().ply_damage_area.size());
  if (result.delamination) layout.interfaces_after_ply = result.delamination->interface_after_ply;
  return layout;
}

std::vector<std::string> history_columns(const HistoryLayout& layout) {
  std::vector<std::string> names{
      "t_s",           "force_N",         "impactor_w_m",   "impactor_v_m_per_s", "plate_w_m",
      "indentation_m", "plate_kinetic_J", "plate_strain_J", "impactor_energy_J",  "contact_work_J"};
  if (layout.damaged_plies > 0) {
    names.emplace_back("damage_dissipation_J");
    names.emplace_back("damage_area_m2");
    for (int k = 1; k <= layout.damaged_plies; ++k)
      names.push_back(fmt::format("ply{}_damage_area_m2", k));
  }
  if (!layout.interfaces_after_ply.empty()) {
    names.emplace_back("delamination_dissipation_J");
    names.emplace_back("delamination_area_m2");
    for (const int p : layout.interfaces_after_ply)
      names.push_back(fmt::format("delamination_area_after_ply{}_m2", p));
  }
  return names;
}

std::string history_csv_header(const HistoryLayout& layout) {
  std::string h;
  for (const std::string& name : history_columns(layout))
    h += (h.empty() ? "" : ",") + name;
  return h + "\n";
}

void append_history_csv_row(std::string& out, const ImpactSample& h) {
  // The shortest text that reads back as the same double (no float noise, no lost digits).
  bool first = true;
  for_each_history_value(h, [&](double v) {
    if (!first) out.push_back(',');
    fmt::format_to(std::back_inserter(out), "{}", v);
    first = false;
  });
  out.push_back('\n');
}

std::string history_csv_row(const ImpactSample& h) {
  std::string row;
  append_history_csv_row(row, h);
  return row;
}

HistoryCsvWriter::HistoryCsvWriter(std::filesystem::path path, int every, const HistoryLayout& layout)
    : path_(std::move(path)), every_(every < 1 ? 1 : every), last_flush_(std::chrono::steady_clock::now()) {
  fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw std::runtime_error(fmt::format("{}: cannot write: {}", path_.string(), std::strerror(errno)));
  buffer_ = history_csv_header(layout);
  flush();
}

HistoryCsvWriter::~HistoryCsvWriter() {
  try {
    flush(); // a run stopped by an exception keeps the rows it computed
  } catch (const std::exception&) {
    // the error that stopped the run is the one reported
  }
  ::close(fd_);
}

void HistoryCsvWriter::on_finish(const StepView& last, const ImpactResult& /*result*/) {
  if (last_step_ != last.step) record(last);
  flush();
}

void HistoryCsvWriter::record(const StepView& v) {
  history_sample(v, sample_);
  append_history_csv_row(buffer_, sample_); // appends in place: no string or vector per step
  last_step_ = v.step;
  if (buffer_.size() >= block_bytes || std::chrono::steady_clock::now() - last_flush_ >= flush_interval)
    flush();
}

void HistoryCsvWriter::flush() {
  last_flush_ = std::chrono::steady_clock::now();
  std::size_t done = 0;
  while (done < buffer_.size()) {
    const ssize_t n = ::write(fd_, buffer_.data() + done, buffer_.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      const std::string why = std::strerror(errno);
      buffer_.clear();
      // the rows of this flush that reached the disk before it filled are cut off: the file keeps whole
      // rows only (issue 77: a full disk left a row cut mid-line under the final name)
      const bool cut = ::ftruncate(fd_, static_cast<off_t>(whole_bytes_)) == 0;
      throw std::runtime_error(
          fmt::format("{}: write failed: {}; {}", path_.string(), why,
                      cut ? "it keeps the whole rows written before" : "its last row may be cut short"));
    }
    done += static_cast<std::size_t>(n);
  }
  whole_bytes_ += buffer_.size();
  buffer_.clear();
}

} // namespace plyimpact
