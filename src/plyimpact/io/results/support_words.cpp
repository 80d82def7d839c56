#include "plyimpact/io/results/support_words.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>

namespace plyimpact {

std::string held_dofs(std::string_view code) {
  constexpr std::array<std::string_view, 5> names = {"u", "v", "w", "θx", "θy"};
  std::string held;
  for (std::size_t i = 0; i < names.size() && i < code.size(); ++i)
    if (code[i] == '1') held += fmt::format("{}{}", held.empty() ? "" : ", ", names[i]);
  return held.empty() ? "nothing held" : held + " held";
}

std::string restraint_words(std::string_view type) {
  if (type == "free") return "free";
  if (type == "clamped") return "clamped (u, v, w, θx, θy held)";
  if (type == "ss")
    return "simply supported, hard (w, the slope along the edge and the displacement along it held)";
  if (type == "ss-soft") return "simply supported, soft (w held both ways)";
  if (type == unilateral_support) return "unilateral (w held against pressing only: it may lift off)";
  return fmt::format("{} ({})", type, held_dofs(type));
}

std::string SupportGroup::words() const {
  return fmt::format("{}: {}", fmt::join(sets, ", "), restraint_words(type));
}

std::vector<SupportGroup> support_groups(const BoundaryConditions& bc) {
  std::vector<SupportGroup> groups;
  for (const SetRestraint& r : bc.sets) {
    auto same = std::ranges::find_if(groups, [&](const SupportGroup& g) { return g.type == r.type; });
    if (same == groups.end())
      groups.push_back({r.type, {r.set}});
    else
      same->sets.push_back(r.set);
  }
  return groups;
}

std::string supports_in_words(const BoundaryConditions& bc) {
  if (bc.sets.empty() && !bc.corners) return "none (free plate)";
  std::string s;
  for (const SupportGroup& g : support_groups(bc))
    s += (s.empty() ? "" : "; ") + g.words();
  if (bc.corners) {
    const std::string code = bc.corners->code();
    s += fmt::format("{}corners: {} ({})", s.empty() ? "" : "; ", code, held_dofs(code));
  }
  return s;
}

} // namespace plyimpact
