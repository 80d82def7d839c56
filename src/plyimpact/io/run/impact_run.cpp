#include "plyimpact/io/run/impact_run.hpp"

#include "plyimpact/analysis/fields/stress_probe.hpp"
#include "plyimpact/analysis/impact/recorders.hpp"
#include "plyimpact/analysis/plate_analyses/nonlinear_static.hpp"
#include "plyimpact/analysis/thresholds/load_drop.hpp"
#include "plyimpact/fem/stacked_plate.hpp"
#include "plyimpact/io/deck/case_from_deck.hpp"
#include "plyimpact/io/results/damage_maps.hpp"
#include "plyimpact/io/results/damage_report.hpp"
#include "plyimpact/io/results/history_csv.hpp"
#include "plyimpact/io/results/html_report.hpp"
#include "plyimpact/io/results/impact_report.hpp"
#include "plyimpact/io/results/impact_text_report.hpp"
#include "plyimpact/io/results/ply_damage_maps.hpp"
#include "plyimpact/io/results/results.hpp"
#include "plyimpact/io/results/vtk_output.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <stdexcept>

namespace plyimpact {

namespace {

/// ParaView frames every `every` steps and at the requested times (docs/deck.md, [output] vtk*), with the
/// plies' damage in every frame of a progressive-damage run (zero before the first step).
class VtkFrames final : public ImpactObserver {
public:
  VtkFrames(const VtkOutputSettings& s, std::filesystem::path dir, const DiscretePlate& model,
            VtkOptions options, const DamageTracker* damage)
      : every_(s.every), at_(s.at), series_(std::move(dir), model, std::move(options)), damage_(damage) {
    std::sort(at_.begin(), at_.end());
  }
  /// The undeformed plate at t = 0 is the first frame, the last step the last one, whatever `every`.
  void on_start(const StepView& initial) override { write(initial); }
  void on_step(const StepView& v) override {
    bool due = every_ > 0 && v.step % every_ == 0;
    while (next_ < at_.size() && v.t >= at_[next_] - 1e-9 * v.dt) {
      due = true;
      ++next_;
    }
    if (due) write(v);
  }
  void on_finish(const StepView& last, const ImpactResult& /*result*/) override {
    if (last.step != last_written_) write(last);
  }
  [[nodiscard]] std::size_t frames() const { return series_.frames(); }

private:
  void write(const StepView& v) {
    const std::vector<DamageOnset>& onsets = damage_ != nullptr ? damage_->onsets() : none_;
    // A progressive run's plate has a damage field from the first frame on (virgin: all zero), a stacked
    // plate its interfaces.
    std::optional<std::vector<ElementPlyDamage>> plies;
    if (const PlyDamageView* field = v.damage()) plies = field->element_ply_damage();
    const std::optional<DelaminationResult> interfaces = v.delamination();
    series_.write(v.step, v.t, v.plate_displacement(), onsets, plies ? &*plies : nullptr,
                  interfaces ? &*interfaces : nullptr);
    last_written_ = v.step;
  }

  long last_written_ = -1;
  int every_;
  std::vector<double> at_;
  std::size_t next_ = 0;
  VtkSeries series_;
  const DamageTracker* damage_;
  std::vector<DamageOnset> none_;
};

/// The plate state at [output] report_displacements_at, for report.txt.
class ReportSnapshot final : public ImpactObserver {
public:
  explicit ReportSnapshot(double t) : t_(t) {}
  void on_step(const StepView& v) override {
    if (!snapshot && v.t >= t_ - 1e-9 * v.dt) snapshot = NodalSnapshot{v.t, v.plate_displacement()};
  }
  std::optional<NodalSnapshot> snapshot;

private:
  double t_;
};

/// The columns of a run's history: the plies' damage of a progressive run, the interfaces of a stacked one.
HistoryLayout history_layout_of(const Deck& deck, const ImpactSettings& s) {
  HistoryLayout layout;
  if (deck.damage.progressive && deck.laminate)
    layout.damaged_plies = static_cast<int>(deck.laminate->ply_count());
  if (s.delamination) layout.interfaces_after_ply = interfaces_after_ply(s.delamination->stack.cuts);
  return layout;
}

/// A run that stopped at a step it could not take, its results written (to `dir`, where there is one), ends
/// in RunFailure, its message the step's error and where the results are.
void report_failure(const ImpactResult& r, const std::optional<std::filesystem::path>& dir) {
  if (r.failure.empty()) return;
  if (!dir) throw RunFailure(r.failure);
  throw RunFailure(fmt::format("{}; the results up to t = {:.6g} s (step {}) are in {}, marked "
                               "\"complete\": false",
                               r.failure, r.end_time, r.steps, dir->string()));
}

} // namespace

const char* plate_response_name(const ImpactResult& result) {
  return result.contact_point_response ? "contact point" : "full";
}

ImpactRunOutcome run_impact(const Deck& deck, const ImpactCase& impact, const ImpactRunOptions& options) {
  ImpactRunOutcome out;
  out.settings =
      resolved_settings(impact_case_description(deck, impact.nonlinear()), impact.explicit_omega_max());
  out.settings.mesh = impact.settings().mesh; // the mesh the shared case runs on
  out.settings.stable_step = impact.settings().stable_step;
  out.settings.mass_scaling = impact.settings().mass_scaling;
  out.history_layout = history_layout_of(deck, out.settings);
  if (out.settings.dt != impact.settings().dt)
    throw std::invalid_argument(
        "impact: a case may reuse another's factorization only with the same time step");
  const DiscretePlate& model = impact.model();
  const bool plate = !impact.settings().rigid_target;
  const std::vector<Criterion> criteria = parse_criteria(deck.damage.criteria);

  RunRequest run;
  run.impactor = out.settings.impactor;
  run.contact_stiffness = out.settings.k;
  run.cancel = options.cancel;
  run.history_every = 0; // history.csv is streamed to the folder below, never kept in memory
  run.field_times = deck.field_times;
  run.observers = options.observers;
  run.threads = options.threads > 0 ? options.threads : deck.threads;
  run.keep_failed_run = true; // written below, then reported (report_failure)
  // ImpactCase::run checks the rest (no observers, no history, no fields)
  run.contact_point_response = options.contact_point_response && !options.output_dir;
  std::optional<DamageTracker> damage;
  if (!criteria.empty() && plate)
    run.observers.push_back(&damage.emplace(model, criteria, damage_options_from_deck(deck)));
  std::optional<StressProbes> probes;
  if (!deck.probes.empty() && plate) run.observers.push_back(&probes.emplace(model, deck.probes));
  // The folder exists before the run: ParaView frames are written while it runs.
  std::optional<ResultsFolder> folder;
  if (options.output_dir) folder.emplace(*options.output_dir, deck);
  std::optional<HistoryCsvWriter> history;
  if (folder && options.history)
    run.observers.push_back(
        &history.emplace(folder->path() / "history.csv", deck.history_every, out.history_layout));
  std::optional<VtkFrames> vtk;
  if (folder && deck.vtk.enabled && plate)
    run.observers.push_back(
        &vtk.emplace(deck.vtk, folder->path(), model,
                     VtkOptions{deck.vtk.plies, deck.vtk.interfaces, deck.vtk.thickness_scale, criteria,
                                damage_options_from_deck(deck).criterion_options},
                     damage ? &*damage : nullptr));
  // report.html, the first load drop and the first delamination; not where the run asks for the
  // contact-point response, which runs without observers
  std::optional<ThinnedHistory> curves;
  if (folder || !run.contact_point_response) run.observers.push_back(&curves.emplace());
  std::optional<ReportSnapshot> snapshot;
  if (deck.report_displacements_at && plate)
    run.observers.push_back(&snapshot.emplace(*deck.report_displacements_at));

  out.result = impact.run(run);
  if (curves)
    out.result.force_history = {first_load_drop(curves->samples()), first_delamination(curves->samples())};
  out.damage_tracked = damage.has_value();
  if (damage) {
    out.first_failures = damage->first_onsets();
    if (plate) out.clamp_tip_elements = clamp_tip_elements(model.mesh(), rig_outline(deck.rig).clamp_tips);
    out.laminate_first_failure = laminate_first_failure(damage->onsets(), out.clamp_tip_elements);
  }
  out.summary = impact_summary_json(deck, out.settings, out.result);
  if (vtk) out.summary["vtk_frames"] = vtk->frames();
  if (damage) {
    out.summary["first_failures"] = nlohmann::json::array();
    for (const auto& f : out.first_failures) {
      nlohmann::json j = onset_json(f);
      j["at_clamp_tip"] = at_clamp_tip(f, out.clamp_tip_elements);
      out.summary["first_failures"].push_back(std::move(j));
    }
    out.summary["laminate_first_failure"] =
        out.laminate_first_failure ? onset_json(*out.laminate_first_failure) : nlohmann::json(nullptr);
  }
  if (!folder) {
    report_failure(out.result, std::nullopt);
    return out;
  }

  if (damage) {
    folder->write_text("damage_onsets.csv", damage_onsets_csv(damage->onsets()));
    folder->write_text("damage_area.csv", damage_area_csv(damage->area_history()));
    // an interrupted run writes its tables and leaves the pictures out: it has a second to end in
    // (docs/robustness.md, "Interrupting a run"); plyimpact plot draws them later
    const bool interrupted = options.cancel != nullptr && options.cancel->load();
    if (options.pictures && !interrupted) {
      const DamageMapFiles maps = write_damage_maps(folder->path() / damage_maps_folder, model.mesh(),
                                                    damage->onsets(), rig_outline(deck.rig));
      if (!maps.warning.empty()) out.notes.push_back(maps.warning);
    }
  }
  if (out.result.progressive)
    folder->write_text(
        damage_elements_file,
        damage_elements_csv(model, PlyDamageTable(model, out.result.progressive->element_ply_damage)));
  if (out.result.delamination) {
    folder->write_text(delamination_elements_file,
                       delamination_elements_csv(model.mesh(), *out.result.delamination));
    folder->write_text(delamination_points_file, delamination_points_csv(*out.result.delamination));
  }
  if (probes) folder->write_text("probes.csv", probes_csv(*probes));
  folder->write_text("report.txt",
                     impact_report_text(deck, model, out.settings, out.result, out.first_failures,
                                        out.clamp_tip_elements, out.laminate_first_failure,
                                        snapshot ? snapshot->snapshot : std::nullopt));
  const ImpactReportInput report{deck,
                                 out.settings,
                                 out.summary,
                                 curves->samples(),
                                 plate ? &model.mesh() : nullptr,
                                 damage ? &damage->onsets() : nullptr,
                                 damage ? &out.first_failures : nullptr,
                                 out.clamp_tip_elements,
                                 out.laminate_first_failure,
                                 out.notes,
                                 out.result.delamination ? &*out.result.delamination : nullptr};
  folder->write_text("report.html", impact_report_html(report));
  write_impact_results(*folder, &model, out.result, out.summary);
  report_failure(out.result, folder->path());
  return out;
}

} // namespace plyimpact
