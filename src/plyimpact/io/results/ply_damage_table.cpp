#include "plyimpact/io/results/ply_damage_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace plyimpact {

int most_plies(const DiscretePlate& model) {
  std::size_t plies = 0;
  for (const Laminate& lam : model.laminates())
    plies = std::max(plies, lam.ply_count());
  return static_cast<int>(plies);
}

PlyDamageTable::PlyDamageTable(int elements, int plies, const std::vector<ElementPlyDamage>& list)
    : elements_(elements), plies_(plies), damage_(static_cast<std::size_t>(std::max(elements, 0)) *
                                                  static_cast<std::size_t>(std::max(plies, 0))) {
  for (const ElementPlyDamage& d : list) {
    if (d.element < 0 || d.element >= elements || d.ply < 0 || d.ply >= plies)
      throw std::invalid_argument(
          fmt::format("ply damage of element {} ply {} outside the model ({} elements, "
                      "{} plies; both 0-based)",
                      d.element, d.ply, elements, plies));
    damage_[static_cast<std::size_t>(d.ply) * static_cast<std::size_t>(elements) +
            static_cast<std::size_t>(d.element)] = d.damage;
  }
}

PlyDamageTable::PlyDamageTable(const DiscretePlate& model, const std::vector<ElementPlyDamage>& list)
    : PlyDamageTable(model.mesh().element_count(), most_plies(model), list) {}

const PerDamageMode& PlyDamageTable::of(int ply, int e) const {
  return damage_.at(static_cast<std::size_t>(ply) * static_cast<std::size_t>(elements_) +
                    static_cast<std::size_t>(e));
}

double PlyDamageTable::largest(int ply, int e) const {
  const auto& v = of(ply, e).values;
  return *std::max_element(v.begin(), v.end());
}

double PlyDamageTable::projected(int e) const {
  double d = 0.0;
  for (int k = 0; k < plies_; ++k)
    d = std::max(d, largest(k, e));
  return d;
}

} // namespace plyimpact
