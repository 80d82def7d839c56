// Newton–Newmark's settings by row of the table of what runs (newton_settings.hpp). The values are those
// each physics carried in its fem/ settings before issue 78 (NonlinearImpactSettings,
// ProgressiveDamageSettings, DelaminationSettings), so that no example's numbers move; why each differs is
// written at its row.
#include "plyimpact/analysis/integrators/newton_settings.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace plyimpact {

namespace {

/// At most every this many steps, the von Kármán plate refactors at uₙ after a step needing more than one
/// solve: its tangent moves with u.
constexpr long von_karman_refresh_interval = 200;

/// The von Kármán plate: modified Newton on the tangent, refreshed after 4 solves or when the corrections
/// contract by less than 4×.
NewtonSettings von_karman_plate() {
  NewtonSettings ns;
  ns.control.max_iterations = 30;
  ns.control.refresh_ratio = 0.25;
  ns.control.refresh_after = 4;
  ns.residual_tolerance = 1e-4;
  ns.displacement_tolerance = 1e-6;
  ns.physics = "non-linear impact";
  return ns;
}

/// Plies that crack: the secant's tighter tolerances close the damage's energy balance. No refresh after a
/// count of solves: the tighter tolerance takes more solves per step, and with it the plate of
/// examples/damage-progressive.toml refactored in 415 of its 266 steps (13 s) instead of 44 times (2.5 s)
/// with the contraction rule alone.
NewtonSettings plies_that_crack(Integrator i) {
  NewtonSettings ns;
  ns.control.max_iterations = 60;
  ns.control.refresh_ratio = 0.5;
  ns.residual_tolerance = 1e-6;
  ns.displacement_tolerance = 1e-8;
  ns.physics = "progressive damage";
  if (i != Integrator::lagged)
    ns.advice = "set [damage] integration = \"lagged\" (no iteration on the damage; its energy balance "
                "error shrinks with time.dt), or reduce time.dt";
  return ns;
}

/// Sub-laminates tied by interfaces. Where the interfaces are iterated, and on the lagged linear stack, the
/// corrections that do not lower the residual are halved and the matrix refreshed every 4 solves (the
/// softening law is only piecewise smooth); the lagged stacks with ply damage or large deflections refresh
/// after 4 solves and do not halve.
NewtonSettings stack(const ModelKind& m, Integrator i) {
  NewtonSettings ns;
  ns.control.max_iterations = 30;
  ns.control.refresh_ratio = 0.5;
  ns.residual_tolerance = 1e-5;
  ns.displacement_tolerance = 1e-6;
  ns.physics = m.von_karman   ? "non-linear delamination"
               : m.ply_damage ? "ply damage and delamination"
                              : "delamination";
  if ((m.ply_damage || m.von_karman) && i == Integrator::lagged) {
    ns.control.refresh_after = 4;
  } else {
    ns.control.refresh_every = 4;
    ns.max_halvings = 6;
  }
  if (m.ply_damage && i == Integrator::implicit)
    ns.advice = "set integration = \"lagged\" in [damage] and [delamination] (no iteration on either law), "
                "or reduce time.dt";
  return ns;
}

} // namespace

NewtonSettings newton_newmark_defaults(const ModelKind& m, Integrator i) {
  if (m.rigid_target || !(m.von_karman || m.ply_damage || m.interfaces) ||
      i == Integrator::central_difference)
    throw std::invalid_argument(
        fmt::format("Newton–Newmark does not step the {} with {} steps", model_name(m), to_string(i)));
  NewtonSettings ns = m.interfaces ? stack(m, i) : m.ply_damage ? plies_that_crack(i) : von_karman_plate();
  if (m.von_karman) ns.refresh_interval = von_karman_refresh_interval;
  return ns;
}

} // namespace plyimpact
