#pragma once
// ParaView output through VTK (Debian's libvtk9-dev): two time series, each a `.pvd` collection of
// `.vtu` unstructured grids, written while the impact runs.
//
//   plate.pvd   the mid-plane as VTK_BIQUADRATIC_QUAD cells (our Q9 node order is VTK's): point data
//               u, v, w, θx, θy and the displacement vector (for "Warp By Vector"); cell data per
//               selected ply: σ̄11, σ̄22, τ̄12, τ̄13, τ̄23 (material axes), failure indices and the
//               damaged fraction; per selected interface: (τyz, τxz) and the delaminated fraction.
//               Progressive damage: per selected ply d_ft, d_fc, d_mt, d_mc and their largest, and the
//               projected damage_max (largest over all plies and modes). Stacked plate (delamination):
//               cohesive_d_after_plyP per interface (the largest damage of the element's interface
//               points, 1: delaminated) and cohesive_d_max (largest over the interfaces: the C-scan view).
//   layers.pvd  the laminate in 3-D, one VTK_HEXAHEDRON layer per ply (each Q9 split into its 2×2
//               node cells), thickness optionally exaggerated; cell data ply number, angle, stresses,
//               damaged fraction and the delaminated fraction of the interface below; progressive damage:
//               d_ft, d_fc, d_mt, d_mc and d_max of the ply; stacked plate: cohesive_d_below, the cohesive
//               damage of the interface below the ply (0 where the laminate is not cut).
//
// Coordinates are SPEC §1's: z points in the impact direction (the impacted face is z = −h/2).
// Cell values are sampled at element centres (analysis/fields/element_fields.hpp). Every file is written to
// a temporary name and renamed, and the collections are rewritten after every frame, so an
// interrupted run leaves valid `.pvd` files listing every frame already written.
#include "plyimpact/analysis/fields/damage_tracker.hpp"
#include "plyimpact/analysis/impact/impact_result.hpp"
#include "plyimpact/fem/discrete_plate.hpp"
#include "plyimpact/io/results/ply_damage_table.hpp"
#include "plyimpact/laminate/failure_criteria.hpp"

#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

namespace plyimpact {

struct VtkOptions {
  std::vector<int> plies;          ///< 1-based plies with cell data in plate.pvd (empty: all)
  std::vector<int> interfaces;     ///< 1-based interfaces with cell data in plate.pvd (empty: all)
  double thickness_scale = 1.0;    ///< z-scale of the layered view (1: true thickness)
  std::vector<Criterion> criteria; ///< failure indices written (usually the [damage] criteria)
  CriterionOptions criterion_options;
};

/// One frame of plate.pvd: the mid-plane grid with its point and cell data. `progressive`: the plies'
/// damage of a progressive-damage run, `interfaces`: those of a stacked plate (their arrays are written
/// only when given).
void write_plate_vtu(const std::filesystem::path& file, const DiscretePlate& model, const Eigen::VectorXd& u,
                     const std::vector<DamageOnset>& onsets, double t, const VtkOptions& options,
                     const PlyDamageTable* progressive = nullptr,
                     const DelaminationResult* interfaces = nullptr);
/// One frame of layers.pvd: the laminate as hexahedra, one layer per ply.
void write_layers_vtu(const std::filesystem::path& file, const DiscretePlate& model, const Eigen::VectorXd& u,
                      const std::vector<DamageOnset>& onsets, double t, const VtkOptions& options,
                      const PlyDamageTable* progressive = nullptr,
                      const DelaminationResult* interfaces = nullptr);

/// A `.pvd` collection: (time, file relative to the .pvd) pairs.
struct PvdEntry {
  double t = 0.0;
  std::string file;
};
void write_pvd(const std::filesystem::path& file, const std::vector<PvdEntry>& entries);

/// Writes frames into DIR/paraview/ and keeps DIR/plate.pvd and DIR/layers.pvd up to date.
class VtkSeries {
public:
  VtkSeries(std::filesystem::path dir, const DiscretePlate& model, VtkOptions options);
  /// Writes the frame of `step` at time t (seconds) for the plate state u (free DOFs); `progressive`:
  /// the plies' damage of a progressive-damage run (DamageField::element_ply_damage()), null otherwise;
  /// `interfaces`: the stacked plate's (PlateStateAccess::delamination()), null otherwise.
  void write(long step, double t, const Eigen::VectorXd& u, const std::vector<DamageOnset>& onsets,
             const std::vector<ElementPlyDamage>* progressive = nullptr,
             const DelaminationResult* interfaces = nullptr);
  [[nodiscard]] std::size_t frames() const { return plate_.size(); }

private:
  std::filesystem::path dir_;
  const DiscretePlate& model_;
  VtkOptions options_;
  std::vector<PvdEntry> plate_, layers_;
};

/// A static solution u as ParaView files: plate.pvd and layers.pvd holding one frame (t = 0).
void write_static_vtk(const std::filesystem::path& dir, const DiscretePlate& model, const Eigen::VectorXd& u,
                      const VtkOptions& options);

/// Mode shapes (columns of `modes`, free DOFs) as ParaView files: plate.pvd and layers.pvd with one frame
/// per mode, whose "time" is the mode number (ParaView's time control steps through the modes). Each
/// shape is scaled so that its largest deflection |w| is 1 mm (modes have no amplitude of their own).
void write_modes_vtk(const std::filesystem::path& dir, const DiscretePlate& model,
                     const Eigen::MatrixXd& modes, const VtkOptions& options);

} // namespace plyimpact
