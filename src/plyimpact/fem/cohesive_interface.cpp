#include "plyimpact/fem/cohesive_interface.hpp"

#include "plyimpact/fem/element_loop.hpp"
#include "plyimpact/fem/quadrature.hpp"
#include "plyimpact/fem/shape_functions.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace plyimpact {

namespace {

std::vector<QuadraturePoint> rule_points(CohesiveQuadrature rule) {
  static constexpr auto lobatto3x3 = tensor_product(lobatto3);
  if (rule == CohesiveQuadrature::nodal) return {lobatto3x3.begin(), lobatto3x3.end()};
  return {gauss3x3.begin(), gauss3x3.end()};
}

const QuadratureRule1D<3>& rule_1d(CohesiveQuadrature rule) {
  return rule == CohesiveQuadrature::nodal ? lobatto3 : gauss3;
}

/// The step's traction and tangent at a point whose damage is held (`held`: the law's at the held
/// damage; `held_step_mean`: 2 τ̄ − τ(δ₀) and 2 ∂τ̄/∂δ, DL6); the response's state is not the trial one.
CohesiveResponse held_response(const CohesiveLaw& law, const CohesiveState& committed,
                               const Eigen::Vector3d& delta, CohesiveDamage damage) {
  if (damage == CohesiveDamage::held) return law.at_fixed_damage(committed, delta);
  CohesiveResponse mean = law.step_mean(committed, delta);
  mean.traction = 2.0 * mean.traction - law.at_fixed_damage(committed, committed.separation).traction;
  mean.tangent *= 2.0;
  return mean;
}

/// The law's response at one point of separation `delta` from its committed state, as `damage` says.
CohesiveResponse point_response(const CohesiveLaw& law, const CohesiveState& committed,
                                const Eigen::Vector3d& delta, CohesiveDamage damage, double loading_band) {
  CohesiveResponse r = law.update(committed, delta, damage == CohesiveDamage::evolve ? loading_band : 0.0);
  if (damage != CohesiveDamage::evolve) { // the damage held: only the trial state comes from update
    const CohesiveResponse held = held_response(law, committed, delta, damage);
    r.traction = held.traction;
    r.tangent = held.tangent;
  }
  return r;
}

/// (DL1) for one node pair: columns 0–4 the upper node's (u, v, w, θx, θy), 5–9 the lower node's.
NodeJump jump_of_node_pair(double half_upper, double half_lower) {
  NodeJump L = NodeJump::Zero();
  L(0, 0) = -1.0;
  L(0, 3) = -half_upper;
  L(0, 5) = 1.0;
  L(0, 8) = -half_lower;
  L(1, 1) = -1.0;
  L(1, 4) = -half_upper;
  L(1, 6) = 1.0;
  L(1, 9) = -half_lower;
  L(2, 2) = -1.0;
  L(2, 7) = 1.0;
  return L;
}

/// Index of the node pair (a, b) of an element, 9a + b.
std::size_t node_pair(int a, int b) {
  return 9 * static_cast<std::size_t>(a) + static_cast<std::size_t>(b);
}

/// Index among an element's 90 DOFs of column l (0–9) of node a's NodeJump.
int element_dof(int a, int l) {
  return l < 5 ? 5 * a + l : q9_dofs + 5 * a + (l - 5);
}

} // namespace

CohesiveInterface::CohesiveInterface(const DiscretePlate& upper, const DiscretePlate& lower, int upper_offset,
                                     int lower_offset, CohesiveLaw law, CohesiveQuadrature rule,
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
    const Eigen::Matrix<double, 9, 1> N = q9_shape(q.xi, q.eta).N;
    shape_.push_back(N);
    std::vector<int>& nodes = nodes_.emplace_back();
    for (int a = 0; a < 9; ++a)
      if (N(a) != 0.0) nodes.push_back(a);
    for (int a = 0; a < 9; ++a)
      for (int b = 0; b < 9; ++b)
        coupled_[node_pair(a, b)] |= N(a) * N(b) != 0.0; // Lobatto: a = b only
  }
  node_jump_ = jump_of_node_pair(half_upper_, half_lower_);
  const Mesh& mesh = upper.mesh();
  for (int e = 0; e < element_count_; ++e) {
    const ElementCoordinates xy = mesh.element_coordinates(e);
    for (const Point& q : rule_) {
      position_.push_back(mesh.map(e, q.xi, q.eta));
      area_.push_back(q.weight * point_kinematics(xy, q.xi, q.eta).detJ);
    }
    for (const auto& [plate, offset] : {std::pair{&upper_, upper_offset_}, std::pair{&lower_, lower_offset_}})
      for (const int eq : plate->element_equations(e))
        equations_.push_back(eq < 0 ? -1 : offset + eq);
  }
  index_node_users(mesh);
}

void CohesiveInterface::index_node_users(const Mesh& mesh) {
  node_first_.assign(static_cast<std::size_t>(mesh.node_count()) + 1, 0);
  for (int e = 0; e < element_count_; ++e)
    for (const int n : mesh.element_nodes(e))
      ++node_first_[static_cast<std::size_t>(n) + 1];
  std::partial_sum(node_first_.begin(), node_first_.end(), node_first_.begin());
  node_users_.resize(static_cast<std::size_t>(node_first_.back()));
  std::vector<int> next(node_first_.begin(), node_first_.end() - 1);
  for (int e = 0; e < element_count_; ++e)
    for (int a = 0; a < 9; ++a)
      node_users_[static_cast<std::size_t>(next[static_cast<std::size_t>(mesh.element_nodes(e)[a])]++)] =
          9 * e + a;
  // add_node_forces writes each equation from the one mesh node it belongs to.
  std::vector<int> owner(equations_.empty() ? 0 : static_cast<std::size_t>(std::ranges::max(equations_)) + 1,
                         -1);
  for (int e = 0; e < element_count_; ++e)
    for (int a = 0; a < 9; ++a) {
      const int node = mesh.element_nodes(e)[a];
      for (int l = 0; l < 10; ++l)
        if (const int eq = equation(e, element_dof(a, l)); eq >= 0) {
          int& o = owner[static_cast<std::size_t>(eq)];
          if (o >= 0 && o != node)
            throw std::logic_error("cohesive interface: an equation shared by two mesh nodes");
          o = node;
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

Eigen::Matrix<double, 2 * q9_dofs, 1> CohesiveInterface::element_dofs(int e, const Eigen::VectorXd& u) const {
  Eigen::Matrix<double, 2 * q9_dofs, 1> ue;
  for (int i = 0; i < 2 * q9_dofs; ++i) {
    const int eq = equation(e, i);
    ue(i) = eq >= 0 ? u(eq) : 0.0;
  }
  return ue;
}

Eigen::Vector3d CohesiveInterface::point_separation(int q,
                                                    const Eigen::Matrix<double, 2 * q9_dofs, 1>& ue) const {
  const auto i = static_cast<std::size_t>(q);
  Eigen::Vector3d delta = Eigen::Vector3d::Zero();
  for (const int a : nodes_[i]) {
    Eigen::Matrix<double, 10, 1> pair;
    pair << ue.segment<5>(5 * a), ue.segment<5>(q9_dofs + 5 * a);
    delta += shape_[i](a) * (node_jump_ * pair);
  }
  return delta;
}

Eigen::Vector3d CohesiveInterface::separation(int p, const Eigen::VectorXd& u) const {
  const int n = points_per_element();
  return point_separation(p % n, element_dofs(p / n, u));
}

// (DL2) by node pairs: with J = (N_1 L, …, N_9 L), f_a = Lᵀ Σ_p area_p N_a τ_p and
// K_ab = Lᵀ (Σ_p area_p N_a N_b ∂τ/∂δ_p) L, only for the node pairs that share a point (the diagonal
// under the nodal rule), instead of the 90 × 90 products Jᵀ (∂τ/∂δ) J.
double CohesiveInterface::assemble_into(const Eigen::VectorXd& u, std::span<const CohesiveState> committed,
                                        Eigen::VectorXd& f, std::vector<Eigen::Triplet<double>>* tangent,
                                        CohesiveDamage damage, std::vector<CohesiveState>& trial,
                                        CohesiveWorkspace& work) const {
  trial.resize(committed.size());
  work.point_energy.resize(committed.size());
  work.node_forces.resize(9 * static_cast<std::size_t>(element_count_));
  if (tangent) work.point_tangents.resize(committed.size());
  const int n = points_per_element();
  for_each_element(element_count_, [&](int e) {
    const auto ue = element_dofs(e, u);
    std::array<Eigen::Vector3d, 9> node_traction;
    node_traction.fill(Eigen::Vector3d::Zero());
    for (int q = 0; q < n; ++q) {
      const std::size_t p =
          static_cast<std::size_t>(e) * static_cast<std::size_t>(n) + static_cast<std::size_t>(q);
      const CohesiveResponse r =
          point_response(law_, committed[p], point_separation(q, ue), damage, loading_band_);
      trial[p] = r.state;
      work.point_energy[p] = area_[p] * r.dissipated_energy;
      const Eigen::Matrix<double, 9, 1>& N = shape_[static_cast<std::size_t>(q)];
      const Eigen::Vector3d t = area_[p] * r.traction;
      for (int a = 0; a < 9; ++a)
        if (N(a) != 0.0) node_traction[static_cast<std::size_t>(a)] += N(a) * t;
      if (tangent) work.point_tangents[p] = area_[p] * r.tangent;
    }
    for (int a = 0; a < 9; ++a)
      work.node_forces[9 * static_cast<std::size_t>(e) + static_cast<std::size_t>(a)] =
          node_jump_.transpose() * node_traction[static_cast<std::size_t>(a)];
  });
  add_node_forces(work, f);
  if (tangent) add_tangent(work, *tangent);
  double dissipated = 0.0;
  for (const double d : work.point_energy)
    dissipated += d;
  return dissipated;
}

void CohesiveInterface::add_node_forces(const CohesiveWorkspace& work, Eigen::VectorXd& f) const {
  const auto nodes = static_cast<Eigen::Index>(node_first_.size()) - 1;
  for_each_block(nodes, [&](Eigen::Index first_node, Eigen::Index last_node) {
    const auto first = static_cast<std::size_t>(node_first_[static_cast<std::size_t>(first_node)]);
    const auto last = static_cast<std::size_t>(node_first_[static_cast<std::size_t>(last_node)]);
    for (std::size_t k = first; k < last; ++k) {
      const int user = node_users_[k], e = user / 9, a = user % 9;
      const Eigen::Matrix<double, 10, 1>& fa = work.node_forces[static_cast<std::size_t>(user)];
      for (int l = 0; l < 10; ++l)
        if (const int eq = equation(e, element_dof(a, l)); eq >= 0) f(eq) += fa(l);
    }
  });
}

void CohesiveInterface::add_tangent(const CohesiveWorkspace& work,
                                    std::vector<Eigen::Triplet<double>>& tangent) const {
  const int n = points_per_element();
  std::array<Eigen::Matrix3d, 81> pair_tangent;
  for (int e = 0; e < element_count_; ++e) {
    pair_tangent.fill(Eigen::Matrix3d::Zero());
    for (int q = 0; q < n; ++q) {
      const Eigen::Matrix<double, 9, 1>& N = shape_[static_cast<std::size_t>(q)];
      const Eigen::Matrix3d& T =
          work.point_tangents[static_cast<std::size_t>(e) * static_cast<std::size_t>(n) +
                              static_cast<std::size_t>(q)];
      for (int a = 0; a < 9; ++a)
        for (int b = 0; b < 9; ++b)
          if (N(a) * N(b) != 0.0) pair_tangent[node_pair(a, b)] += (N(a) * N(b)) * T;
    }
    for (int a = 0; a < 9; ++a)
      for (int b = 0; b < 9; ++b)
        if (coupled_[node_pair(a, b)]) add_node_block(e, a, b, pair_tangent[node_pair(a, b)], tangent);
  }
}

void CohesiveInterface::add_node_block(int e, int a, int b, const Eigen::Matrix3d& C,
                                       std::vector<Eigen::Triplet<double>>& tangent) const {
  const Eigen::Matrix<double, 10, 10> K = node_jump_.transpose() * C * node_jump_;
  for (int i = 0; i < 10; ++i) {
    const int ei = equation(e, element_dof(a, i));
    if (ei < 0) continue;
    for (int j = 0; j < 10; ++j) {
      const int ej = equation(e, element_dof(b, j));
      if (ej >= 0 && K(i, j) != 0.0) tangent.emplace_back(ei, ej, K(i, j));
    }
  }
}

void CohesiveInterface::point_tangents(const Eigen::VectorXd& u, std::span<const CohesiveState> committed,
                                       CohesiveDamage damage, std::vector<Eigen::Matrix3d>& out) const {
  out.resize(committed.size());
  const int n = points_per_element();
  for (int e = 0; e < element_count_; ++e) {
    const auto ue = element_dofs(e, u);
    for (int q = 0; q < n; ++q) {
      const std::size_t p =
          static_cast<std::size_t>(e) * static_cast<std::size_t>(n) + static_cast<std::size_t>(q);
      const Eigen::Vector3d delta = point_separation(q, ue);
      // Held damage: the tangent alone, without the trial state's update.
      out[p] =
          area_[p] * (damage == CohesiveDamage::evolve ? law_.update(committed[p], delta, loading_band_)
                                                       : held_response(law_, committed[p], delta, damage))
                         .tangent;
    }
  }
}

void CohesiveInterface::jump_row(int p, int k, std::vector<std::pair<int, double>>& out) const {
  const int n = points_per_element();
  const JumpOperator& J = jump_[static_cast<std::size_t>(p % n)];
  for (int i = 0; i < 2 * q9_dofs; ++i)
    if (const int eq = equation(p / n, i); eq >= 0 && J(k, i) != 0.0) out.emplace_back(eq, J(k, i));
}

double CohesiveInterface::stored_energy(const Eigen::VectorXd& u, std::span<const CohesiveState> states,
                                        CohesiveWorkspace& work) const {
  work.point_energy.resize(states.size());
  const int n = points_per_element();
  for_each_element(element_count_, [&](int e) {
    const auto ue = element_dofs(e, u); // once per element, not per point
    for (int q = 0; q < n; ++q) {
      const std::size_t p =
          static_cast<std::size_t>(e) * static_cast<std::size_t>(n) + static_cast<std::size_t>(q);
      work.point_energy[p] = area_[p] * law_.stored_energy(states[p], point_separation(q, ue));
    }
  });
  double energy = 0.0;
  for (const double w : work.point_energy)
    energy += w;
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
