#pragma once
// The cohesive interface between two neighbouring sub-laminates of a stacked plate (issue 19,
// docs/delamination.md "The stacked plate"). Both sub-laminates are Mindlin plates on the same mesh,
// each on its own mid-plane; the interface lies at the bottom face of the upper one (local z = +h_u/2)
// and the top face of the lower one (local z = −h_l/2). With u(z) = u0 + z θx, v(z) = v0 + z θy
// (plate_element.hpp) the separation of the faces at a point is
//
//   δ_s1 = (u_l − ½h_l θx_l) − (u_u + ½h_u θx_u),
//   δ_s2 = (v_l − ½h_l θy_l) − (v_u + ½h_u θy_u),                       (DL1)
//   δ_n  = w_l − w_u            (> 0 opens: z points in the impact direction),
//
// interpolated with the Q9 shape functions of the element: δ = J (u_e,upper; u_e,lower) with the 3 × 90
// jump operator J. The interface frame is the plate's (x, y, z). The element's force and tangent are
//
//   f_e = Σ_p w_p detJ_p J_pᵀ τ(δ_p),   K_e = Σ_p w_p detJ_p J_pᵀ (∂τ/∂δ)_p J_p,     (DL2)
//
// with τ, ∂τ/∂δ from the bilinear mixed-mode law (laminate/cohesive_law.hpp) at each point.
//
// Integration: the nodal (Lobatto 3 × 3, Newton–Cotes) rule by default — it uncouples the points of
// a stiff penalty and avoids the traction oscillations of Gauss integration (Schellekens & de Borst
// 1993) — or 3 × 3 Gauss.
#include "plyimpact/fem/discrete_plate.hpp"
#include "plyimpact/laminate/cohesive_law.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <functional>
#include <span>
#include <utility>
#include <vector>

namespace plyimpact {

/// The integration rule of the interface elements.
enum class CohesiveQuadrature {
  nodal, ///< Lobatto 3 × 3: the points are the nine nodes (Simpson weights)
  gauss, ///< Gauss 3 × 3
};

using JumpOperator = Eigen::Matrix<double, 3, 2 * q9_dofs>;
/// The separation (DL1) of one node pair of the faces: δ = L (u, v, w, θx, θy)_upper, lower; the jump
/// operator is J = (N_1 L, …, N_9 L) with its columns grouped by node.
using NodeJump = Eigen::Matrix<double, 3, 10>;

/// How an evaluation treats the damage of the interface points.
enum class CohesiveDamage {
  evolve, ///< the law's update from the committed states: the damage grows with the separation
  /// the tractions at the committed damage held fixed (CohesiveLaw::at_fixed_damage), the
  /// trial states' damage and dissipation the law's update (for the next step)
  held,
  /// as held, with the end tractions τ = 2 τ̄ − τ(δ₀) whose trapezoid with the start's, τ(δ₀) at the
  /// held damage, is the step's mean traction τ̄ from the committed separations δ₀ (CohesiveLaw::step_mean,
  /// DL6): the trapezoidal rule then keeps the energy where faces open or close within a step
  held_step_mean,
};

/// Buffers of one interface evaluation on threads (CohesiveInterface::assemble_into, stored_energy), sized
/// on first use and reused from step to step. Scratch, not state: their contents mean nothing between calls.
struct CohesiveWorkspace {
  std::vector<Eigen::Matrix<double, 10, 1>> node_forces; ///< per element node a: Lᵀ Σ_p area_p N_a τ_p (DL2)
  std::vector<double> point_energy;                      ///< per point, its dissipated or stored energy [J]
  std::vector<Eigen::Matrix3d> point_tangents;           ///< per point, area_p ∂τ/∂δ (with a tangent)
};

class CohesiveInterface {
public:
  /// `upper` and `lower` on the same mesh; their free DOFs start at `upper_offset` and `lower_offset`
  /// of the stacked vector. `loading_band`: the tangent's choice at the law's kink (CohesiveLaw::update).
  CohesiveInterface(const DiscretePlate& upper, const DiscretePlate& lower, int upper_offset,
                    int lower_offset, CohesiveLaw law, CohesiveQuadrature rule = CohesiveQuadrature::nodal,
                    double loading_band = 0.0);

  [[nodiscard]] const CohesiveLaw& law() const { return law_; }
  [[nodiscard]] int points_per_element() const { return static_cast<int>(rule_.size()); }
  [[nodiscard]] int point_count() const { return element_count_ * points_per_element(); }
  /// (x, y) of point p (index e · points_per_element() + q).
  [[nodiscard]] const Eigen::Vector2d& point_position(int p) const {
    return position_[static_cast<std::size_t>(p)];
  }
  /// Area the point stands for, w_q detJ [m²].
  [[nodiscard]] double point_area(int p) const { return area_[static_cast<std::size_t>(p)]; }
  /// The part of its element that point p stands for: the image of the parent rectangle of its tributary
  /// intervals (tributary_interval), corners counter-clockwise [m]. Its parent area is the point's weight,
  /// so on an affine element its area is point_area(p); the cells tile the element.
  [[nodiscard]] std::array<Eigen::Vector2d, 4> point_cell(int p) const;

  /// The separation (DL1) at point p for the stacked displacement u.
  [[nodiscard]] Eigen::Vector3d separation(int p, const Eigen::VectorXd& u) const;

  /// Adds the interface force (DL2) at u to f and, unless `tangent` is null, its tangent to `*tangent`
  /// (triplets over the stacked equations), evaluating the law from the `committed` states; writes the
  /// trial states into `trial` (resized; its storage reused from step to step) and returns the energy
  /// dissipated from the committed to the trial states [J]. The buffers are `work`'s: the points on every
  /// thread of the element loops (fem/element_loop.hpp), the forces added node by node in element order,
  /// the dissipation point by point in point order, so the numbers are those of a one-thread loop for any
  /// thread count.
  double assemble_into(const Eigen::VectorXd& u, std::span<const CohesiveState> committed, Eigen::VectorXd& f,
                       std::vector<Eigen::Triplet<double>>* tangent, CohesiveDamage damage,
                       std::vector<CohesiveState>& trial, CohesiveWorkspace& work) const;

  /// Each point's tangent ∂τ/∂δ times its area, as assemble_into adds it (DL2), into `out` (one per point).
  void point_tangents(const Eigen::VectorXd& u, std::span<const CohesiveState> committed,
                      CohesiveDamage damage, std::vector<Eigen::Matrix3d>& out) const;
  /// Appends row k of point p's jump operator over the stacked equations to `out`: δ_k = Σ c u(eq)
  /// over its (eq, c).
  void jump_row(int p, int k, std::vector<std::pair<int, double>>& out) const;

  /// Free energy stored in the interface, Σ_p area_p ψ(δ_p) [J].
  /// `work` holds its buffers: the points on threads, their energies summed in point order.
  [[nodiscard]] double stored_energy(const Eigen::VectorXd& u, std::span<const CohesiveState> states,
                                     CohesiveWorkspace& work) const;
  /// Area of the points whose damage has reached `threshold` [m²] (1: fully delaminated).
  [[nodiscard]] double damaged_area(std::span<const CohesiveState> states, double threshold) const;

private:
  struct Point {
    double xi, eta, weight;
    std::pair<double, double> xi_range, eta_range; ///< the tributary intervals
  };
  [[nodiscard]] JumpOperator jump(double xi, double eta) const;
  [[nodiscard]] Eigen::Matrix<double, 2 * q9_dofs, 1> element_dofs(int e, const Eigen::VectorXd& u) const;
  /// δ at point q of the rule from the element's DOFs: jump_[q] ue (DL1) as Σ_a N_a(q) L u_a over the
  /// nodes whose shape function is not zero there (one node with the nodal rule).
  [[nodiscard]] Eigen::Vector3d point_separation(int q,
                                                 const Eigen::Matrix<double, 2 * q9_dofs, 1>& ue) const;
  /// Stacked equation of element e's DOF i (0–44 upper, 45–89 lower), −1 where constrained.
  [[nodiscard]] int equation(int e, int i) const {
    return equations_[static_cast<std::size_t>(e) * 2 * q9_dofs + static_cast<std::size_t>(i)];
  }
  /// node_first_, node_users_ from the mesh; throws where an equation would belong to two mesh nodes.
  void index_node_users(const Mesh& mesh);
  /// Adds the element nodes' forces work.node_forces to f: mesh node by mesh node on threads, each node's
  /// sum in element order (node_users_), as the one-thread element loop adds them.
  void add_node_forces(const CohesiveWorkspace& work, Eigen::VectorXd& f) const;
  /// Appends the tangent's triplets, element by element from work.point_tangents (DL2 by node pairs).
  void add_tangent(const CohesiveWorkspace& work, std::vector<Eigen::Triplet<double>>& tangent) const;
  /// Adds Lᵀ C L, the block of nodes (a, b) of an element tangent, to `tangent` (DL2 by node pairs).
  void add_node_block(int e, int a, int b, const Eigen::Matrix3d& C,
                      std::vector<Eigen::Triplet<double>>& tangent) const;

  const DiscretePlate& upper_;
  const DiscretePlate& lower_;
  int upper_offset_, lower_offset_;
  double half_upper_, half_lower_;
  CohesiveLaw law_;
  double loading_band_;
  std::vector<Point> rule_;
  int element_count_;
  std::vector<JumpOperator> jump_; ///< per point of the rule (same parent operator for every element)
  std::vector<Eigen::Matrix<double, 9, 1>> shape_; ///< the nodes' shape functions at each point of the rule
  std::vector<std::vector<int>> nodes_;            ///< per point of the rule, the nodes with N_a ≠ 0 there
  std::array<bool, 81> coupled_{};                 ///< nodes a, b share a point: N_a N_b ≠ 0 (index 9a + b)
  NodeJump node_jump_;
  std::vector<int> equations_; ///< per element, its 90 stacked equations (equation())
  /// Per mesh node n, the element nodes 9e + a on it, e ascending: node_users_[node_first_[n] …
  /// node_first_[n + 1]). Every equation belongs to one mesh node, so nodes can be added on threads.
  std::vector<int> node_first_, node_users_;
  std::vector<Eigen::Vector2d> position_;
  std::vector<double> area_;
};

} // namespace plyimpact
