#pragma once
// Contact law between the rigid sphere and the plate (SPEC §4, thesis (2.5)–(2.7)).
//
//   loading      F = k α^n                                    (Hertz n = 1.5, modified constant k)
//   unloading    F = Fm ((α − α0)/(αm − α0))^q                (Tan & Sun), α0 = β(αm − αcr) if αm > αcr
//   reloading    F = Fm ((α − α0)/(αm − α0))^n    for α ≤ αm  (Yang & Sun), after a full unload
// n = 1.5 for the hemisphere; 1 (flat-ended cylinder) and 2 (cone) for the other noses, which unload
// elastically (parameters.hpp, docs/impactor.md).
//
// αm, Fm: indentation and force at the start of unloading (the largest indentation so far). The
// unloading and reloading curves are reversible: moving back and forth below αm retraces them (no
// chatter from switching exponents mid-way). Beyond αm the loading law applies. No tension: F = 0
// for α ≤ α0.
#include "plyimpact/analysis/impact/parameters.hpp"

namespace plyimpact {

class HertzContact {
public:
  /// `exponent`: n of the loading law F = k α^n (contact_exponent of the nose; 1.5 for Hertz). The
  /// reloading curve uses n too; the unloading exponent q is the law's (n when elastic).
  HertzContact(double k, const ContactLawParameters& law, double exponent = 1.5);

  /// Contact force for indentation α with the current history (does not change the history).
  [[nodiscard]] double force(double alpha) const;
  /// dF/dα at α (one-sided from the right at kinks; 0 where F = 0).
  [[nodiscard]] double stiffness(double alpha) const;
  /// ∫ F dα from `from` to `to` with the current history, exact (the antiderivative of each branch):
  /// the work the law asks for over a step, against which the time integration's trapezoids are
  /// checked (the energy balance of impact_loop.cpp). Call before commit(to).
  [[nodiscard]] double work(double from, double to) const;
  /// Records a converged indentation: updates αm, Fm, α0 and the branch.
  void commit(double alpha);

  [[nodiscard]] double k() const { return k_; }
  [[nodiscard]] double max_indentation() const { return alpha_m_; }
  [[nodiscard]] double permanent_indentation() const { return alpha_0_; }
  [[nodiscard]] bool reloading() const { return reloading_; }

private:
  /// An antiderivative of force(α) with the current history, 0 at α ≤ α0.
  [[nodiscard]] double work_to(double alpha) const;

  /// k α^n, written α√α for Hertz (the historical arithmetic, bit for bit).
  [[nodiscard]] double loading(double alpha) const;

  double k_;
  ContactLawParameters law_;
  double n_ = 1.5;
  double alpha_m_ = 0.0;   ///< largest indentation reached
  double force_m_ = 0.0;   ///< force at αm (on the loading curve)
  double alpha_0_ = 0.0;   ///< permanent indentation
  bool reloading_ = false; ///< a full unload (separation) happened since αm was reached
};

/// Solves Fc = F(α̂ − C·Fc) for the contact force, with F the contact law, α̂ the indentation the
/// step would have without contact force and C > 0 the combined compliance of impactor and plate at
/// the contact point (SPEC §4: ws is affine in Fc). Safeguarded Newton; |ΔF| ≤ 1e-13·F at exit.
struct ContactSolution {
  double force = 0.0;
  double alpha = 0.0;
  int iterations = 0;
};
[[nodiscard]] ContactSolution solve_contact_force(const HertzContact& law, double alpha_free,
                                                  double compliance);

} // namespace plyimpact
