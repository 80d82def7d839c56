#pragma once
// The physical rules that turn "auto" in a deck into numbers (SPEC §4): the contact constant of the
// law F = k α^n for the impactor's nose and the time step that resolves the contact.
#include "plyimpact/analysis/impact/parameters.hpp"
#include "plyimpact/laminate/laminate.hpp"

namespace plyimpact {

/// k of F = k α^n with the effective modulus E* = 1/((1 − νi²)/Ei + 1/E2), E2 of the impacted ply
/// (ply 1) of `laminate` (the modified Hertz law of SPEC §4):
///   hemisphere  k = (4/3) √R E*      [N/m^1.5]  (Hertz)
///   flat        k = 2 R E*           [N/m]      (Boussinesq's flat punch, radius R)
///   cone        k = (2/π) tan θ E*   [N/m²]     (Sneddon, half-angle θ)
[[nodiscard]] double automatic_contact_stiffness(const Impactor& impactor, const Laminate& laminate);

/// The radius of the contact circle at indentation α: √(R α) (hemisphere), R (flat, whatever α: its
/// load keeps one shape, so that the plate's compliance under it does not jump at the first touch),
/// (2/π) α tan θ (cone, Sneddon) [m].
[[nodiscard]] double contact_radius(const Impactor& impactor, double alpha);

/// Contact time of a mass m striking a rigid half-space at v0 with F = k α^n:
/// t_c = 2 (α_m/v0) ∫₀¹ dx/√(1 − x^(n+1)) = 2 B(1/(n+1), 1/2)/(n+1) · α_m/v0, α_m = ((n+1) m
/// v0²/(2k))^(1/(n+1)) (n = 3/2: 0.8 B(2/5, 1/2) α_m/v0 = 2.9432 α_m/v0; n = 1: π √(m/k)); the plate's
/// compliance only lengthens the contact [s].
[[nodiscard]] double hertz_contact_time(double mass, double velocity, double k, double exponent = 1.5);

/// The largest indentation on a rigid target, α_m = ((n+1) m v0²/(2k))^(1/(n+1)) [m].
[[nodiscard]] double rigid_target_indentation(double mass, double velocity, double k, double exponent = 1.5);

/// The largest contact radius of the impactor on a rigid target, contact_radius(α_m): an upper bound of
/// the radius on a plate, whose compliance lowers the force [m].
[[nodiscard]] double expected_contact_radius(const Impactor& impactor, double k);

/// Time step chosen for dt = "auto": the rigid-target contact time divided by 1000, rounded down to two
/// significant digits (for the hemisphere 3.21807 (m²/(k² v0))^(1/5), as it always was) [s].
[[nodiscard]] double automatic_time_step(double mass, double k, double velocity, double exponent = 1.5);

} // namespace plyimpact
