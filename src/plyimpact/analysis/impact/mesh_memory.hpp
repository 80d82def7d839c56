#pragma once
// Memory an impact case's mesh needs, estimated from the mesh size alone before anything is built or
// assembled (docs/robustness.md): a 1000 × 1000 mesh is refused in a fraction of a second with the
// estimate and the machine's memory, instead of growing to 15 GB or ending in std::bad_alloc. ImpactCase
// checks its graded mesh first thing; the factorization is checked again, exactly, from its symbolic analysis
// once K̄ is assembled (guards.hpp).
#include "plyimpact/analysis/impact/impact_case.hpp"

#include <array>
#include <string>

namespace plyimpact {

struct MeshMemoryEstimate {
  double nodes = 0.0;           ///< (2 nx + 1)(2 ny + 1) nine-node element nodes
  double equations = 0.0;       ///< 5 DOFs per node (none removed by supports: an upper bound)
  double matrix_nonzeros = 0.0; ///< of K (both triangles): 25 DOF pairs × 16 neighbour nodes per node
  double factor_nonzeros = 0.0; ///< of L: c · n · log2(n)² (fill of AMD on a 2-D grid, fitted)
  double bytes = 0.0;           ///< 12 bytes per non-zero of L and of K, M, K̄ (value + row index)
};

/// The fill constant c of factor_nonzeros. The symbolic analysis of K̄ (AMD ordering) of structured
/// meshes from 4 × 4 to 48 × 48 elements gives nnz(L) / (n log2(n)²) between 0.4 and 0.65, slowly
/// growing with n (tests/io/test_memory_estimate.cpp): c = 1 errs on the large side.
inline constexpr double factor_fill_constant = 1.0;

/// The estimate for a structured nx × ny mesh of 9-node elements.
[[nodiscard]] MeshMemoryEstimate estimate_mesh_memory(long nx, long ny);
/// The estimate for a mesh of 9-node elements with `nodes` nodes.
[[nodiscard]] MeshMemoryEstimate estimate_mesh_memory(double nodes);

/// The message of a refusal of a uniform mesh: the mesh, the estimate and the memory available.
[[nodiscard]] std::string memory_refusal_message(long nx, long ny, const MeshMemoryEstimate& e,
                                                 double available_bytes);

/// The message of a refusal of a mesh read from a gmsh file, a .geo or a rig preset: its size, the
/// estimate and the memory available, and how to make such a mesh coarser.
[[nodiscard]] std::string memory_refusal_message(int elements, const MeshMemoryEstimate& e,
                                                 double available_bytes);

/// Elements along x and y of an impact case's graded mesh (MeshSpec::grading engaged), from its
/// element lines alone.
[[nodiscard]] std::array<long, 2> graded_mesh_size(const ImpactCaseDescription& d);

/// Throws InsufficientMemory (guards.hpp) where the case's mesh graded toward the impact point
/// (graded_mesh_size) would need more than d.memory_limit_bytes: nothing is built. A uniform nx × ny mesh
/// is checked from the deck, whose file its refusal names (io/system/memory_estimate.hpp, when the deck
/// becomes a case); a mesh read from a file, a rigid target and a case without a limit pass.
void check_memory_before_assembly(const ImpactCaseDescription& d);

} // namespace plyimpact
