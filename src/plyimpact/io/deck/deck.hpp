#pragma once
// Input decks (TOML, SPEC §10): one file describes a whole analysis. See docs/deck.md.
#include "plyimpact/analysis/impact/parameters.hpp"
#include "plyimpact/analysis/integrators/step_policy.hpp"
#include "plyimpact/analysis/plate_analyses/nonlinear_static.hpp"
#include "plyimpact/fem/boundary.hpp"
#include "plyimpact/fem/loads.hpp"
#include "plyimpact/fem/mesh.hpp"
#include "plyimpact/fem/mesh_spec.hpp"
#include "plyimpact/fem/regions.hpp"
#include "plyimpact/io/deck/deck_error.hpp"
#include "plyimpact/io/deck/deck_units.hpp"
#include "plyimpact/io/mesh/test_rigs.hpp"
#include "plyimpact/laminate/laminate.hpp"

#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace plyimpact {

/// Per-ply overrides of the layup's default material and thickness ([[laminate.override]]).
struct PlyOverride {
  std::vector<int> plies; ///< 1-based ply numbers (1 = impacted face)
  std::optional<std::string> material;
  std::optional<double> thickness;
};

/// The laminate as written in the deck, kept for reports and parameter sweeps.
struct LaminateSpec {
  std::string material;
  std::string layup;
  double ply_thickness = 0.0;
  double shear_correction = 5.0 / 6.0;
  ReducedStiffnessModel reduced_stiffness = ReducedStiffnessModel::exact;
  std::vector<PlyOverride> overrides;
  /// The angle of `reference_direction` (the layup's 0°) from the plate's x axis toward y [deg]: added to
  /// every ply angle of the layup.
  double reference_angle = 0.0;
};

/// A laminate of [laminates.NAME] (regions of the panel refer to it by name).
struct NamedLaminate {
  std::string name;
  LaminateSpec spec;
  Laminate laminate;
};

/// [output] ParaView files (docs/deck.md): a frame every `every` steps and/or at the times `at`.
struct VtkOutputSettings {
  static constexpr int default_every = 100;
  bool enabled = false;
  int every = 0;                ///< steps between frames; 0: only at `at`
  std::vector<double> at;       ///< [s]
  std::vector<int> plies;       ///< 1-based plies with cell data in plate.pvd (empty: all)
  std::vector<int> interfaces;  ///< 1-based interfaces with cell data in plate.pvd (empty: all)
  double thickness_scale = 1.0; ///< thickness exaggeration of the layered (3-D) view
};

/// [impactor] as written where Impactor keeps only what follows from it (for plausibility checks).
struct ImpactorInput {
  std::optional<double> density; ///< [kg/m^3] when the mass was given as a density
  std::optional<double> energy;  ///< [J] when the velocity was given as an impact energy (or the rig's rule)
};

/// What a [rig] preset lets [impactor] leave out.
struct ImpactorDefaults {
  std::optional<double> radius; ///< [m]
  std::optional<double> energy; ///< [J]
};

/// The most threads a run's element loops may be given ([run] threads, --threads, Python threads=).
inline constexpr int max_run_threads = 1024;

struct Deck {
  std::string source;                ///< file name used in messages
  UnitSystem units = UnitSystem::si; ///< top-level `units`: how the numbers were written (all SI here)
  std::string title;
  AnalysisKind analysis = AnalysisKind::impact;
  std::vector<Material> materials;
  /// The materials that take a card of the material library ([materials.NAME] library): (NAME, card), in
  /// the deck's order; provenance.json records each card with its source and values.
  std::vector<std::pair<std::string, std::string>> material_cards;
  std::optional<LaminateSpec> laminate_spec;
  std::optional<Laminate> laminate;     ///< [laminate]: the plate's own
  std::vector<NamedLaminate> laminates; ///< [laminates.NAME]
  std::vector<Region> regions;          ///< [[region]]: Region::laminate indexes 1 + laminates
  std::optional<PlateGeometry> plate;
  std::optional<MeshSpec> mesh;
  std::string mesh_file; ///< [mesh] file as written ("" for the structured rectangle)
  std::shared_ptr<const Mesh>
      file_mesh; ///< the mesh read from mesh_file (io/mesh/gmsh_mesh.hpp) or the rig's
  std::optional<GeometryMeshing> geo_meshing; ///< the sizes the deck gave mesh.geo or a [rig]
  std::optional<RigSpec> rig;                 ///< [rig] preset (io/mesh/test_rigs.hpp)
  std::string rig_description;                ///< what the preset built, for the reports ("" without [rig])
  ImpactorDefaults impactor_defaults;         ///< what the rig lets [impactor] leave out
  std::optional<BoundaryConditions> boundary;
  std::optional<Impactor> impactor;
  ImpactorInput impactor_input;
  ContactLawParameters contact;
  TimeStepping time;
  std::optional<StaticLoad> load;
  ModalSettings modal;
  std::optional<BucklingSettings> buckling;
  DamageSettings damage;
  /// [delamination]: the laminate cut into sub-laminates tied by cohesive interfaces (impact only,
  /// docs/delamination.md); the cuts are 0-based (after ply k), the penalty stiffness resolved
  std::optional<DelaminationSettings> delamination;
  ThresholdSettings threshold;
  std::vector<StressProbeSpec> probes; ///< [[output.probe]]
  std::string output_dir = "results";
  std::vector<double> field_times; ///< [output] fields_at: displacement fields at these times [s]
  int history_every = 1;           ///< [output] history_every
  /// [run] threads: the threads of a run's element loops, 1 to max_run_threads (0: every core). The
  /// command's --threads and Python's threads= override it; a sweep runs each case on one thread.
  int threads = 0;
  VtkOutputSettings vtk;                         ///< [output] vtk*
  std::optional<double> report_displacements_at; ///< [output] nodal displacements in report.txt [s]
  std::string text;                              ///< the deck's own text, recorded next to results
  bool nonlinear = false;                        ///< top-level `nonlinear`: large deflections (SPEC §8)
  NonlinearSettings nonlinear_settings;          ///< top-level `strain_measure`, `load_steps`
  /// Plausibility warnings (deck_plausibility.hpp): values that look like a unit slip. The CLI prints
  /// them, summary.json lists them under "warnings", --strict refuses the deck.
  std::vector<std::string> warnings;
};

/// Parses a deck from text; `source` names it in messages. Throws DeckError.
[[nodiscard]] Deck parse_deck(std::string_view text, const std::string& source);
/// Reads and parses a deck file. Throws DeckError (also for an unreadable file, a FIFO, a device, or a
/// file larger than 16 MiB).
[[nodiscard]] Deck load_deck(const std::filesystem::path& path);
/// Checks that every section `kind` needs is present; throws DeckError naming the missing ones.
void require_sections(const Deck& deck, AnalysisKind kind);

[[nodiscard]] std::string_view to_string(AnalysisKind kind);
[[nodiscard]] std::optional<AnalysisKind> parse_analysis_kind(std::string_view name);

/// The plate's laminates in the order regions refer to them: [laminate] first, then [laminates.NAME].
[[nodiscard]] std::vector<Laminate> all_laminates(const Deck& deck);

/// "WHAT: unknown criterion "NAME" (did you mean "tsai-wu"?)", or with the list of the known names.
[[nodiscard]] std::string unknown_criterion(std::string_view what, std::string_view name);
/// The same for a threshold criterion: the failure criteria and the damage criteria ("fibre-damage", …).
[[nodiscard]] std::string unknown_threshold_criterion(std::string_view what, std::string_view name);

} // namespace plyimpact
