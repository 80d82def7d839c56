#include "plyimpact/io/mesh/test_rigs.hpp"

#include "plyimpact/analysis/impact/mesh_memory.hpp"
#include "plyimpact/io/mesh/gmsh_api.hpp"
#include "plyimpact/io/mesh/gmsh_mesh.hpp"
#include "plyimpact/io/system/system_memory.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <vector>

namespace plyimpact {

namespace {

// The coupon of ASTM D7136M and AITM 1-0010 (the same geometry as examples/meshes/astm-d7136-coupon.geo) [m].
constexpr double coupon_a = 0.150, coupon_b = 0.100, window_a = 0.125, window_b = 0.075;
constexpr double clamp_dx = 0.050, clamp_dy = 0.04375; // clamp tips from the centre (R. Kok's model)

void name_group(const GmshApi& gmsh, int dim, const std::vector<int>& tags, const std::string& name) {
  gmsh.set_physical_name(dim, gmsh.add_physical_group(dim, tags), name);
}

/// A closed polygon of lines through the points; returns the lines.
std::vector<int> polygon(const GmshApi& gmsh, const std::vector<int>& points) {
  std::vector<int> lines;
  for (std::size_t i = 0; i < points.size(); ++i)
    lines.push_back(gmsh.add_line(points[i], points[(i + 1) % points.size()]));
  return lines;
}

/// The coupon with the window's edge and the clamp tips as lines and points of its mesh.
void add_astm_coupon() {
  const GmshApi& gmsh = gmsh_api();
  const double x0 = (coupon_a - window_a) / 2, y0 = (coupon_b - window_b) / 2;
  const double cx = coupon_a / 2, cy = coupon_b / 2;
  const std::vector<int> edges =
      polygon(gmsh, {gmsh.add_point(0, 0, 0), gmsh.add_point(coupon_a, 0, 0),
                     gmsh.add_point(coupon_a, coupon_b, 0), gmsh.add_point(0, coupon_b, 0)});
  const int plate = gmsh.add_plane_surface({gmsh.add_curve_loop(edges)});
  const std::vector<int> window =
      polygon(gmsh, {gmsh.add_point(x0, y0, 0), gmsh.add_point(x0 + window_a, y0, 0),
                     gmsh.add_point(x0 + window_a, y0 + window_b, 0), gmsh.add_point(x0, y0 + window_b, 0)});
  const std::vector<int> clamps{
      gmsh.add_point(cx - clamp_dx, cy - clamp_dy, 0), gmsh.add_point(cx + clamp_dx, cy - clamp_dy, 0),
      gmsh.add_point(cx + clamp_dx, cy + clamp_dy, 0), gmsh.add_point(cx - clamp_dx, cy + clamp_dy, 0)};
  const int centre = gmsh.add_point(cx, cy, 0);
  gmsh.synchronize();
  gmsh.embed(1, window, 2, plate);
  std::vector<int> points = clamps;
  points.push_back(centre);
  gmsh.embed(0, points, 2, plate);
  name_group(gmsh, 1, edges, "edges");
  name_group(gmsh, 1, window, "window");
  name_group(gmsh, 0, clamps, "clamps");
  name_group(gmsh, 0, {centre}, "centre");
  name_group(gmsh, 2, {plate}, "plate");
}

/// The disk of diameter `d` centred at the origin, with its centre a node.
void add_disk(double d) {
  const GmshApi& gmsh = gmsh_api();
  const double r = d / 2;
  const int c = gmsh.add_point(0, 0, 0);
  const std::vector<int> rim_points{gmsh.add_point(r, 0, 0), gmsh.add_point(0, r, 0),
                                    gmsh.add_point(-r, 0, 0), gmsh.add_point(0, -r, 0)};
  std::vector<int> rim;
  for (std::size_t i = 0; i < rim_points.size(); ++i)
    rim.push_back(gmsh.add_circle_arc(rim_points[i], c, rim_points[(i + 1) % rim_points.size()]));
  const int plate = gmsh.add_plane_surface({gmsh.add_curve_loop(rim)});
  gmsh.synchronize();
  gmsh.embed(0, {c}, 2, plate);
  name_group(gmsh, 1, rim, "rim");
  name_group(gmsh, 0, {c}, "centre");
  name_group(gmsh, 2, {plate}, "plate");
}

} // namespace

RigOutline rig_outline(const std::optional<RigSpec>& spec) {
  if (!spec || spec->kind == RigKind::circular) return {};
  const double x0 = (coupon_a - window_a) / 2, y0 = (coupon_b - window_b) / 2;
  const double cx = coupon_a / 2, cy = coupon_b / 2;
  return {{{x0, y0}, {x0 + window_a, y0}, {x0 + window_a, y0 + window_b}, {x0, y0 + window_b}},
          {{cx - clamp_dx, cy - clamp_dy},
           {cx + clamp_dx, cy - clamp_dy},
           {cx + clamp_dx, cy + clamp_dy},
           {cx - clamp_dx, cy + clamp_dy}}};
}

std::vector<int> clamp_tip_elements(const Mesh& mesh, const std::vector<Eigen::Vector2d>& tips) {
  std::vector<int> held;
  if (mesh.node_count() == 0) return held;
  for (const Eigen::Vector2d& tip : tips) {
    int nearest = 0;
    for (int n = 1; n < mesh.node_count(); ++n)
      if ((mesh.node(n) - tip).squaredNorm() < (mesh.node(nearest) - tip).squaredNorm()) nearest = n;
    for (int e = 0; e < mesh.element_count(); ++e)
      if (std::ranges::find(mesh.element_nodes(e), nearest) != mesh.element_nodes(e).end())
        held.push_back(e + 1);
  }
  std::ranges::sort(held);
  held.erase(std::unique(held.begin(), held.end()), held.end());
  return held;
}

std::string_view to_string(RigKind kind) {
  switch (kind) {
  case RigKind::astm_d7136:
    return "astm-d7136";
  case RigKind::aitm_1_0010:
    return "aitm-1-0010";
  case RigKind::circular:
    return "circular";
  }
  return "circular";
}

GeometryMeshing rig_meshing(const RigSpec& spec) {
  GeometryMeshing how;
  how.size_at_point = 2e-3;
  how.max_size = spec.kind == RigKind::circular ? std::max(2e-3, spec.diameter / 20.0) : 5e-3;
  return how;
}

Rig build_rig(const RigSpec& spec, bool static_analysis) {
  require_rig_mesh_fits_memory(spec); // every rig, the one refined for damage too, before gmsh meshes
  if (spec.kind == RigKind::circular) {
    std::string note;
    Mesh mesh = mesh_gmsh_model(
        "circular rig", [&] { add_disk(spec.diameter); }, spec.meshing, &note);
    BoundaryConditions bc;
    bc.set("rim", "clamped");
    std::string description =
        fmt::format("circular rig: plate clamped on a circle of {:g} mm diameter; {} elements",
                    spec.diameter * 1e3, mesh.element_count());
    if (!note.empty()) description += "; " + note;
    return {std::move(mesh), std::move(bc), 0.0, std::nullopt, std::move(description)};
  }
  // ASTM D7136M and AITM 1-0010: one coupon on one stand (docs/mesh.md); AITM gives no energy rule.
  const bool astm = spec.kind == RigKind::astm_d7136;
  std::string note;
  Mesh mesh =
      mesh_gmsh_model(fmt::format("{} rig", to_string(spec.kind)), add_astm_coupon, spec.meshing, &note);
  BoundaryConditions bc;
  bc.set("window", static_analysis ? unilateral_support : "ss-soft");
  bc.set("clamps", "11100");
  std::string description = fmt::format(
      "{} rig: 150 x 100 mm plate on a 125 x 75 mm window ({}), four clamp tips at (75 +/- 50, "
      "50 +/- 43.75) mm holding u, v, w; 16 mm hemispherical impactor; {} elements",
      astm ? "ASTM D7136" : "AITM 1-0010",
      static_analysis ? "unilateral: the plate may lift off" : "held in w both ways: lift-off not modelled",
      mesh.element_count());
  if (!note.empty()) description += "; " + note;
  const std::optional<double> energy_rule =
      astm ? std::optional<double>(astm_d7136_energy_per_thickness) : std::nullopt;
  return {std::move(mesh), std::move(bc), 0.008, energy_rule, std::move(description)};
}

BoundingBox rig_bounds(const RigSpec& spec) {
  if (spec.kind == RigKind::circular) {
    const double r = spec.diameter / 2.0;
    return {-r, r, -r, r};
  }
  return {0.0, coupon_a, 0.0, coupon_b};
}

void require_rig_mesh_fits_memory(const RigSpec& spec) {
  const std::optional<double> available = available_memory_bytes();
  if (!available || !spec.meshing.size_at_point) return;
  const BoundingBox box = rig_bounds(spec);
  const double elements =
      estimated_element_count(box, spec.meshing.refine_at.value_or(box.centre()), spec.meshing);
  // a 9-node element brings about four nodes of its own to a large mesh
  const MeshMemoryEstimate e = estimate_mesh_memory(4.0 * elements);
  if (e.bytes <= *available) return;
  throw MeshFileError(
      fmt::format("before meshing: {}",
                  memory_refusal_message(static_cast<int>(std::min(elements, 2e9)), e, *available)));
}

} // namespace plyimpact
