#include "plyimpact/analysis/impact/recorders.hpp"

#include <algorithm>

namespace plyimpact {

ImpactSample history_sample(const StepView& v) {
  ImpactSample h;
  history_sample(v, h);
  return h;
}

void history_sample(const StepView& v, ImpactSample& h) {
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
  h.damage_dissipation = 0.0; // zero / empty where the run has no damage or no interfaces
  h.damage_area = 0.0;
  h.ply_damage_area.clear();
  h.delamination_dissipation = 0.0;
  h.delaminated_area = 0.0;
  h.interface_delaminated_area.clear();
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
