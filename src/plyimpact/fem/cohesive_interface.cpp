#include "plyimpact/fem/cohesive_interface.hpp"

#include "plyimpact/fem/quadrature.hpp"
#include "plyimpact/fem/shape_functions.hpp"

#include <stdexcept>

namespace plyimpact {

namespace {

std::vector<QuadraturePoint> rule_points(CohesiveIntegration rule) {
  static constexpr auto lobatto3x3 = tensor_product(lobatto3);
  if (rule == CohesiveIntegration::nodal) return {lobatto3x3.begin(), lobatto3x3.end()};
  return {gauss3x3.begin(), gauss3x3.end()};
}

const QuadratureRule1D<3>& rule_1d(CohesiveIntegration rule) {
  return rule == CohesiveIntegration::nodal ? lobatto3 : gauss3;
}

/// The law's response at one point of separation `delta` from its committed state, as `damage` says.
CohesiveResponse point_response(const CohesiveLaw& law, const CohesiveState& committed,
                                const Eigen::Vector3d& delta, CohesiveDamage damage, double loading_band) {
  CohesiveResponse r = law.update(committed, delta, damage == CohesiveDamage::evolve ? loading_band : 0.0);
  if (damage == CohesiveDamage::lagged) { // the damage held: only the trial state comes from update
    const CohesiveResponse held = law.at_fixed_damage(committed, delta);
    r.traction = held.traction;
    r.tangent = held.tangent;
  } else if (damage == CohesiveDamage::lagged_mean) { // 2 τ̄ − τ(δ₀), tangent 2 ∂τ̄/∂δ (DL6)
    const CohesiveResponse mean = law.step_mean(committed, delta);
    r.traction = 2.0 * mean.traction - law.at_fixed_damage(committed, committed.separation).traction;
    r.tangent = 2.0 * mean.tangent;
  }
  return r;
}

} // namespace

CohesiveInterface::CohesiveInterface(const PlateModel& upper, const PlateModel& lower, int upper_offset,
                                     int lower_offset, CohesiveLaw law, CohesiveIntegration rule,
                                     double loading_band)
    : upper_(upper), lower_(lower), upper_offset_(upper_offset), lower_offset_(lower_offset),
      half_upper_(0.5 * upper.laminate().thickness()), half_lower_(0.5 * lower.laminate().thickness()),
      law_(law), loading_band_(loading_band), element_count_(upper.mesh().element_count()) {
  if (lower.mesh().element_count() != element_count_ ||
      lower.mesh().node_count() != upper.mesh().node_count())
    throw std::invalid_argument("cohesive interface: the two sub-laminates must share one mesh");
  for (const QuadraturePoint& q : rule_points(rule)) {
    rule_.push_back({q.xi, q.eta, q.weight, tributary_interval(rule_1d(rule), static_cast<std::size_t>(q.i)),
                     tributary_interval(rule_1d(rule), static_cast<std::size_t>(q.j))});
    jump_.push_back(jump(q.xi, q.eta));
  }
  const Mesh& mesh = upper.mesh();
  for (int e = 0; e < element_count_; ++e) {
    const ElementCoordinates xy = mesh.element_coordinates(e);
    for (const Point& q : rule_) {
      position_.push_back(mesh.map(e, q.xi, q.eta));
      area_.push_back(q.weight * point_kinematics(xy, q.xi, q.eta).detJ);
    }
  }
}

// (DL1): the rows δ_s1, δ_s2, δ_n; columns 0–44 the upper element's DOFs, 45–89 the lower one's.
JumpOperator CohesiveInterface::jump(double xi, double eta) const {
  const Q9Shape s = q9_shape(xi, eta);
  JumpOperator J = JumpOperator::Zero();
  for (int a = 0; a < 9; ++a) {
    const double N = s.N(a);
    const int up = 5 * a;
    const int lo = q9_dofs + 5 * a;
    J(0, up + 0) = -N;
    J(0, up + 3) = -half_upper_ * N;
    J(0, lo + 0) = N;
    J(0, lo + 3) = -half_lower_ * N;
    J(1, up + 1) = -N;
    J(1, up + 4) = -half_upper_ * N;
    J(1, lo + 1) = N;
    J(1, lo + 4) = -half_lower_ * N;
    J(2, up + 2) = -N;
    J(2, lo + 2) = N;
  }
  return J;
}

int CohesiveInterface::equation(int e, int i) const {
  if (i < q9_dofs) {
    const int eq = upper_.element_equations(e)[static_cast<std::size_t>(i)];
    return eq < 0 ? -1 : upper_offset_ + eq;
  }
  const int eq = lower_.element_equations(e)[static_cast<std::size_t>(i - q9_dofs)];
  return eq < 0 ? -1 : lower_offset_ + eq;
}

Eigen::Matrix<double, 2 * q9_dofs, 1> CohesiveInterface::element_dofs(int e, const Eigen::VectorXd& u) const {
  Eigen::Matrix<double, 2 * q9_dofs, 1> ue;
  for (int i = 0; i < 2 * q9_dofs; ++i) {
    const int eq = equation(e, i);
    ue(i) = eq >= 0 ? u(eq) : 0.0;
  }
  return ue;
}

Eigen::Vector3d CohesiveInterface::separation(int p, const Eigen::VectorXd& u) const {
  const int n = points_per_element();
  return jump_[static_cast<std::size_t>(p % n)] * element_dofs(p / n, u);
}

CohesiveEvaluation CohesiveInterface::assemble(const Eigen::VectorXd& u,
                                               std::span<const CohesiveState> committed, Eigen::VectorXd& f,
                                               std::vector<Eigen::Triplet<double>>* tangent,
                                               CohesiveDamage damage) const {
  CohesiveEvaluation out;
  out.trial.resize(committed.size());
  const int n = points_per_element();
  for (int e = 0; e < element_count_; ++e) {
    const auto ue = element_dofs(e, u);
    Eigen::Matrix<double, 2 * q9_dofs, 1> fe = Eigen::Matrix<double, 2 * q9_dofs, 1>::Zero();
    Eigen::Matrix<double, 2 * q9_dofs, 2 * q9_dofs> Ke =
        Eigen::Matrix<double, 2 * q9_dofs, 2 * q9_dofs>::Zero();
    for (int q = 0; q < n; ++q) {
      const std::size_t p =
          static_cast<std::size_t>(e) * static_cast<std::size_t>(n) + static_cast<std::size_t>(q);
      const JumpOperator& J = jump_[static_cast<std::size_t>(q)];
      const CohesiveResponse r = point_response(law_, committed[p], J * ue, damage, loading_band_);
      out.trial[p] = r.state;
      out.dissipated += area_[p] * r.dissipated_energy;
      fe.noalias() += area_[p] * (J.transpose() * r.traction);
      if (tangent) Ke.noalias() += area_[p] * (J.transpose() * r.tangent * J);
    }
    for (int i = 0; i < 2 * q9_dofs; ++i) {
      const int ei = equation(e, i);
      if (ei < 0) continue;
      f(ei) += fe(i);
      if (!tangent) continue;
      for (int j = 0; j < 2 * q9_dofs; ++j) {
        const int ej = equation(e, j);
        if (ej >= 0 && Ke(i, j) != 0.0) tangent->emplace_back(ei, ej, Ke(i, j));
      }
    }
  }
  return out;
}

double CohesiveInterface::stored_energy(const Eigen::VectorXd& u,
                                        std::span<const CohesiveState> states) const {
  double energy = 0.0;
  for (int p = 0; p < point_count(); ++p)
    energy += area_[static_cast<std::size_t>(p)] *
              law_.stored_energy(states[static_cast<std::size_t>(p)], separation(p, u));
  return energy;
}

std::array<Eigen::Vector2d, 4> CohesiveInterface::point_cell(int p) const {
  const int e = p / points_per_element();
  const Point& q = rule_[static_cast<std::size_t>(p % points_per_element())];
  const Mesh& mesh = upper_.mesh();
  const auto [xi0, xi1] = q.xi_range;
  const auto [eta0, eta1] = q.eta_range;
  return {mesh.map(e, xi0, eta0), mesh.map(e, xi1, eta0), mesh.map(e, xi1, eta1), mesh.map(e, xi0, eta1)};
}

double CohesiveInterface::damaged_area(std::span<const CohesiveState> states, double threshold) const {
  double area = 0.0;
  for (std::size_t p = 0; p < states.size(); ++p)
    if (states[p].damage >= threshold) area += area_[p];
  return area;
}

} // namespace plyimpact
