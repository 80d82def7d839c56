#include "plyimpact/analysis/contact/contact_load.hpp"

#include "plyimpact/analysis/contact/contact_rules.hpp"
#include "plyimpact/fem/circle_load.hpp"
#include "plyimpact/fem/element_loop.hpp"

#include <algorithm>
#include <cmath>

namespace plyimpact {

namespace {

/// Radii of the table grow by this factor: linear interpolation between two then errs by about
/// (0.08)²/8 of the curvature of s_load(a), 1e-5 of the compliance (docs/validation.md).
constexpr double radius_ratio = 1.08;
/// The table's first non-zero radius [m]: far below any contact radius that carries a force worth
/// resolving (below it the load is interpolated toward the point load); 120 entries reach 10 mm.
constexpr double smallest_radius = 1e-6;
/// Quadrature of circle_load: 9e-12 of the force on a circle straddling an edge (tests/fem).
constexpr CircleQuadrature quadrature{16, 8};

} // namespace

ContactLoading::ContactLoading(const DiscretePlate& model, const EquationSubset& equations,
                               const Impactor& impactor, ContactLoad kind, int size)
    : model_(model), equations_(equations), impactor_(impactor), kind_(kind),
      size_(std::max(size, equations.size())),
      sw_(padded(equations.restrict(model.sampler(impactor.x, impactor.y).as_vector(model.size())))) {
  loads_ = std::make_shared<std::deque<Load>>();
  loads_->push_back({0.0, sw_}); // radius 0: the point load
  if (flat_punch()) {
    // One load shape, the punch's pressure over its end; the punch's indentation is measured with the
    // same weights (the plate's deflection under a rigid punch, by reciprocity), which keeps the
    // contact work-conjugate: with the centre's deflection instead, the stiff linear law and the
    // spread load exchange energy and the run blows up.
    loads_->push_back({impactor_.radius, pressure_load(impactor_.radius)});
    sw_ = loads_->back().vector;
    loads_->front().vector = sw_;
  }
}

ContactLoading::ContactLoading(const ContactLoading& other, Solve solve)
    : model_(other.model_), equations_(other.equations_), impactor_(other.impactor_), kind_(other.kind_),
      size_(other.size_), sw_(other.sw_), solve_(std::move(solve)), loads_(other.loads_) {}

bool ContactLoading::flat_punch() const {
  return distributed() && impactor_.nose == NoseShape::flat;
}

void ContactLoading::set_solver(Solve solve) {
  solve_ = std::move(solve);
  responses_.clear();
}

Eigen::VectorXd ContactLoading::padded(Eigen::VectorXd v) const {
  const Eigen::Index n = v.size();
  if (n == size_) return v;
  v.conservativeResize(size_);
  v.tail(size_ - n).setZero();
  return v;
}

Eigen::VectorXd ContactLoading::pressure_load(double radius) const {
  return padded(
      equations_.restrict(hertz_pressure_weights(model_, impactor_.x, impactor_.y, radius, impactor_.nose)));
}

const ContactLoading::Load& ContactLoading::load_entry(std::size_t j) const {
  while (loads_->size() <= j) {
    const double radius =
        loads_->size() == 1 ? smallest_radius : loads_->back().radius * radius_ratio; // geometric from a_1
    loads_->push_back({radius, pressure_load(radius)});
  }
  return (*loads_)[j];
}

const ContactLoading::Response& ContactLoading::response_entry(std::size_t j) const {
  const Load& load = load_entry(j);
  if (responses_.size() <= j) responses_.resize(j + 1);
  Response& r = responses_[j];
  if (r.vector.size() == 0 && solve_) {
    r.vector = solve_(load.vector);
    r.compliance = sw_.dot(r.vector);
  }
  return r;
}

ContactLoading::Bracket ContactLoading::bracket(double alpha) const {
  if (!distributed()) return {0, 0.0};
  if (flat_punch()) return {1, 0.0};
  const double radius = contact_radius(impactor_, alpha);
  if (radius <= 0.0) return {0, 0.0};
  if (radius < smallest_radius) return {0, radius / smallest_radius};
  // a_j = a_1 · ratio^(j−1) ≤ radius < a_{j+1}
  auto j =
      1 + static_cast<std::size_t>(std::floor(std::log(radius / smallest_radius) / std::log(radius_ratio)));
  while (j > 1 && load_entry(j).radius > radius) // round-off of the logarithm
    --j;
  while (load_entry(j + 1).radius <= radius)
    ++j;
  const double a0 = load_entry(j).radius, a1 = load_entry(j + 1).radius;
  return {j, (radius - a0) / (a1 - a0)};
}

double ContactLoading::compliance(double alpha) const {
  const Bracket b = bracket(alpha);
  const double c0 = response_entry(b.j).compliance;
  if (b.weight == 0.0) return c0;
  return (1.0 - b.weight) * c0 + b.weight * response_entry(b.j + 1).compliance;
}

ContactSolution ContactLoading::solve(const CondensedContact& step, double w_hat) const {
  if (!distributed()) return step.solve(w_hat, response_entry(0).compliance);
  // c depends weakly on α (through the radius): a fixed point on c converges in a few passes.
  double c = compliance(step.previous_indentation());
  ContactSolution cs = step.solve(w_hat, c);
  for (int pass = 0; pass < 50; ++pass) {
    const double c_new = compliance(cs.alpha);
    if (std::abs(c_new - c) <= 1e-13 * std::abs(c)) break;
    c = c_new;
    cs = step.solve(w_hat, c);
  }
  return cs;
}

void ContactLoading::add_response(double alpha, double force, Eigen::VectorXd& u) const {
  const Bracket b = bracket(alpha);
  if (b.weight == 0.0) {
    u += force * response_entry(b.j).vector;
    return;
  }
  u += ((1.0 - b.weight) * force) * response_entry(b.j).vector +
       (b.weight * force) * response_entry(b.j + 1).vector;
}

Eigen::VectorXd ContactLoading::load(double alpha) const {
  Eigen::VectorXd s_load;
  scaled_load(alpha, 1.0, s_load); // × 1.0 is exact: the same numbers as the interpolation itself
  return s_load;
}

void ContactLoading::scaled_load(double alpha, double force, Eigen::VectorXd& out) const {
  const Bracket b = bracket(alpha);
  if (b.weight == 0.0)
    out.noalias() = force * load_entry(b.j).vector;
  else
    out.noalias() =
        force * ((1.0 - b.weight) * load_entry(b.j).vector + b.weight * load_entry(b.j + 1).vector);
}

void ContactLoading::scaled_load_minus(double alpha, double force, const Eigen::VectorXd& f,
                                       Eigen::VectorXd& out) const {
  const Bracket b = bracket(alpha);
  const Eigen::VectorXd& lower = load_entry(b.j).vector;
  out.resize(lower.size());
  elementwise_on_threads(out.size(), [&](Eigen::Index first, Eigen::Index last) {
    const Eigen::Index n = last - first;
    if (b.weight == 0.0) {
      out.segment(first, n) = force * lower.segment(first, n) - f.segment(first, n);
    } else {
      const Eigen::VectorXd& upper = load_entry(b.j + 1).vector;
      out.segment(first, n) =
          force * ((1.0 - b.weight) * lower.segment(first, n) + b.weight * upper.segment(first, n)) -
          f.segment(first, n);
    }
  });
}

double ContactLoading::load_dot(double alpha, const Eigen::VectorXd& u) const {
  const Bracket b = bracket(alpha);
  if (b.weight == 0.0) return load_entry(b.j).vector.dot(u);
  return ((1.0 - b.weight) * load_entry(b.j).vector + b.weight * load_entry(b.j + 1).vector).dot(u);
}

Eigen::VectorXd hertz_pressure_weights(const DiscretePlate& model, double x, double y, double a,
                                       NoseShape nose) {
  const Mesh& mesh = model.mesh();
  Eigen::VectorXd f = Eigen::VectorXd::Zero(model.size());
  const CircularPressure p = nose == NoseShape::hemisphere ? hertz_pressure({x, y}, a, 1.0)
                             : nose == NoseShape::flat     ? flat_punch_pressure({x, y}, a, 1.0)
                                                           : cone_pressure({x, y}, a, 1.0);
  double total = 0.0;
  for (int e = 0; e < mesh.element_count(); ++e) {
    const ElementCoordinates xy = mesh.element_coordinates(e);
    if (xy.col(0).maxCoeff() < x - a || xy.col(0).minCoeff() > x + a || xy.col(1).maxCoeff() < y - a ||
        xy.col(1).minCoeff() > y + a)
      continue; // the circle cannot reach it (curved sides bulge a little: their midpoints are nodes)
    const Eigen::Matrix<double, 9, 1> fe = circle_load(xy, p, quadrature);
    total += fe.sum();
    for (int n = 0; n < 9; ++n)
      if (const int eq = model.dofs().equation(mesh.element_nodes(e)[static_cast<std::size_t>(n)], 2);
          eq >= 0)
        f(eq) += fe(n);
  }
  if (total > 0.0) f /= total; // the part of the circle off the plate carries nothing
  return f;
}

} // namespace plyimpact
