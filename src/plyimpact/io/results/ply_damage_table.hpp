#pragma once
// The plies' damage of a progressive-damage run (fem/damaged_plate.hpp) as a dense table for the outputs
// (ParaView cell data, damage_elements.csv): the largest damage variable of each mode over an element's
// integration points, for every element and ply. DamageField::element_ply_damage() lists only the
// elements that evaluated the damage law; every other element and ply is undamaged (0).
#include "plyimpact/fem/damaged_plate.hpp"

#include <vector>

namespace plyimpact {

class PlyDamageTable {
public:
  /// `plies`: the most plies of any laminate of the model. Throws std::invalid_argument for an entry of
  /// `list` outside [0, elements) × [0, plies).
  PlyDamageTable(int elements, int plies, const std::vector<ElementPlyDamage>& list);
  /// The table of a model: its element count and the most plies of its laminates.
  PlyDamageTable(const DiscretePlate& model, const std::vector<ElementPlyDamage>& list);

  [[nodiscard]] int elements() const { return elements_; }
  [[nodiscard]] int plies() const { return plies_; }
  /// d_ft, d_fc, d_mt, d_mc of ply `ply` (0-based) in element e.
  [[nodiscard]] const PerDamageMode& of(int ply, int e) const;
  /// The largest of the four damage variables of ply `ply` (0-based) in element e.
  [[nodiscard]] double largest(int ply, int e) const;
  /// The largest damage variable of any ply and mode in element e (the projected damage).
  [[nodiscard]] double projected(int e) const;

private:
  int elements_ = 0, plies_ = 0;
  std::vector<PerDamageMode> damage_; ///< [ply · elements + e]
};

/// The most plies of any laminate of the model.
[[nodiscard]] int most_plies(const DiscretePlate& model);

} // namespace plyimpact
