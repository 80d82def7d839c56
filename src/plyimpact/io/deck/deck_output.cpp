#include "plyimpact/io/deck/deck_tables.hpp"

#include <fmt/format.h>

namespace plyimpact::deck_tables {

namespace {

/// A list of times in s (each finite and >= 0), e.g. output.fields_at.
std::vector<double> time_list(const TableReader& t, std::string_view key) {
  std::vector<double> times;
  const toml::node* f = t.node(key);
  if (f == nullptr) return times;
  const toml::array* arr = f->as_array();
  if (arr == nullptr) t.fail_at(key, fmt::format("{}.{} must be an array of times in s", t.path(), key));
  for (const toml::node& item : *arr) {
    const auto v = item.value<double>();
    if (!v || !(*v >= 0.0) || !std::isfinite(*v))
      fail(t.file(), item.source(),
           fmt::format("{}.{}: expected a time in s (a number >= 0)", t.path(), key));
    times.push_back(t.to_si(*v, "s"));
  }
  return times;
}

/// A list of 1-based layer numbers in 1..count (plies or interfaces).
std::vector<int> layer_list(const TableReader& t, std::string_view key, int count, std::string_view what) {
  std::vector<int> layers;
  const toml::node* f = t.node(key);
  if (f == nullptr) return layers;
  const toml::array* arr = f->as_array();
  if (arr == nullptr)
    t.fail_at(key, fmt::format("{}.{} must be an array of {} numbers", t.path(), key,
                               what.substr(what.find(' ') + 1)));
  for (const toml::node& item : *arr) {
    // Integers only: value<long>() of a float node casts it, undefined beyond the range of long
    // (the deck fuzzer found vtk_plies = [5e87]).
    const auto* i = item.as_integer();
    const std::optional<long> v = i != nullptr ? std::optional<long>(i->get()) : std::nullopt;
    if (!v || *v < 1 || (count > 0 && *v > count))
      fail(t.file(), item.source(),
           fmt::format("{}.{}: expected {} number from 1 to {}", t.path(), key, what, count));
    layers.push_back(static_cast<int>(*v));
  }
  return layers;
}

/// [output] vtk, vtk_every, vtk_at, vtk_plies, vtk_interfaces, vtk_thickness_scale.
void read_vtk_output(const TableReader& t, Deck& d) {
  VtkOutputSettings& v = d.vtk;
  if (const toml::node* n = t.node("vtk")) {
    const auto b = n->value<bool>();
    if (!b) t.fail_at("vtk", "output.vtk must be true or false");
    v.enabled = *b;
  }
  if (const auto every = t.optional_integer("vtk_every")) {
    if (*every < 1 || *every > 100'000'000)
      t.fail_at("vtk_every", fmt::format("output.vtk_every must be a positive step count, got {}", *every));
    v.every = static_cast<int>(*every);
    v.enabled = true;
  }
  v.at = time_list(t, "vtk_at");
  if (!v.at.empty()) v.enabled = true;
  if (v.enabled && v.every == 0 && v.at.empty()) v.every = VtkOutputSettings::default_every;
  const int plies = d.laminate ? static_cast<int>(d.laminate->ply_count()) : 0;
  v.plies = layer_list(t, "vtk_plies", plies, "a ply");
  v.interfaces = layer_list(t, "vtk_interfaces", plies - 1, "an interface");
  if (t.has("vtk_thickness_scale")) v.thickness_scale = t.positive("vtk_thickness_scale", "-");
}

} // namespace

void read_output(const TableReader& t, Deck& d) {
  t.only_keys_of("output");
  if (const toml::node* pr = t.node("probe")) {
    const toml::array* arr = pr->as_array();
    if (arr == nullptr || !arr->is_array_of_tables())
      t.fail_at("probe", "output.probe must be an array of tables: [[output.probe]]");
    for (const toml::node& item : *arr) {
      const TableReader p = t.nested(*item.as_table(), "output.probe");
      p.only_keys_of("output.probe");
      StressProbeSpec spec;
      spec.x = p.number("x", "m");
      spec.y = p.number("y", "m");
      spec.ply = static_cast<int>(p.optional_integer("ply").value_or(0));
      spec.interface = static_cast<int>(p.optional_integer("interface").value_or(0));
      spec.position = p.optional_choice<std::string>(
                           "position", {{"average", "average"}, {"top", "top"}, {"bottom", "bottom"}})
                          .value_or("average");
      const int plies = d.laminate ? static_cast<int>(d.laminate->ply_count()) : 0;
      if ((spec.ply > 0) == (spec.interface > 0))
        p.fail_here("output.probe needs exactly one of ply = N or interface = N (1-based)");
      if (d.laminate &&
          (spec.ply > plies || spec.interface > plies - 1 || spec.ply < 0 || spec.interface < 0))
        p.fail_here(
            fmt::format("output.probe: the laminate has {} plies and {} interfaces", plies, plies - 1));
      if ((d.plate && !(spec.x >= 0 && spec.x <= d.plate->a && spec.y >= 0 && spec.y <= d.plate->b)) ||
          (d.file_mesh && !d.file_mesh->locate(spec.x, spec.y)))
        p.fail_at("x", fmt::format("output.probe point ({}, {}) m lies outside the plate", spec.x, spec.y));
      spec.name =
          p.optional_string("name").value_or(spec.ply > 0 ? fmt::format("ply{}_{}", spec.ply, spec.position)
                                                          : fmt::format("interface{}", spec.interface));
      d.probes.push_back(spec);
    }
  }
  d.output_dir = t.optional_string("dir").value_or("results");
  d.field_times = time_list(t, "fields_at");
  const long every = t.optional_integer("history_every").value_or(1);
  if (every < 1)
    t.fail_at("history_every",
              fmt::format("output.history_every must be a positive step count, got {}", every));
  d.history_every = static_cast<int>(every);
  read_vtk_output(t, d);
  if (t.has("report_displacements_at")) d.report_displacements_at = t.number("report_displacements_at", "s");
}

void read_run(const TableReader& t, Deck& d) {
  t.only_keys_of("run");
  if (!t.has("threads")) return;
  const long threads = t.optional_integer("threads").value_or(0);
  if (threads < 1 || threads > max_run_threads)
    t.fail_at("threads",
              fmt::format("run.threads must be a whole number of threads from 1 to {}, got {} (leave "
                          "it out to use every core)",
                          max_run_threads, threads));
  d.threads = static_cast<int>(threads);
}

} // namespace plyimpact::deck_tables
