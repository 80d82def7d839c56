#include "plyimpact/analysis/recorders.hpp"

#include <algorithm>

namespace plyimpact {

ImpactSample history_sample(const StepView& v) {
  ImpactSample h;
  h.t = v.t;
  h.force = v.force;
  h.impactor_w = v.impactor_w;
  h.impactor_v = v.impactor_v;
  h.plate_w = v.plate_w;
  h.indentation = v.indentation;
  h.plate_kinetic = v.plate_kinetic_energy();
  h.plate_strain = v.plate_strain_energy();
  h.impactor_energy = v.impactor_energy;
  h.contact_work = v.contact_work;
  if (const PlyDamageView* d = v.damage()) {
    h.damage_dissipation = d->dissipated().sum();
    h.damage_area = d->projected_damage_area();
    h.ply_damage_area = d->ply_damage_area();
  }
  if (const DelaminationAreas* d = v.delamination_areas()) {
    h.delamination_dissipation = d->dissipated;
    h.delaminated_area = d->projected_area;
    h.interface_delaminated_area = d->delaminated_area;
  }
  return h;
}

FieldRecorder::FieldRecorder(std::vector<double> times) : times_(std::move(times)) {
  std::sort(times_.begin(), times_.end());
}

void FieldRecorder::on_step(const StepView& view) {
  while (next_ < times_.size() && view.t >= times_[next_] - 1e-12 * view.dt) {
    fields_.push_back({view.t, view.plate ? view.plate_displacement() : Eigen::VectorXd()});
    ++next_;
  }
}

} // namespace plyimpact
