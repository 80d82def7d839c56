// The peak force of the default deck does not depend on where the impactor lands relative to the nodes
// (issue 16). A deck that gives only the plate, its laminate and supports, and the impactor runs MITC9
// with the Hertz pressure on a mesh graded toward the impact point; its peak force, time of peak and
// contact duration must lie within 1 % of the Navier modal reference of the same problem (Hertz pressure
// of radius √(Rα), the same contact law; tests/support/navier_impact.hpp, converged in modes and Δt:
// docs/notes/contact-reference.md §2) with the impact point on the element-centre node, a mid-side
// node, a corner node and an arbitrary point of its element (mesh.impact_offset).
#include "plyimpact/io/deck/case_from_deck.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <array>
#include <cstdio>
#include <string>
#include <tuple>
#include <vector>

namespace plyimpact::mesh_objective_impact_tests {
namespace {

struct Reference {
  const char* name;
  const char* layup;
  double ply_thickness;
  const char* impactor;                      // [impactor] keys
  const char* contact;                       // [contact] keys
  const char* time;                          // [time] keys
  double peak_force, time_of_peak, duration; // Navier reference [N], [s], [s]
};

// (i) thesis §3.6: [45/90/-45/0]3s, 6.14 kg at 2.68 m/s; (ii) §4.2 plate [0_2/90_4/0_2] hit by 0.314 kg
// at 2.92 m/s; (iii) the same plate hit by an 8.4 g steel ball (R = 6.35 mm) at 3 m/s, k = auto.
// (iii) ends at 400 µs instead of the end-of-event rule's 1.2 ms of free vibration: the contact is over
// at 135 µs, and the three numbers are those of the contact.
constexpr std::array<Reference, 3> cases{{
    {"i", "[45/90/-45/0]3s", 0.19375e-3, "mass = 6.14\nradius = 12.7e-3\nE = 207e9\nvelocity = 2.68",
     "k = 0.6e9", "end = \"auto\"", 12878.0, 2050.7e-6, 4269.4e-6},
    {"ii", "[0_2/90_4/0_2]", 0.58125e-3, "mass = 0.314\nradius = 12.7e-3\nE = 207e9\nvelocity = 2.92",
     "k = 0.6e9", "end = \"auto\"", 2544.06, 615.46e-6, 1451.44e-6},
    {"iii", "[0_2/90_4/0_2]", 0.58125e-3,
     "density = 7850.0\nradius = 6.35e-3\nE = 207e9\nnu = 0.3\nvelocity = 3.0", "k = \"auto\"",
     "end = 400e-6", 447.94, 52.604e-6, 134.98e-6},
}};

/// The deck of a case: Table 3.1 material, 127 × 76.2 mm, hard simply supported, Tan–Sun unloading with
/// the defaults (q = 2.5, β = 0.094, α_cr = 1.7e-4 m); `mesh` holds only where the point lies.
std::string default_deck(const Reference& c, const std::string& mesh) {
  return fmt::format(R"(
analysis = "impact"
[materials.thesis_3_6]
E1 = 129.0e9
E2 = 7.5e9
G12 = 3.5e9
G13 = 3.5e9
G23 = 3.5e9
nu12 = 0.33
rho = 1540.0
[laminate]
material = "thesis_3_6"
layup = "{}"
ply_thickness = {}
[plate]
a = 0.127
b = 0.0762
{}
[boundary]
x0 = "ss"
xa = "ss"
y0 = "ss"
yb = "ss"
[impactor]
{}
[contact]
{}
[time]
{}
)",
                     c.layup, c.ply_thickness, mesh, c.impactor, c.contact, c.time);
}

/// The time of peak force as the middle of the interval around the maximum where F ≥ 0.995 F_max (the
/// contiguous one: a heavy impactor's force has several humps). The sampled maximum of a
/// light impactor's flat peak is ill-conditioned: in case (iii) F changes by 0.02 % over ±1 µs (2 % of
/// t_F) around it, less than the FE model's own 0.1 % force error, so the argmax wanders by ±1 µs with
/// the mesh while the curve does not (docs/validation.md).
double plateau_midpoint(const ImpactResult& r) {
  const auto& h = r.history;
  std::size_t peak = 0;
  for (std::size_t i = 1; i < h.size(); ++i)
    if (h[i].force > h[peak].force) peak = i;
  std::size_t first = peak, last = peak;
  while (first > 0 && h[first - 1].force >= 0.995 * h[peak].force)
    --first;
  while (last + 1 < h.size() && h[last + 1].force >= 0.995 * h[peak].force)
    ++last;
  return 0.5 * (h[first].t + h[last].t);
}

struct Placement {
  const char* name;
  double ox, oy; // mesh.impact_offset: where the impact point lies in its element
};

constexpr std::array<Placement, 4> placements{{
    {"centre_node", 0.5, 0.5},
    {"mid_side_node", 0.5, 0.0},
    {"corner_node", 0.0, 0.0},
    {"arbitrary_point", 0.3, 0.17},
}};

using Param = std::tuple<std::size_t, std::size_t>; // case, placement

class DefaultDeck : public ::testing::TestWithParam<Param> {};

TEST_P(DefaultDeck, GivesTheNavierPeakForceWhereverTheImpactorLands) {
  const Reference& c = cases[std::get<0>(GetParam())];
  const Placement& p = placements[std::get<1>(GetParam())];
  const std::string mesh = fmt::format("[mesh]\nimpact_offset = [{}, {}]", p.ox, p.oy);
  const Deck deck = parse_deck(default_deck(c, mesh), "default.toml");
  const ImpactCase impact(impact_case_description(deck));
  EXPECT_TRUE(impact.settings().mesh.graded);
  EXPECT_EQ(impact.settings().mesh.element, ElementFormulation::mitc9);
  EXPECT_EQ(impact.settings().contact.load, ContactLoad::hertz_pressure);
  RunRequest request;
  request.history_every = 1;
  const ImpactResult r = impact.run(request);
  const double t_band = plateau_midpoint(r);
  std::printf("  case (%s), %s: %d elements, dt = %.3g us: F = %.2f N (%+.3f %%), t_F = %.2f us (%+.3f %%; "
              "sampled maximum %.2f us, %+.3f %%), T_c = %.2f us (%+.3f %%)\n",
              c.name, p.name, impact.settings().mesh.elements, impact.settings().dt * 1e6, r.peak_force,
              100.0 * (r.peak_force / c.peak_force - 1.0), t_band * 1e6,
              100.0 * (t_band / c.time_of_peak - 1.0), r.time_of_peak_force * 1e6,
              100.0 * (r.time_of_peak_force / c.time_of_peak - 1.0), r.contact_duration * 1e6,
              100.0 * (r.contact_duration / c.duration - 1.0));
  EXPECT_NEAR(r.peak_force, c.peak_force, 0.01 * c.peak_force);
  EXPECT_NEAR(t_band, c.time_of_peak, 0.01 * c.time_of_peak);
  EXPECT_NEAR(r.contact_duration, c.duration, 0.01 * c.duration);
  // No mesh or time-step guard fires. Case (i) is the §3.6 impact, deflected by 0.63 h in this linear
  // run: its large-deflection warning (guards.hpp) is due and left aside here.
  std::vector<std::string> said = r.warnings;
  std::erase_if(said, [](const std::string& w) { return w.find("laminate thickness") != std::string::npos; });
  EXPECT_TRUE(said.empty()) << said.front();
}

INSTANTIATE_TEST_SUITE_P(Issue16, DefaultDeck,
                         ::testing::Combine(::testing::Range<std::size_t>(0, 3),
                                            ::testing::Range<std::size_t>(0, 4)),
                         [](const ::testing::TestParamInfo<Param>& param) {
                           return std::string("case_") + cases[std::get<0>(param.param)].name + "_" +
                                  placements[std::get<1>(param.param)].name;
                         });

} // namespace
} // namespace plyimpact::mesh_objective_impact_tests
