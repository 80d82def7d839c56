#include "plyimpact/fem/stacked_damage.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace plyimpact {

namespace {

/// `into` becomes `first` (a sub-laminate's), its ply numbered in the laminate, unless it already holds one.
void take_first(const std::optional<PlyDamageView::FirstDamage>& first, int first_ply,
                std::optional<PlyDamageView::FirstDamage>& into) {
  if (into || !first) return;
  into = *first;
  into->ply += first_ply;
}

} // namespace

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
    take_first(part.first_damage(), first_ply_[k], first_);
    for (const DamageMode m : all_damage_modes)
      take_first(part.first_damage_by_mode()[m], first_ply_[k], first_by_mode_[m]);
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

StrengthReduction StackedDamageField::strength_reduction() const {
  StrengthReduction r;
  if (parts_ == nullptr) return r;
  for (const DamageField& part : *parts_) {
    const StrengthReduction p = part.strength_reduction();
    r.elements = std::max(r.elements, p.elements);
    keep_larger_reduction(r.largest, p.largest);
    keep_larger_reduction(r.largest_where_damaged, p.largest_where_damaged);
  }
  return r;
}

} // namespace plyimpact
