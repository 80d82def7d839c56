#include "plyimpact/analysis/nonlinear_impact.hpp"

#include "plyimpact/analysis/impact_event.hpp"
#include "plyimpact/analysis/newmark.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace plyimpact {

NonlinearImpactSolver::NonlinearImpactSolver(const PlateModel& model, ImpactSettings settings,
                                             NonlinearImpactSettings nonlinear)
    : model_(model), settings_(std::move(settings)), nonlinear_(nonlinear), plate_(model, nonlinear.measure),
      M_(model.mass()) {
  if (!(settings_.dt > 0.0)) throw std::invalid_argument("impact: time step must be positive");
  if (!(settings_.impactor.mass > 0.0)) throw std::invalid_argument("impact: impactor mass must be positive");
  if (settings_.rigid_target)
    throw std::invalid_argument(
        "non-linear impact needs a plate: a rigid target has no deflection to stiffen");
  if (settings_.contact.load != ContactLoad::point)
    throw std::invalid_argument(
        "non-linear impact applies the contact force as a point load: set contact.load = \"point\"");
  // The lumped mass is diagonal when I1 = 0; a symmetric layup gives I1 at round-off level (~1e-20),
  // whose u–θ entries are dropped rather than turning every M·x into a sparse product.
  const double m_max = M_.diagonal().cwiseAbs().maxCoeff();
  bool diagonal = true;
  for (int col = 0; col < M_.outerSize() && diagonal; ++col)
    for (SparseMatrix::InnerIterator it(M_, col); it; ++it)
      if (it.row() != col && std::abs(it.value()) > 1e-14 * m_max) {
        diagonal = false;
        break;
      }
  if (diagonal) m_diag_ = M_.diagonal();
  if (!settings_.end) period_ = fundamental_period(model); // end-of-event rule (SPEC §4)
}

NonlinearImpactResult NonlinearImpactSolver::run(const ImpactObserver& observer) const {
  return run(settings_.impactor, observer);
}

NonlinearImpactResult NonlinearImpactSolver::run(const Impactor& imp, const ImpactObserver& observer) const {
  const auto wall0 = std::chrono::steady_clock::now();
  const ImpactSettings& s = settings_;
  const NonlinearImpactSettings& ns = nonlinear_;
  const NewmarkCoefficients nc(s.dt, s.newmark_beta, s.newmark_gamma);
  const auto n = static_cast<Eigen::Index>(model_.size());
  const auto mass_times = [&](const Eigen::VectorXd& x) -> Eigen::VectorXd {
    if (m_diag_.size() > 0) return m_diag_.cwiseProduct(x);
    return M_ * x;
  };

  NonlinearImpactResult out;
  ImpactResult& r = out.impact;
  r.dofs = static_cast<int>(n);

  // Effective tangent K̄ = K_T(u) + c0 M, refreshed on demand (modified Newton).
  const Eigen::VectorXd sw = model_.sampler(imp.x, imp.y).as_vector(static_cast<int>(n));
  SpdSolver factor(s.solver);
  Eigen::VectorXd t_load, kbar_diagonal;
  double c = 0.0; // sᵀ K̄⁻¹ s
  const auto refactor = [&](const Eigen::VectorXd& at) {
    const SparseMatrix Kbar = plate_.tangent_stiffness(at) + nc.c0 * M_;
    factor.factorize(Kbar);
    kbar_diagonal = Kbar.diagonal();
    t_load = factor.solve(sw);
    c = sw.dot(t_load);
    ++out.factorizations;
  };
  refactor(Eigen::VectorXd::Zero(n));

  HertzContact law(s.k, s.contact);
  NewmarkStepper impactor(nc, imp.mass, 0.0, imp.velocity);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(n), v = Eigen::VectorXd::Zero(n), a = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd f_int = Eigen::VectorXd::Zero(n), f_int_previous_step = Eigen::VectorXd::Zero(n);

  const double e0 = 0.5 * imp.mass * imp.velocity * imp.velocity;
  double force = 0.0, alpha = 0.0, ws = 0.0, contact_work = 0.0, strain_energy = 0.0;
  ImpactEvent event(r, s, period_);
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
    h.plate_kinetic = 0.5 * v.dot(mass_times(v));
    h.plate_strain = strain_energy; // ∫ f_intᵀ du (trapezoidal): the elastic energy of the plate
    h.impactor_energy = impactor.kinetic_energy();
    h.contact_work = contact_work;
    r.history.push_back(h);
  };
  record(0, 0.0, true);

  long step = 0;
  long last_refactor = 0;
  bool refresh = false; // the last step needed more than one solve: refactor at uₙ first
  double t = 0.0;
  for (;;) {
    if (event.must_stop(step, t)) break;
    ++step;
    t = static_cast<double>(step) * s.dt;

    // Newton iterations on (u, Fc); start from constant acceleration (a_{n+1} = aₙ).
    if (refresh && step - last_refactor >= ns.refresh_interval) {
      refactor(u);
      last_refactor = step;
    }
    Eigen::VectorXd uk = u + s.dt * v + (0.5 * s.dt * s.dt) * a;
    ContactSolution cs;
    double previous_correction = INFINITY;
    int iterations = 0; // linear solves in this step
    for (;;) {
      const Eigen::VectorXd ak = nc.c0 * (uk - u) - nc.c2 * v - nc.c3 * a;
      const Eigen::VectorXd inertia = mass_times(ak);
      f_int = plate_.internal_force(uk);
      const Eigen::VectorXd g = -inertia - f_int; // force-free residual
      // Converged: the residual is small, and so is the next correction, estimated without a solve
      // by the diagonal of K̄ (δ ≈ diag(K̄)⁻¹ r).
      if (iterations > 0) {
        const Eigen::VectorXd residual = g + cs.force * sw;
        const double scale = f_int.norm() + inertia.norm() + std::abs(cs.force) * sw.norm();
        if (residual.norm() <= ns.residual_tolerance * scale &&
            residual.cwiseQuotient(kbar_diagonal).norm() <= ns.displacement_tolerance * uk.norm())
          break;
      }
      if (iterations == ns.max_iterations)
        throw NewtonFailure(fmt::format(
            "non-linear impact: Newton iterations did not converge in step {} (t = {:.6g} s) after {} "
            "iterations; reduce time.dt",
            step, t, ns.max_iterations));
      // Plate predictor û and the exact scalar contact problem with ws affine in Fc (SPEC §4).
      const Eigen::VectorXd u_hat = uk + factor.solve(g);
      cs = solve_contact_force(law, impactor.predicted_displacement() - sw.dot(u_hat),
                               impactor.compliance() + c);
      Eigen::VectorXd u_next = u_hat + cs.force * t_load;
      const double correction = (u_next - uk).norm();
      ++iterations;
      if (!std::isfinite(correction) || !std::isfinite(cs.force))
        throw NewtonFailure(fmt::format(
            "non-linear impact: non-finite state in step {} (t = {:.6g} s); reduce time.dt", step, t));
      const bool slow = correction > ns.refresh_ratio * previous_correction || iterations > ns.refresh_after;
      previous_correction = correction;
      uk.swap(u_next);
      if (slow && iterations > 1) {
        refactor(uk); // modified Newton: a new tangent where the iterations slowed down
        previous_correction = INFINITY;
      }
    }
    refresh = iterations > 1;
    out.newton_iterations += iterations;
    out.max_iterations_per_step = std::max(out.max_iterations_per_step, iterations);

    const double force_old = force, alpha_old = alpha;
    force = cs.force;
    alpha = cs.alpha;
    r.newton_iterations_max = std::max(r.newton_iterations_max, cs.iterations);
    law.commit(alpha);
    contact_work += 0.5 * (force + force_old) * (alpha - alpha_old);
    impactor.advance(force);
    // Work of the internal forces, trapezoidal; f_int of the last iterate stands for f_int(u_{n+1}) to
    // the Newton tolerance (no extra evaluation).
    strain_energy += 0.5 * (f_int + f_int_previous_step).dot(uk - u);
    f_int_previous_step = f_int;
    const Eigen::VectorXd a_new = nc.c0 * (uk - u) - nc.c2 * v - nc.c3 * a;
    v += nc.c6 * a + nc.c7 * a_new;
    a = a_new;
    u.swap(uk);
    ws = sw.dot(u);

    event.record(t, force, alpha, ws);
    if (observer) observer(step, t, force, u);
    while (next_field < field_times.size() && t >= field_times[next_field] - 1e-12 * s.dt) {
      r.fields.push_back({t, u});
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
  return out;
}

} // namespace plyimpact
