#include "plyimpact/analysis/contact/contact_point_response.hpp"

#include <algorithm>
#include <stdexcept>

namespace plyimpact {

namespace {
/// The impulse run goes ahead of the runs that need it by at least this many steps, or a sixteenth of its
/// length: few copies of the series, and a run that uses it once costs hardly more than a full run.
constexpr std::size_t chunk = 256;
} // namespace

std::shared_ptr<const std::vector<double>> ContactPointResponse::at_least(std::size_t n) const {
  const std::lock_guard lock(mutex_);
  if (g_->size() >= n) return g_;
  const std::size_t length = std::max(n, g_->size() + std::max(chunk, g_->size() / 16));
  auto longer = std::make_shared<std::vector<double>>(*g_);
  longer->reserve(length);
  while (longer->size() < length)
    longer->push_back(step_(longer->empty() ? 1.0 : 0.0)); // the unit force in the first step only
  g_ = std::move(longer);
  return g_;
}

ContactPointStepper::ContactPointStepper(std::shared_ptr<const ContactPointResponse> response)
    : response_(std::move(response)), g_(response_->at_least(1)) {
  reversed_forces_ = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(g_->size()) + 1); // F = 0 from rest
  set_facts({.contact_point_only = true});
}

void ContactPointStepper::store_force(long k, double force) {
  const Eigen::Index size = reversed_forces_.size();
  if (k >= size) { // grow at the front: the stored forces keep their distance from the end
    Eigen::VectorXd longer = Eigen::VectorXd::Zero(std::max<Eigen::Index>(2 * size, k + 1));
    longer.tail(size) = reversed_forces_;
    reversed_forces_.swap(longer);
  }
  reversed_forces_(reversed_forces_.size() - 1 - k) = force;
}

double ContactPointStepper::free_deflection(long n, const std::vector<double>& g) const {
  // Over a span of steps k ∈ [b, e) in contact, Σ g_{n−k} F_k = Σ_{j=n−e+1..n−b} g_j F_{n−j}: with F
  // stored in reverse (F_{n−j} at size − 1 − n + j) both ranges increase with j.
  const Eigen::Index last = reversed_forces_.size() - 1;
  double w = 0.0;
  for (const Span& span : in_contact_) {
    const long end = std::min(span.end, n); // F_n itself is the unknown of the step
    if (end <= span.begin) continue;
    const long j0 = n - end + 1;
    const auto length = static_cast<Eigen::Index>(end - span.begin);
    const Eigen::Map<const Eigen::VectorXd> response(g.data() + j0, length);
    w += response.dot(reversed_forces_.segment(last - n + j0, length));
  }
  return w;
}

ContactSolution ContactPointStepper::advance(long step, double /*t*/, const PlateState& /*s*/,
                                             const CondensedContact& contact, Eigen::VectorXd& u_next) {
  const auto n = static_cast<std::size_t>(step);
  if (g_->size() <= n) g_ = response_->at_least(n + 1);
  const std::vector<double>& g = *g_;
  const double w_hat = free_deflection(step, g); // (CP1) without the step's own force
  const ContactSolution cs = contact.solve(w_hat, g[0]);
  store_force(step, cs.force);
  if (cs.force != 0.0) {
    if (in_contact_.empty() || in_contact_.back().end < step)
      in_contact_.push_back({step, step + 1});
    else
      in_contact_.back().end = step + 1;
  }
  force_ = cs.force;
  u_next(0) = w_hat + g[0] * cs.force;
  return cs;
}

void ContactPointStepper::accept(const PlateState& before, const Eigen::VectorXd& u_next) {
  energy_ += 0.5 * (previous_force_ + force_) * (u_next(0) - before.u(0)); // trapezoidal rule's work
  previous_force_ = force_;
}

void ContactPointStepper::to_model(const Eigen::VectorXd& /*u*/, Eigen::VectorXd& /*out*/) const {
  throw std::logic_error("a run through the contact-point response has no displacement field: run it "
                         "without RunRequest::contact_point_response to observe the plate");
}

} // namespace plyimpact
