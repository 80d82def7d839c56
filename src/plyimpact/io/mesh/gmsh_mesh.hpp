#pragma once
// Meshes from gmsh (docs/mesh.md): a .msh file read through the gmsh library itself (Debian's
// libgmsh-dev; no parser of our own). The plate is meshed with 9-node quadrilaterals (gmsh's QUAD9,
// element type 10) in the z = 0 plane; gmsh's physical groups become the mesh's named sets, so that
// boundary conditions refer to them by name:
//   - a physical curve (dimension 1, meshed with 3-node lines) → an edge set and its node set;
//   - a physical point (dimension 0) → a node set;
//   - a physical surface (dimension 2) → the node set of its elements' nodes (a clamp's patch).
// A group without a name is named by its number. Anything else — other element types, no QUAD9,
// nodes off the z = 0 plane, an inverted (clockwise) or degenerate element, a file that is not a gmsh
// mesh — is refused with a message that says what is wrong and how to fix it in gmsh.
#include "plyimpact/fem/mesh.hpp"

#include <Eigen/Core>
#include <chrono>
#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

namespace plyimpact {

/// What is wrong with a mesh file (the message names the file).
class MeshFileError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// How long gmsh may read or mesh one file before its child process is killed (docs/robustness.md), unless
/// PLYIMPACT_GMSH_TIME_LIMIT_S (io/system/environment.hpp) says otherwise.
inline constexpr std::chrono::seconds gmsh_time_limit{120};

/// gmsh_time_limit, or PLYIMPACT_GMSH_TIME_LIMIT_S when set (EnvironmentValueError when malformed).
[[nodiscard]] std::chrono::milliseconds gmsh_time_limit_in_effect();

/// Reads a gmsh mesh file (.msh, format 2 or 4, ASCII or binary). gmsh runs in a child process
/// (io/system/child_process.hpp) with a time limit (gmsh_time_limit) and the available memory: whatever it
/// does, the caller gets the mesh or a MeshFileError. Safe to call from several threads. Throws
/// MeshFileError.
[[nodiscard]] Mesh read_gmsh_mesh(const std::filesystem::path& file);

/// How to mesh a gmsh geometry (.geo): with a size field graded toward a point, or with the sizes the
/// geometry sets itself when `size_at_point` is empty.
struct GeometryMeshing {
  std::optional<Eigen::Vector2d> refine_at; ///< [m]; empty: the centre of the geometry's bounding box
  std::optional<double> size_at_point;      ///< element size at `refine_at` [m]
  std::optional<double> max_size;           ///< largest element size [m]; empty: no cap
  double growth = 1.25;                     ///< size ratio of neighbouring elements (≥ 1)
  /// The size stays size_at_point within this distance of `refine_at` and grows from there [m] (the
  /// damage zone of a progressive or stacked run: docs/mesh.md, "Meshes for damage"); 0: grows from it.
  double uniform_radius = 0.0;
};

/// The element size at distance d from the refinement point: min(max_size, size_at_point + (growth − 1)
/// ⟨d − uniform_radius⟩), the continuous form of sizes that grow by `growth` from one element to the next.
[[nodiscard]] double graded_size(const GeometryMeshing& how, double d);

/// About how many quadrilaterals the size field of `how` (graded from `at`) makes on `box`: the integral of
/// 1/h² over the box. 0 without how.size_at_point (the geometry's own sizes).
[[nodiscard]] double estimated_element_count(const BoundingBox& box, const Eigen::Vector2d& at,
                                             const GeometryMeshing& how);

/// Meshes a gmsh geometry script with 9-node quadrilaterals (recombined, second order, complete
/// elements: these options are set whatever the script says) and reads it as read_gmsh_mesh does.
/// Throws MeshFileError.
[[nodiscard]] Mesh mesh_gmsh_geometry(const std::filesystem::path& geo, const GeometryMeshing& how);

/// Meshes the geometry that `build` adds to an empty gmsh model (built-in kernel, synchronised by
/// `build`) as mesh_gmsh_geometry does; `name` stands for the file in messages. Where gmsh cannot pair
/// the triangles into quadrilaterals it meshes again by subdivision (every element split into
/// quadrilaterals) and says so in `note`. Throws MeshFileError.
[[nodiscard]] Mesh mesh_gmsh_model(const std::string& name, const std::function<void()>& build,
                                   const GeometryMeshing& how, std::string* note = nullptr);

} // namespace plyimpact
