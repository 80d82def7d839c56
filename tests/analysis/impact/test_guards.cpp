// Numerical guards (docs/robustness.md): every guard provoked once, in one table, with the message it
// must give; plus independent checks of the numbers the guards rely on.
#include "plyimpact/analysis/impact/guards.hpp"
#include "plyimpact/analysis/impact/impact_case.hpp"
#include "plyimpact/analysis/plate_analyses/static_analysis.hpp"
#include "plyimpact/fem/structured_mesh.hpp"
#include "plyimpact/io/deck/deck.hpp"
#include "plyimpact/io/system/system_memory.hpp"
#include "support/decks.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace plyimpact::guards_tests {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double inf = std::numeric_limits<double>::infinity();

/// The thesis §3.6 plate (Table 3.1), 127 x 76.2 mm, simply supported, on an nx x ny mesh.
DiscretePlate thesis_plate(int nx, int ny, const BoundaryConditions& bc = test::all_edges("ss")) {
  return {test::laminate_of(test::thesis_3_6(), "[45/90/-45/0]3s", 0.19375e-3), PlateGeometry{0.127, 0.0762},
          MeshSpec{nx, ny}, bc};
}

/// The §3.6 plate on an nx x ny mesh struck by its 6.14 kg steel sphere at `velocity`, k = 0.6e9.
ImpactCaseDescription steel_sphere(double velocity, int nx = 5, int ny = 5) {
  ImpactCaseDescription d;
  d.plate = PlateGeometry{0.127, 0.0762};
  d.mesh = MeshSpec{nx, ny};
  d.laminates = {test::laminate_of(test::thesis_3_6(), "[45/90/-45/0]3s", 0.19375e-3)};
  d.boundary = test::all_edges("ss");
  d.impactor.mass = 6.14;
  d.impactor.radius = 12.7e-3;
  d.impactor.velocity = velocity;
  d.impactor.x = 0.127 / 2;
  d.impactor.y = 0.0762 / 2;
  d.contact.k = 0.6e9;
  d.time.dt = 1e-6;
  d.time.end = 20e-6;
  return d;
}

/// What a guard says: the message of the exception thrown, else the warnings given, else nothing.
using Provoke = std::function<std::vector<std::string>()>;

std::vector<std::string> thrown_by(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return {e.what()};
  }
  return {};
}

std::vector<std::string> warning_of(const std::optional<std::string>& w) {
  return w ? std::vector<std::string>{*w} : std::vector<std::string>{};
}

Laminate two_plies(const Material& m, double t2) {
  return Laminate({m}, {{0.0, 0.125e-3, 0}, {90.0, t2, 0}});
}

struct GuardCase {
  const char* name;
  Provoke provoke;
  std::vector<std::string> expected; ///< parts of the one message; empty: the guard must stay silent
};

// The Hertz contact time of the 6.14 kg, 2.68 m/s, k = 0.6e9 case, by hand: α_m = (5 m v²/4k)^0.4 =
// 1.5321e-3 m, t_c = 2.9433 α_m / v = 1.6826e-3 s; t_c/50 = 33.65 µs. The constant
// 2∫₀¹ dx/√(1 − x^2.5) = 2.94328 by midpoint quadrature (x = 1 − u², 2e6 points).
const std::vector<GuardCase>& guard_cases() {
  static const std::vector<GuardCase> cases{
      {"insufficient restraint: free plate in a static solve",
       [] {
         BoundaryConditions free;
         const DiscretePlate m = thesis_plate(3, 3, free);
         StaticLoad load;
         load.pressure = 1e3;
         return thrown_by([&] { (void)solve_static(m, load); });
       },
       {"insufficient restraint", "rigid body", "Restrain it"}},
      {"zero ply thickness",
       [] { return thrown_by([] { (void)two_plies(test::t300_976(), 0.0); }); },
       {"ply 2 has thickness 0 m", "give every ply a positive thickness"}},
      {"negative ply thickness",
       [] { return thrown_by([] { (void)two_plies(test::t300_976(), -1e-4); }); },
       {"ply 2 has thickness -0.0001 m"}},
      {"non-positive-definite ply: nu12^2 > E1/E2",
       [] {
         Material m = test::isotropic(70e9, 0.3, 2700);
         m.E1 = 4 * m.E2; // sqrt(E1/E2) = 2
         m.nu12 = 2.5;    // 1 - nu12^2 E2/E1 = 1 - 6.25/4 = -0.5625
         return thrown_by([&] { (void)two_plies(m, 0.125e-3); });
       },
       {"not positive definite", "1 - nu12*nu21 = -0.5625", "sqrt(E1/E2) = 2", "lower nu12"}},
      {"non-positive-definite ply in a deck: located",
       [] {
         return thrown_by([] {
           (void)parse_deck("[materials.m]\nE1 = 40e9\nE2 = 10e9\nG12 = 5e9\nnu12 = 2.5\nrho = 1500\n",
                            "deck.toml");
         });
       },
       {"deck.toml:5:8: error: material 'm' is not physical", "1 - nu12*nu21 = -0.5625"}},
      {"zero shear modulus",
       [] {
         Material m = test::t300_976();
         m.G23 = 0.0;
         return thrown_by([&] { (void)two_plies(m, 0.125e-3); });
       },
       {"material 'T300_976' of ply 1: G23 = 0 Pa"}},
      {"non-finite contact force in an impact step",
       [] {
         // 1e300 m/s: the first predicted indentation is 1e294 m and k α^1.5 overflows.
         return thrown_by([&] { (void)ImpactCase(steel_sphere(1e300)).run(); });
       },
       {"non-finite contact force Fc [N] at step 1 (t = 1e-06 s): contact force Fc [N] = inf"}},
      {"non-finite impactor velocity named with step and time",
       [] {
         return thrown_by([] {
           check_finite_step(
               42, 4.2e-5,
               {{"contact force Fc [N]", 1.0}, {"impactor velocity [m/s]", nan}, {"ws [m]", inf}});
         });
       },
       {"non-finite impactor velocity [m/s] at step 42 (t = 4.2e-05 s)"}},
      {"NaN in the full plate state vector",
       [] {
         Eigen::VectorXd u = Eigen::VectorXd::Ones(10);
         u(7) = nan;
         return thrown_by([&] { check_finite_vector(300, 3e-4, "plate displacement u", u); });
       },
       {"non-finite plate displacement u at step 300 (t = 0.0003 s): entry 7 of 10 is nan"}},
      {"coarse time step: t_c/10",
       [] { return warning_of(time_step_warning(6.14, 2.68, 0.6e9, 1.6826e-3 / 10)); },
       {"gives only 10.0 steps", "t_c = 0.001683 s", "use time.dt <= 3.365e-05 s (t_c/50)"}},
      {"time step just fine: t_c/51",
       [] { return warning_of(time_step_warning(6.14, 2.68, 0.6e9, 1.6826e-3 / 51)); },
       {}},
      {"impact point on an element corner: centre of an even 4 x 4 mesh",
       [] {
         return warning_of(impact_point_warning(structured_rectangle({0.1, 0.1}, 4, 4), 0.05, 0.05));
       },
       {"(0.05, 0.05) m lies on an element corner of the 4 x 4 mesh", "Change mesh.nx/mesh.ny"}},
      {"impact point on an element edge",
       [] {
         return warning_of(impact_point_warning(structured_rectangle({0.1, 0.1}, 4, 4), 0.05, 0.03));
       },
       {"lies on an element edge of the 4 x 4 mesh"}},
      {"impact point inside an element: centre of an odd 5 x 5 mesh",
       [] {
         return warning_of(impact_point_warning(structured_rectangle({0.1, 0.1}, 5, 5), 0.05, 0.05));
       },
       {}},
      {"impact warnings reach the result",
       [] {
         ImpactCaseDescription d = steel_sphere(2.68, 4, 4);
         d.time.dt = 1e-4; // 16.8 steps over t_c
         d.time.end = 2e-4;
         d.contact.load = ContactLoad::point; // the corner warning is the point load's
         return ImpactCase(d).run().warnings;
       },
       {"time.dt = 0.0001 s gives only 16.8 steps", "lies on an element corner of the 4 x 4 mesh",
        "the contact is not resolved"}},
      {"no corner warning for the Hertz pressure, integrated over every element its circle touches",
       [] {
         ImpactCaseDescription d = steel_sphere(2.68, 4, 4);
         d.time.end = 2e-5;
         std::vector<std::string> said = ImpactCase(d).run().warnings;
         std::erase_if(
             said, // only the boundary warning is in question here
             [](const std::string& w) { return w.find("lies on an element") == std::string::npos; });
         return said;
       },
       {}},
      {"time.end shorter than one time step: refused before the factorization, not clamped",
       [] {
         ImpactCaseDescription d = steel_sphere(2.68);
         d.time.end = 0.5e-6; // dt = 1e-6
         return thrown_by([&] { const ImpactCase impact(d); });
       },
       {"impact: time.end = 5e-07 s is shorter than one time step, time.dt = 1e-06 s",
        "Set [time] end to at least 1e-06 s"}},
      {"time.end of exactly one time step runs",
       [] {
         ImpactCaseDescription d = steel_sphere(2.68);
         d.time.end = 1e-6;
         return thrown_by([&] { (void)ImpactCase(d).run(); });
       },
       {}},
      {"energy balance error above 1 %: suspect, with the Δt to use",
       // The §3.6 impactor (t_c = 1.683 ms, see above) with Δt = 0.1 s: 0.0168 steps per contact.
       [] { return warning_of(energy_balance_reason(7.977, 22.05, 6.14, 2.68, 0.6e9, 0.1)); },
       {"energy balance error 176 J, 798 % of the initial kinetic energy 22.05 J (tolerance 1 %)",
        "t_c = 0.001683 s, 0.0168 steps of time.dt = 0.1 s", "lower [time] dt to t_c/50 = 3.365e-05 s"}},
      {"energy balance error above 1 % with the contact resolved: suspect, with half the step to try",
       // The same impactor with Δt = 1 µs: 1 683 steps per contact, so Δt of the contact is not the cause.
       [] { return warning_of(energy_balance_reason(0.02, 22.05, 6.14, 2.68, 0.6e9, 1e-6)); },
       {"2 % of the initial kinetic energy 22.05 J",
        "1.68e+03 steps of time.dt = 1e-06 s, enough for the contact",
        "run again with [time] dt = 5e-07 s (half)"}},
      {"energy balance error above 1 % where the plate dissipated most of the energy: a collapse",
       [] {
         return warning_of(
             energy_balance_reason(0.349, 6.5, 2.0, 2.55, 2e9, 1e-7, 1.5, {ContactLoad::point, 0.62, 1}));
       },
       {"34.9 % of the initial kinetic energy 6.5 J",
        "Likely cause: the plate collapsed under the impactor (62 % of the impact energy dissipated in the "
        "plate; contact episodes: 1)"}},
      {"energy balance error above 1 % after 41 contact episodes: a collapse",
       [] {
         return warning_of(energy_balance_reason(0.349, 6.5, 2.0, 2.55, 2e9, 1e-7, 1.5,
                                                 {ContactLoad::hertz_pressure, 0.2, 41}));
       },
       {"(20 % of the impact energy dissipated in the plate; contact episodes: 41)"}},
      {"energy balance error above 1 % with the Hertz pressure load: its balance term, try the point load",
       [] {
         return warning_of(energy_balance_reason(0.012, 22.05, 6.14, 2.68, 0.6e9, 1e-6, 1.5,
                                                 {ContactLoad::hertz_pressure, 0.05, 1}));
       },
       {"Likely cause: the Hertz pressure load's own balance term", "[contact] load = \"point\""}},
      {"energy balance error of 0.99 %: not suspect",
       [] { return warning_of(energy_balance_reason(0.0099, 22.05, 6.14, 2.68, 0.6e9, 1e-6)); },
       {}},
      {"linear run deflected by 1/3 of the thickness: suggest nonlinear = true",
       [] { return warning_of(large_deflection_warning(1.0e-3, 3.0e-3)); },
       {"the peak deflection 1 mm is 0.333 times the laminate thickness h = 3 mm in a linear run",
        "Set nonlinear = true"}},
      {"linear run deflected by 0.3 h: no warning",
       [] { return warning_of(large_deflection_warning(0.9e-3, 3.0e-3)); },
       {}},
      // Selective scaling keeps the faces' added relative inertia after they crack (docs/validation.md §20):
      // the run warns once an interface has delaminated where plies broke, not before, not unscaled.
      {"selective scaling, delaminated interfaces over broken plies",
       [] { return warning_of(selective_scaling_after_drop_warning(51.3, 1.31e-6, 1.0e-3)); },
       {"interfaces delaminated (1.31 mm^2) where plies broke", "(51.3 times the unscaled)",
        "Read the results up to the load drop (F_d)", "docs/validation.md §20"}},
      {"selective scaling, delaminated interfaces, no broken ply: no warning",
       [] { return warning_of(selective_scaling_after_drop_warning(51.3, 1.31e-6, 0.0)); },
       {}},
      {"selective scaling, broken plies, no delamination: no warning",
       [] { return warning_of(selective_scaling_after_drop_warning(51.3, 0.0, 1.0e-3)); },
       {}},
      {"no selective scaling: no warning",
       [] { return warning_of(selective_scaling_after_drop_warning(0.0, 1.31e-6, 1.0e-3)); },
       {}},
      {"factorization larger than the available memory",
       [] {
         ImpactCaseDescription d = steel_sphere(2.68, 15, 11);
         d.memory_limit_bytes = 1e5;
         return thrown_by([&] { const ImpactCase impact(d); });
       },
       {"the factorization of K̄ (1927 equations", "MB but only 0.1 MB are available", "coarser mesh"}},
      {"factorization within the available memory",
       [] {
         ImpactCaseDescription d = steel_sphere(2.68, 15, 11);
         d.memory_limit_bytes = 1e9;
         return thrown_by([&] { const ImpactCase impact(d); });
       },
       {}},
  };
  return cases;
}

TEST(Guards, EveryGuardGivesItsMessageAndOnlyWhenDue) {
  for (const GuardCase& c : guard_cases()) {
    SCOPED_TRACE(c.name);
    const std::vector<std::string> said = c.provoke();
    if (c.expected.empty()) {
      EXPECT_TRUE(said.empty()) << said.front();
      continue;
    }
    std::string all;
    for (const auto& s : said)
      all += s + "\n";
    for (const std::string& part : c.expected)
      EXPECT_NE(all.find(part), std::string::npos) << "missing \"" << part << "\" in:\n" << all;
  }
}

TEST(Guards, HertzContactTimeMatchesTheRigidTargetIntegration) {
  // t_c of the guard (closed form, SPEC §4 loading law) against the contact duration the Newmark
  // integration of the impactor on a rigid target finds with Δt = t_c/20000 and an elastic law.
  const double t_c = hertz_contact_time(6.14, 2.68, 0.6e9);
  EXPECT_NEAR(t_c, 1.6826e-3, 0.0001e-3); // by hand, see guard_cases()
  ImpactCaseDescription d = steel_sphere(2.68, 1, 1);
  d.plate.rigid = true;
  d.contact.unloading = UnloadingLaw::elastic;
  d.time.dt = t_c / 20000;
  d.time.end = 1.2 * t_c;
  const ImpactResult r = ImpactCase(d).run();
  std::printf("  Hertz contact time %.6e s, rigid-target integration %.6e s\n", t_c, r.contact_duration);
  EXPECT_NEAR(r.contact_duration, t_c, 2 * *d.time.dt);
}

TEST(Guards, FactorMemoryEstimateLiesBetweenTheMatrixAndTheDenseTriangle) {
  // L has at least the pattern of A's strict lower triangle and at most n(n-1)/2 entries.
  const DiscretePlate m = thesis_plate(8, 6);
  const SparseMatrix K = m.stiffness();
  const FactorMemoryEstimate e = estimate_factor_memory(K);
  const long n = K.rows();
  const long lower = (K.nonZeros() - n) / 2;
  std::printf("  %ld equations, nnz(A) = %ld, nnz(L) = %ld (fill %.2f), %.3g MB\n", n, e.matrix_nonzeros,
              e.factor_nonzeros, static_cast<double>(e.factor_nonzeros) / static_cast<double>(lower),
              e.bytes / 1e6);
  EXPECT_EQ(e.equations, n);
  EXPECT_GE(e.factor_nonzeros, lower);
  EXPECT_LE(e.factor_nonzeros, n * (n - 1) / 2);
  // Equal to the factor that is actually computed.
  SpdSolver solver;
  solver.factorize(K);
  EXPECT_EQ(e.factor_nonzeros, solver.factor_nonzeros());
  EXPECT_DOUBLE_EQ(e.bytes, 12.0 * static_cast<double>(e.factor_nonzeros + n + 3 * e.matrix_nonzeros));
}

TEST(Guards, MemAvailableIsReadInBytes) {
  EXPECT_EQ(mem_available_from_meminfo("MemTotal:  16000 kB\nMemFree:  100 kB\nMemAvailable:    2048 kB\n"),
            2048.0 * 1024.0);
  EXPECT_FALSE(mem_available_from_meminfo("MemTotal: 16000 kB\n").has_value());
}

} // namespace
} // namespace plyimpact::guards_tests
