#pragma once
// The deck parser's table readers (private to io/): one per table or group of tables of the deck
// (docs/deck.md), each validating its keys with TableReader.
#include "plyimpact/io/deck/deck.hpp"
#include "plyimpact/io/deck/table_reader.hpp"

#include <string>
#include <vector>

namespace plyimpact::deck_tables {

inline constexpr int max_elements_per_side = 2000;
inline constexpr long max_elements = 1'000'000;
inline constexpr long max_step_cap = 100'000'000;

// deck_materials.cpp
[[nodiscard]] Material read_material(const TableReader& t, const std::string& name);
/// Index of material `name` in `materials`; otherwise an error at `key` with the closest name.
[[nodiscard]] std::size_t material_index(const std::vector<Material>& materials, const TableReader& t,
                                         std::string_view key, const std::string& name);

// deck_laminates.cpp
/// [laminate] or [laminates.NAME] (`t.path()` names it in messages).
[[nodiscard]] NamedLaminate read_laminate(const std::vector<Material>& materials, const TableReader& t,
                                          std::string name);
/// [[region]] tables: each names a laminate of [laminates.NAME] and its x, y bounds.
[[nodiscard]] std::vector<Region> read_regions(const Deck& d, const TableReader& top);

// deck_plate.cpp
[[nodiscard]] PlateGeometry read_plate(const TableReader& t);
[[nodiscard]] MeshSpec read_mesh(const TableReader& t);
/// mesh.size_at_impact, growth and max_size for a plate that gmsh meshes, graded toward `refine_at`.
[[nodiscard]] GeometryMeshing read_geometry_meshing(const TableReader& t,
                                                    const std::optional<Eigen::Vector2d>& refine_at);
/// [rig]: the preset's plate, mesh and supports into `d` (with [mesh] `mesh`'s sizes, when given).
/// The preset's mesh is graded toward `refine_at` (the impact or load point), else the rig's centre.
void read_rig(const TableReader& top, const TableReader& t, const std::optional<TableReader>& mesh,
              const std::optional<Eigen::Vector2d>& refine_at, Deck& d);
/// A rig whose [mesh] gives no sizes, struck with progressive ply damage or [delamination]: meshed again
/// with the elements that the damage needs within its zone about the impact point (analysis/
/// damage_zone.hpp, DZ1–DZ3), graded beyond; the rig's description says so. Unchanged where the rig's own
/// elements are small enough.
void size_rig_for_damage(Deck& d);
/// [mesh] file: the gmsh mesh it names (relative to the deck's folder), read and checked; nullptr without
/// the key. mesh.geo: the gmsh geometry it names, meshed by gmsh, graded toward `refine_at` (the impact or
/// load point, when the deck gives one), with the sizes it was meshed with in `meshing`.
[[nodiscard]] std::shared_ptr<const Mesh> read_mesh_file(const TableReader& t, std::string& written,
                                                         const std::optional<Eigen::Vector2d>& refine_at,
                                                         std::optional<GeometryMeshing>& meshing);
/// [boundary] of the structured rectangle (x0, xa, y0, yb, corners), or of `file_mesh`: its named sets.
[[nodiscard]] BoundaryConditions read_boundary(const TableReader& t, const Mesh* file_mesh);

// deck_impact.cpp
/// [impactor] gives the impact's speed itself (velocity or energy): a rig's energy rule does not apply.
[[nodiscard]] bool gives_impact_speed(const TableReader& impactor);
/// [impactor]; `input` receives the density and energy when the deck gives them.
/// With `file_mesh`, the impact point defaults to the centre of its bounding box and must lie on it.
[[nodiscard]] Impactor read_impactor(const TableReader& t, const std::optional<PlateGeometry>& plate,
                                     const Mesh* file_mesh, ImpactorInput& input,
                                     const ImpactorDefaults& defaults = {});
/// [contact] for the impactor's nose (the unit of contact.k, the default unloading law).
[[nodiscard]] ContactLawParameters read_contact(const TableReader& t, NoseShape nose);
[[nodiscard]] TimeStepping read_time(const TableReader& t);
/// Top-level `nonlinear`, `strain_measure`, `load_steps`.
void read_nonlinear_keys(const TableReader& top, Deck& d);

// deck_analyses.cpp
/// [load]; its points must lie on the plate (the rectangle, or `file_mesh` when the mesh came from a file).
[[nodiscard]] StaticLoad read_load(const TableReader& t, const std::optional<PlateGeometry>& plate,
                                   const Mesh* file_mesh);
[[nodiscard]] ModalSettings read_modal(const TableReader& t);
[[nodiscard]] BucklingSettings read_buckling(const TableReader& t);
/// [damage]; with progressive damage its `integration` (given, or as [time] implies) sets d.time.laws.
[[nodiscard]] DamageSettings read_damage(const TableReader& t, Deck& d);
/// [threshold]; `d` has its [damage] already (damage criteria need the progressive model).
[[nodiscard]] ThresholdSettings read_threshold(const TableReader& t, const Deck& d);

// deck_delamination.cpp
/// [delamination]; `d` has its laminate and [damage] already (the cuts follow the layup; progressive ply
/// damage runs with the stacked plate in the same steps: capabilities.hpp).
/// `plies_given`: [damage] gives its `integration`; where it does not, the plies follow the interfaces'.
/// Sets d.time.laws to the interfaces' integration (the plate steps with one).
[[nodiscard]] DelaminationSettings read_delamination(const TableReader& t, Deck& d, bool plies_given);
/// [damage] or [delamination] `integration` where given: "implicit", "lagged" or "explicit".
[[nodiscard]] std::optional<Integrator> optional_law_integrator(const TableReader& t);

// deck_output.cpp
void read_output(const TableReader& t, Deck& d);
/// [run] threads: the threads of a run's element loops (Deck::threads).
void read_run(const TableReader& t, Deck& d);

} // namespace plyimpact::deck_tables
