#pragma once
// The contact of one time step condensed to one scalar equation (SPEC §4): with the plate's deflection
// at the contact point affine in the force, ws = ŵs + c Fc, the indentation is
// α = (ŵi − ŵs) − (βΔt²/m + c) Fc and Fc = F(α) by the contact law.
#include "plyimpact/analysis/contact/hertz_contact.hpp"
#include "plyimpact/analysis/integrators/newmark.hpp"

namespace plyimpact {

class CondensedContact {
public:
  /// `previous`: Fc and α of the last converged step.
  CondensedContact(const HertzContact& law, const NewmarkStepper& impactor, const ContactSolution& previous)
      : law_(law), impactor_(impactor), previous_(previous) {}
  /// Fc and α for the load-free plate deflection ŵs and the plate's compliance c at the contact point.
  [[nodiscard]] ContactSolution solve(double w_hat, double c) const {
    return solve_contact_force(law_, impactor_.predicted_displacement() - w_hat, impactor_.compliance() + c);
  }
  /// α of the last converged step.
  [[nodiscard]] double previous_indentation() const { return previous_.alpha; }
  /// Fc of the last converged step.
  [[nodiscard]] double previous_force() const { return previous_.force; }

private:
  const HertzContact& law_;
  const NewmarkStepper& impactor_;
  ContactSolution previous_;
};

} // namespace plyimpact
