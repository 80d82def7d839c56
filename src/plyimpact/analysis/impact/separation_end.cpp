#include "plyimpact/analysis/impact/separation_end.hpp"

#include <fmt/format.h>

#include <cmath>

namespace plyimpact {

bool SeparationRule::cannot_hit_again(const SeparationState& s) {
  if (failure_ || end_) return end_.has_value();
  const double reach = std::sqrt(2.0 * std::max(s.plate_energy, 0.0) * compliance_); // SE1
  if (std::abs(s.plate_w) > reach * (1.0 + 1e-9) + 1e-15) {
    failure_ = fmt::format(
        "the separation end (time.end = \"separation\") was given up at t = {:.6g} s: the plate's deflection "
        "at the impact point, {:.4g} m, passed the bound sqrt(2 E c) = {:.4g} m of the undamaged plate (E = "
        "{:.4g} J, c = {:.4g} m/N): damage has made it softer than the rule assumes. The run went on to the "
        "SPEC §4 end-of-event rule",
        s.t, s.plate_w, reach, s.plate_energy, compliance_);
    return false;
  }
  if (!(s.impactor_v < 0.0)) return false; // still moving toward the plate
  const double bound = separation_safety_factor * reach;
  const double gap = s.permanent_indentation - s.impactor_w - bound; // SE2
  if (gap < 0.0) return false;
  end_ = SeparationEnd{s.t, gap, bound, s.plate_energy, compliance_};
  return true;
}

} // namespace plyimpact
