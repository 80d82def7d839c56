#include "plyimpact/io/deck/case_from_deck.hpp"

#include "plyimpact/analysis/impact/capabilities.hpp"
#include "plyimpact/analysis/integrators/newton_settings.hpp"
#include "plyimpact/fem/structured_mesh.hpp"
#include "plyimpact/io/system/memory_estimate.hpp"
#include "plyimpact/io/system/system_memory.hpp"

namespace plyimpact {

DiscretePlate plate_model(const Deck& deck) {
  const MeshSpec spec = deck.mesh.value_or(MeshSpec{}); // static, modal, buckling: nx × ny (15 × 11)
  Mesh mesh = deck.file_mesh ? *deck.file_mesh : structured_rectangle(*deck.plate, spec.nx, spec.ny);
  std::vector<int> of_element = element_laminates(mesh, deck.regions);
  return {std::move(mesh), PlateSections{all_laminates(deck), std::move(of_element)},
          Discretization{spec.mass, spec.element}, *deck.boundary};
}

ImpactCaseDescription impact_case_description(const Deck& deck, bool nonlinear) {
  check_deck_fits_memory(deck); // a uniform mesh, naming the deck; ImpactCase checks a graded one
  ImpactCaseDescription d;
  d.plate = deck.plate.value_or(PlateGeometry{});
  d.mesh_from_file = deck.file_mesh;
  MeshSpec graded; // no [mesh] table: graded toward the impact point (a mesh from gmsh is used as it is)
  if (!deck.file_mesh) graded.grading = MeshGrading{};
  d.mesh = deck.mesh.value_or(graded);
  d.laminates = all_laminates(deck);
  d.regions = deck.regions;
  d.boundary = deck.boundary.value_or(BoundaryConditions{});
  d.impactor = *deck.impactor;
  d.contact = deck.contact;
  d.time = deck.time;
  if (nonlinear || deck.nonlinear) {
    NonlinearImpactSettings ns;
    ns.measure = deck.nonlinear_settings.measure;
    d.nonlinear = ns;
  }
  d.progressive_damage = deck.damage.progressive;
  d.delamination = deck.delamination;
  if (d.delamination) { // the seed (if any) lies under the impactor
    d.delamination->stack.seed_x = d.impactor.x;
    d.delamination->stack.seed_y = d.impactor.y;
  }
  const Integrator integrator = case_integrator(d);
  if (deck.damage.refactor_tolerance && integrator != Integrator::central_difference) {
    // the one Newton key of the deck: the integrator's setting, over the row's defaults
    d.newton = newton_newmark_defaults(model_kind(d), integrator);
    d.newton->refactor_tolerance = *deck.damage.refactor_tolerance;
  }
  d.memory_limit_bytes = available_memory_bytes(); // factorization guard (docs/robustness.md)
  return d;
}

DamageOptions damage_options_from_deck(const Deck& deck) {
  DamageOptions d;
  d.every = deck.damage.every;
  d.criterion_options.delamination_ply_n =
      deck.damage.delamination_ply_n_lower ? DelaminationPlyN::lower : DelaminationPlyN::upper;
  return d;
}

} // namespace plyimpact
