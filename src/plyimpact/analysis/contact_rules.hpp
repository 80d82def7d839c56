#pragma once
// The physical rules that turn "auto" in a deck into numbers (SPEC §4): the modified Hertz constant
// of the contact law and the time step that resolves the contact.
#include "plyimpact/analysis/parameters.hpp"
#include "plyimpact/laminate/laminate.hpp"

namespace plyimpact {

/// k = (4/3)√R / ((1 − νi²)/Ei + 1/E2) with E2 of the impacted ply (ply 1) of `laminate` [N/m^1.5].
[[nodiscard]] double automatic_contact_stiffness(const Impactor& impactor, const Laminate& laminate);

/// Hertz contact time of a sphere of mass m striking a rigid half-space at v0 with F = k α^1.5:
/// t_c = 2 (α_m/v0) ∫₀¹ dx/√(1 − x^{5/2}) = 0.8 B(2/5, 1/2) α_m/v0, α_m = (5 m v0²/(4k))^{2/5}
/// (the plate's compliance only lengthens the contact) [s].
[[nodiscard]] double hertz_contact_time(double mass, double velocity, double k);

/// The largest contact radius of a sphere of radius R on a rigid target, √(R α_m), α_m = (5 m
/// v0²/(4k))^(2/5): an upper bound of the radius on a plate, whose compliance lowers the force [m].
[[nodiscard]] double expected_contact_radius(double mass, double velocity, double k, double radius);

/// Time step chosen for dt = "auto": the rigid-target Hertz contact time 3.21807 (m²/(k² v0))^(1/5)
/// divided by 1000, rounded down to two significant digits [s].
[[nodiscard]] double automatic_time_step(double mass, double k, double velocity);

} // namespace plyimpact
