#pragma once
// Restraints on named sets of the mesh (SPEC §3, thesis §3.2.2 f and Annex 2).
//
// Each set gets a type: free = 00000; clamped = 11111; ss (hard simple support: w, the tangential
// in-plane displacement and the tangential rotation) = 01101 on an edge along y (x = const), 10110 on an
// edge along x; ss-soft = 00100; or an explicit 5-character code of 0/1 for (u, v, w, θx, θy).
// "unilateral" is a support the plate rests on and may lift off (w ≤ 0 with w positive in the impact
// direction, SPEC §1): no bilateral restraint here; the static analysis solves its contact set.
// A node on several sets gets the union of their restraints; `corners`, when given, replaces it on the
// mesh's "corners" node set (Annex 2 fixes its corners fully while the edges carry 10101).
#include "plyimpact/fem/mesh.hpp"

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace plyimpact {

/// The four edges of the structured rectangle: x = 0, x = a, y = 0, y = b.
enum class Edge { x0 = 0, xa = 1, y0 = 2, yb = 3 };
[[nodiscard]] std::string_view to_string(Edge e);

/// Direction of a straight edge, which decides what "ss" fixes on it.
enum class EdgeDirection { along_x, along_y };

/// Which of the five nodal DOFs (u, v, w, θx, θy) are fixed on a set of nodes.
struct Restraint {
  std::array<bool, 5> fixed{};
  [[nodiscard]] std::string code() const; ///< "uvwθxθy" as 0/1, e.g. "01101"
  friend bool operator==(const Restraint&, const Restraint&) = default;
};

/// A type name or a code for an edge of the given direction; nullopt when `text` is neither.
[[nodiscard]] std::optional<Restraint> parse_restraint(std::string_view text, EdgeDirection direction);
/// The same for an edge of the structured rectangle (x0, xa run along y; y0, yb along x).
[[nodiscard]] std::optional<Restraint> parse_restraint(std::string_view text, Edge edge);
/// True for free | clamped | ss | ss-soft | unilateral | a 5-character code of 0/1.
[[nodiscard]] bool is_restraint_type(std::string_view text);

/// The type of a support that only pushes: the plate rests on it and may lift off.
inline constexpr std::string_view unilateral_support = "unilateral";

/// The type given to one named set of the mesh (an edge set, or a node set for types other than ss).
struct SetRestraint {
  std::string set;
  std::string type;
  friend bool operator==(const SetRestraint&, const SetRestraint&) = default;
};

struct BoundaryConditions {
  std::vector<SetRestraint> sets;   ///< in the order given
  std::optional<Restraint> corners; ///< replaces the union on the "corners" node set

  /// The four edges x0, xa, y0, yb of the structured rectangle.
  [[nodiscard]] static BoundaryConditions on_edges(std::string_view x0, std::string_view xa,
                                                   std::string_view y0, std::string_view yb);
  /// The type of `set`, nullptr when it has none.
  [[nodiscard]] const SetRestraint* find(std::string_view set) const;
  /// Gives `set` the type `type` (replacing an earlier one).
  void set(std::string_view set, std::string_view type);
  /// True when a set rests on a unilateral support.
  [[nodiscard]] bool has_unilateral() const;
  friend bool operator==(const BoundaryConditions&, const BoundaryConditions&) = default;
};

/// Throws std::invalid_argument when `bc` has a unilateral support, which only the linear static analysis
/// solves; the message names the set and the bilateral stand-in ("ss-soft") for `analysis`.
void require_bilateral(const BoundaryConditions& bc, std::string_view analysis);

/// The restraint of one set on `mesh`. Throws std::invalid_argument for an unknown set, an invalid type,
/// or ss on a set that is not a straight edge along x or y (curved edges need rotated DOFs).
[[nodiscard]] Restraint resolve_restraint(const Mesh& mesh, const SetRestraint& s);

/// The nodes of the unilateral sets whose w no bilateral set holds, in increasing order.
[[nodiscard]] std::vector<int> unilateral_nodes(const Mesh& mesh, const BoundaryConditions& bc);

/// The restraint of every node of `mesh` (index = node).
[[nodiscard]] std::vector<Restraint> node_restraints(const Mesh& mesh, const BoundaryConditions& bc);

} // namespace plyimpact
