#include "plyimpact/fem/stacked_damage.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace plyimpact {

StackedDamageField::StackedDamageField(std::vector<int> first_ply, int plies, int elements)
    : first_ply_(std::move(first_ply)), ply_area_(static_cast<std::size_t>(plies), 0.0),
      counted_(static_cast<std::size_t>(elements) * 9, 0) {}

void StackedDamageField::gather(const std::vector<DamageField>& parts) {
  if (parts.size() != first_ply_.size())
    throw std::logic_error("stacked damage: one damage field per sub-laminate expected");
  parts_ = &parts;
  dissipated_ = {};
  active_elements_ = 0;
  std::fill(ply_area_.begin(), ply_area_.end(), 0.0);
  for (const int i : marked_)
    counted_[static_cast<std::size_t>(i)] = 0;
  marked_.clear();
  projected_area_ = 0.0;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const DamageField& part = parts[k];
    for (const DamageMode m : all_damage_modes)
      dissipated_[m] += part.dissipated()[m];
    active_elements_ += part.active_elements();
    const std::vector<double>& area = part.ply_damage_area();
    for (std::size_t j = 0; j < area.size(); ++j)
      ply_area_.at(static_cast<std::size_t>(first_ply_[k]) + j) += area[j];
    for (const DamagedPoint& p : part.damaged_points()) { // the union over the sub-laminates
      const int i = p.element * 9 + p.point;
      if (counted_[static_cast<std::size_t>(i)] != 0) continue;
      counted_[static_cast<std::size_t>(i)] = 1;
      marked_.push_back(i);
      projected_area_ += p.area;
    }
    if (!first_ && part.first_damage()) {
      first_ = *part.first_damage();
      first_->ply += first_ply_[k];
    }
  }
}

std::vector<ElementPlyDamage> StackedDamageField::element_ply_damage() const {
  std::vector<ElementPlyDamage> out;
  if (parts_ == nullptr) return out;
  for (std::size_t k = 0; k < parts_->size(); ++k)
    for (ElementPlyDamage e : (*parts_)[k].element_ply_damage()) {
      e.ply += first_ply_[k];
      out.push_back(e);
    }
  return out;
}

} // namespace plyimpact
