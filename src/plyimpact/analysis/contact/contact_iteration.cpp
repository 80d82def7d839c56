#include "plyimpact/analysis/contact/contact_iteration.hpp"

#include <cmath>

namespace plyimpact {

ContactIteration::ContactIteration(int equations) {
  for (Eigen::VectorXd* v : {&uk_, &ak_, &inertia_, &g_, &s_load_, &residual_, &correction_, &u_iterate_})
    v->resize(equations);
}

void ContactIteration::predict(const PlateState& s, const NewmarkCoefficients& nc) {
  uk_.noalias() = s.u + nc.dt * s.v + (0.5 * nc.dt * nc.dt) * s.a;
}

void ContactIteration::step_inertia(const PlateState& s, const NewmarkCoefficients& nc, const MassOperator& M,
                                    bool two_point) {
  if (two_point)
    ak_.noalias() = nc.c0 * (uk_ - s.u - nc.dt * s.v); // DL7
  else
    ak_.noalias() = nc.c0 * (uk_ - s.u) - nc.c2 * s.v - nc.c3 * s.a;
  M.apply(ak_, inertia_);
}

bool ContactIteration::converged(const ContactLoading& loading, const ContactSolution& cs,
                                 const Eigen::VectorXd& f, const Eigen::VectorXd& kbar_diagonal,
                                 double residual_tolerance, double displacement_tolerance) {
  loading.scaled_load(cs.alpha, 1.0, s_load_);
  residual_.noalias() = g_ + cs.force * s_load_;
  residual_norm_ = residual_.norm();
  const double scale = f.norm() + inertia_.norm() + std::abs(cs.force) * s_load_.norm();
  return residual_norm_ <= residual_tolerance * scale &&
         residual_.cwiseQuotient(kbar_diagonal).norm() <= displacement_tolerance * uk_.norm();
}

} // namespace plyimpact
