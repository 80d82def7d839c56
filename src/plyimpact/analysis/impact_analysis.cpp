#include "plyimpact/analysis/impact_analysis.hpp"

#include "plyimpact/analysis/guards.hpp"
#include "plyimpact/analysis/impact_event.hpp"
#include "plyimpact/analysis/modal_analysis.hpp"
#include "plyimpact/analysis/newmark.hpp"
#include "plyimpact/fem/quadrature.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace plyimpact {

double fundamental_period(const PlateModel& model) {
  const ModalResult r = solve_modal(model, 7); // room for up to 6 rigid-body modes of a free plate
  for (const double f : r.frequencies_hz)
    if (f > 0.0) return 1.0 / f;
  throw std::runtime_error("impact: the plate has no elastic mode among its lowest 7");
}

namespace {

/// The whole plate state is checked for NaN/Inf every this many steps (the contact scalars every step).
constexpr long full_state_check_every = 100;

/// Rows/columns `keep` of a square sparse matrix.
SparseMatrix restrict_to(const SparseMatrix& A, const std::vector<int>& keep,
                         const std::vector<int>& new_index) {
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(static_cast<std::size_t>(A.nonZeros()));
  for (const int col : keep)
    for (SparseMatrix::InnerIterator it(A, col); it; ++it)
      if (const int r = new_index[static_cast<std::size_t>(it.row())]; r >= 0)
        t.emplace_back(r, new_index[static_cast<std::size_t>(col)], it.value());
  SparseMatrix R(static_cast<Eigen::Index>(keep.size()), static_cast<Eigen::Index>(keep.size()));
  R.setFromTriplets(t.begin(), t.end());
  return R;
}

/// Largest |A(i, j)| with i in-plane (u, v) and j bending (w, θx, θy), relative to max |A|.
double inplane_coupling(const PlateModel& model, const SparseMatrix& A) {
  std::vector<bool> inplane(static_cast<std::size_t>(model.size()));
  for (int n = 0; n < model.mesh().node_count(); ++n)
    for (int d = 0; d < 2; ++d)
      if (const int eq = model.dofs().equation(n, d); eq >= 0) inplane[static_cast<std::size_t>(eq)] = true;
  double coupling = 0.0, scale = 0.0;
  for (int col = 0; col < A.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(A, col); it; ++it) {
      scale = std::max(scale, std::abs(it.value()));
      if (inplane[static_cast<std::size_t>(it.row())] != inplane[static_cast<std::size_t>(col)])
        coupling = std::max(coupling, std::abs(it.value()));
    }
  return scale > 0.0 ? coupling / scale : 0.0;
}

/// Unit-force Hertz pressure p = 3/(2π a²) √(1 − r²/a²) over the contact circle of radius a, as
/// consistent nodal forces on w (model numbering), renormalised to a total of 1 where the circle
/// leaves the plate.
Eigen::VectorXd hertz_pressure_weights(const PlateModel& model, double x, double y, double a) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(model.size());
  double total = 0.0;
  constexpr int n_theta = 16;
  for (std::size_t i = 0; i < 3; ++i) {
    const double rho = 0.5 * (1.0 + gauss3.points[i]); // r/a on (0, 1)
    const double w_r = 0.5 * gauss3.weights[i];
    for (int j = 0; j < n_theta; ++j) {
      const double th = 2.0 * std::numbers::pi * (j + 0.5) / n_theta;
      const double px = x + a * rho * std::cos(th), py = y + a * rho * std::sin(th);
      const auto loc = model.mesh().locate(px, py);
      if (!loc) continue;
      const double w = w_r * (2.0 * std::numbers::pi / n_theta) * a * a * rho * 1.5 /
                       (std::numbers::pi * a * a) * std::sqrt(1.0 - rho * rho);
      const Q9Shape sh = q9_shape(loc->xi, loc->eta);
      const auto& conn = model.mesh().element_nodes(loc->element);
      for (int n = 0; n < 9; ++n)
        if (const int eq = model.dofs().equation(conn[static_cast<std::size_t>(n)], 2); eq >= 0)
          f(eq) += w * sh.N(n);
      total += w;
    }
  }
  if (total > 0.0) f /= total;
  return f;
}

} // namespace

struct ImpactSolver::Plate {
  std::vector<int> keep;      ///< model equations in the time loop (all, or the bending ones)
  std::vector<int> new_index; ///< model equation → loop equation (−1 if eliminated)
  SparseMatrix K, M;
  Eigen::VectorXd m_diag; ///< M when it is diagonal (lumped, I1 = 0), else empty
  SpdSolver factor;
  double period = 0.0;

  [[nodiscard]] Eigen::VectorXd mass_times(const Eigen::VectorXd& x) const {
    if (m_diag.size() > 0) return m_diag.cwiseProduct(x);
    return M * x;
  }
  [[nodiscard]] Eigen::VectorXd restrict_vector(const Eigen::VectorXd& v) const {
    Eigen::VectorXd r(static_cast<Eigen::Index>(keep.size()));
    for (std::size_t i = 0; i < keep.size(); ++i)
      r(static_cast<Eigen::Index>(i)) = v(keep[i]);
    return r;
  }
  [[nodiscard]] Eigen::VectorXd expand(const Eigen::VectorXd& r, int size) const {
    Eigen::VectorXd v = Eigen::VectorXd::Zero(size);
    for (std::size_t i = 0; i < keep.size(); ++i)
      v(keep[i]) = r(static_cast<Eigen::Index>(i));
    return v;
  }
};

ImpactSolver::ImpactSolver(const PlateModel& model, ImpactSettings settings)
    : model_(model), settings_(std::move(settings)), plate_(std::make_unique<Plate>()) {
  if (!(settings_.dt > 0.0)) throw std::invalid_argument("impact: time step must be positive");
  if (!(settings_.impactor.mass > 0.0)) throw std::invalid_argument("impact: impactor mass must be positive");
  if (settings_.rigid_target) return;
  Plate& p = *plate_;
  const SparseMatrix K = model.stiffness();
  const SparseMatrix M = model.mass();
  // In-plane DOFs carry no load and, for B = 0 and I1 = 0, no coupling: they stay exactly zero and
  // are left out of the time loop (about 2/5 of the equations).
  const bool decoupled = inplane_coupling(model, K) <= 1e-13 && inplane_coupling(model, M) <= 1e-13;
  p.new_index.assign(static_cast<std::size_t>(model.size()), -1);
  for (int n = 0; n < model.mesh().node_count(); ++n)
    for (int d = decoupled ? 2 : 0; d < dofs_per_node; ++d)
      if (const int eq = model.dofs().equation(n, d); eq >= 0) p.keep.push_back(eq);
  std::sort(p.keep.begin(), p.keep.end());
  for (std::size_t i = 0; i < p.keep.size(); ++i)
    p.new_index[static_cast<std::size_t>(p.keep[i])] = static_cast<int>(i);
  p.K = decoupled ? restrict_to(K, p.keep, p.new_index) : K;
  p.M = decoupled ? restrict_to(M, p.keep, p.new_index) : M;
  bool diagonal = true;
  for (int col = 0; col < p.M.outerSize() && diagonal; ++col)
    for (SparseMatrix::InnerIterator it(p.M, col); it; ++it)
      if (it.row() != col && it.value() != 0.0) {
        diagonal = false;
        break;
      }
  if (diagonal) p.m_diag = p.M.diagonal();
  const NewmarkCoefficients c(settings_.dt, settings_.newmark_beta, settings_.newmark_gamma);
  const SparseMatrix Kbar = p.K + c.c0 * p.M; // effective stiffness, factored once per run
  if (settings_.memory_limit_bytes)
    check_factor_memory(estimate_factor_memory(Kbar), *settings_.memory_limit_bytes);
  p.factor = SpdSolver(settings_.solver);
  p.factor.factorize(Kbar);
  if (!settings_.end) p.period = fundamental_period(model); // for the end-of-event rule
}

ImpactSolver::~ImpactSolver() = default;

int ImpactSolver::equations() const {
  return static_cast<int>(plate_->keep.size());
}

double ImpactSolver::time_one_solve(int repeats) const {
  if (plate_->keep.empty()) return 0.0;
  Eigen::VectorXd b = Eigen::VectorXd::Ones(static_cast<Eigen::Index>(plate_->keep.size()));
  std::vector<double> t;
  Eigen::VectorXd x;
  for (int i = 0; i < repeats; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    x = plate_->factor.solve(b);
    t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    b(0) += 1e-30 * x(0);
  }
  std::nth_element(t.begin(), t.begin() + repeats / 2, t.end());
  return t[static_cast<std::size_t>(repeats / 2)];
}

ImpactResult ImpactSolver::run(const ImpactObserver& observer) const {
  return run(settings_.impactor, observer);
}

ImpactResult ImpactSolver::run(const Impactor& imp, const ImpactObserver& observer) const {
  return run(imp, settings_.k, observer);
}

ImpactResult ImpactSolver::run(const Impactor& imp, double k, const ImpactObserver& observer) const {
  const auto wall0 = std::chrono::steady_clock::now();
  const ImpactSettings& s = settings_;
  const NewmarkCoefficients nc(s.dt, s.newmark_beta, s.newmark_gamma);
  const Plate& p = *plate_;
  const bool rigid = s.rigid_target;
  const auto n = static_cast<Eigen::Index>(p.keep.size());
  const bool hertz_pressure = s.contact.load == ContactLoad::hertz_pressure && !rigid;

  // Contact point: ws = sᵀu; the point force loads the plate with F·s. t_load = K̄⁻¹ s_load.
  Eigen::VectorXd sw, s_load, t_load;
  double c = 0.0; // ∂ws/∂Fc at fixed predictor
  if (!rigid) {
    sw = p.restrict_vector(model_.sampler(imp.x, imp.y).as_vector(model_.size()));
    s_load = sw;
    t_load = p.factor.solve(s_load);
    c = sw.dot(t_load);
  }
  double load_radius = 0.0;

  HertzContact law(k, s.contact);
  NewmarkStepper impactor(nc, imp.mass, 0.0, imp.velocity);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(n), v = Eigen::VectorXd::Zero(n), a = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd rhs(n), u_hat(n), u_new(n), a_new(n);

  ImpactResult r;
  if (auto w = time_step_warning(imp.mass, imp.velocity, s.k, s.dt)) r.warnings.push_back(std::move(*w));
  if (!rigid)
    if (auto w = impact_point_warning(model_.mesh(), imp.x, imp.y)) r.warnings.push_back(std::move(*w));
  r.dofs = static_cast<int>(n);
  r.inplane_eliminated = !rigid && n < model_.size();
  const double e0 = 0.5 * imp.mass * imp.velocity * imp.velocity;
  double force = 0.0, alpha = 0.0, ws = 0.0, contact_work = 0.0;
  ImpactEvent event(r, s, p.period);
  std::size_t next_field = 0;
  std::vector<double> field_times = s.field_times;
  std::sort(field_times.begin(), field_times.end());

  const auto record = [&](long step, double t, bool force_keep) {
    if (!force_keep && step % s.history_every != 0) return;
    ImpactSample h;
    h.t = t;
    h.force = force;
    h.impactor_w = impactor.displacement();
    h.impactor_v = impactor.velocity();
    h.plate_w = ws;
    h.indentation = alpha;
    if (!rigid) {
      h.plate_kinetic = 0.5 * v.dot(p.mass_times(v));
      h.plate_strain = 0.5 * (force * s_load.dot(u) - u.dot(p.mass_times(a))); // K u = F s − M a
    }
    h.impactor_energy = impactor.kinetic_energy();
    h.contact_work = contact_work;
    r.history.push_back(h);
  };
  record(0, 0.0, true);

  long step = 0;
  double t = 0.0;
  for (;;) {
    if (event.must_stop(step, t)) break;
    ++step;
    t = static_cast<double>(step) * s.dt;

    // 1. Load-free predictor û = K̄⁻¹ M (c0 u + c2 v + c3 a): one back-substitution.
    double w_hat = 0.0;
    if (!rigid) {
      rhs = p.mass_times(nc.c0 * u + nc.c2 * v + nc.c3 * a);
      u_hat = p.factor.solve(rhs);
      w_hat = sw.dot(u_hat);
      if (hertz_pressure) { // contact radius from the last converged indentation (lagged one step)
        const double radius = std::sqrt(imp.radius * std::max(alpha, 0.0));
        if (std::abs(radius - load_radius) > 1e-3 * std::max(radius, 1e-12)) {
          load_radius = radius;
          s_load =
              radius > 0.0 ? p.restrict_vector(hertz_pressure_weights(model_, imp.x, imp.y, radius)) : sw;
          t_load = p.factor.solve(s_load);
          c = sw.dot(t_load);
        }
      }
    }
    // 2. Scalar contact problem: α = (ŵi − ŵs) − (βΔt²/m + c) Fc.
    const double alpha_free = impactor.predicted_displacement() - w_hat;
    const ContactSolution cs = solve_contact_force(law, alpha_free, impactor.compliance() + c);
    r.newton_iterations_max = std::max(r.newton_iterations_max, cs.iterations);
    const double force_old = force, alpha_old = alpha;
    force = cs.force;
    alpha = cs.alpha;
    check_finite_step(step, t, {{"contact force Fc [N]", force}, {"indentation alpha [m]", alpha}});
    law.commit(alpha);
    contact_work += 0.5 * (force + force_old) * (alpha - alpha_old);
    impactor.advance(force);

    // 3. Plate update.
    if (!rigid) {
      u_new = u_hat + force * t_load;
      a_new = nc.c0 * (u_new - u) - nc.c2 * v - nc.c3 * a;
      v += nc.c6 * a + nc.c7 * a_new;
      u.swap(u_new);
      a.swap(a_new);
      ws = sw.dot(u);
    }
    check_finite_step(step, t,
                      {{"impactor displacement [m]", impactor.displacement()},
                       {"impactor velocity [m/s]", impactor.velocity()},
                       {"contact-point deflection ws [m]", ws}});
    if (!rigid && step % full_state_check_every == 0) {
      check_finite_vector(step, t, "plate displacement u", u);
      check_finite_vector(step, t, "plate velocity", v);
      check_finite_vector(step, t, "plate acceleration", a);
    }

    // 4. Bookkeeping: episodes, peaks, snapshots, end of event.
    event.record(t, force, alpha, ws);
    if (observer) observer(step, t, force, rigid ? Eigen::VectorXd() : p.expand(u, model_.size()));
    while (next_field < field_times.size() && t >= field_times[next_field] - 1e-12 * s.dt) {
      r.fields.push_back({t, rigid ? Eigen::VectorXd() : p.expand(u, model_.size())});
      ++next_field;
    }
    if (s.progress && step % 1000 == 0) s.progress(t, step);

    const bool done = event.over(t);
    record(step, t, done);
    if (done) {
      r.complete = true;
      break;
    }
  }
  if (!r.complete && r.history.back().t != t) record(step, t, true);
  event.finish(step, law, impactor, e0, contact_work, wall0);
  return r;
}

} // namespace plyimpact
