#include "plyimpact/io/mesh/gmsh_mesh.hpp"

#include "plyimpact/io/mesh/geo_script.hpp"

#include "plyimpact/io/mesh/gmsh_api.hpp"
#include "plyimpact/io/mesh/sandbox.hpp"
#include "plyimpact/io/system/child_process.hpp"
#include "plyimpact/io/system/system_memory.hpp"

#include "plyimpact/fem/shape_functions.hpp"

#include <Eigen/LU>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <mutex>
#include <numbers>
#include <string>
#include <unordered_map>
#include <vector>

namespace plyimpact {

namespace {

constexpr int gmsh_line3 = 8;  ///< 3-node line: end, end, middle
constexpr int gmsh_quad9 = 10; ///< 9-node quadrilateral, nodes in the order of shape_functions.hpp

/// How to get QUAD9 elements out of gmsh (for the messages).
constexpr const char* how_to_quad9 =
    "mesh the plate with 9-node quadrilaterals: in gmsh recombine the surface mesh into quadrilaterals "
    "(Mesh.RecombineAll = 1, or Recombine Surface{...}), make it second order (Mesh.ElementOrder = 2) with "
    "complete elements (Mesh.SecondOrderIncomplete = 0), then save it as .msh";

/// gmsh's names of the element types a plate mesh file may hold instead.
std::string element_type_name(int type) {
  switch (type) {
  case 2:
    return "3-node triangles (gmsh type 2)";
  case 3:
    return "4-node quadrilaterals (gmsh type 3)";
  case 9:
    return "6-node triangles (gmsh type 9)";
  case 10:
    return "9-node quadrilaterals (gmsh type 10)";
  case 16:
    return "8-node quadrilaterals (gmsh type 16)";
  default:
    return fmt::format("elements of gmsh type {}", type);
  }
}

/// The gmsh library is one global model: one reader at a time, initialised and finalised around it.
class GmshSession {
public:
  GmshSession() : lock_(mutex()) {
    gmsh_.initialize(/*read_config_files=*/false);
    gmsh_.set_option("General.Terminal", 0);
    gmsh_.set_option("General.Verbosity", 0);
  }
  ~GmshSession() { gmsh_.finalize(); }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

private:
  static std::mutex& mutex() {
    static std::mutex m;
    return m;
  }
  std::lock_guard<std::mutex> lock_;
  const GmshApi& gmsh_ = gmsh_api();
};

/// A .msh file starts with $MeshFormat: anything else (a .geo script, a text file) is not handed to
/// gmsh, which would run a script.
void require_msh_header(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw MeshFileError(fmt::format("{}: error: cannot open the mesh file", file.string()));
  std::string word;
  in >> word;
  if (word != "$MeshFormat")
    throw MeshFileError(fmt::format("{}: error: not a gmsh mesh file (a .msh file starts with $MeshFormat); "
                                    "mesh the geometry in gmsh and save the mesh as .msh",
                                    file.string()));
}

struct RawMesh {
  std::vector<Eigen::Vector2d> nodes;
  std::vector<ElementNodes> elements;
  std::vector<std::size_t> element_tags; ///< gmsh's tag of each element (messages)
  std::map<std::string, std::vector<EdgeSegment>> edge_sets;
  std::map<std::string, std::vector<int>> node_sets;
};

/// Only QUAD9 elements on surfaces; anything else on a surface is named in the error.
void require_quad9_only(const std::filesystem::path& file) {
  const std::vector<int> types = gmsh_api().element_types(2);
  std::vector<int> others;
  std::copy_if(types.begin(), types.end(), std::back_inserter(others), [](int t) { return t != gmsh_quad9; });
  if (others.empty() && !types.empty()) return;
  std::string found;
  for (const int t : others)
    found += (found.empty() ? "" : ", ") + element_type_name(t);
  throw MeshFileError(fmt::format("{}: error: the mesh holds {}: {}", file.string(),
                                  types.empty() ? "no surface elements" : found, how_to_quad9));
}

/// The QUAD9 elements and the nodes they use, numbered from 0 in the order met.
void read_elements(const std::filesystem::path& file, RawMesh& m,
                   std::unordered_map<std::size_t, int>& index) {
  const GmshApi& gmsh = gmsh_api();
  const auto [all_nodes, coords] = gmsh.nodes();
  std::unordered_map<std::size_t, std::size_t> where; // gmsh node tag → position in coords
  for (std::size_t i = 0; i < all_nodes.size(); ++i)
    where[all_nodes[i]] = i;
  const auto [tags, node_tags] = gmsh.elements_by_type(gmsh_quad9);
  double size = 0.0;
  for (const double c : coords)
    size = std::max(size, std::abs(c));
  for (std::size_t e = 0; e < tags.size(); ++e) {
    ElementNodes element{};
    for (std::size_t a = 0; a < 9; ++a) {
      const std::size_t tag = node_tags[9 * e + a];
      auto [it, added] = index.try_emplace(tag, static_cast<int>(m.nodes.size()));
      if (added) {
        const std::size_t p = where.at(tag);
        if (!std::isfinite(coords[3 * p]) || !std::isfinite(coords[3 * p + 1]) ||
            !std::isfinite(coords[3 * p + 2]))
          throw MeshFileError(
              fmt::format("{}: error: node {} has the coordinates ({}, {}, {}): every node of "
                          "a mesh needs finite coordinates",
                          file.string(), tag, coords[3 * p], coords[3 * p + 1], coords[3 * p + 2]));
        const double z = coords[3 * p + 2];
        if (std::abs(z) > 1e-9 * std::max(size, 1e-300))
          throw MeshFileError(
              fmt::format("{}: error: node {} lies at z = {:g}, off the plate's mid-plane z = 0: "
                          "draw the plate in the x-y plane",
                          file.string(), tag, z));
        m.nodes.emplace_back(coords[3 * p], coords[3 * p + 1]);
      }
      element[a] = it->second;
    }
    m.elements.push_back(element);
    m.element_tags.push_back(tags[e]);
  }
}

/// det J at the nine nodes of every element: positive everywhere, else the element is inverted
/// (nodes clockwise: all negative) or degenerate/distorted (mixed signs or zero).
void require_valid_elements(const std::filesystem::path& file, const RawMesh& m) {
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo, scale = 0.0;
    for (const auto& [xi, eta] : q9_node_coordinates) {
      const Q9Shape s = q9_shape(xi, eta);
      Eigen::Matrix2d J = Eigen::Matrix2d::Zero();
      for (std::size_t a = 0; a < 9; ++a) {
        const Eigen::Vector2d& x = m.nodes[static_cast<std::size_t>(m.elements[e][a])];
        J.col(0) += s.dN_dxi(static_cast<Eigen::Index>(a)) * x;
        J.col(1) += s.dN_deta(static_cast<Eigen::Index>(a)) * x;
      }
      lo = std::min(lo, J.determinant());
      hi = std::max(hi, J.determinant());
      scale = std::max(scale, J.squaredNorm());
    }
    if (lo > 1e-12 * scale) continue;
    if (hi < 0.0)
      throw MeshFileError(
          fmt::format("{}: error: element {} is inverted (its nodes run clockwise seen from "
                      "+z): orient the surface's normal along +z in gmsh (Reverse Surface{{...}})",
                      file.string(), m.element_tags[e]));
    throw MeshFileError(
        fmt::format("{}: error: element {} is degenerate or folded (its Jacobian changes sign "
                    "or vanishes): remesh or move its nodes",
                    file.string(), m.element_tags[e]));
  }
}

std::string group_name(int dim, int tag) {
  const std::string name = gmsh_api().physical_name(dim, tag);
  return name.empty() ? std::to_string(tag) : name;
}

/// Physical curves → edge sets (their 3-node lines), physical points → node sets.
void read_groups(const std::filesystem::path& file, RawMesh& m,
                 const std::unordered_map<std::size_t, int>& index) {
  const GmshApi& gmsh = gmsh_api();
  const std::vector<std::pair<int, int>> groups = gmsh.physical_groups();
  if (groups.empty())
    throw MeshFileError(
        fmt::format("{}: error: the mesh has no physical groups: supports and loads refer to "
                    "edges and points by name, so name them in gmsh (Physical Curve(\"clamp\") "
                    "= {{...}}; Physical Surface(\"plate\") = {{...}})",
                    file.string()));
  const auto node_of = [&](std::size_t tag, const std::string& set) {
    const auto it = index.find(tag);
    if (it == index.end())
      throw MeshFileError(fmt::format("{}: error: physical group \"{}\" holds node {}, which no 9-node "
                                      "quadrilateral of the plate uses",
                                      file.string(), set, tag));
    return it->second;
  };
  for (const auto& [dim, tag] : groups) {
    const std::string name = group_name(dim, tag);
    if (dim == 1) {
      const std::vector<int> curves = gmsh.entities_for_physical_group(dim, tag);
      std::vector<EdgeSegment>& edges = m.edge_sets[name];
      for (const int curve : curves) {
        const std::vector<int> types = gmsh.element_types(1, curve);
        if (std::any_of(types.begin(), types.end(), [](int t) { return t != gmsh_line3; }))
          throw MeshFileError(
              fmt::format("{}: error: physical curve \"{}\" is not meshed with 3-node lines: {}",
                          file.string(), name, how_to_quad9));
        const auto [tags, nodes] = gmsh.elements_by_type(gmsh_line3, curve);
        for (std::size_t s = 0; s < tags.size(); ++s) // gmsh: end, end, middle; ours: end, middle, end
          edges.push_back({node_of(nodes[3 * s], name), node_of(nodes[3 * s + 2], name),
                           node_of(nodes[3 * s + 1], name)});
      }
    } else if (dim == 0 || dim == 2) {
      std::vector<int>& nodes = m.node_sets[name];
      for (const std::size_t t : gmsh.nodes_for_physical_group(dim, tag).tags)
        nodes.push_back(node_of(t, name));
    }
  }
}

/// How the triangles become quadrilaterals.
enum class QuadMeshing {
  /// gmsh's default: the triangles paired into quadrilaterals (Blossom matching); the better mesh, but
  /// gmsh 4.8 aborts from inside its threads where the matching fails (an ASTM rig struck 7.5 mm from the
  /// window's edge: docs/robustness.md)
  recombine,
  /// no pairing: every triangle split into three quadrilaterals, always all quadrilaterals, at twice the
  /// field's size so that the elements come out about as large as with `recombine`
  subdivide,
};

/// The most elements a size field may ask of gmsh: the deck's limit of a structured mesh (docs/robustness.md,
/// "Limits").
constexpr double max_field_elements = 1e6;

/// Refuses a size field that would make more than max_field_elements elements, before gmsh meshes (a tiny
/// size meshes for minutes, then runs out of memory): counted on the geometry's bounding box.
void require_reasonable_field(const std::string& name, const GeometryMeshing& how, const Eigen::Vector2d& at,
                              const std::vector<double>& box) { // gmsh's: x0, y0, z0, x1, y1, z1
  const double n = estimated_element_count({box[0], box[3], box[1], box[4]}, at, how);
  if (n > max_field_elements)
    throw MeshFileError(fmt::format(
        "{}: error: the element sizes asked for would make about {:.3g} elements on this {:.4g} x {:.4g} m "
        "geometry (size {:.3g} m at ({:.4g}, {:.4g}) m, growing by {:.3g}{}), more than {:.0e}: give a "
        "larger mesh.size_at_impact or mesh.max_size",
        name, n, box[3] - box[0], box[4] - box[1], how.size_at_point.value_or(0.0), at.x(), at.y(),
        how.growth,
        how.max_size ? fmt::format(" up to {:.3g} m", *how.max_size) : std::string(" without a cap"),
        max_field_elements));
}

/// Meshes the geometry gmsh has open, in QUAD9, with the size field of `how`.
void generate_quad9(const std::string& name, const GeometryMeshing& how,
                    QuadMeshing quads = QuadMeshing::recombine) {
  const GmshApi& gmsh = gmsh_api();
  double scale = 1.0; // of the size field
  if (quads == QuadMeshing::subdivide) {
    gmsh.set_option("Mesh.RecombineAll", 0);         // no pairing at all
    gmsh.set_option("Mesh.SubdivisionAlgorithm", 1); // every triangle split into three quadrilaterals
    scale = 2.0;
  } else {
    gmsh.set_option("Mesh.RecombineAll", 1);
  }
  gmsh.set_option("Mesh.ElementOrder", 2);
  gmsh.set_option("Mesh.SecondOrderIncomplete", 0);
  if (how.max_size) gmsh.set_option("Mesh.MeshSizeMax", scale * *how.max_size);
  if (how.size_at_point) {
    const std::vector<double> box = gmsh.bounding_box(); // x0, y0, z0, x1, y1, z1
    const Eigen::Vector2d at =
        how.refine_at ? *how.refine_at : Eigen::Vector2d((box[0] + box[3]) / 2.0, (box[1] + box[4]) / 2.0);
    require_reasonable_field(name, how, at, box);
    // h(d) = min(max_size, size_at_point + (growth − 1) ⟨d − uniform_radius⟩), as gmsh's MathEval of the
    // distance.
    const int field = gmsh.add_field("MathEval");
    // x − a written as x + |a| for a < 0: gmsh's MathEval cannot parse "x - -0.02" (it threw from inside
    // gmsh's threads, which aborted the program: the circular rig struck at negative x or y).
    const auto minus = [](const char* var, double a) {
      return fmt::format("{} {} {:.17g}", var, a < 0.0 ? '+' : '-', std::abs(a));
    };
    std::string d = fmt::format("Sqrt(({})^2 + ({})^2)", minus("x", at.x()), minus("y", at.y()));
    if (how.uniform_radius > 0.0) d = fmt::format("Max(0, {} - {:.17g})", d, how.uniform_radius);
    std::string h = fmt::format("{:.17g} + {:.17g} * {}", scale * *how.size_at_point, how.growth - 1.0, d);
    if (how.max_size) h = fmt::format("Min({:.17g}, {})", scale * *how.max_size, h);
    gmsh.set_field_string(field, "F", h);
    gmsh.set_background_field(field);
    gmsh.set_option("Mesh.MeshSizeFromPoints", 0);
    gmsh.set_option("Mesh.MeshSizeFromCurvature", 0);
    gmsh.set_option("Mesh.MeshSizeExtendFromBoundary", 0);
  }
  gmsh.generate(2);
}

/// Reads the mesh gmsh holds after `load` (opening a .msh, or meshing a .geo), in this process.
template <class Load>
RawMesh read_raw_here(const std::filesystem::path& file, const Load& load) {
  std::optional<GmshSession> session;
  try {
    session.emplace();
  } catch (const GmshError& e) { // the library could not be loaded or initialised
    throw MeshFileError(fmt::format("{}: error: {}", file.string(), e.what()));
  }
  try {
    load();
    require_quad9_only(file);
    RawMesh m;
    std::unordered_map<std::size_t, int> index;
    read_elements(file, m, index);
    require_valid_elements(file, m);
    read_groups(file, m, index);
    return m;
  } catch (const MeshFileError&) {
    throw;
  } catch (...) { // gmsh's own errors (the type depends on its version): say what gmsh said last
    const std::string last = gmsh_api().last_error();
    throw MeshFileError(fmt::format("{}: error: gmsh could not read or mesh it{}", file.string(),
                                    last.empty() ? "" : ": " + last));
  }
}

// RawMesh as bytes, from the child process that meshed it to the caller: counts, then the arrays.

template <class T>
void put(std::string& out, const T* data, std::size_t n) {
  const std::uint64_t count = n;
  out.append(reinterpret_cast<const char*>(&count), sizeof count);
  out.append(reinterpret_cast<const char*>(data), n * sizeof(T));
}

template <class T>
std::vector<T> get(const std::string& in, std::size_t& at) {
  std::uint64_t count = 0;
  std::memcpy(&count, in.data() + at, sizeof count);
  at += sizeof count;
  std::vector<T> out(count);
  std::memcpy(out.data(), in.data() + at, count * sizeof(T));
  at += count * sizeof(T);
  return out;
}

template <class T>
void put_sets(std::string& out, const std::map<std::string, std::vector<T>>& sets) {
  const std::uint64_t count = sets.size();
  out.append(reinterpret_cast<const char*>(&count), sizeof count);
  for (const auto& [name, items] : sets) {
    put(out, name.data(), name.size());
    put(out, items.data(), items.size());
  }
}

template <class T>
std::map<std::string, std::vector<T>> get_sets(const std::string& in, std::size_t& at) {
  std::uint64_t count = 0;
  std::memcpy(&count, in.data() + at, sizeof count);
  at += sizeof count;
  std::map<std::string, std::vector<T>> sets;
  for (std::uint64_t i = 0; i < count; ++i) {
    const std::vector<char> name = get<char>(in, at);
    sets.emplace(std::string(name.begin(), name.end()), get<T>(in, at));
  }
  return sets;
}

std::string to_bytes(const RawMesh& m) {
  std::string out;
  std::vector<double> xy; // Eigen's vectors are not trivially copyable: their coordinates are
  xy.reserve(2 * m.nodes.size());
  for (const Eigen::Vector2d& p : m.nodes)
    xy.insert(xy.end(), {p.x(), p.y()});
  put(out, xy.data(), xy.size());
  put(out, m.elements.data(), m.elements.size());
  put(out, m.element_tags.data(), m.element_tags.size());
  put_sets(out, m.edge_sets);
  put_sets(out, m.node_sets);
  return out;
}

RawMesh from_bytes(const std::string& in) {
  std::size_t at = 0;
  RawMesh m;
  const std::vector<double> xy = get<double>(in, at);
  for (std::size_t i = 0; i + 1 < xy.size(); i += 2)
    m.nodes.emplace_back(xy[i], xy[i + 1]);
  m.elements = get<ElementNodes>(in, at);
  m.element_tags = get<std::size_t>(in, at);
  m.edge_sets = get_sets<EdgeSegment>(in, at);
  m.node_sets = get_sets<int>(in, at);
  return m;
}

/// The limits of the child that runs gmsh: two minutes (a plate meshes in well under a second), the
/// memory available to the run on top of what the caller's address space already holds, and the sandbox
/// (reads below `folder` and the system's libraries, writes in `scratch` only) unless the user trusts
/// every script of the session (PLYIMPACT_TRUST_GEO=1).
IsolationLimits gmsh_limits(const std::optional<std::filesystem::path>& folder,
                            const std::filesystem::path& scratch) {
  IsolationLimits limits;
  limits.time = gmsh_time_limit_in_effect();
  const std::optional<double> available = available_memory_bytes();
  std::ifstream statm("/proc/self/statm");
  std::uint64_t pages = 0;
  // at least 2 GiB of address space on top: gmsh's libraries (OpenCASCADE's among them) are mapped when the
  // child opens the library, and a small limit would refuse them, not a large mesh
  constexpr double library_space = 2.0 * (1U << 30U);
  if (available && (statm >> pages))
    limits.memory_bytes = pages * static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE)) +
                          static_cast<std::uint64_t>(std::max(*available, library_space));
  if (!geo_scripts_trusted()) {
    SandboxPolicy policy{system_read_paths(), scratch};
    if (folder) policy.readable.push_back(*folder);
    limits.sandbox = std::move(policy);
  }
  return limits;
}

/// The folder of a file that gmsh reads (a .geo and what it includes, a .msh); none for a model built
/// in memory (a rig), which reads nothing.
std::optional<std::filesystem::path> folder_of(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) return std::nullopt;
  return std::filesystem::absolute(file, ec).parent_path();
}

/// read_raw_here in a child process (docs/robustness.md, "gmsh in a child process" and "The sandbox"):
/// gmsh's aborts, crashes, Exit commands, prompts and endless loops end the child, never the caller, and
/// become a MeshFileError that names the file and says what happened; a program or a write the script
/// attempts is stopped by the kernel.
template <class Load>
RawMesh read_raw(const std::filesystem::path& file, const Load& load, std::string_view advice = {}) {
  try {
    const PrivateFolder scratch;
    return from_bytes(run_in_child_process([&] { return to_bytes(read_raw_here(file, load)); },
                                           fmt::format("{}: error: gmsh", file.string()),
                                           gmsh_limits(folder_of(file), scratch.path())));
  } catch (const SandboxError& e) {
    throw MeshFileError(fmt::format("{}: error: {}", file.string(), e.what()));
  } catch (const IsolatedWorkError& e) {
    if (e.thrown_by_work()) throw MeshFileError(e.what()); // read_raw_here's own message
    // advice on the script's options fits a crash or a time limit, not a stop by the sandbox or the user
    if (e.cause() == IsolatedWorkError::Cause::sandbox || e.cause() == IsolatedWorkError::Cause::interrupted)
      throw MeshFileError(fmt::format("{}; nothing of it was used", e.what()));
    throw MeshFileError(
        fmt::format("{} (reading or meshing it); nothing of it was used{}", e.what(), advice));
  }
}

/// What to change in a .geo that gmsh crashed on or could not finish.
constexpr std::string_view geo_advice =
    ". The usual causes are the script's own meshing options (Mesh.Algorithm, Recombine, "
    "Mesh.RecombinationAlgorithm: plyimpact recombines and makes second-order elements itself, so leave them "
    "out) and characteristic lengths far below the plate's size (give mesh.size_at_impact and mesh.max_size "
    "instead); the time limit is PLYIMPACT_GMSH_TIME_LIMIT_S (docs/robustness.md)";

Mesh to_mesh(RawMesh raw) {
  Mesh mesh(std::move(raw.nodes), std::move(raw.elements));
  for (auto& [name, edges] : raw.edge_sets)
    mesh.add_edge_set(name, std::move(edges));
  for (auto& [name, nodes] : raw.node_sets)
    if (!mesh.has_node_set(name)) mesh.add_node_set(name, std::move(nodes));
  return mesh;
}

} // namespace

std::chrono::milliseconds gmsh_time_limit_in_effect() {
  const std::optional<double> seconds = positive_number_from_environment(gmsh_time_limit_variable, "seconds");
  if (!seconds) return gmsh_time_limit;
  return std::chrono::milliseconds(static_cast<long long>(std::ceil(std::min(*seconds, 1e9) * 1000.0)));
}

Mesh read_gmsh_mesh(const std::filesystem::path& file) {
  std::error_code ec;
  if (std::filesystem::exists(file, ec) && !std::filesystem::is_regular_file(file, ec))
    throw MeshFileError( // a FIFO or a device would block the reader
        fmt::format("{}: error: not a regular file (a FIFO, a device or a folder): give a .msh file",
                    file.string()));
  require_msh_header(file);
  return to_mesh(read_raw(file, [&] { gmsh_api().open(file.string()); }));
}

double estimated_element_count(const BoundingBox& box, const Eigen::Vector2d& at,
                               const GeometryMeshing& how) {
  if (!how.size_at_point) return 0.0;
  // ∫∫ dA / h(d)² in polar coordinates about `at`, each ray to the box's edge: a quadrilateral of side h
  // covers h². The radial integral ∫ r dr / h(r)² is summed on geometric steps (h grows linearly).
  constexpr int rays = 720;
  double count = 0.0;
  const Eigen::Vector2d p =
      at.cwiseMax(Eigen::Vector2d(box.x_min, box.y_min)).cwiseMin(Eigen::Vector2d(box.x_max, box.y_max));
  for (int k = 0; k < rays; ++k) {
    const double t = 2.0 * std::numbers::pi * (k + 0.5) / rays;
    const Eigen::Vector2d u(std::cos(t), std::sin(t));
    double reach = std::numeric_limits<double>::infinity(); // to the box's edge along u
    if (u.x() > 1e-12) reach = std::min(reach, (box.x_max - p.x()) / u.x());
    if (u.x() < -1e-12) reach = std::min(reach, (box.x_min - p.x()) / u.x());
    if (u.y() > 1e-12) reach = std::min(reach, (box.y_max - p.y()) / u.y());
    if (u.y() < -1e-12) reach = std::min(reach, (box.y_min - p.y()) / u.y());
    double r = 0.0, integral = 0.0;
    while (r < reach) {
      const double h = std::max(graded_size(how, r), 1e-300);
      const double step = std::min(reach - r, 0.25 * h + 0.1 * r);
      const double mid = r + 0.5 * step;
      const double hm = std::max(graded_size(how, mid), 1e-300);
      integral += mid * step / (hm * hm);
      r += step;
      if (integral > 1e12) break; // far beyond any limit
    }
    count += integral * 2.0 * std::numbers::pi / rays;
  }
  return count;
}

double graded_size(const GeometryMeshing& how, double d) {
  const double h =
      how.size_at_point.value_or(0.0) + (how.growth - 1.0) * std::max(0.0, d - how.uniform_radius);
  return how.max_size ? std::min(*how.max_size, h) : h;
}

Mesh mesh_gmsh_geometry(const std::filesystem::path& geo, const GeometryMeshing& how) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(geo, ec))
    throw MeshFileError(fmt::format("{}: error: cannot open the geometry file", geo.string()));
  require_safe_geo(geo); // no shell command, no file written, nothing read from outside its folder
  return to_mesh(read_raw(
      geo,
      [&] {
        gmsh_api().open(geo.string());
        generate_quad9(geo.string(), how);
      },
      geo_advice));
}

Mesh mesh_gmsh_model(const std::string& name, const std::function<void()>& build, const GeometryMeshing& how,
                     std::string* note) {
  const auto mesh_with = [&](QuadMeshing quads) {
    return to_mesh(read_raw(name, [&] {
      gmsh_api().add_model(name);
      build();
      generate_quad9(name, how, quads);
    }));
  };
  try {
    return mesh_with(QuadMeshing::recombine);
  } catch (const MeshFileError& recombined) {
    try {
      Mesh mesh = mesh_with(QuadMeshing::subdivide);
      if (note != nullptr)
        *note = fmt::format("meshed by subdivision: gmsh could not pair this geometry's triangles into "
                            "quadrilaterals ({})",
                            recombined.what());
      return mesh;
    } catch (const MeshFileError&) {
      throw recombined; // the first failure is the one to report
    }
  }
}

} // namespace plyimpact
