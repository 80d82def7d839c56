#pragma once
// report.html of a sweep (docs/sweep.md): one self-contained file beside sweep.csv that reads as a
// study report — what was swept, the cases that did not complete, the results against each swept
// variable (peak force, absorbed energy, damage; the threshold velocity of a threshold sweep) and the
// table of every case in engineering units. Written by SweepFolder::write_table, so the command, its
// MPI ranks and the Python module all get it.
#include "plyimpact/io/sweeps/sweep_spec.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace plyimpact {

/// The HTML text of a sweep's report.html; `records` are the cases' records (cases/NNNNNN.json) in
/// case order, one per case.
[[nodiscard]] std::string sweep_report_html(const Sweep& sweep, const std::vector<nlohmann::json>& records);

} // namespace plyimpact
