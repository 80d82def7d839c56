#pragma once
// Edge restraints of the rectangular plate (SPEC §3, thesis §3.2.2 f and Annex 2).
#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace plyimpact {

/// The four plate edges: x = 0, x = a, y = 0, y = b.
enum class Edge { x0 = 0, xa = 1, y0 = 2, yb = 3 };

/// Which of the five nodal DOFs (u, v, w, θx, θy) are fixed on a set of nodes.
struct Restraint {
  std::array<bool, 5> fixed{};
  [[nodiscard]] std::string code() const; ///< "uvwθxθy" as 0/1, e.g. "01101"
  friend bool operator==(const Restraint&, const Restraint&) = default;
};

/// Named edge types: free = 00000; clamped = 11111; ss (hard simple support: w, tangential in-plane
/// displacement and tangential rotation) = 01101 on x-edges, 10110 on y-edges; ss-soft = 00100.
/// Or an explicit 5-character code of 0/1. Returns nullopt for anything else.
[[nodiscard]] std::optional<Restraint> parse_restraint(std::string_view text, Edge edge);

/// Restraints of the four edges; `corners`, when given, replaces the edge codes at the 4 corner nodes
/// (Annex 2 fixes its corners fully while the edges carry 10101). Otherwise a corner node gets the
/// union of its two edges' restraints.
struct BoundaryConditions {
  std::array<Restraint, 4> edges{};
  std::optional<Restraint> corners;
  [[nodiscard]] const Restraint& edge(Edge e) const { return edges[static_cast<int>(e)]; }
};

[[nodiscard]] std::string_view to_string(Edge e);

} // namespace plyimpact
