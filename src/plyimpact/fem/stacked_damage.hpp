#pragma once
// The plies' damage of a stacked plate (fem/stacked_plate.hpp) whose sub-laminates each carry a damage
// field (fem/damaged_plate.hpp), seen as the one laminate they were cut from: sub-laminate k's ply j is
// the laminate's ply first_ply[k] + j, the dissipated energies are the sums over the sub-laminates, and the
// projected area is the union over every ply of every sub-laminate. The sub-laminates share the mesh and its
// 3×3 Gauss points, so the union is taken point by point.
#include "plyimpact/fem/damaged_plate.hpp"

#include <vector>

namespace plyimpact {

class StackedDamageField final : public PlyDamageView {
public:
  /// `first_ply[k]`: the laminate's index of sub-laminate k's first ply; `plies`: the laminate's ply count;
  /// `elements`: the mesh's element count.
  StackedDamageField(std::vector<int> first_ply, int plies, int elements);

  /// The view of `parts` (one field per sub-laminate, in the stack's order) as they stand after a commit;
  /// the view reads them again for element_ply_damage(), so they must outlive it unmoved.
  void gather(const std::vector<DamageField>& parts);

  [[nodiscard]] const PerDamageMode& dissipated() const override { return dissipated_; }
  [[nodiscard]] const std::vector<double>& ply_damage_area() const override { return ply_area_; }
  [[nodiscard]] double projected_damage_area() const override { return projected_area_; }
  [[nodiscard]] int active_elements() const override { return active_elements_; }
  /// Every sub-laminate's entries with their plies numbered in the laminate.
  [[nodiscard]] std::vector<ElementPlyDamage> element_ply_damage() const override;
  /// The first sub-laminate's first damage, in the step it first appeared anywhere.
  [[nodiscard]] const std::optional<FirstDamage>& first_damage() const override { return first_; }
  /// Per mode, the same: the first sub-laminate's, in the step the mode first appeared anywhere.
  [[nodiscard]] const FirstDamageByMode& first_damage_by_mode() const override { return first_by_mode_; }
  /// The largest reductions over the sub-laminates; `elements` is the most elements lowered in one of them
  /// (the sub-laminates share the mesh and their band limits differ only through their materials).
  [[nodiscard]] StrengthReduction strength_reduction() const override;

private:
  std::vector<int> first_ply_;
  const std::vector<DamageField>* parts_ = nullptr;
  PerDamageMode dissipated_;
  std::vector<double> ply_area_;
  double projected_area_ = 0.0;
  int active_elements_ = 0;
  std::optional<FirstDamage> first_;
  FirstDamageByMode first_by_mode_;
  std::vector<unsigned char> counted_; ///< [element · 9 + point]: already in projected_area_
  std::vector<int> marked_;            ///< the entries of counted_ set by the last gather()
};

} // namespace plyimpact
