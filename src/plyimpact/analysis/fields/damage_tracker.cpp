#include "plyimpact/analysis/fields/damage_tracker.hpp"

#include "plyimpact/fem/quadrature.hpp"

#include <cmath>
#include <limits>

#include <algorithm>
#include <map>
#include <stdexcept>
#include <tuple>

namespace plyimpact {

namespace {

/// What a proof keeps in hand against the rounding of its sums (indices are of order 1–10).
constexpr double rounding_guard = 1e-12;

/// Stress points per element: the 3×3 Gauss points of PlateElement::stress_points().
constexpr Eigen::Index stress_points = 9;
static_assert(gauss3x3.size() == stress_points);

/// Criteria evaluated at the faces of the plies (all but Choi–Chang's, which use the ply averages).
bool on_faces(Criterion c) {
  return c != Criterion::choi_chang_matrix && c != Criterion::choi_chang_delamination;
}

} // namespace

std::vector<Criterion> parse_criteria(const std::vector<std::string>& names) {
  std::vector<Criterion> out;
  for (const auto& n : names) {
    const auto c = parse_criterion(n);
    if (!c) throw std::invalid_argument("unknown failure criterion '" + n + "'");
    out.push_back(*c);
  }
  return out;
}

DamageTracker::SectionOperators DamageTracker::section_operators(const Laminate& lam) {
  using StressOperator = Eigen::Matrix<double, 5, 8>; // (σ11, σ22, τ12, τ13, τ23) from (ε0, κ, γ)
  SectionOperators o;
  o.laminate = &lam;
  o.plies = lam.ply_count();
  o.A_average.resize(5 * static_cast<Eigen::Index>(o.plies), 8);
  o.A_top.resize(o.A_average.rows(), 8);
  o.A_bottom.resize(o.A_average.rows(), 8);
  for (std::size_t k = 0; k < o.plies; ++k) {
    const auto op = [&](double z) {
      StressOperator A;
      for (int c = 0; c < 8; ++c) {
        Eigen::Matrix<double, 8, 1> unit = Eigen::Matrix<double, 8, 1>::Zero();
        unit(c) = 1.0;
        const PlateAxesStress ps{lam.Qbar(k) * (unit.head<3>() + z * unit.segment<3>(3)),
                                 lam.Qbar_shear(k) * unit.tail<2>()};
        const PlyStress m = to_material_axes(ps, lam.plies()[k].angle_deg);
        A.col(c) << m.s11, m.s22, m.t12, m.t13, m.t23;
      }
      return A;
    };
    const auto row = 5 * static_cast<Eigen::Index>(k);
    o.A_average.middleRows<5>(row) = op(0.5 * (lam.z_top(k) + lam.z_bottom(k)));
    o.A_top.middleRows<5>(row) = op(lam.z_top(k));
    o.A_bottom.middleRows<5>(row) = op(lam.z_bottom(k));
  }
  for (std::size_t k = 0; k < o.plies; ++k) {
    const auto row = 5 * static_cast<Eigen::Index>(k);
    o.average_bending.emplace_back(o.A_average.block<5, 5>(row, 3));
    Eigen::Matrix<double, 3, 5> transverse;
    transverse << o.A_average.block<1, 5>(row + 1, 3), o.A_average.block<1, 5>(row + 3, 3),
        o.A_average.block<1, 5>(row + 4, 3);
    o.transverse_bending.push_back(transverse);
    o.top_bending.emplace_back(o.A_top.block<5, 5>(row, 3));
    o.bottom_bending.emplace_back(o.A_bottom.block<5, 5>(row, 3));
  }
  return o;
}

Eigen::Matrix<double, 5, 1> DamageTracker::layer_bound(const SectionOperators& sec, std::size_t k,
                                                       bool interface) {
  const auto inv = [](const std::optional<double>& v) { return v ? 1.0 / *v : 0.0; };
  const auto inverse_strength = [&](std::size_t ply) {
    const Strengths& st = sec.laminate->material_of(ply).strength;
    return std::max({inv(st.Yt), inv(st.Yc), inv(st.S23)});
  };
  Eigen::Matrix<double, 5, 1> bound;
  for (int j = 0; j < 5; ++j) {
    const double nk = sec.transverse_bending[k].col(j).norm();
    if (!interface) {
      bound(j) = inverse_strength(k) * nk;
      continue;
    }
    const Strengths& s0 = sec.laminate->material_of(k).strength;
    const Strengths& s1 = sec.laminate->material_of(k + 1).strength;
    const double da = 0.5 * (s0.Da.value_or(0.0) + s1.Da.value_or(0.0));
    const double n1 = sec.transverse_bending[k + 1].col(j).norm();
    bound(j) =
        std::sqrt(da) * std::max(inverse_strength(k), inverse_strength(k + 1)) * std::sqrt(nk * nk + n1 * n1);
  }
  return bound;
}

DamageTracker::DamageTracker(const DiscretePlate& model, std::vector<Criterion> criteria,
                             DamageOptions options)
    : model_(model), criteria_(std::move(criteria)), options_(options) {
  if (options_.every < 1) throw std::invalid_argument("damage: evaluation interval must be at least 1 step");
  track_cracks_for_delamination_ =
      std::find(criteria_.begin(), criteria_.end(), Criterion::choi_chang_delamination) != criteria_.end();
  for (const Laminate& lam : model.laminates()) {
    sections_.push_back(section_operators(lam));
    layers_ = std::max(layers_, lam.ply_count());
  }
  const Mesh& mesh = model.mesh();
  uniform_ = mesh.shape_class_count() == 1 && model.single_section();
  const auto rule = PlateElement::stress_points();
  // The strain–displacement operators of elements of one shape are equal: one set per shape class.
  for (int c = 0; c < mesh.shape_class_count(); ++c) {
    const ElementCoordinates xy = mesh.element_coordinates(mesh.representative(c));
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        const QuadraturePoint& q = rule[gauss3x3_index(i, j)];
        B_.push_back(model.element().strain_operator(xy, q.xi, q.eta));
      }
  }
  for (int e = 0; e < mesh.element_count(); ++e) {
    const ElementCoordinates xy = mesh.element_coordinates(e);
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        const QuadraturePoint& q = rule[gauss3x3_index(i, j)];
        const PointKinematics k = point_kinematics(xy, q.xi, q.eta);
        const Eigen::Vector2d p = xy.transpose() * k.shape.N;
        points_.push_back({e, i, j, p.x(), p.y(), q.weight * k.detJ});
      }
  }
  needs_faces_ = std::any_of(criteria_.begin(), criteria_.end(), on_faces);
  const auto n_points = static_cast<Eigen::Index>(points_.size());
  const auto n_elements = static_cast<Eigen::Index>(mesh.element_count());
  U_.resize(q9_dofs, n_elements);
  local_strains_.resize(8, n_elements);
  E_.resize(8, n_points);
  for (const StrainOperator& B : B_) {
    Eigen::Matrix<double, 5, 27> Bb;
    for (int a = 0; a < 9; ++a)
      Bb.middleCols<3>(3 * a) = B.block<5, 3>(3, 5 * a + 2);
    B_bending_.push_back(Bb);
  }
  for (int n = 0; n < mesh.node_count(); ++n)
    for (int d = 0; d < 2; ++d)
      if (const int eq = model.dofs().equation(n, d); eq >= 0) inplane_equations_.push_back(eq);
  S_average_.setZero(5 * static_cast<Eigen::Index>(layers_), n_points);
  // ‖T e‖ ≤ Σ_j ‖T(:, j)‖ |e_j| with T_k the (σ̄22, τ̄13, τ̄23) rows of ply k and e = (κ, γ), so
  // e_M ≤ Σ_j [max(1/Yt, 1/Yc, 1/S23)_k ‖T_k(:, j)‖] |e_j|, and likewise for e_D with √Da and the two
  // plies of an interface (layer_bound); choi_chang_bound_ takes the largest over the layers of every
  // laminate of the plate. A point whose bound stays below both 1 and the peak index so far can
  // neither fail nor raise the peak. Matrix cracks gate (2.43): with delamination tracked, the
  // cracks are one more bound slot (no new crack while its bound stays below 1).
  // A face criterion's gauge branches grow by at most their column norms times |Δe| (W·A, per face
  // and ply); the slot takes the largest over them.
  bound_slots_ = criteria_.size() + (track_cracks_for_delamination_ ? 1 : 0);
  build_gauges();
  for (std::size_t c = 0; c < bound_slots_; ++c) {
    if (c < criteria_.size() && on_faces(criteria_[c])) {
      Eigen::Matrix<double, 5, 1> bound = Eigen::Matrix<double, 5, 1>::Zero();
      for (const auto& terms : gauge_terms_[c])
        for (const GaugeTerm& term : terms)
          bound = bound.cwiseMax(term.branch.W.colwise().norm().transpose());
      slot_bound_.push_back(bound);
      continue;
    }
    const bool interfaces = c < criteria_.size() && criteria_[c] == Criterion::choi_chang_delamination;
    Eigen::Matrix<double, 5, 1> bound = Eigen::Matrix<double, 5, 1>::Zero();
    for (std::size_t s = 0; s < sections_.size(); ++s) {
      const SectionOperators& sec = sections_[s];
      for (std::size_t k = 0; k < sec.plies - (interfaces ? 1 : 0); ++k) {
        bound = bound.cwiseMax(layer_bound(sec, k, interfaces));
      }
    }
    slot_bound_.push_back(bound);
  }
  // |Δe_j| ≤ Σ_a |B(j, w_a)| max|Δw| + Σ_a (|B(j, θx_a)| + |B(j, θy_a)|) max|Δθ|, so the bound β·|e|
  // grows by at most (β·R_w) max|Δw| + (β·R_θ) max|Δθ| (see lipschitz_).
  for (const auto& Bb : B_bending_) {
    Eigen::Matrix<double, 5, 1> rw = Eigen::Matrix<double, 5, 1>::Zero(), rr = rw;
    for (int a = 0; a < 9; ++a) {
      rw += Bb.col(3 * a).cwiseAbs();
      rr += Bb.col(3 * a + 1).cwiseAbs() + Bb.col(3 * a + 2).cwiseAbs();
    }
    for (const auto& bound : slot_bound_)
      lipschitz_.push_back({bound.dot(rw), bound.dot(rr)});
  }
  path_w_.assign(static_cast<std::size_t>(n_elements), 0.0);
  path_rotation_.assign(path_w_.size(), 0.0);
  proof_path_w_.assign(points_.size(), 0.0);
  proof_path_rotation_.assign(points_.size(), 0.0);
  margin_.assign(bound_slots_ * points_.size(), 0.0);
  proof_margin_.assign(margin_.size(), -1.0);
  proof_strains_.assign(points_.size(), Eigen::Matrix<double, 5, 1>::Zero());
  point_largest_.assign(bound_slots_, 0.0);
  point_unfailed_.assign(bound_slots_, 0.0);
  if (needs_faces_) {
    S_top_.setZero(S_average_.rows(), n_points);
    S_bottom_.setZero(S_average_.rows(), n_points);
  }
  averaged_.resize(layers_);
  matrix_.resize(layers_);
  needs_matrix_ =
      track_cracks_for_delamination_ ||
      std::find(criteria_.begin(), criteria_.end(), Criterion::choi_chang_matrix) != criteria_.end();
  failed_.assign(criteria_.size() * layers_ * points_.size(), 0);
  cracked_.assign(layers_ * points_.size(), 0);
  area_.assign(criteria_.size() * layers_, 0.0);
  peak_.assign(criteria_.size(), 0.0);
  for (const Criterion c : criteria_)
    for (const Laminate& lam : model.laminates())
      for (std::size_t k = 0; k < lam.ply_count(); ++k)
        for (const StrengthId s : required_strengths(c))
          if (!strength_value(lam.material_of(k).strength, s))
            throw std::invalid_argument("criterion " + std::string(to_string(c)) + " needs " +
                                        std::string(to_string(s)) + " for material '" +
                                        lam.material_of(k).name + "'");
}

void DamageTracker::observe(long step, double t, double force, const Eigen::VectorXd& u) {
  if (step % options_.every != 0) return;
  observed_points_ += static_cast<long>(points_.size());
  // Under a transverse load a laminate with B = 0 and I1 = 0 never moves in-plane: then only the
  // bending DOFs (w, θx, θy) and strains (κ, γ) enter, 27 of 45 columns and 5 of 8 rows.
  bool bending_only = true;
  for (std::size_t i = 0; i < inplane_equations_.size() && bending_only; ++i)
    bending_only = u(inplane_equations_[i]) == 0.0;
  if (bending_only && options_.skip_proven_points && (!needs_faces_ || gauged_)) {
    observe_skipping_bending(u, t, force);
    return;
  }
  proofs_valid_ = false;
  gather_all(u);
  if (bending_only)
    observe_bending(t, force);
  else
    observe_general(t, force);
}

void DamageTracker::gather_all(const Eigen::VectorXd& u) {
  // Batched: element DOFs U (45 × elements) → generalized strains E (8 × points) → ply stresses
  // S = A E (5·plies × points), as dense matrix products; then the criteria point by point.
  for (int e = 0; e < model_.mesh().element_count(); ++e)
    U_.col(e) = gather(u, model_.element_equations(e));
}

Eigen::Matrix<double, 27, 1> DamageTracker::bending_dofs(const Eigen::VectorXd& u, int e) const {
  const ElementEquations& eq = model_.element_equations(e);
  Eigen::Matrix<double, 27, 1> ub;
  for (std::size_t a = 0; a < 9; ++a)
    for (std::size_t d = 0; d < 3; ++d) {
      const int i = eq[5 * a + 2 + d];
      ub(static_cast<Eigen::Index>(3 * a + d)) = i >= 0 ? u(i) : 0.0;
    }
  return ub;
}

void DamageTracker::advance_paths(const Eigen::VectorXd& u) {
  // Each element's path: the largest change of w and of θx, θy over its nodes since the last
  // observation, summed over observations.
  for (std::size_t e = 0; e < path_w_.size(); ++e) {
    const ElementEquations& eq = model_.element_equations(static_cast<int>(e));
    double dw = 0.0, dr = 0.0;
    for (std::size_t a = 0; a < 9; ++a) {
      const auto change = [&](std::size_t d) {
        const int i = eq[5 * a + d];
        return i >= 0 ? std::abs(u(i) - previous_u_(i)) : 0.0;
      };
      dw = std::max(dw, change(2));
      dr = std::max({dr, change(3), change(4)});
    }
    path_w_[e] += dw;
    path_rotation_[e] += dr;
  }
  previous_u_ = u;
}

bool DamageTracker::still_proven(std::size_t g, std::size_t e, std::size_t shape) const {
  const double dw = path_w_[e] - proof_path_w_[g], dr = path_rotation_[e] - proof_path_rotation_[g];
  const auto points_per_element = static_cast<std::size_t>(stress_points);
  const std::size_t base = (points_per_element * shape + g % points_per_element) * bound_slots_;
  for (std::size_t c = 0; c < bound_slots_; ++c) {
    const PointLipschitz& L = lipschitz_[base + c];
    // rounding_guard covers the rounding of the sums (a NaN state fails the test: evaluated).
    if (!(L.w * dw + L.rotation * dr < margin_[c * points_.size() + g] - rounding_guard)) return false;
  }
  return true;
}

void DamageTracker::refresh_proof(std::size_t g, std::size_t e, const Eigen::Matrix<double, 5, 1>& strains) {
  // From the bounds at this state: the largest over the layers below min(1, peak) (no new failure,
  // no new peak), the crack slot below 1 (no new crack).
  const Eigen::Matrix<double, 5, 1> magnitude = strains.cwiseAbs();
  for (std::size_t c = 0; c < bound_slots_; ++c) {
    const double limit = c == criteria_.size() ? 1.0 : std::min(1.0, peak_[c]);
    margin_[c * points_.size() + g] = headroom(c, limit) - slot_bound_[c].dot(magnitude);
  }
  keep_proof(g, e, strains);
}

void DamageTracker::keep_proof(std::size_t g, std::size_t e, const Eigen::Matrix<double, 5, 1>& strains) {
  proof_path_w_[g] = path_w_[e];
  proof_path_rotation_[g] = path_rotation_[e];
  proof_strains_[g] = strains;
  for (std::size_t c = 0; c < bound_slots_; ++c)
    proof_margin_[c * points_.size() + g] = margin_[c * points_.size() + g];
}

bool DamageTracker::proven_again(std::size_t g, std::size_t e, const Eigen::Matrix<double, 5, 1>& strains) {
  // The path bound has run out, but the strains themselves may have moved less: every bound and
  // index grows by at most β·|e − e_proof| from the state of the last proof, so what is left of
  // that proof's margins holds from here, with the element's path counted from now.
  const Eigen::Matrix<double, 5, 1> change = (strains - proof_strains_[g]).cwiseAbs();
  for (std::size_t c = 0; c < bound_slots_; ++c) {
    const std::size_t i = c * points_.size() + g;
    margin_[i] = proof_margin_[i] - slot_bound_[c].dot(change);
    if (!(margin_[i] > rounding_guard)) return false;
  }
  proof_path_w_[g] = path_w_[e];
  proof_path_rotation_[g] = path_rotation_[e];
  return true;
}

void DamageTracker::refresh_proof_exactly(std::size_t g, std::size_t e,
                                          const Eigen::Matrix<double, 5, 1>& strains) {
  // The indices are Lipschitz in (κ, γ) with the constants of their bounds (each is a weighted
  // Euclidean norm of stresses linear in (κ, γ)), so the margins can start from the exact indices
  // just evaluated (evaluate_point keeps their largest, and the largest over the layers that can
  // still fail). Interfaces that (2.43) did not evaluate (no adjacent crack) stay unevaluated while
  // the crack slot's margin holds, and do not count.
  for (std::size_t c = 0; c < bound_slots_; ++c) {
    if (c < criteria_.size() && on_faces(criteria_[c])) {
      margin_[c * points_.size() + g] = gauge_margin(c, g, strains);
      continue;
    }
    double margin = 1.0 - point_unfailed_[c];
    if (c < criteria_.size()) margin = std::min(margin, peak_[c] - point_largest_[c]);
    margin_[c * points_.size() + g] = margin;
  }
  keep_proof(g, e, strains);
}

bool DamageTracker::proven_now(std::size_t g) const {
  for (std::size_t c = 0; c < bound_slots_; ++c)
    if (!(margin_[c * points_.size() + g] > 0.0)) return false;
  return true;
}

void DamageTracker::observe_skipping_bending(const Eigen::VectorXd& u, double t, double force) {
  if (proofs_valid_) {
    advance_paths(u);
  } else {
    previous_u_ = u;
    std::fill(margin_.begin(), margin_.end(), -1.0); // nothing proven: evaluate every point
    std::fill(proof_margin_.begin(), proof_margin_.end(), -1.0);
    proofs_valid_ = true;
  }
  const Mesh& mesh = model_.mesh();
  for (int e = 0; e < mesh.element_count(); ++e) {
    const auto ue = static_cast<std::size_t>(e);
    const auto first = ue * static_cast<std::size_t>(stress_points);
    const auto shape = static_cast<std::size_t>(mesh.shape_class(e));
    bool all_proven = true;
    for (std::size_t l = 0; l < static_cast<std::size_t>(stress_points) && all_proven; ++l)
      all_proven = still_proven(first + l, ue, shape);
    if (all_proven) continue;
    const Eigen::Matrix<double, 27, 1> ub = bending_dofs(u, e);
    const auto& sec = sections_[static_cast<std::size_t>(model_.section_index(e))];
    for (std::size_t l = 0; l < static_cast<std::size_t>(stress_points); ++l) {
      const std::size_t g = first + l;
      if (still_proven(g, ue, shape)) continue;
      const Eigen::Matrix<double, 5, 1> eb =
          B_bending_[static_cast<std::size_t>(stress_points) * shape + l] * ub;
      if (proven_again(g, ue, eb)) continue;
      refresh_proof(g, ue, eb);
      if (!proven_now(g)) { // not proven by the bounds at this state: evaluate the plies
        point_stresses_bending(g, sec, eb);
        evaluate_point(g, t, force);
        refresh_proof_exactly(g, ue, eb);
      }
    }
  }
}

void DamageTracker::point_stresses_bending(std::size_t g, const SectionOperators& sec,
                                           const Eigen::Matrix<double, 5, 1>& eb) {
  const auto col = static_cast<Eigen::Index>(g);
  for (std::size_t k = 0; k < sec.plies; ++k) {
    const auto row = 5 * static_cast<Eigen::Index>(k);
    if (needs_faces_) {
      S_average_.block<5, 1>(row, col).noalias() = sec.average_bending[k] * eb;
      S_top_.block<5, 1>(row, col).noalias() = sec.top_bending[k] * eb;
      S_bottom_.block<5, 1>(row, col).noalias() = sec.bottom_bending[k] * eb;
      continue;
    }
    // Choi–Chang alone reads the averages' σ̄22, τ̄13, τ̄23.
    const Eigen::Matrix<double, 3, 1> v = sec.transverse_bending[k] * eb;
    S_average_(row + 1, col) = v(0);
    S_average_(row + 3, col) = v(1);
    S_average_(row + 4, col) = v(2);
  }
}

void DamageTracker::build_gauges() {
  // Every face criterion's gauge branches on the top and bottom face of every ply, as maps of the
  // bending strains (κ, γ); a criterion without a gauge on some ply leaves the skipping off.
  gauged_ = true;
  gauge_terms_.assign(criteria_.size(), {});
  gauge_largest_h_.assign(criteria_.size(), -1.0);
  gauge_linear_.assign(criteria_.size(), 0);
  for (std::size_t c = 0; c < criteria_.size(); ++c) {
    if (!on_faces(criteria_[c])) continue;
    for (const SectionOperators& sec : sections_) {
      std::vector<GaugeTerm>& terms = gauge_terms_[c].emplace_back();
      for (std::size_t k = 0; k < sec.plies; ++k) {
        const auto gauge =
            criterion_gauge(criteria_[c], sec.laminate->material_of(k), options_.criterion_options);
        if (!gauge) {
          gauged_ = false;
          continue;
        }
        for (const GaugeBranch& b : *gauge) {
          if (b.quadratic)
            gauge_largest_h_[c] = std::max(gauge_largest_h_[c], b.h.norm());
          else
            gauge_linear_[c] = 1;
          for (const Eigen::Matrix<double, 5, 5>* A : {&sec.top_bending[k], &sec.bottom_bending[k]}) {
            GaugeTerm term{k, b};
            term.branch.W = b.W * *A;
            terms.push_back(term);
          }
        }
      }
    }
  }
}

double DamageTracker::headroom(std::size_t c, double limit) const {
  // What β·|e| may reach at a state before the slot's bound could reach `limit`: the limit itself for
  // the Choi–Chang indices (index ≤ β·|e|); for a gauge, N ≤ ‖h‖ + β·|e| stays below the branch's
  // threshold √(limit + ‖h‖²) (quadratic; least room at the largest ‖h‖) or limit (linear).
  if (c >= criteria_.size() || !on_faces(criteria_[c])) return limit;
  double room = gauge_linear_[c] != 0 ? limit : std::numeric_limits<double>::infinity();
  if (const double H = gauge_largest_h_[c]; H >= 0.0)
    room = std::min(room, std::sqrt(std::max(limit + H * H, 0.0)) - H);
  return room;
}

double DamageTracker::gauge_margin(std::size_t c, std::size_t g,
                                   const Eigen::Matrix<double, 5, 1>& eb) const {
  // Exact at this state: how far every branch's norm is from its threshold, with the limit 1 or the
  // peak for a ply that has not failed, the peak for one that has.
  const auto section = static_cast<std::size_t>(model_.section_index(points_[g].element));
  const double open_limit = std::min(1.0, peak_[c]);
  double margin = std::numeric_limits<double>::infinity();
  for (const GaugeTerm& term : gauge_terms_[c][section]) {
    const double limit = failed_[slot(c, term.ply, g)] != 0 ? peak_[c] : open_limit;
    margin = std::min(margin, term.branch.threshold(limit) - term.branch.norm(eb));
  }
  return margin;
}

void DamageTracker::observe_bending(double t, double force) {
  // Every point of a bending-only state (face criteria without a gauge, or no skipping): fixed-size products,
  // point by point, 5×27 for the strains, then the stresses the criteria read (point_stresses_bending).
  Eigen::Matrix<double, 27, 1> ub;
  const Mesh& mesh = model_.mesh();
  for (Eigen::Index e = 0; e < U_.cols(); ++e) {
    for (Eigen::Index a = 0; a < 9; ++a)
      ub.segment<3>(3 * a) = U_.block<3, 1>(5 * a + 2, e);
    const auto& sec = sections_[static_cast<std::size_t>(model_.section_index(static_cast<int>(e)))];
    const auto shape = static_cast<std::size_t>(mesh.shape_class(static_cast<int>(e)));
    for (Eigen::Index l = 0; l < stress_points; ++l) {
      const Eigen::Matrix<double, 5, 1> eb =
          B_bending_[static_cast<std::size_t>(stress_points) * shape + static_cast<std::size_t>(l)] * ub;
      const auto g = static_cast<std::size_t>(e * stress_points + l);
      point_stresses_bending(g, sec, eb);
      evaluate_point(g, t, force);
    }
  }
}

void DamageTracker::observe_general(double t, double force) {
  if (uniform_) {
    for (Eigen::Index l = 0; l < stress_points; ++l) {
      local_strains_.noalias() = B_[static_cast<std::size_t>(l)].lazyProduct(U_);
      for (Eigen::Index e = 0; e < U_.cols(); ++e)
        E_.col(e * stress_points + l) = local_strains_.col(e);
    }
    const SectionOperators& sec = sections_.front();
    S_average_.noalias() = sec.A_average.lazyProduct(E_);
    if (needs_faces_) {
      S_top_.noalias() = sec.A_top.lazyProduct(E_);
      S_bottom_.noalias() = sec.A_bottom.lazyProduct(E_);
    }
  } else {
    for (Eigen::Index g = 0; g < E_.cols(); ++g) {
      const auto e = static_cast<int>(g / stress_points);
      E_.col(g).noalias() = strain_operator(e, static_cast<int>(g % stress_points)) * U_.col(e);
      const SectionOperators& sec = section_at(static_cast<std::size_t>(g));
      const Eigen::Index rows = sec.A_average.rows();
      S_average_.col(g).head(rows).noalias() = sec.A_average * E_.col(g);
      if (needs_faces_) {
        S_top_.col(g).head(rows).noalias() = sec.A_top * E_.col(g);
        S_bottom_.col(g).head(rows).noalias() = sec.A_bottom * E_.col(g);
      }
    }
  }
  for (std::size_t g = 0; g < points_.size(); ++g)
    evaluate_point(g, t, force);
}

namespace {

PlyStress as_ply_stress(const Eigen::Matrix<double, 5, 1>& v) {
  PlyStress s;
  s.s11 = v(0);
  s.s22 = v(1);
  s.t12 = v(2);
  s.t13 = v(3);
  s.t23 = v(4);
  return s;
}

} // namespace

void DamageTracker::evaluate_point(std::size_t g, double t, double force) {
  ++evaluated_points_;
  const SectionOperators& sec = section_at(g);
  const Laminate& lam = *sec.laminate;
  const std::size_t plies = sec.plies;
  const GaussPoint& p = points_[g];
  // Ply-averaged stresses in material axes (what Choi–Chang use), and the faces of each ply for the
  // point-wise criteria (their indices are convex along the linear through-ply distribution, so the
  // largest value over the ply is at a face).
  std::vector<PlyStress>& avg = averaged_; // reused buffer: no allocation per point
  const auto col = static_cast<Eigen::Index>(g);
  for (std::size_t k = 0; k < plies; ++k)
    avg[k] = as_ply_stress(S_average_.block<5, 1>(5 * static_cast<Eigen::Index>(k), col));
  const auto record = [&](std::size_t c, std::size_t layer, const FailureResult& r, bool interface) {
    peak_[c] = std::max(peak_[c], r.index);
    point_largest_[c] = std::max(point_largest_[c], r.index);
    char& flag = failed_[slot(c, layer, g)];
    if (flag != 0) return;
    if (!r.failed()) {
      point_unfailed_[c] = std::max(point_unfailed_[c], r.index);
      return;
    }
    flag = 1;
    DamageOnset o;
    o.criterion = criteria_[c];
    o.mode = r.mode;
    o.ply = interface ? 0 : static_cast<int>(layer) + 1;
    o.interface = interface ? static_cast<int>(layer) + 1 : 0;
    o.element = p.element + 1;
    o.ipgs = p.i + 1;
    o.jpgs = p.j + 1;
    o.x = p.x;
    o.y = p.y;
    o.time = t;
    o.force = force;
    o.sigma22 = avg[layer].s22;
    o.tau23 = avg[layer].t23;
    o.index = r.index;
    onsets_.push_back(o);
    double& a = area_[c * layers_ + layer];
    a += p.area;
    areas_.push_back({t, criteria_[c], o.ply, o.interface, a});
  };
  std::fill(point_largest_.begin(), point_largest_.end(), 0.0);
  std::fill(point_unfailed_.begin(), point_unfailed_.end(), 0.0);
  // Choi–Chang matrix cracking, once per ply: a criterion of its own and the gate of (2.43).
  std::vector<FailureResult>& matrix = matrix_;
  if (needs_matrix_)
    for (std::size_t k = 0; k < plies; ++k) {
      matrix[k] = choi_chang_matrix_cracking(avg[k], lam.material_of(k).strength);
      if (!track_cracks_for_delamination_) continue;
      char& cracked = cracked_[k * points_.size() + g];
      if (matrix[k].failed())
        cracked = 1;
      else if (cracked == 0)
        point_unfailed_.back() = std::max(point_unfailed_.back(), matrix[k].index);
    }
  for (std::size_t c = 0; c < criteria_.size(); ++c) {
    const Criterion crit = criteria_[c];
    if (crit == Criterion::choi_chang_delamination) {
      for (std::size_t k = 0; k + 1 < plies; ++k) {
        // (2.43) is checked where an adjacent ply has a matrix crack.
        if (cracked_[k * points_.size() + g] == 0 && cracked_[(k + 1) * points_.size() + g] == 0) continue;
        record(c, k,
               choi_chang_delamination(avg[k], lam.material_of(k).strength, avg[k + 1],
                                       lam.material_of(k + 1).strength,
                                       options_.criterion_options.delamination_ply_n),
               true);
      }
      continue;
    }
    for (std::size_t k = 0; k < plies; ++k) {
      if (crit == Criterion::choi_chang_matrix) {
        record(c, k, matrix[k], false);
        continue;
      }
      FailureResult worst{0.0, FailureMode::none, 0.0};
      for (const Eigen::MatrixXd* S : {&S_top_, &S_bottom_}) {
        const PlyStress face = as_ply_stress(S->block<5, 1>(5 * static_cast<Eigen::Index>(k), col));
        const FailureResult r = evaluate(crit, face, lam.material_of(k), options_.criterion_options);
        if (r.index > worst.index) worst = r;
      }
      record(c, k, worst, false);
    }
  }
}

std::vector<DamageOnset> DamageTracker::first_onsets() const {
  std::vector<DamageOnset> first;
  std::map<std::tuple<int, int, int, int>, std::size_t> seen; // (criterion, mode, ply, interface)
  for (const DamageOnset& o : onsets_) {
    const auto key =
        std::make_tuple(static_cast<int>(o.criterion), static_cast<int>(o.mode), o.ply, o.interface);
    const auto it = seen.find(key);
    if (it == seen.end()) {
      seen.emplace(key, first.size());
      first.push_back(o);
    } else if (first[it->second].time == o.time && o.index > first[it->second].index) {
      first[it->second] = o; // same step: the point with the larger index
    }
  }
  return first;
}

double DamageTracker::peak_index(Criterion criterion) const {
  for (std::size_t c = 0; c < criteria_.size(); ++c)
    if (criteria_[c] == criterion) return peak_[c];
  return 0.0;
}

} // namespace plyimpact
