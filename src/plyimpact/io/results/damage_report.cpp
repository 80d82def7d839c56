#include "plyimpact/io/results/damage_report.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace plyimpact {

nlohmann::json onset_json(const DamageOnset& o) {
  nlohmann::json j;
  j["criterion"] = std::string(to_string(o.criterion));
  j["mode"] = std::string(to_string(o.mode));
  j["ply"] = o.ply > 0 ? nlohmann::json(o.ply) : nlohmann::json(nullptr);
  j["interface"] = o.interface > 0 ? nlohmann::json(o.interface) : nlohmann::json(nullptr);
  j["element"] = o.element;
  j["ipgs"] = o.ipgs;
  j["jpgs"] = o.jpgs;
  j["x"] = o.x;
  j["y"] = o.y;
  j["time"] = o.time;
  j["force"] = o.force;
  j["sigma22"] = o.sigma22;
  j["tau23"] = o.tau23;
  j["index"] = o.index;
  return j;
}

std::string damage_onsets_csv(const std::vector<DamageOnset>& onsets) {
  std::string csv =
      "criterion,mode,ply,interface,element,ipgs,jpgs,x_m,y_m,time_s,force_N,sigma22_Pa,tau23_Pa,index\n";
  for (const auto& o : onsets)
    csv += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", // numbers: shortest round-trip text
                       to_string(o.criterion), to_string(o.mode), o.ply > 0 ? std::to_string(o.ply) : "",
                       o.interface > 0 ? std::to_string(o.interface) : "", o.element, o.ipgs, o.jpgs, o.x,
                       o.y, o.time, o.force, o.sigma22, o.tau23, o.index);
  return csv;
}

std::string damage_area_csv(const std::vector<DamageAreaSample>& areas) {
  std::string csv = "time_s,criterion,ply,interface,failed_area_m2\n";
  for (const auto& a : areas)
    csv += fmt::format("{},{},{},{},{}\n", a.time, to_string(a.criterion),
                       a.ply > 0 ? std::to_string(a.ply) : "",
                       a.interface > 0 ? std::to_string(a.interface) : "", a.area);
  return csv;
}

std::string probes_csv(const StressProbes& probes) {
  std::string csv;
  const auto cols = probes.columns();
  for (std::size_t i = 0; i < cols.size(); ++i)
    csv += (i ? "," : "") + cols[i];
  csv += "\n";
  for (const auto& row : probes.rows()) {
    for (std::size_t i = 0; i < row.size(); ++i)
      csv += fmt::format("{}{}", i ? "," : "", row[i]);
    csv += "\n";
  }
  return csv;
}

bool at_clamp_tip(const DamageOnset& o, const std::vector<int>& clamp_tip_elements) {
  return std::ranges::binary_search(clamp_tip_elements, o.element);
}

std::optional<DamageOnset> laminate_first_failure(const std::vector<DamageOnset>& onsets,
                                                  const std::vector<int>& clamp_tip_elements) {
  std::optional<DamageOnset> first;
  for (const DamageOnset& o : onsets)
    if (!at_clamp_tip(o, clamp_tip_elements) && (!first || o.time < first->time)) first = o;
  return first;
}

namespace {

/// "hashin matrix-tension in ply 3 at (x, y) mm, t = … us, Fc = … N".
std::string onset_words(const DamageOnset& o) {
  return fmt::format("{} {} in {} {}, element {} at ({:.1f}, {:.1f}) mm, t = {:.2f} us, Fc = {:.1f} N",
                     to_string(o.criterion), to_string(o.mode), o.ply > 0 ? "ply" : "interface",
                     o.ply > 0 ? o.ply : o.interface, o.element, o.x * 1e3, o.y * 1e3, o.time * 1e6, o.force);
}

} // namespace

std::string first_failures_text(const std::vector<DamageOnset>& first,
                                const std::vector<int>& clamp_tip_elements,
                                const std::optional<DamageOnset>& laminate_first) {
  if (first.empty()) return "  no failure\n";
  const bool rig = !clamp_tip_elements.empty();
  std::string t = fmt::format("  {:<24}{:<20}{:>5}{:>6}{:>6}{:>5}{:>5}{:>10}{:>10}{:>12}{:>12}{}\n",
                              "criterion", "mode", "ply", "intf", "elem", "IPGS", "JPGS", "t[us]", "Fc[N]",
                              "s22[MPa]", "t23[MPa]", rig ? "  where" : "");
  int at_tips = 0;
  for (const auto& o : first) {
    const bool tip = rig && at_clamp_tip(o, clamp_tip_elements);
    at_tips += tip ? 1 : 0;
    t += fmt::format("  {:<24}{:<20}{:>5}{:>6}{:>6}{:>5}{:>5}{:>10.2f}{:>10.1f}{:>12.3f}{:>12.3f}{}\n",
                     to_string(o.criterion), to_string(o.mode), o.ply > 0 ? std::to_string(o.ply) : "-",
                     o.interface > 0 ? std::to_string(o.interface) : "-", o.element, o.ipgs, o.jpgs,
                     o.time * 1e6, o.force, o.sigma22 / 1e6, o.tau23 / 1e6, tip ? "  clamp tip" : "");
  }
  if (!rig) return t;
  t += fmt::format("  {} of {} rows at clamp tips (point supports: their stresses are singular, not the "
                   "laminate's failure)\n",
                   at_tips, first.size());
  t += "  laminate's first failure away from the clamp tips: " +
       (laminate_first ? onset_words(*laminate_first) : std::string("none")) + "\n";
  return t;
}

std::string threshold_text(const std::string& criterion, const ThresholdResult& r) {
  std::string t = fmt::format("threshold ({}): ", criterion);
  if (!r.found) // a result, not an error (issue 77: it exited 4, the internal-error code)
    return t +
           fmt::format("no failure up to the velocity limit: the plate holds at every velocity tried, the "
                       "highest {:.4g} m/s ({} runs); raise [threshold] max_velocity to search higher\n",
                       r.trials.empty() ? 0.0 : r.trials.back().velocity, r.trials.size());
  t += fmt::format("{:.4f} m/s (no failure at {:.4f} m/s), {} runs\n", r.velocity, r.lower, r.trials.size());
  if (r.first_failure) t += first_failures_text({*r.first_failure});
  if (r.damage)
    t += fmt::format("  {} damage in ply {}, element {}, at {:.2f} us, Fc = {:.1f} N; projected damage area "
                     "{:.3f} mm^2\n",
                     to_string(r.damage->mode), r.damage->ply, r.damage->element, r.damage->time * 1e6,
                     r.damage->force, r.damage->projected_area * 1e6);
  return t;
}

} // namespace plyimpact
