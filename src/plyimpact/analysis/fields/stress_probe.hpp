#pragma once
// Stress histories at chosen points (thesis Fig. 4.12–4.15, 4.24–4.29): material-axis stresses of a
// ply (its top or bottom face, or its average) or of both plies at an interface, every step.
#include "plyimpact/analysis/fields/stress_recovery.hpp"
#include "plyimpact/analysis/impact/impact_observer.hpp"
#include "plyimpact/analysis/impact/parameters.hpp"
#include "plyimpact/fem/discrete_plate.hpp"

#include <string>
#include <vector>

namespace plyimpact {

class StressProbes final : public ImpactObserver {
public:
  /// Throws std::invalid_argument for a probe outside the plate or naming a ply or interface that the
  /// laminate at its point does not have.
  StressProbes(const DiscretePlate& model, std::vector<StressProbeSpec> specs);
  void observe(long step, double t, double force, const Eigen::VectorXd& u);
  void on_step(const StepView& v) override { observe(v.step, v.t, v.force, v.plate_displacement()); }
  /// Column names (unit in each): t_s, then per probe <name>_s11_Pa, ... (interfaces: _upper_/_lower_).
  [[nodiscard]] std::vector<std::string> columns() const;
  [[nodiscard]] const std::vector<std::vector<double>>& rows() const { return rows_; }
  [[nodiscard]] bool empty() const { return specs_.empty(); }

private:
  const DiscretePlate& model_;
  std::vector<StressProbeSpec> specs_;
  std::vector<PointLocation> where_;
  std::vector<std::vector<double>> rows_;
};

} // namespace plyimpact
