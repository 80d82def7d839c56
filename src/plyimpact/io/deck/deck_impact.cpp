#include "plyimpact/io/deck/deck_tables.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace plyimpact::deck_tables {

bool gives_impact_speed(const TableReader& impactor) {
  return impactor.has("velocity") || impactor.has("energy");
}

namespace {

/// impactor.velocity, or the velocity √(2E/m) of the impact energy impactor.energy: exactly one.
double read_impact_velocity(const TableReader& t, double mass, ImpactorInput& input,
                            const std::optional<double>& default_energy) {
  const bool velocity = t.has("velocity");
  const bool energy = t.has("energy");
  if (!gives_impact_speed(t) && default_energy) { // the rig's rule
    input.energy = default_energy;
    return std::sqrt(2.0 * *default_energy / mass);
  }
  if (velocity && energy)
    t.fail_at("energy", fmt::format("give impactor.velocity ({}) or impactor.energy ({}), not both",
                                    t.deck_unit("m/s"), t.deck_unit("J")));
  if (!velocity && !energy)
    t.fail_here(fmt::format("[impactor] needs velocity ({}, towards the plate) or energy ({}, the impact "
                            "energy: velocity = sqrt(2 energy / mass))",
                            t.deck_unit("m/s"), t.deck_unit("J")));
  if (velocity) return t.positive("velocity", "m/s");
  input.energy = t.positive("energy", "J");
  return std::sqrt(2.0 * *input.energy / mass);
}

} // namespace

Impactor read_impactor(const TableReader& t, const std::optional<PlateGeometry>& plate, const Mesh* file_mesh,
                       ImpactorInput& input, const ImpactorDefaults& defaults) {
  t.only_keys_of("impactor");
  Impactor imp;
  imp.nose = t.optional_choice<NoseShape>("nose", {{"hemisphere", NoseShape::hemisphere},
                                                   {"flat", NoseShape::flat},
                                                   {"cone", NoseShape::cone}})
                 .value_or(NoseShape::hemisphere);
  if (imp.nose == NoseShape::cone) {
    const double degrees = t.positive("half_angle", "-");
    if (!(degrees < 90.0))
      t.fail_at("half_angle", fmt::format("impactor.half_angle is the angle between the cone's axis and its "
                                          "flank, in degrees, below 90; got {}",
                                          degrees));
    imp.half_angle = degrees * std::numbers::pi / 180.0;
    if (t.has("radius"))
      t.fail_at("radius", "a cone has no radius: its contact radius grows with the indentation (leave out "
                          "impactor.radius)");
    if (t.has("density"))
      t.fail_at("density", "impactor.density gives the mass of a sphere: give the cone's impactor.mass");
  } else if (t.has("half_angle")) {
    t.fail_at("half_angle", "impactor.half_angle belongs to nose = \"cone\"");
  }
  if (imp.nose != NoseShape::cone)
    imp.radius = defaults.radius ? t.optional_positive("radius", "m").value_or(*defaults.radius)
                                 : t.positive("radius", "m");
  const auto mass = t.optional_positive("mass", "kg");
  const auto density = t.optional_positive("density", "kg/m^3");
  if (mass && density) t.fail_at("density", "give impactor.mass or impactor.density, not both");
  if (!mass && !density)
    t.fail_here(
        fmt::format("[impactor] needs mass ({}) or density ({}, mass of the sphere of the given radius)",
                    t.deck_unit("kg"), t.deck_unit("kg/m^3")));
  input.density = density;
  imp.mass = mass ? *mass : *density * 4.0 / 3.0 * std::numbers::pi * imp.radius * imp.radius * imp.radius;
  imp.E = t.positive("E", "Pa");
  imp.nu = t.optional_number("nu", "-").value_or(0.3);
  if (!(imp.nu > -1.0 && imp.nu < 0.5))
    t.fail_at("nu", fmt::format("impactor.nu must lie in (-1, 0.5), got {}", imp.nu));
  imp.velocity = read_impact_velocity(t, imp.mass, input, defaults.energy);
  const auto x = t.optional_number("x", "m");
  const auto y = t.optional_number("y", "m");
  if (plate) {
    imp.x = x.value_or(plate->a / 2.0);
    imp.y = y.value_or(plate->b / 2.0);
    if (!(imp.x > 0.0 && imp.x < plate->a))
      t.fail_at(x ? "x" : "radius",
                fmt::format("impact point x = {} m lies outside the plate: expected 0 < x < a = {} m", imp.x,
                            plate->a));
    if (!(imp.y > 0.0 && imp.y < plate->b))
      t.fail_at(y ? "y" : "radius",
                fmt::format("impact point y = {} m lies outside the plate: expected 0 < y < b = {} m", imp.y,
                            plate->b));
  }
  if (file_mesh != nullptr) {
    const Eigen::Vector2d centre = file_mesh->bounds().centre();
    imp.x = x.value_or(centre.x());
    imp.y = y.value_or(centre.y());
    if (!file_mesh->locate(imp.x, imp.y))
      t.fail_at(
          x ? "x" : "radius",
          x || y ? fmt::format("impact point ({}, {}) m lies outside the mesh", imp.x, imp.y)
                 : fmt::format("the impact point defaults to the centre of the mesh's bounding box, ({}, {}) "
                               "m, which is not on the plate: give impactor.x and impactor.y",
                               imp.x, imp.y));
  }
  return imp;
}

ContactLawParameters read_contact(const TableReader& t, NoseShape nose) {
  t.only_keys_of("contact");
  ContactLawParameters c;
  c.k = t.positive_or_auto("k", contact_constant_unit(nose));
  const auto unloading = t.optional_choice<UnloadingLaw>(
      "unloading", {{"tan-sun", UnloadingLaw::tan_sun}, {"elastic", UnloadingLaw::elastic}});
  if (nose != NoseShape::hemisphere && unloading == UnloadingLaw::tan_sun)
    t.fail_at("unloading", fmt::format("contact.unloading = \"tan-sun\" was measured with hemispherical "
                                       "impactors; a {} nose unloads elastically here (docs/impactor.md)",
                                       to_string(nose)));
  c.unloading =
      unloading.value_or(nose == NoseShape::hemisphere ? UnloadingLaw::tan_sun : UnloadingLaw::elastic);
  c.q = t.optional_positive("q", "-").value_or(2.5);
  c.beta = t.optional_number("beta", "-").value_or(0.094);
  if (!(c.beta >= 0.0 && c.beta < 1.0))
    t.fail_at("beta", fmt::format("contact.beta must lie in [0, 1), got {}", c.beta));
  c.alpha_cr = t.optional_number("alpha_cr", "m").value_or(1.7e-4);
  if (!(c.alpha_cr >= 0.0)) t.fail_at("alpha_cr", "contact.alpha_cr must be zero or positive (m)");
  c.load = t.optional_choice<ContactLoad>(
                "load", {{"point", ContactLoad::point}, {"hertz-pressure", ContactLoad::hertz_pressure}})
               .value_or(ContactLoad::hertz_pressure);
  return c;
}

namespace {

/// `adaptive`, `tolerance`, `levels` of [time] (error-controlled steps,
/// analysis/integrators/time_step_control.hpp).
std::optional<AdaptiveTimeStep> read_adaptive_time_step(const TableReader& t) {
  bool adaptive = false;
  if (const toml::node* n = t.node("adaptive")) {
    const auto* b = n->as_boolean();
    if (b == nullptr)
      t.fail_at("adaptive", fmt::format("time.adaptive must be true or false, got {}", type_name(*n)));
    adaptive = b->get();
  }
  if (!adaptive) {
    for (const char* key : {"tolerance", "levels"})
      if (t.has(key))
        t.fail_at(key,
                  fmt::format("time.{} sets the error-controlled steps: add adaptive = true to [time], or "
                              "remove {}",
                              key, key));
    return std::nullopt;
  }
  AdaptiveTimeStep a;
  if (const auto tol = t.optional_positive("tolerance", "-")) {
    if (!(*tol < 1.0))
      t.fail_at("tolerance",
                fmt::format("time.tolerance is the local error of the indentation relative to the "
                            "rigid-target indentation; it must lie in (0, 1), got {}",
                            *tol));
    a.tolerance = *tol;
  }
  if (const auto levels = t.optional_integer("levels")) {
    if (*levels < 1 || *levels > 24)
      t.fail_at("levels", fmt::format("time.levels must lie between 1 and 24 (the smallest step is "
                                      "dt/2^(levels - 1)), got {}",
                                      *levels));
    a.levels = static_cast<int>(*levels);
  }
  return a;
}

/// `mass_scaling` and `target_dt` of [time] (explicit steps, analysis/impact/mass_scaling.hpp).
MassScaling read_mass_scaling(const TableReader& t) {
  MassScaling m;
  m.kind = t.optional_choice<MassScalingKind>("mass_scaling", {{"none", MassScalingKind::none},
                                                               {"rotary", MassScalingKind::rotary},
                                                               {"nodal", MassScalingKind::nodal},
                                                               {"selective", MassScalingKind::selective}})
               .value_or(MassScalingKind::none);
  m.target_dt = t.optional_positive("target_dt", "s");
  if (m.target_dt && m.kind == MassScalingKind::none)
    t.fail_at("target_dt", "time.target_dt is the stable step that mass scaling aims at: add mass_scaling = "
                           "\"rotary\", \"selective\" or \"nodal\", or remove target_dt");
  if (m.kind == MassScalingKind::nodal && !m.target_dt)
    t.fail_at("mass_scaling", "time.mass_scaling = \"nodal\" adds mass up to a stable step that the deck "
                              "gives: add target_dt (s), e.g. target_dt = 2e-8");
  return m;
}

/// `[time] end`: a time, "auto" (SPEC §4's re-hit rule) or "separation" (separation_end.hpp).
void read_end(const TableReader& t, TimeStepping& ts) {
  const toml::node* n = t.table().get("end");
  if (const auto* s = n ? n->as_string() : nullptr) {
    const std::string v = s->get();
    if (v == "separation") {
      ts.end_rule = EventEnd::separation;
      return;
    }
    if (v != "auto") {
      const auto best = closest_name(v, std::vector<std::string_view>{"auto", "separation"});
      t.fail_at("end", fmt::format("time.end must be a positive number in {}, \"auto\" or \"separation\", "
                                   "got \"{}\"{}",
                                   t.deck_unit("s"), v,
                                   best ? fmt::format(" (did you mean \"{}\"?)", *best) : std::string()));
    }
    return;
  }
  ts.end = t.positive_or_auto("end", "s");
}

} // namespace

TimeStepping read_time(const TableReader& t) {
  t.only_keys_of("time");
  TimeStepping ts;
  ts.integration =
      t.optional_choice<TimeScheme>(
           "integration", {{"implicit", TimeScheme::newmark}, {"explicit", TimeScheme::central_difference}})
          .value_or(ts.integration);
  ts.dt = t.positive_or_auto("dt", "s");
  read_end(t, ts);
  ts.newmark_beta = t.optional_positive("newmark_beta", "-").value_or(0.25);
  ts.newmark_gamma = t.optional_number("newmark_gamma", "-").value_or(0.5);
  if (!(ts.newmark_gamma >= 0.5))
    t.fail_at("newmark_gamma", fmt::format("time.newmark_gamma must be at least 0.5 (no numerical energy "
                                           "growth), got {}",
                                           ts.newmark_gamma));
  if (!(ts.newmark_beta <= 0.5)) t.fail_at("newmark_beta", "time.newmark_beta must lie in (0, 0.5]");
  if (const auto m = t.optional_integer("max_steps")) {
    if (*m < 1 || *m > max_step_cap)
      t.fail_at("max_steps",
                fmt::format("time.max_steps must lie between 1 and {}, got {}", max_step_cap, *m));
    ts.max_steps = *m;
  }
  ts.adaptive = read_adaptive_time_step(t);
  ts.mass_scaling = read_mass_scaling(t);
  if (const auto stop = t.optional_positive("stop_at_energy_error", "-")) {
    if (!(*stop <= 1.0))
      t.fail_at(
          "stop_at_energy_error",
          fmt::format("time.stop_at_energy_error is a fraction of the impact energy from 0 to 1 (0.05 stops "
                      "the run at an error of 5 %), got {}",
                      *stop));
    ts.stop_at_energy_error = stop;
  }
  if (ts.dt && ts.end && *ts.end / *ts.dt > static_cast<double>(max_step_cap))
    t.fail_at("end", fmt::format("time.end / time.dt = {:.3g} steps: more than the limit of {} steps",
                                 *ts.end / *ts.dt, max_step_cap));
  return ts;
}

/// Top-level `nonlinear` (bool), `strain_measure` and `load_steps` (SPEC §8, docs/deck.md).
void read_nonlinear_keys(const TableReader& top, Deck& d) {
  if (const toml::node* n = top.table().get("nonlinear")) {
    const auto* b = n->as_boolean();
    if (b == nullptr)
      top.fail_at("nonlinear", fmt::format("nonlinear must be true or false, got {}", type_name(*n)));
    d.nonlinear = b->get();
  }
  if (const auto m = top.optional_string("strain_measure")) {
    if (*m == "von-karman")
      d.nonlinear_settings.measure = StrainMeasure::von_karman;
    else if (*m == "green-lagrange")
      d.nonlinear_settings.measure = StrainMeasure::green_lagrange;
    else
      top.fail_at("strain_measure",
                  fmt::format("strain_measure must be \"von-karman\" or \"green-lagrange\", got \"{}\"", *m));
  }
  if (const auto steps = top.optional_integer("load_steps")) {
    if (*steps < 1 || *steps > 100000)
      top.fail_at("load_steps", fmt::format("load_steps must be between 1 and 100000, got {}", *steps));
    d.nonlinear_settings.load_steps = static_cast<int>(*steps);
  }
}

} // namespace plyimpact::deck_tables
