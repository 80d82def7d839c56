#pragma once
// Newmark's method (2.11)–(2.16), (3.13)–(3.16) with the SPEC §4 misprint corrections:
//   u_{n+1} = u_n + Δt v_n + Δt² ((½ − β) a_n + β a_{n+1})
//   v_{n+1} = v_n + Δt ((1 − γ) a_n + γ a_{n+1})
// written as the effective-stiffness update K̄ u_{n+1} = f_{n+1} + M (c0 u_n + c2 v_n + c3 a_n).
#include <cmath>

namespace plyimpact {

struct NewmarkCoefficients {
  double dt, beta, gamma;
  double c0, c2, c3, c6, c7;

  NewmarkCoefficients(double dt_, double beta_, double gamma_)
      : dt(dt_), beta(beta_), gamma(gamma_), c0(1.0 / (beta_ * dt_ * dt_)), c2(1.0 / (beta_ * dt_)),
        c3(0.5 / beta_ - 1.0), c6(dt_ * (1.0 - gamma_)), c7(gamma_ * dt_) {}

  /// The coefficients of the step Δt/2^k (the levels of error-controlled steps, time_step_control.hpp).
  [[nodiscard]] NewmarkCoefficients halved(int k) const { return {std::ldexp(dt, -k), beta, gamma}; }
  /// a_{n+1} from the new displacement.
  [[nodiscard]] double acceleration(double u1, double u0, double v0, double a0) const {
    return c0 * (u1 - u0) - c2 * v0 - c3 * a0;
  }
  [[nodiscard]] double velocity(double v0, double a0, double a1) const { return v0 + c6 * a0 + c7 * a1; }
  /// u_{n+1} of a free body for a given a_{n+1} (the impactor).
  [[nodiscard]] double displacement(double u0, double v0, double a0, double a1) const {
    return u0 + dt * v0 + dt * dt * ((0.5 - beta) * a0 + beta * a1);
  }
};

/// A Newmark stepper for one scalar DOF: the rigid impactor m ẅ = −Fc (2.4).
class NewmarkStepper {
public:
  NewmarkStepper(const NewmarkCoefficients& c, double mass, double w0, double v0)
      : c_(c), mass_(mass), w_(w0), v_(v0) {}
  /// Displacement at the end of the step if the force there were zero, and the compliance
  /// ∂w_{n+1}/∂F = −β Δt²/m.
  [[nodiscard]] double predicted_displacement() const { return c_.displacement(w_, v_, a_, 0.0); }
  [[nodiscard]] double compliance() const { return c_.beta * c_.dt * c_.dt / mass_; }
  void advance(double force) {
    const double a1 = -force / mass_;
    const double w1 = c_.displacement(w_, v_, a_, a1);
    v_ = c_.velocity(v_, a_, a1);
    w_ = w1;
    a_ = a1;
  }
  /// The next steps use these coefficients (a new Δt): the state (w, v, a) carries over.
  void set_coefficients(const NewmarkCoefficients& c) { c_ = c; }
  [[nodiscard]] const NewmarkCoefficients& coefficients() const { return c_; }
  [[nodiscard]] double displacement() const { return w_; }
  [[nodiscard]] double velocity() const { return v_; }
  [[nodiscard]] double acceleration() const { return a_; }
  [[nodiscard]] double kinetic_energy() const { return 0.5 * mass_ * v_ * v_; }

private:
  NewmarkCoefficients c_;
  double mass_, w_, v_, a_ = 0.0;
};

} // namespace plyimpact
