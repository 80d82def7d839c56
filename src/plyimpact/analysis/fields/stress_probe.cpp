#include "plyimpact/analysis/fields/stress_probe.hpp"

#include <stdexcept>

namespace plyimpact {

StressProbes::StressProbes(const DiscretePlate& model, std::vector<StressProbeSpec> specs)
    : model_(model), specs_(std::move(specs)) {
  for (const auto& s : specs_) {
    const auto loc = model.mesh().locate(s.x, s.y);
    if (!loc) throw std::invalid_argument("stress probe '" + s.name + "' lies outside the plate");
    const auto plies = static_cast<int>(model.laminate_of(loc->element).ply_count());
    if (s.ply > plies || s.interface > plies - 1)
      throw std::invalid_argument("stress probe '" + s.name + "': the laminate at its point has " +
                                  std::to_string(plies) + " plies");
    where_.push_back(*loc);
  }
}

std::vector<std::string> StressProbes::columns() const {
  std::vector<std::string> c{"t_s"};
  for (const auto& s : specs_) {
    const std::vector<std::string> sides =
        s.ply > 0 ? std::vector<std::string>{""} : std::vector<std::string>{"upper_", "lower_"};
    for (const auto& side : sides)
      for (const char* comp : {"s11", "s22", "t12", "t13", "t23"})
        c.push_back(s.name + "_" + side + comp + "_Pa");
  }
  return c;
}

void StressProbes::observe(long /*step*/, double t, double /*force*/, const Eigen::VectorXd& u) {
  std::vector<double> row{t};
  const auto push = [&row](const PlyStress& s) {
    row.insert(row.end(), {s.s11, s.s22, s.t12, s.t13, s.t23});
  };
  for (std::size_t p = 0; p < specs_.size(); ++p) {
    const PointLocation& loc = where_[p];
    const Laminate& lam = model_.laminate_of(loc.element);
    const GeneralizedStrains e = model_.element().strains(
        model_.mesh().element_coordinates(loc.element), model_.element_dofs(u, loc.element), loc.xi, loc.eta);
    const StressProbeSpec& s = specs_[p];
    if (s.ply > 0) {
      const auto k = static_cast<std::size_t>(s.ply - 1);
      const PlateAxesStress ps =
          s.position == "average"
              ? ply_average_stress(lam, k, e)
              : ply_stress(lam, k, e, s.position == "top" ? lam.z_top(k) : lam.z_bottom(k));
      push(to_material_axes(ps, lam.plies()[k].angle_deg));
    } else {
      const InterfaceStress is = interface_stress(lam, static_cast<std::size_t>(s.interface - 1), e);
      push(is.upper);
      push(is.lower);
    }
  }
  rows_.push_back(std::move(row));
}

} // namespace plyimpact
