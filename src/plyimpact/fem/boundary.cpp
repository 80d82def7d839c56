#include "plyimpact/fem/boundary.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace plyimpact {

std::string Restraint::code() const {
  std::string s;
  for (const bool f : fixed)
    s.push_back(f ? '1' : '0');
  return s;
}

std::string_view to_string(Edge e) {
  switch (e) {
  case Edge::x0:
    return "x0";
  case Edge::xa:
    return "xa";
  case Edge::y0:
    return "y0";
  case Edge::yb:
    return "yb";
  }
  return "?";
}

std::optional<Restraint> parse_restraint(std::string_view text, EdgeDirection direction) {
  std::string_view code;
  if (text == "free" || text == unilateral_support) // unilateral: held by the static analysis's contact set
    code = "00000";
  else if (text == "clamped")
    code = "11111";
  else if (text == "ss")
    code = direction == EdgeDirection::along_y ? "01101" : "10110";
  else if (text == "ss-soft")
    code = "00100";
  else
    code = text;
  if (code.size() != 5) return std::nullopt;
  Restraint r;
  for (std::size_t i = 0; i < 5; ++i) {
    if (code[i] != '0' && code[i] != '1') return std::nullopt;
    r.fixed[i] = code[i] == '1';
  }
  return r;
}

std::optional<Restraint> parse_restraint(std::string_view text, Edge edge) {
  const bool along_y = edge == Edge::x0 || edge == Edge::xa;
  return parse_restraint(text, along_y ? EdgeDirection::along_y : EdgeDirection::along_x);
}

bool is_restraint_type(std::string_view text) {
  return parse_restraint(text, EdgeDirection::along_x).has_value();
}

BoundaryConditions BoundaryConditions::on_edges(std::string_view x0, std::string_view xa, std::string_view y0,
                                                std::string_view yb) {
  BoundaryConditions bc;
  bc.set("x0", x0);
  bc.set("xa", xa);
  bc.set("y0", y0);
  bc.set("yb", yb);
  return bc;
}

const SetRestraint* BoundaryConditions::find(std::string_view name) const {
  for (const SetRestraint& s : sets)
    if (s.set == name) return &s;
  return nullptr;
}

void BoundaryConditions::set(std::string_view name, std::string_view type) {
  for (SetRestraint& s : sets)
    if (s.set == name) {
      s.type = type;
      return;
    }
  sets.push_back({std::string(name), std::string(type)});
}

bool BoundaryConditions::has_unilateral() const {
  for (const SetRestraint& s : sets)
    if (s.type == unilateral_support) return true;
  return false;
}

void require_bilateral(const BoundaryConditions& bc, std::string_view analysis) {
  for (const SetRestraint& s : bc.sets)
    if (s.type == unilateral_support)
      throw std::invalid_argument("boundary." + s.set +
                                  " = \"unilateral\": a support the plate may lift off "
                                  "is solved by the linear static analysis only, not by " +
                                  std::string(analysis) +
                                  "; give \"ss-soft\" (the set held in w both ways) for this analysis");
}

namespace {

/// The direction of a straight edge set; nullopt when its segments are neither all along x nor all
/// along y.
std::optional<EdgeDirection> direction_of(const Mesh& mesh, const std::vector<EdgeSegment>& edges) {
  bool along_x = true, along_y = true;
  for (const EdgeSegment& s : edges) {
    const Eigen::Vector2d d = mesh.node(s[2]) - mesh.node(s[0]);
    const Eigen::Vector2d m = mesh.node(s[1]) - mesh.node(s[0]);
    const double tol = 1e-9 * d.norm();
    along_x = along_x && std::abs(d.y()) <= tol && std::abs(m.y()) <= tol;
    along_y = along_y && std::abs(d.x()) <= tol && std::abs(m.x()) <= tol;
  }
  if (along_x == along_y) return std::nullopt; // mixed, oblique or curved (or empty)
  return along_x ? EdgeDirection::along_x : EdgeDirection::along_y;
}

} // namespace

Restraint resolve_restraint(const Mesh& mesh, const SetRestraint& s) {
  if (!is_restraint_type(s.type))
    throw std::invalid_argument(
        "boundary." + s.set + " = \"" + s.type +
        "\": expected ss | ss-soft | clamped | free | unilateral or a 5-character code of 0/1 for "
        "(u, v, w, θx, θy)");
  (void)mesh.node_set(s.set); // throws std::out_of_range naming the sets that exist
  if (s.type != "ss") return *parse_restraint(s.type, EdgeDirection::along_x);
  if (!mesh.has_edge_set(s.set))
    throw std::invalid_argument("boundary." + s.set +
                                " = \"ss\" needs an edge set (a simple support acts along an edge); give "
                                "a code such as \"00100\" for a set of points");
  const auto direction = direction_of(mesh, mesh.edge_set(s.set));
  if (!direction)
    throw std::invalid_argument("boundary." + s.set +
                                " = \"ss\": the edge is not straight along x or y, so its tangential "
                                "rotation is not a nodal DOF; use \"ss-soft\" (w only) or a code");
  return *parse_restraint(s.type, *direction);
}

std::vector<int> unilateral_nodes(const Mesh& mesh, const BoundaryConditions& bc) {
  const std::vector<Restraint> held = node_restraints(mesh, bc);
  std::vector<int> nodes;
  for (const SetRestraint& s : bc.sets)
    if (s.type == unilateral_support)
      for (const int n : mesh.node_set(s.set))
        if (!held[static_cast<std::size_t>(n)].fixed[2]) nodes.push_back(n);
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

std::vector<Restraint> node_restraints(const Mesh& mesh, const BoundaryConditions& bc) {
  std::vector<Restraint> r(static_cast<std::size_t>(mesh.node_count()));
  for (const SetRestraint& s : bc.sets) {
    const Restraint code = resolve_restraint(mesh, s);
    for (const int n : mesh.node_set(s.set))
      for (std::size_t d = 0; d < 5; ++d)
        r[static_cast<std::size_t>(n)].fixed[d] = r[static_cast<std::size_t>(n)].fixed[d] || code.fixed[d];
  }
  if (bc.corners && mesh.has_node_set("corners"))
    for (const int n : mesh.node_set("corners"))
      r[static_cast<std::size_t>(n)] = *bc.corners;
  return r;
}

} // namespace plyimpact
