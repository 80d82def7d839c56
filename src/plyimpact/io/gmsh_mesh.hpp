#pragma once
// Meshes from gmsh (docs/mesh.md): a .msh file read through the gmsh library itself (Debian's
// libgmsh-dev; no parser of our own). The plate is meshed with 9-node quadrilaterals (gmsh's QUAD9,
// element type 10) in the z = 0 plane; gmsh's physical groups become the mesh's named sets, so that
// boundary conditions refer to them by name:
//   - a physical curve (dimension 1, meshed with 3-node lines) → an edge set and its node set;
//   - a physical point (dimension 0) → a node set.
// A group without a name is named by its number. Anything else — other element types, no QUAD9,
// nodes off the z = 0 plane, an inverted (clockwise) or degenerate element, a file that is not a gmsh
// mesh — is refused with a message that says what is wrong and how to fix it in gmsh.
#include "plyimpact/fem/mesh.hpp"

#include <filesystem>
#include <stdexcept>

namespace plyimpact {

/// What is wrong with a mesh file (the message names the file).
class MeshFileError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// Reads a gmsh mesh file (.msh, format 2 or 4, ASCII or binary). Safe to call from several threads
/// (gmsh holds one model: the calls are serialised). Throws MeshFileError.
[[nodiscard]] Mesh read_gmsh_mesh(const std::filesystem::path& file);

} // namespace plyimpact
