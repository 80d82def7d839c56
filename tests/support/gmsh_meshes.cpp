#include "support/gmsh_meshes.hpp"

#include <gmsh.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace plyimpact::test {

namespace {

/// Runs `geometry` (built-in CAD kernel) in a fresh gmsh model, meshes it as `o` says and writes `file`.
void write_mesh(const std::filesystem::path& file, const GmshMeshOptions& o,
                const std::function<void()>& geometry) {
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::model::add("plate");
  geometry();
  gmsh::model::geo::synchronize();
  gmsh::option::setNumber("Mesh.RecombineAll", o.recombine ? 1 : 0);
  // Frontal-Delaunay, then recombined (Blossom). Debian's gmsh 4.8.4 crashes in "Frontal-Delaunay for
  // Quads" (Mesh.Algorithm = 8) on a disk.
  gmsh::option::setNumber("Mesh.Algorithm", 6);
  gmsh::option::setNumber("Mesh.SecondOrderIncomplete", o.incomplete ? 1 : 0);
  gmsh::model::mesh::generate(2);
  gmsh::model::mesh::setOrder(o.order);
  if (o.degenerate) {
    std::vector<std::size_t> tags, nodes;
    gmsh::model::mesh::getElementsByType(10, tags, nodes); // QUAD9: corners, mid-sides, centre
    std::vector<double> corner, parametric;
    gmsh::model::mesh::getNode(nodes[0], corner, parametric);
    gmsh::model::mesh::setNode(nodes[8], corner, {});
  }
  if (o.not_a_number) {
    std::vector<std::size_t> tags, nodes;
    gmsh::model::mesh::getElementsByType(10, tags, nodes);
    std::vector<double> centre, parametric;
    gmsh::model::mesh::getNode(nodes[8], centre, parametric);
    centre[0] = std::numeric_limits<double>::quiet_NaN();
    gmsh::model::mesh::setNode(nodes[8], centre, {});
  }
  gmsh::write(file.string());
  gmsh::finalize();
}

/// A closed loop of circle arcs through `n` points on the circle of radius `r` (counter-clockwise).
std::vector<int> circle(int centre, double r, double size, double z, int n = 4) {
  std::vector<int> points, arcs;
  for (int k = 0; k < n; ++k) {
    const double t = 2.0 * M_PI * k / n;
    points.push_back(gmsh::model::geo::addPoint(r * std::cos(t), r * std::sin(t), z, size));
  }
  for (int k = 0; k < n; ++k)
    arcs.push_back(gmsh::model::geo::addCircleArc(points[static_cast<std::size_t>(k)], centre,
                                                  points[static_cast<std::size_t>((k + 1) % n)]));
  return arcs;
}

std::vector<int> reversed(std::vector<int> curves) {
  std::vector<int> r;
  for (auto it = curves.rbegin(); it != curves.rend(); ++it)
    r.push_back(-*it);
  return r;
}

void name(int dim, const std::vector<int>& tags, const std::string& group) {
  const int g = gmsh::model::addPhysicalGroup(dim, tags);
  gmsh::model::setPhysicalName(dim, g, group);
}

/// The sets structured_rectangle makes (edges x0, xa, y0, yb; node set "corners") and the surface.
void name_rectangle_sets(const std::vector<int>& corners, int y0, int xa, int yb, int x0, int surface) {
  name(1, {x0}, "x0");
  name(1, {xa}, "xa");
  name(1, {y0}, "y0");
  name(1, {yb}, "yb");
  name(0, corners, "corners");
  name(2, {surface}, "plate");
}

} // namespace

void write_disk_mesh(const std::filesystem::path& file, double radius, double size,
                     const GmshMeshOptions& o) {
  write_mesh(file, o, [&] {
    const int centre = gmsh::model::geo::addPoint(0.0, 0.0, o.z, size);
    const std::vector<int> rim = circle(centre, radius, size, o.z);
    const int loop = gmsh::model::geo::addCurveLoop(o.clockwise ? reversed(rim) : rim);
    const int surface = gmsh::model::geo::addPlaneSurface({loop});
    gmsh::model::geo::synchronize();
    gmsh::model::mesh::embed(0, {centre}, 2, surface);
    if (!o.physical_groups) return;
    name(1, rim, "rim");
    name(0, {centre}, "centre");
    name(2, {surface}, "plate");
  });
}

void write_annulus_mesh(const std::filesystem::path& file, double outer, double inner, double size,
                        const GmshMeshOptions& o) {
  write_mesh(file, o, [&] {
    const int centre = gmsh::model::geo::addPoint(0.0, 0.0, o.z, size);
    const std::vector<int> out = circle(centre, outer, size, o.z), in = circle(centre, inner, size, o.z);
    const int outer_loop = gmsh::model::geo::addCurveLoop(out);
    const int inner_loop = gmsh::model::geo::addCurveLoop(in);
    const int surface = gmsh::model::geo::addPlaneSurface({outer_loop, inner_loop});
    gmsh::model::geo::synchronize();
    if (!o.physical_groups) return;
    name(1, out, "outer");
    name(1, in, "inner");
    name(2, {surface}, "plate");
  });
}

void write_rectangle_mesh(const std::filesystem::path& file, double a, double b, int nx, int ny,
                          const GmshMeshOptions& o) {
  write_mesh(file, o, [&] {
    const int p0 = gmsh::model::geo::addPoint(0.0, 0.0, o.z), p1 = gmsh::model::geo::addPoint(a, 0.0, o.z),
              p2 = gmsh::model::geo::addPoint(a, b, o.z), p3 = gmsh::model::geo::addPoint(0.0, b, o.z);
    const int y0 = gmsh::model::geo::addLine(p0, p1), xa = gmsh::model::geo::addLine(p1, p2),
              yb = gmsh::model::geo::addLine(p2, p3), x0 = gmsh::model::geo::addLine(p3, p0);
    const std::vector<int> loop{y0, xa, yb, x0};
    const int surface = gmsh::model::geo::addPlaneSurface(
        {gmsh::model::geo::addCurveLoop(o.clockwise ? reversed(loop) : loop)});
    // Through the geo kernel: constraints set on the model would be reset by its next synchronize.
    for (const int line : {y0, yb})
      gmsh::model::geo::mesh::setTransfiniteCurve(line, nx + 1);
    for (const int line : {xa, x0})
      gmsh::model::geo::mesh::setTransfiniteCurve(line, ny + 1);
    gmsh::model::geo::mesh::setTransfiniteSurface(surface);
    gmsh::model::geo::synchronize();
    if (!o.physical_groups) return;
    name_rectangle_sets({p0, p1, p2, p3}, y0, xa, yb, x0, surface);
  });
}

void write_refined_rectangle_mesh(const std::filesystem::path& file, double a, double b, double size,
                                  double centre_size) {
  write_mesh(file, GmshMeshOptions{}, [&] {
    const int p0 = gmsh::model::geo::addPoint(0.0, 0.0, 0.0, size),
              p1 = gmsh::model::geo::addPoint(a, 0.0, 0.0, size),
              p2 = gmsh::model::geo::addPoint(a, b, 0.0, size),
              p3 = gmsh::model::geo::addPoint(0.0, b, 0.0, size);
    const int centre = gmsh::model::geo::addPoint(0.5 * a, 0.5 * b, 0.0, centre_size);
    const int y0 = gmsh::model::geo::addLine(p0, p1), xa = gmsh::model::geo::addLine(p1, p2),
              yb = gmsh::model::geo::addLine(p2, p3), x0 = gmsh::model::geo::addLine(p3, p0);
    const int surface = gmsh::model::geo::addPlaneSurface({gmsh::model::geo::addCurveLoop({y0, xa, yb, x0})});
    gmsh::model::geo::synchronize();
    gmsh::model::mesh::embed(0, {centre}, 2, surface);
    name_rectangle_sets({p0, p1, p2, p3}, y0, xa, yb, x0, surface);
  });
}

} // namespace plyimpact::test
