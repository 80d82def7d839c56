#include "plyimpact/analysis/plate_analyses/static_analysis.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

namespace plyimpact {

namespace {

std::string restraint_advice(const DiscretePlate& model) {
  const auto free = unrestrained_rigid_motions(model);
  std::string s;
  if (!free.empty()) {
    s = "the plate can move as a rigid body: ";
    for (std::size_t i = 0; i < free.size(); ++i)
      s += (i ? "; " : "") + free[i];
    s +=
        ". Restrain it, e.g. boundary.x0 = \"ss\" and boundary.xa = \"ss\" (w, tangential u/v and rotation), "
        "or boundary.x0 = \"clamped\" for a cantilever";
  } else {
    s = "no rigid-body motion is free, so a zero-energy mechanism of the elements is: use [mesh] element = "
        "\"mitc9\" or restrain w on more edges";
  }
  std::string codes;
  for (const SetRestraint& r : model.boundary().sets)
    codes +=
        fmt::format("{}{} = {}", codes.empty() ? "" : ", ", r.set, resolve_restraint(model.mesh(), r).code());
  return s + fmt::format(" (current edge codes uvwθxθy: {})", codes.empty() ? "none" : codes);
}

} // namespace

SpdSolver factor_stiffness(const DiscretePlate& model, const SparseMatrix& K, SparseSolverKind kind) {
  if (const auto free = unrestrained_rigid_motions(model); !free.empty())
    throw InsufficientRestraint("insufficient restraint for a static solve: " + restraint_advice(model));
  SpdSolver solver(kind);
  try {
    solver.factorize(K);
  } catch (const NotPositiveDefinite& e) {
    throw InsufficientRestraint(
        fmt::format("the stiffness matrix is singular ({}): {}", e.what(), restraint_advice(model)));
  }
  return solver;
}

StaticResult static_result(const DiscretePlate& model, const StaticLoad& load, Eigen::VectorXd u) {
  StaticResult r;
  r.u = std::move(u);
  const Eigen::Vector2d centre = model.mesh().bounds().centre();
  // The centre of the mesh's bounding box; not a number where it is not on the plate (an annulus).
  r.center_deflection = model.mesh().locate(centre.x(), centre.y())
                            ? model.sampler(centre.x(), centre.y()).value(r.u)
                            : std::numeric_limits<double>::quiet_NaN();
  if (load.point)
    r.load_point_deflection = model.sampler(load.point->x, load.point->y).value(r.u);
  else if (load.patch)
    r.load_point_deflection = model.sampler(load.patch->x, load.patch->y).value(r.u);
  else
    r.load_point_deflection = r.center_deflection;
  for (int n = 0; n < model.mesh().node_count(); ++n)
    if (const int eq = model.dofs().equation(n, 2); eq >= 0)
      r.max_abs_deflection = std::max(r.max_abs_deflection, std::abs(r.u(eq)));
  return r;
}

StaticResult solve_static(const DiscretePlate& model, const StaticLoad& load) {
  if (model.boundary().has_unilateral()) {
    UnilateralSolution s = solve_unilateral_static(model, load);
    StaticResult r = static_result(model, load, std::move(s.u));
    r.support_contacts = std::move(s.contacts);
    r.contact_set_solves = s.iterations;
    return r;
  }
  const SparseMatrix K = model.stiffness();
  const SpdSolver solver = factor_stiffness(model, K);
  Eigen::VectorXd u = solver.solve(static_load_vector(model, load));
  if (!u.allFinite())
    throw InsufficientRestraint("the static solution is not finite: " + restraint_advice(model));
  return static_result(model, load, std::move(u));
}

} // namespace plyimpact
