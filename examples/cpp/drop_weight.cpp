// One impact through the engine's facade, as a program of your own would run it: read a deck, build the
// case (plate, mesh, step policy: analysis/impact/impact_case.hpp), run it, print what a test lab reads off a
// drop-weight test. Then the same plate struck at twice the energy (the case is built once; each run
// changes only the impactor).
#include "plyimpact/analysis/impact/impact_case.hpp"
#include "plyimpact/io/deck/case_from_deck.hpp"
#include "plyimpact/io/deck/deck.hpp"

#include <cmath>
#include <cstdio>
#include <exception>

namespace {

void print(const char* label, const plyimpact::ImpactResult& r, double energy_J) {
  std::printf("%s: energy %.4g J, peak force %.6g N at %.6g ms, contact %.6g ms, deflection %.6g mm, "
              "energy balance error %.2g\n",
              label, energy_J, r.peak_force, 1e3 * r.time_of_peak_force, 1e3 * r.contact_duration,
              1e3 * r.peak_contact_deflection, r.energy_balance_error);
}

} // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: drop_weight DECK.toml\n");
    return 2;
  }
  try {
    const plyimpact::Deck deck = plyimpact::load_deck(argv[1]);
    const plyimpact::ImpactCase impact(plyimpact::impact_case_description(deck));
    plyimpact::Impactor impactor = impact.description().impactor;
    const auto energy = [&] { return 0.5 * impactor.mass * impactor.velocity * impactor.velocity; };
    print("deck", impact.run(), energy());
    impactor.velocity *= std::sqrt(2.0);
    print("twice the energy", impact.run({.impactor = impactor}), energy());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "drop_weight: %s\n", e.what());
    return 1;
  }
}
