#pragma once
// Plate meshes made with the gmsh library (as a user makes them in gmsh) and saved as .msh files, for
// the tests of mesh files (io/mesh/gmsh_mesh.hpp): a disk, an annulus, and a rectangle meshed by transfinite
// lines. The options say how the surface is meshed, so that the tests can also make the meshes that
// plyimpact must refuse.
#include "plyimpact/io/mesh/geo_script.hpp"

#include <cstdlib>
#include <filesystem>

namespace plyimpact::test {

/// PLYIMPACT_TRUST_GEO=1 while it lives (the user's opt-in of io/mesh/geo_script.hpp), unset after.
class TrustedGeoScripts {
public:
  TrustedGeoScripts() { ::setenv(trust_geo_variable, "1", 1); } // NOLINT(concurrency-mt-unsafe)
  ~TrustedGeoScripts() { ::unsetenv(trust_geo_variable); }      // NOLINT(concurrency-mt-unsafe)
  TrustedGeoScripts(const TrustedGeoScripts&) = delete;
  TrustedGeoScripts& operator=(const TrustedGeoScripts&) = delete;
  TrustedGeoScripts(TrustedGeoScripts&&) = delete;
  TrustedGeoScripts& operator=(TrustedGeoScripts&&) = delete;
};

struct GmshMeshOptions {
  int order = 2;               ///< 1: 4-node elements; 2: 9-node (or 8-node, see incomplete)
  bool recombine = true;       ///< quadrilaterals (false: triangles)
  bool incomplete = false;     ///< second order without the centre node (QUAD8)
  bool physical_groups = true; ///< name the edges (and the surface)
  double z = 0.0;              ///< the plane of the plate
  bool clockwise = false;      ///< the surface's boundary run clockwise: elements inverted
  bool degenerate = false; ///< the first element's centre node moved onto its first corner (det J = 0 there)
  bool not_a_number = false; ///< the first element's centre node at x = NaN
};

/// A disk of radius `radius` centred at the origin, elements of about `size`; its centre is a mesh
/// node ("centre" node set); edge set "rim".
void write_disk_mesh(const std::filesystem::path& file, double radius, double size,
                     const GmshMeshOptions& options = {});

/// An annulus (radii `inner` < `outer`) centred at the origin; edge sets "outer" and "inner".
void write_annulus_mesh(const std::filesystem::path& file, double outer, double inner, double size,
                        const GmshMeshOptions& options = {});

/// The rectangle 0 ≤ x ≤ a, 0 ≤ y ≤ b as nx × ny equal elements (transfinite lines), edge sets x0, xa,
/// y0, yb and the node set "corners" (the four corner points), as structured_rectangle names them.
void write_rectangle_mesh(const std::filesystem::path& file, double a, double b, int nx, int ny,
                          const GmshMeshOptions& options = {});

/// The same rectangle and named sets, meshed unstructured: elements of about `size` at the corners,
/// `centre_size` at the centre (a mesh node), graded between by gmsh.
void write_refined_rectangle_mesh(const std::filesystem::path& file, double a, double b, double size,
                                  double centre_size);

} // namespace plyimpact::test
