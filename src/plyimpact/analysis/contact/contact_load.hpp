#pragma once
// Where the contact force acts on the plate (SPEC §4). The deflection under the impactor is sampled at
// the impact point, ws = swᵀu, by the shape functions of the element holding it (under a flat-ended
// impactor, by the weights of its pressure: flat_punch()). The force loads the plate with Fc s_load:
//   point            s_load = sw (the thesis; a point force on a Mindlin plate has no converged
//                    answer: w under it is logarithmically singular, docs/validation.md);
//   hertz-pressure   the Hertz pressure p = 3Fc/(2πa²) √(1 − r²/a²) over the contact circle of radius
//                    a = √(R α), integrated exactly against the shape functions of every element the
//                    circle touches (fem/circle_load.hpp), whatever the size of the circle against the
//                    elements and wherever it lies.
//
// The pressure's load vector depends on the indentation. It is tabulated at radii a_j growing
// geometrically from 1 µm (8 % apart; the same radii for every case, so that runs sharing a plate give
// the same numbers in any order), computed when the contact first reaches them, and interpolated linearly
// in a between two entries; so is the plate's response K̄⁻¹ s_load and the contact compliance
// c = swᵀK̄⁻¹ s_load. The contact force and the radius of the step are solved together (no lag).
#include "plyimpact/analysis/contact/condensed_contact.hpp"
#include "plyimpact/analysis/impact/parameters.hpp"
#include "plyimpact/fem/discrete_plate.hpp"
#include "plyimpact/fem/equation_subset.hpp"

#include <deque>
#include <functional>
#include <memory>
#include <vector>

namespace plyimpact {

class ContactLoading {
public:
  /// x = K̄⁻¹ b with the factor the step uses.
  using Solve = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;

  /// Vectors in the numbering of `equations` (a subset of the model's). With `size` larger than the
  /// subset, they are the leading block of vectors of `size` equations, zero beyond: the impacted
  /// sub-laminate of a stacked plate comes first (fem/stacked_plate.hpp).
  ContactLoading(const DiscretePlate& model, const EquationSubset& equations, const Impactor& impactor,
                 ContactLoad kind, int size = 0);

  [[nodiscard]] const Eigen::VectorXd& sampler() const { return sw_; }
  [[nodiscard]] bool distributed() const { return kind_ == ContactLoad::hertz_pressure; }
  /// A flat-ended impactor with the distributed load: one pressure over its end, and the deflection
  /// under it sampled with the same weights (sampler() is that load).
  [[nodiscard]] bool flat_punch() const;

  /// The same contact on a plate with another factor (another time step): the load table is shared with
  /// `other` (its loads are computed once for both), the responses are computed with `solve`.
  ContactLoading(const ContactLoading& other, Solve solve);

  /// The factor changed: responses are recomputed with `solve` when next needed.
  void set_solver(Solve solve);

  /// The contact force and indentation of the step, the plate's deflection being ŵ + c(α) Fc at the
  /// contact point (SPEC §4; c depends on α through the contact radius for the Hertz pressure).
  [[nodiscard]] ContactSolution solve(const CondensedContact& step, double w_hat) const;
  /// u += Fc K̄⁻¹ s_load(α).
  void add_response(double alpha, double force, Eigen::VectorXd& u) const;
  /// s_load(α), the load of a unit contact force.
  [[nodiscard]] Eigen::VectorXd load(double alpha) const;
  /// out = force · s_load(α), the same numbers as force * load(alpha), into a vector sized once.
  void scaled_load(double alpha, double force, Eigen::VectorXd& out) const;
  /// out = force · s_load(α) − f, the numbers of scaled_load followed by out -= f, in one pass over blocks
  /// of entries on the element-loop threads (elementwise_on_threads: the same bits for any thread count).
  void scaled_load_minus(double alpha, double force, const Eigen::VectorXd& f, Eigen::VectorXd& out) const;
  /// s_load(α)ᵀ u, the numbers of load(alpha).dot(u) without forming the vector.
  [[nodiscard]] double load_dot(double alpha, const Eigen::VectorXd& u) const;

private:
  struct Load {
    double radius = 0.0;
    Eigen::VectorXd vector; ///< s_load of a unit force
  };
  struct Response {
    Eigen::VectorXd vector;  ///< K̄⁻¹ s_load (empty until needed)
    double compliance = 0.0; ///< swᵀ K̄⁻¹ s_load
  };
  /// Entry j (built on first use) and j + 1 around the radius of α, and the weight of j + 1.
  struct Bracket {
    std::size_t j = 0;
    double weight = 0.0;
  };
  [[nodiscard]] Bracket bracket(double alpha) const;
  /// Load j, computed on first use (the table is a cache).
  const Load& load_entry(std::size_t j) const;
  /// The plate's response to load j, computed on first use.
  const Response& response_entry(std::size_t j) const;
  [[nodiscard]] double compliance(double alpha) const;
  [[nodiscard]] Eigen::VectorXd pressure_load(double radius) const;
  /// v (subset numbering) padded with zeros to `size_` equations.
  [[nodiscard]] Eigen::VectorXd padded(Eigen::VectorXd v) const;

  const DiscretePlate& model_;
  const EquationSubset& equations_;
  Impactor impactor_;
  ContactLoad kind_;
  int size_;
  Eigen::VectorXd sw_;
  Solve solve_;
  /// radius 0 (= the point load), then 1 µm · 1.08^(j−1); shared by the loadings of one run's time steps
  /// (a deque: references to its entries stay valid as it grows)
  std::shared_ptr<std::deque<Load>> loads_;
  mutable std::deque<Response> responses_; ///< responses_[j] to loads_[j]
};

/// Unit-force contact pressure over the contact circle of radius a centred at (x, y) — Hertz's for the
/// hemisphere, the flat punch's or the cone's (fem/circle_load.hpp) —, as consistent nodal forces on w
/// (model numbering), renormalised to a total of 1 where the circle leaves the plate.
[[nodiscard]] Eigen::VectorXd hertz_pressure_weights(const DiscretePlate& model, double x, double y, double a,
                                                     NoseShape nose = NoseShape::hemisphere);

} // namespace plyimpact
