#include "plyimpact/io/sweeps/sweep_runner.hpp"

#include "plyimpact/fem/element_loop.hpp"
#include "plyimpact/io/deck/json_text.hpp"

#include "plyimpact/analysis/fields/damage_tracker.hpp"
#include "plyimpact/analysis/thresholds/threshold_search.hpp"
#include "plyimpact/io/deck/case_from_deck.hpp"
#include "plyimpact/io/results/damage_report.hpp"
#include "plyimpact/io/results/impact_report.hpp"
#include "plyimpact/io/results/results.hpp"
#include "plyimpact/io/run/impact_run.hpp"
#include "plyimpact/io/sweeps/sweep_report.hpp"
#include "plyimpact/io/sweeps/threshold_run.hpp"
#include "plyimpact/io/system/atomic_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <limits>
#include <map>
#include <mutex>
#include <new>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <utility>

namespace plyimpact {

namespace fs = std::filesystem;

namespace {

constexpr int record_format = 1;

/// Columns of sweep.csv after the swept keys: (header, record key in "results").
struct Column {
  const char* header;
  const char* key;
};
constexpr std::array<Column, 14> result_columns{{
    {"peak_force_N", "peak_force"},
    {"time_of_peak_force_s", "time_of_peak_force"},
    {"contact_duration_s", "contact_duration"},
    {"peak_contact_deflection_m", "peak_contact_deflection"},
    {"max_indentation_m", "max_indentation"},
    {"absorbed_energy_J", "absorbed_energy"},
    {"rebound_velocity_m_per_s", "rebound_velocity"},
    {"contacts", "contacts"},
    {"first_failure_time_s", "first_failure_time"},
    {"first_failure_criterion", "first_failure_criterion"},
    {"first_failure_mode", "first_failure_mode"},
    {"first_failure_ply", "first_failure_ply"},
    {"first_failure_interface", "first_failure_interface"},
    {"threshold_velocity_m_per_s", "threshold_velocity"},
}};
/// Columns added later, after `error`, so that every earlier column keeps its place (scripts that read
/// the table by position). Empty where they do not apply: onset damage and threshold runs compute no
/// dissipation or damaged area; runs without [delamination] no delaminated area.
constexpr std::array<Column, 5> later_columns{{
    {"damage_dissipation_J", "damage_dissipation"},
    {"damage_area_m2", "damage_area"},
    {"delamination_dissipation_J", "delamination_dissipation"},
    {"delamination_area_m2", "delamination_area"},
    {"plate_response", "plate_response"},
}};

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string q(1, '"');
  for (const char c : s) {
    if (c == '"') q += '"';
    q += c;
  }
  q += '"';
  return q;
}

/// A JSON scalar as table text: doubles by their shortest round-trip text, null as an empty field.
std::string cell(const nlohmann::json& j) {
  if (j.is_null()) return "";
  if (j.is_number_float()) return fmt::format("{}", j.get<double>());
  if (j.is_number_integer()) return fmt::format("{}", j.get<long>());
  if (j.is_boolean()) return j.get<bool>() ? "true" : "false";
  if (j.is_string()) return csv_field(j.get<std::string>());
  return csv_field(json_text(j));
}

std::vector<std::string> value_texts(const SweepCase& c) {
  std::vector<std::string> v;
  v.reserve(c.values.size());
  for (const auto& x : c.values)
    v.push_back(to_text(x));
  return v;
}

void put_first_failure(nlohmann::json& results, const std::optional<DamageOnset>& f) {
  results["first_failure_time"] = f ? nlohmann::json(f->time) : nlohmann::json(nullptr);
  results["first_failure_criterion"] =
      f ? nlohmann::json(std::string(to_string(f->criterion))) : nlohmann::json(nullptr);
  results["first_failure_mode"] =
      f ? nlohmann::json(std::string(to_string(f->mode))) : nlohmann::json(nullptr);
  results["first_failure_ply"] = f && f->ply > 0 ? nlohmann::json(f->ply) : nlohmann::json(nullptr);
  results["first_failure_interface"] =
      f && f->interface > 0 ? nlohmann::json(f->interface) : nlohmann::json(nullptr);
}

/// The first_failure_* columns of a damage threshold: the damage found at the threshold velocity
/// (criterion "matrix-damage", mode "matrix-tension", its ply; no interface).
void put_damage_reached(nlohmann::json& results, const std::string& criterion, const DamageReached& d) {
  results["first_failure_time"] = d.time;
  results["first_failure_criterion"] = criterion;
  results["first_failure_mode"] = std::string(to_string(d.mode));
  results["first_failure_ply"] = d.ply;
  results["first_failure_interface"] = nullptr;
}

} // namespace

// --- folder -----------------------------------------------------------------------------------

SweepFolder::SweepFolder(fs::path dir, const Sweep& sweep) : dir_(std::move(dir)), sweep_(sweep) {}

fs::path SweepFolder::record_path(std::size_t index) const {
  return dir_ / "cases" / fmt::format("{:06}.json", index);
}

namespace {

bool has_records(const fs::path& cases) {
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(cases, ec))
    if (e.path().extension() == ".json") return true;
  return false;
}

} // namespace

std::optional<std::pair<std::string, std::string>> SweepFolder::foreign_record() const {
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir_ / "cases", ec)) {
    if (e.path().extension() != ".json") continue;
    std::ifstream in(e.path());
    const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
    if (!j.is_object() || !j.contains("fingerprint") || !j["fingerprint"].is_string()) continue; // damaged
    const std::string theirs = j["fingerprint"].get<std::string>();
    if (theirs != sweep_.fingerprint()) return std::pair{e.path().string(), theirs};
  }
  return std::nullopt;
}

std::optional<std::string> SweepFolder::check(bool resume) const {
  const fs::path manifest = dir_ / "sweep.json";
  const bool records = has_records(dir_ / "cases");
  std::optional<std::string> warning;
  if (fs::exists(manifest)) {
    std::ifstream in(manifest);
    const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
    if (j.is_object() && j.contains("fingerprint") && j["fingerprint"].is_string()) {
      const std::string theirs = j["fingerprint"].get<std::string>();
      if (theirs != sweep_.fingerprint())
        throw std::runtime_error(fmt::format(
            "{} holds another sweep (fingerprint {}, this deck and options give {}): the deck or the sweep "
            "changed; use another output folder, or add --overwrite to replace it",
            dir_.string(), theirs, sweep_.fingerprint()));
    } else { // truncated or corrupt: the records say which sweep they belong to
      if (records && !resume)
        throw std::runtime_error(fmt::format(
            "{} is truncated or corrupt (not the JSON object plyimpact writes), so it no longer says which "
            "sweep the folder holds; each record in cases/ carries its sweep's fingerprint: run the same "
            "command with --resume to check them against this sweep, rewrite sweep.json and run only the "
            "missing cases",
            manifest.string()));
      if (const auto other = foreign_record())
        throw std::runtime_error(fmt::format("{} holds another sweep ({} has fingerprint {}, this deck and "
                                             "options give {}; sweep.json is truncated or corrupt): use "
                                             "another output folder, or add --overwrite to replace it",
                                             dir_.string(), other->first, other->second,
                                             sweep_.fingerprint()));
      warning = fmt::format("{} was truncated or corrupt: rewritten for this sweep (the records in cases/ "
                            "belong to it)",
                            manifest.string());
    }
  }
  if (resume || !records) return warning;
  throw std::runtime_error(fmt::format("{} already holds case records: add --resume to run only the missing "
                                       "cases, --overwrite to start again, or use another output folder",
                                       dir_.string()));
}

void SweepFolder::write_manifest() const {
  const SweepSpec& s = sweep_.spec();
  nlohmann::json j;
  j["program"] = "plyimpact";
  j["version"] = PLYIMPACT_VERSION;
  j["deck"] = sweep_.source();
  j["fingerprint"] = sweep_.fingerprint();
  j["analysis"] = std::string(to_string(s.analysis));
  j["mode"] = s.mode == SweepMode::zip ? "zip" : "product";
  j["keys"] = sweep_.keys();
  j["cases"] = sweep_.size();
  j["samples"] = s.samples;
  j["seed"] = s.seed;
  write_file_atomically(dir_ / "sweep.json", json_text(j, 2) + "\n");
}

std::optional<nlohmann::json> SweepFolder::read_record(std::size_t index, std::string* problem) const {
  std::ifstream in(record_path(index));
  if (!in) return std::nullopt;
  const auto damaged = [&](const std::string& why) -> std::optional<nlohmann::json> {
    if (problem != nullptr) *problem = why;
    return std::nullopt;
  };
  nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded()) return damaged("not valid JSON (truncated?)");
  try {
    if (!j.is_object()) return damaged("not a JSON object");
    if (j.value("fingerprint", std::string()) != sweep_.fingerprint() ||
        j.value("case", std::numeric_limits<std::size_t>::max()) != index ||
        j.value("values", std::vector<std::string>{}) != value_texts(sweep_.case_at(index)))
      return std::nullopt;
    // what sweep.csv reads of a record
    (void)j.at("status").get<std::string>();
    if (!j.at("results").is_object()) return damaged("\"results\" is not an object");
  } catch (const nlohmann::json::exception& e) { // what() starts with "[json.exception.type_error.302] "
    const std::string what = e.what();
    const std::size_t end = what.find("] ");
    return damaged("a field has the wrong type: " + (end == std::string::npos ? what : what.substr(end + 2)));
  }
  return j;
}

SweepFolder::Pending SweepFolder::scan() const {
  Pending p;
  for (std::size_t i = 0; i < sweep_.size(); ++i) {
    std::string problem;
    if (read_record(i, &problem)) continue;
    p.cases.push_back(i);
    if (!problem.empty())
      p.damaged.push_back(
          fmt::format("{} is damaged ({}): case {} runs again", record_path(i).string(), problem, i));
  }
  return p;
}

SweepFolder::TableStatus SweepFolder::write_table() const {
  TableStatus status;
  std::vector<nlohmann::json> records;
  records.reserve(sweep_.size());
  for (std::size_t i = 0; i < sweep_.size(); ++i) {
    auto r = read_record(i);
    if (!r) {
      ++status.missing;
      continue;
    }
    if (r->value("status", std::string()) != "ok") ++status.failed;
    records.push_back(std::move(*r));
  }
  if (status.missing == 0) {
    write_file_atomically(dir_ / "sweep.csv", sweep_table_csv(sweep_, records));
    write_file_atomically(dir_ / "report.html", sweep_report_html(sweep_, records));
  }
  return status;
}

std::string sweep_table_csv(const Sweep& sweep, const std::vector<nlohmann::json>& records) {
  std::string csv = "case";
  const auto add = [&csv](const std::string& field) {
    csv += ',';
    csv += field;
  };
  for (const auto& k : sweep.keys())
    add(csv_field(k));
  add("status");
  for (const Column& c : result_columns)
    add(c.header);
  add("error");
  for (const Column& c : later_columns)
    add(c.header);
  csv += '\n';
  for (const nlohmann::json& r : records) {
    csv += fmt::format("{}", r.at("case").get<std::size_t>());
    for (const auto& v : r.at("values"))
      add(csv_field(v.get<std::string>()));
    add(cell(r.at("status")));
    const nlohmann::json& results = r.at("results");
    const auto result_cell = [&results](const Column& c) {
      return cell(results.contains(c.key) ? results.at(c.key) : nlohmann::json(nullptr));
    };
    for (const Column& c : result_columns)
      add(result_cell(c));
    add(cell(r.value("error", nlohmann::json(nullptr))));
    for (const Column& c : later_columns)
      add(result_cell(c));
    csv += '\n';
  }
  return csv;
}

// --- one case ---------------------------------------------------------------------------------

/// The impact cases the workers of one process share. A case is built once per plate (same_plate,
/// analysis/impact/impact_case.hpp), by the first worker that asks for it (the others wait for it), run by
/// every worker whose case has that plate (ImpactCase::run is const; what it builds lazily, the factors of
/// finer steps and the contact-point response, is built once under a lock), and freed when the last worker
/// holding it has moved on and another case has been built since (the newest is kept, so a worker that
/// starts late, or comes back to it, does not build it again: at most one case more than the workers hold).
class SharedImpactCases {
public:
  /// The case of the plate of `description`, built by `build` unless a worker holds it; `built` says
  /// whether this call built it.
  std::shared_ptr<const ImpactCase> get(const ImpactCaseDescription& description,
                                        const std::function<std::unique_ptr<ImpactCase>()>& build,
                                        bool& built) {
    std::shared_ptr<Entry> entry;
    {
      const std::lock_guard lock(mutex_);
      std::erase_if(entries_, [](const auto& e) { return e.expired(); });
      for (const std::weak_ptr<Entry>& e : entries_) {
        std::shared_ptr<Entry> held = e.lock();
        if (held && same_plate(held->description, description)) entry = std::move(held);
      }
      if (!entry) {
        entry = std::make_shared<Entry>(description);
        entries_.push_back(entry);
        newest_ = entry;
      }
    }
    built = false;
    std::call_once(entry->once, [&] { // a throwing build leaves it to the next caller
      entry->impact = build();
      built = true;
    });
    return {entry, entry->impact.get()}; // keeps the entry, and so the case, alive
  }

private:
  struct Entry {
    explicit Entry(ImpactCaseDescription d) : description(std::move(d)) {}
    ImpactCaseDescription description;
    std::once_flag once;
    std::unique_ptr<ImpactCase> impact;
  };
  std::mutex mutex_;
  std::vector<std::weak_ptr<Entry>> entries_;
  std::shared_ptr<Entry> newest_;
};

struct SweepWorker::Cache {
  ImpactCaseDescription description;
  std::shared_ptr<const ImpactCase> impact;
};

SweepWorker::SweepWorker(const Sweep& sweep, const SweepFolder& folder, SweepOptions options,
                         SharedImpactCases& cases)
    : sweep_(sweep), folder_(folder), options_(std::move(options)), cases_(cases) {}

SweepWorker::~SweepWorker() = default;

namespace {

/// The threshold search of one case (its own ImpactCase: the search shares it between its trials).
void run_threshold_case(const Deck& deck, nlohmann::json& record, const std::optional<fs::path>& case_dir) {
  nlohmann::json& results = record["results"];
  if (deck.threshold.criterion.empty() && deck.damage.criteria.empty())
    throw DeckError(fmt::format("{}: error: a threshold sweep needs [threshold] criterion", deck.source));
  const ThresholdCriterion criterion = threshold_criterion(deck, "");
  const ImpactCase impact(impact_case_description(deck)); // refuses a mesh beyond the memory available
  const ThresholdOptions to = threshold_options(deck);
  const ThresholdResult r = search_threshold(impact, criterion, to);
  results["threshold_velocity"] = r.found ? nlohmann::json(r.velocity) : nlohmann::json(nullptr);
  results["threshold_criterion"] = criterion.name;
  results["plate_response"] = "full"; // every trial looks at the plies' stresses or damage
  if (r.damage)
    put_damage_reached(results, criterion.name, *r.damage);
  else
    put_first_failure(results, r.first_failure);
  record["status"] = r.found ? "ok" : "incomplete";
  if (!r.found)
    record["error"] = fmt::format(
        "no {} below threshold.max_velocity = {} m/s",
        std::holds_alternative<DamageCriterion>(criterion.criterion) ? "damage" : "failure", to.max_velocity);
  if (case_dir) {
    const ResultsFolder out(*case_dir, deck);
    nlohmann::json j = summary_header(deck, "threshold");
    put_threshold_summary(j, criterion, r);
    out.write_summary(j);
  }
}

void put_impact_results(nlohmann::json& results, const ImpactRunOutcome& o) {
  const ImpactResult& r = o.result;
  results["peak_force"] = r.peak_force;
  results["time_of_peak_force"] = r.time_of_peak_force;
  results["contact_duration"] = r.contact_duration;
  results["peak_contact_deflection"] = r.peak_contact_deflection;
  results["max_indentation"] = r.max_indentation;
  // null while the impactor has not left the plate (ImpactResult)
  results["absorbed_energy"] =
      r.absorbed_energy ? nlohmann::json(*r.absorbed_energy) : nlohmann::json(nullptr);
  results["rebound_velocity"] =
      r.rebound_velocity ? nlohmann::json(*r.rebound_velocity) : nlohmann::json(nullptr);
  results["contacts"] = r.episodes.size();
  results["steps"] = r.steps;
  results["dt"] = o.settings.dt;
  // how the plate was solved: every step with K̄, or through its impulse response at the contact point
  results["plate_response"] = plate_response_name(r);
  if (r.progressive) { // ply damage (docs/progressive_damage.md); absent for onset runs
    results["damage_dissipation"] = r.progressive->dissipated.sum();
    results["damage_area"] = r.progressive->projected_damage_area;
  }
  if (r.delamination) { // the stacked plate's interfaces (docs/delamination.md)
    results["delamination_area"] = r.delamination->projected_area;
    results["delamination_dissipation"] = r.delamination->dissipated;
  }
  if (o.damage_tracked) put_first_failure(results, o.laminate_first_failure); // away from a rig's clamp tips
}

} // namespace

std::optional<nlohmann::json> SweepWorker::run(std::size_t index) {
  const SweepCase c = sweep_.case_at(index);
  nlohmann::json record;
  record["format"] = record_format;
  record["case"] = index;
  record["fingerprint"] = sweep_.fingerprint();
  record["values"] = value_texts(c);
  record["results"] = nlohmann::json::object();
  try {
    const Deck deck = sweep_.deck_for(c);
    require_sections(deck, sweep_.spec().analysis);
    std::optional<fs::path> case_dir;
    if (options_.case_folders) case_dir = folder_.path() / "cases" / fmt::format("{:06}", index);
    if (sweep_.spec().analysis == AnalysisKind::threshold) {
      run_threshold_case(deck, record, case_dir);
      ++factorizations_; // a finished search is recorded even after an interrupt: its result is whole
      return record;
    }
    // Impact: reuse this worker's case (plate and factorization) when only what a run may change differs
    // (same_plate: the impactor, the contact stiffness).
    const ImpactCaseDescription description = impact_case_description(deck);
    if (!options_.share_factorization || !cache_ || !same_plate(cache_->description, description)) {
      cache_.reset();
      const auto build = [&description] { return std::make_unique<ImpactCase>(description); };
      bool built = true;
      cache_ = std::make_unique<Cache>(Cache{description, options_.share_factorization
                                                              ? cases_.get(description, build, built)
                                                              : std::shared_ptr<const ImpactCase>(build())});
      if (built) ++factorizations_;
    }
    ImpactRunOptions run;
    run.output_dir = case_dir;
    run.history = options_.case_folders; // the table needs no history
    run.pictures = false;
    run.cancel = options_.cancel;
    // where exact and nothing looks at the field (ImpactCase::run)
    run.contact_point_response = sweep_.spec().contact_point_response;
    const ImpactRunOutcome outcome = run_impact(deck, *cache_->impact, run);
    if (options_.cancel != nullptr && options_.cancel->load() && !outcome.result.complete)
      return std::nullopt;
    put_impact_results(record["results"], outcome);
    record["status"] = outcome.result.complete ? "ok" : "incomplete";
    if (!outcome.result.complete) record["error"] = outcome.result.incomplete_reason;
  } catch (const std::bad_alloc&) { // never a bare std::bad_alloc in a table
    record["status"] = "failed";
    record["error"] = "out of memory (std::bad_alloc): use a coarser mesh";
    record["results"] = nlohmann::json::object();
  } catch (const std::exception& e) { // a bad combination of values fails this case only
    // unless the user interrupted it (meshing, building, stepping): a case stopped by Ctrl-C did not fail,
    // it did not run, and --resume runs it (issue 77: it was stored as failed and never run again)
    if (options_.cancel != nullptr && options_.cancel->load()) return std::nullopt;
    record["status"] = "failed";
    record["error"] = e.what();
    record["results"] = nlohmann::json::object();
  }
  return record;
}

int run_sweep_cases(const Sweep& sweep, const SweepFolder& folder, const std::vector<std::size_t>& pending,
                    int jobs, const NextCase& next, const SweepOptions& options) {
  if (jobs < 1 || jobs > max_sweep_jobs)
    throw std::invalid_argument(
        fmt::format("sweep: jobs must lie between 1 and {} threads, got {}", max_sweep_jobs, jobs));
  std::atomic<int> factorizations{0};
  std::mutex error_mutex;
  std::string first_error;
  SharedImpactCases cases;
  const auto work = [&] {
    const ElementThreads one(1); // the sweep's cases are its parallelism: no threads within a case
    try {
      SweepWorker worker(sweep, folder, options, cases);
      while (options.cancel == nullptr || !options.cancel->load()) {
        const auto position = next();
        if (!position || *position >= pending.size()) break;
        const std::size_t index = pending[*position];
        const auto record = worker.run(index);
        if (!record) break; // cancelled part-way: not recorded, runs again on --resume
        write_file_atomically(folder.record_path(index), json_text(*record, 1) + "\n");
        if (options.on_case_recorded) options.on_case_recorded();
      }
      factorizations += worker.factorizations();
    } catch (const std::exception& e) { // cannot write a record: stop this worker, report it
      const std::lock_guard lock(error_mutex);
      if (first_error.empty()) first_error = e.what();
    }
  };
  std::vector<std::thread> threads;
  for (int j = 1; j < jobs; ++j)
    threads.emplace_back(work);
  work();
  for (auto& t : threads)
    t.join();
  if (!first_error.empty()) throw std::runtime_error(first_error);
  return factorizations.load();
}

} // namespace plyimpact
