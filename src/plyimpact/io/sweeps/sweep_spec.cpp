#include "plyimpact/io/sweeps/sweep_spec.hpp"

#include "plyimpact/io/deck/table_reader.hpp"

#include "plyimpact/io/deck/deck_table.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <numbers>
#include <random>
#include <sstream>

namespace plyimpact {

std::string to_text(const SweepValue& value) {
  return std::visit(
      [](const auto& v) -> std::string {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, std::string>)
          return v;
        else if constexpr (std::is_same_v<T, bool>)
          return v ? "true" : "false";
        else
          return fmt::format("{}", v); // shortest round-trip text for doubles
      },
      value);
}

std::vector<double> random_draws(const std::vector<RandomParameter>& parameters, long samples,
                                 std::uint64_t seed) {
  std::mt19937_64 engine(seed); // its output sequence is fixed by the C++ standard
  const auto unit = [&engine] { return static_cast<double>(engine() >> 11U) * 0x1p-53; };
  std::vector<double> draws;
  draws.reserve(static_cast<std::size_t>(samples) * parameters.size());
  for (long s = 0; s < samples; ++s)
    for (const RandomParameter& p : parameters) {
      if (p.distribution == Distribution::uniform) {
        draws.push_back(p.a + (p.b - p.a) * unit());
      } else { // Box–Muller, cosine branch only
        const double u1 = 1.0 - unit(), u2 = unit();
        draws.push_back(p.a + p.b * std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2));
      }
    }
  return draws;
}

namespace {

[[noreturn]] void fail(const std::string& origin, const std::string& message) {
  throw DeckError(fmt::format("{}: error: {}", origin, message));
}

std::string located(const std::string& source, const toml::source_region& where) {
  if (where.begin.line == 0) return source;
  return fmt::format("{}:{}:{}", source, where.begin.line, where.begin.column);
}

template <class T>
std::optional<T> parse_number(std::string_view s) {
  T v{};
  const char* end = s.data() + s.size();
  const auto [ptr, ec] = std::from_chars(s.data(), end, v);
  if (ec != std::errc() || ptr != end) return std::nullopt;
  return v;
}

bool written_as_integer(std::string_view s) {
  return !s.empty() && s.find_first_of(".eEnN") == std::string_view::npos &&
         parse_number<long>(s).has_value();
}

std::vector<std::string_view> split(std::string_view s, char sep) {
  std::vector<std::string_view> parts;
  std::size_t start = 0;
  for (;;) {
    const std::size_t p = s.find(sep, start);
    parts.push_back(s.substr(start, p == std::string_view::npos ? std::string_view::npos : p - start));
    if (p == std::string_view::npos) return parts;
    start = p + 1;
  }
}

/// A --set value: integer, float, true/false, otherwise a string (layups, edge codes, names).
SweepValue value_from_text(std::string_view s) {
  if (const auto i = parse_number<long>(s)) return *i;
  if (const auto d = parse_number<double>(s); d && std::isfinite(*d)) return *d;
  if (s == "true") return true;
  if (s == "false") return false;
  return std::string(s);
}

std::optional<SweepValue> value_from_node(const toml::node& n) {
  if (const auto* i = n.as_integer()) return static_cast<long>(i->get());
  if (const auto* f = n.as_floating_point()) {
    if (!std::isfinite(f->get())) return std::nullopt;
    return f->get();
  }
  if (const auto* b = n.as_boolean()) return b->get();
  if (const auto* s = n.as_string()) return s->get();
  return std::nullopt;
}

std::vector<std::string> key_path(const std::string& key, const std::string& origin) {
  std::vector<std::string> parts;
  for (const auto p : split(key, '.')) {
    if (p.empty())
      fail(origin, fmt::format("malformed key '{}': expected a dotted deck key such as "
                               "impactor.velocity",
                               key));
    parts.emplace_back(p);
  }
  if (parts.size() < 2)
    fail(origin,
         fmt::format("'{}' is not a deck value: expected SECTION.KEY such as impactor.velocity", key));
  return parts;
}

void set_value(toml::table& root, const std::string& key, const SweepValue& value,
               const std::string& origin) {
  const std::vector<std::string> path = key_path(key, origin);
  toml::table* t = &root;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    toml::node* n = t->get(path[i]);
    if (n == nullptr) {
      if (i > 0) // a top-level section may be absent from the base deck; a named table may not
        fail(origin, fmt::format("sweep key '{}': the base deck has no table [{}]", key,
                                 fmt::join(path.begin(), path.begin() + static_cast<long>(i) + 1, ".")));
      t->insert_or_assign(path[i], toml::table{});
      n = t->get(path[i]);
    }
    t = n->as_table();
    if (t == nullptr)
      fail(origin, fmt::format("sweep key '{}': {} is not a table", key,
                               fmt::join(path.begin(), path.begin() + static_cast<long>(i) + 1, ".")));
  }
  std::visit([&](const auto& v) { t->insert_or_assign(path.back(), v); }, value);
}

/// Flattens a table of swept keys written either quoted ("impactor.velocity" = …) or as dotted keys
/// (impactor.velocity = …) into (dotted key, node) pairs in the order written. `is_leaf` says when a
/// table is a value (a distribution) rather than a level of keys.
struct KeyedNode {
  std::string key;
  const toml::node* node = nullptr;
  toml::source_region where; ///< of the key as written
};

template <class IsLeaf>
void flatten(const toml::table& t, const std::string& prefix, const IsLeaf& is_leaf,
             std::vector<KeyedNode>& out) {
  for (auto&& [k, node] : t) {
    const std::string key = prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    if (const auto* sub = node.as_table(); sub != nullptr && !is_leaf(*sub))
      flatten(*sub, key, is_leaf, out);
    else
      out.push_back({key, &node, k.source().begin.line > 0 ? k.source() : node.source()});
  }
}

void sort_by_position(std::vector<KeyedNode>& items) {
  std::stable_sort(items.begin(), items.end(), [](const KeyedNode& x, const KeyedNode& y) {
    const auto& a = x.where.begin;
    const auto& b = y.where.begin;
    return a.line != b.line ? a.line < b.line : a.column < b.column;
  });
}

std::uint64_t fnv1a(std::string_view s, std::uint64_t h = 14695981039346656037ULL) {
  for (const char c : s) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ULL;
  }
  return h;
}

std::string serialize(const toml::table& t) {
  std::ostringstream os;
  os << toml::toml_formatter(t, toml::format_flags::none);
  return os.str();
}

/// The double with the fewest significant decimal digits within `tolerance` of x (x itself if none
/// shorter is).
double shortest_decimal_near(double x, double tolerance) {
  for (int digits = 1; digits < 17; ++digits) {
    const double y = std::strtod(fmt::format("{:.{}g}", x, digits).c_str(), nullptr);
    if (std::abs(y - x) <= tolerance) return y;
  }
  return x;
}

} // namespace

std::vector<SweepValue> parse_range(std::string_view text, const std::string& origin) {
  const auto parts = split(text, ':');
  const auto malformed = [&](const std::string& why) {
    fail(origin,
         fmt::format("malformed range \"{}\": {} (expected start:stop:count, e.g. 0.5:3.0:11)", text, why));
  };
  if (parts.size() != 3) malformed("it needs exactly three fields");
  const auto start = parse_number<double>(parts[0]);
  const auto stop = parse_number<double>(parts[1]);
  const auto count = parse_number<long>(parts[2]);
  if (!start || !std::isfinite(*start)) malformed(fmt::format("start '{}' is not a number", parts[0]));
  if (!stop || !std::isfinite(*stop)) malformed(fmt::format("stop '{}' is not a number", parts[1]));
  if (!count || *count < 2 || *count > 1'000'000)
    malformed(fmt::format("count '{}' must be an integer from 2 to 1000000", parts[2]));
  const long n = *count;
  std::vector<SweepValue> values;
  if (written_as_integer(parts[0]) && written_as_integer(parts[1])) {
    const long a = *parse_number<long>(parts[0]), b = *parse_number<long>(parts[1]);
    if ((b - a) % (n - 1) == 0) {
      for (long i = 0; i < n; ++i)
        values.emplace_back(a + i * ((b - a) / (n - 1)));
      return values;
    }
  }
  // x_i = start + i (stop − start)/(count − 1), end points exact, each rounded to the shortest decimal
  // within a few ulps: 0.1:0.5:5 gives 0.3, not 0.30000000000000004.
  const double ulps =
      8.0 * std::numeric_limits<double>::epsilon() * std::max(std::abs(*start), std::abs(*stop));
  for (long i = 0; i < n; ++i)
    values.emplace_back(i == n - 1
                            ? *stop
                            : shortest_decimal_near(*start + static_cast<double>(i) * (*stop - *start) /
                                                                 static_cast<double>(n - 1),
                                                    ulps));
  return values;
}

struct Sweep::Impl {
  std::string source;
  toml::table base; ///< the base deck without its [sweep] table
  std::string base_text;
  SweepSpec spec;
  std::vector<std::size_t> axis_sizes;
  std::size_t grid = 1; ///< grid points (product or zip of the axes)
  std::vector<double> draws;
  std::string fingerprint;

  /// The base table with the values of case `c` set.
  [[nodiscard]] toml::table table_for(const SweepCase& c) const {
    toml::table t = base;
    for (std::size_t i = 0; i < spec.axes.size(); ++i)
      set_value(t, spec.axes[i].key, c.values[i], spec.axes[i].origin);
    for (std::size_t r = 0; r < spec.random.size(); ++r)
      set_value(t, spec.random[r].key, c.values[spec.axes.size() + r], spec.random[r].origin);
    return t;
  }
};

namespace {

void read_sweep_table(const toml::table& sweep, const std::string& source, SweepSpec& spec) {
  const auto at = [&](const toml::node& n) { return located(source, n.source()); };
  const TableReader table(sweep, "sweep", source);
  table.only_keys_of("sweep");
  if (const auto mode = table.optional_choice<SweepMode>(
          "mode", {{"product", SweepMode::product}, {"zip", SweepMode::zip}}))
    spec.mode = *mode;
  if (const auto kind = table.optional_choice<AnalysisKind>(
          "analysis", {{"impact", AnalysisKind::impact}, {"threshold", AnalysisKind::threshold}}))
    spec.analysis = *kind;
  if (const auto response = table.optional_choice<bool>("plate_response", {{"auto", true}, {"full", false}}))
    spec.contact_point_response = *response;
  if (const toml::node* v = sweep.get("values")) {
    const toml::table* t = v->as_table();
    if (t == nullptr)
      fail(at(*v), "sweep.values must be a table: KEY = [V1, V2, …] or KEY = \"start:stop:count\"");
    std::vector<KeyedNode> items;
    flatten(
        *t, "", [](const toml::table&) { return false; }, items);
    sort_by_position(items);
    for (const auto& [key, node, where] : items) {
      SweepAxis axis{key, {}, located(source, where)};
      if (const auto* s = node->as_string()) {
        axis.values = parse_range(s->get(), axis.origin);
      } else if (const auto* arr = node->as_array()) {
        if (arr->empty()) fail(axis.origin, fmt::format("sweep.values.{}: empty list of values", key));
        for (const toml::node& item : *arr) {
          const auto value = value_from_node(item);
          if (!value)
            fail(located(source, item.source()),
                 fmt::format("sweep.values.{}: a value must be a number, a boolean or a string", key));
          axis.values.push_back(*value);
        }
      } else {
        fail(
            axis.origin,
            fmt::format("sweep.values.{}: expected a list [V1, V2, …] or a range \"start:stop:count\"", key));
      }
      spec.axes.push_back(std::move(axis));
    }
  }
  if (const toml::node* r = sweep.get("random")) {
    const toml::table* t = r->as_table();
    if (t == nullptr)
      fail(at(*r), "sweep.random must be a table: samples, seed and KEY = { normal = [mean, sd] }");
    const auto is_distribution = [](const toml::table& d) {
      return d.size() == 1 && (d.contains("normal") || d.contains("uniform"));
    };
    std::vector<KeyedNode> items;
    flatten(*t, "", is_distribution, items);
    sort_by_position(items);
    bool have_samples = false;
    for (const auto& [key, node, where] : items) {
      const std::string origin = located(source, where);
      if (key == "samples" || key == "seed") {
        const auto* i = node->as_integer();
        if (i == nullptr || i->get() < (key == "samples" ? 1 : 0) ||
            (key == "samples" && i->get() > 10'000'000))
          fail(origin,
               fmt::format("sweep.random.{} must be {}", key,
                           key == "samples" ? "an integer from 1 to 10000000" : "a non-negative integer"));
        if (key == "samples") {
          spec.samples = static_cast<long>(i->get());
          have_samples = true;
        } else {
          spec.seed = static_cast<std::uint64_t>(i->get());
        }
        continue;
      }
      const toml::table* d = node->as_table();
      if (d == nullptr || !is_distribution(*d))
        fail(origin,
             fmt::format("sweep.random.{}: expected {{ normal = [mean, sd] }} or {{ uniform = [lo, hi] }}",
                         key));
      RandomParameter p{key, d->contains("normal") ? Distribution::normal : Distribution::uniform, 0.0, 0.0,
                        origin};
      const toml::array* ab =
          d->get(p.distribution == Distribution::normal ? "normal" : "uniform")->as_array();
      const auto number = [&](std::size_t i) -> std::optional<double> {
        if (ab == nullptr || ab->size() != 2) return std::nullopt;
        const auto v = (*ab)[i].value<double>();
        return v && std::isfinite(*v) ? v : std::nullopt;
      };
      if (!number(0) || !number(1))
        fail(origin, fmt::format("sweep.random.{}: the distribution needs two finite numbers", key));
      p.a = *number(0);
      p.b = *number(1);
      if (p.distribution == Distribution::normal && !(p.b >= 0.0))
        fail(origin, fmt::format("sweep.random.{}: the standard deviation must not be negative", key));
      if (p.distribution == Distribution::uniform && !(p.b >= p.a))
        fail(origin, fmt::format("sweep.random.{}: uniform = [lo, hi] needs lo <= hi", key));
      spec.random.push_back(std::move(p));
    }
    if (spec.random.empty())
      fail(at(*r), "[sweep.random] has no key to sample: add KEY = { normal = [mean, sd] }");
    if (!have_samples) fail(at(*r), "[sweep.random] needs samples = N (the number of Monte Carlo samples)");
  }
}

SweepAxis axis_from_option(const std::string& option) {
  const std::string origin = fmt::format("--set '{}'", option);
  const std::size_t eq = option.find('=');
  if (eq == std::string::npos || eq == 0)
    fail(origin, "expected KEY=V1,V2,… or KEY=start:stop:count, e.g. impactor.velocity=1,2,3");
  SweepAxis axis{option.substr(0, eq), {}, origin};
  const std::string_view list = std::string_view(option).substr(eq + 1);
  if (list.empty()) fail(origin, fmt::format("empty list of values for {}", axis.key));
  if (list.find(':') != std::string_view::npos && list.find(',') == std::string_view::npos &&
      std::count(list.begin(), list.end(), ':') == 2 && list.find('[') == std::string_view::npos) {
    axis.values = parse_range(list, origin);
    return axis;
  }
  for (const auto item : split(list, ',')) {
    if (item.empty()) fail(origin, fmt::format("empty value in the list for {}", axis.key));
    axis.values.push_back(value_from_text(item));
  }
  return axis;
}

/// A key is unknown when the deck parser, given the key's first value, rejects one of its names.
void check_key(const Sweep::Impl& impl, const std::string& key, const SweepValue& first,
               const std::string& origin) {
  toml::table t = impl.base;
  set_value(t, key, first, origin);
  try {
    (void)parse_deck_table(t, "", impl.source);
  } catch (const DeckError& e) {
    const std::string what = e.what();
    for (const auto& name : key_path(key, origin))
      if (what.find(fmt::format("unknown key '{}'", name)) != std::string::npos) {
        const std::size_t p = what.find("error: ");
        fail(origin,
             fmt::format("sweep key '{}': {}", key, p == std::string::npos ? what : what.substr(p + 7)));
      }
    // any other complaint is about this combination of values: the case records it when it runs
  }
}

} // namespace

Sweep::Sweep(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}

Sweep Sweep::from_text(std::string_view text, const std::string& source,
                       const std::vector<std::string>& set_options, std::optional<SweepMode> mode,
                       std::optional<AnalysisKind> analysis) {
  auto impl = std::make_shared<Impl>();
  impl->source = source;
  impl->base_text = std::string(text);
  const Deck base = parse_deck(text, source); // the base deck must be valid by itself
  toml::table root = toml::parse(text, source);
  SweepSpec& spec = impl->spec;
  spec.analysis = base.analysis;
  if (const toml::node* s = root.get("sweep")) {
    if (s->as_table() == nullptr) fail(located(source, s->source()), "sweep must be a table: [sweep]");
    read_sweep_table(*s->as_table(), source, spec);
  }
  root.erase("sweep");
  impl->base = std::move(root);
  for (const std::string& option : set_options) {
    SweepAxis axis = axis_from_option(option);
    const auto same =
        std::find_if(spec.axes.begin(), spec.axes.end(), [&](const auto& a) { return a.key == axis.key; });
    if (same != spec.axes.end())
      *same = std::move(axis);
    else
      spec.axes.push_back(std::move(axis));
  }
  if (mode) spec.mode = *mode;
  if (analysis) spec.analysis = *analysis;
  if (spec.analysis != AnalysisKind::impact && spec.analysis != AnalysisKind::threshold)
    throw DeckError(fmt::format("{}: error: a sweep runs the impact or the threshold analysis, not {}: set "
                                "[sweep] analysis or --analysis",
                                source, to_string(spec.analysis)));
  if (spec.axes.empty() && spec.random.empty())
    throw DeckError(fmt::format("{}: error: nothing to sweep: add [sweep.values], [sweep.random] or "
                                "--set KEY=V1,V2,…",
                                source));
  for (std::size_t i = 0; i < spec.axes.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (spec.axes[i].key == spec.axes[j].key)
        fail(spec.axes[i].origin, fmt::format("{} is swept twice", spec.axes[i].key));
  for (const auto& r : spec.random)
    for (const auto& a : spec.axes)
      if (r.key == a.key) fail(r.origin, fmt::format("{} is both listed and sampled", r.key));
  if (spec.mode == SweepMode::zip)
    for (const auto& a : spec.axes)
      if (a.values.size() != spec.axes.front().values.size())
        fail(a.origin,
             fmt::format("zip sweep: {} has {} values but {} has {}; zipped lists must have equal "
                         "lengths",
                         a.key, a.values.size(), spec.axes.front().key, spec.axes.front().values.size()));
  for (const auto& a : spec.axes) {
    check_key(*impl, a.key, a.values.front(), a.origin);
    impl->axis_sizes.push_back(a.values.size());
  }
  for (const auto& r : spec.random)
    check_key(*impl, r.key, r.a, r.origin);
  if (!spec.axes.empty()) {
    if (spec.mode == SweepMode::zip) {
      impl->grid = spec.axes.front().values.size();
    } else {
      for (const std::size_t n : impl->axis_sizes) {
        if (impl->grid > 100'000'000 / n) fail(spec.axes.front().origin, "the sweep has more than 1e8 cases");
        impl->grid *= n;
      }
    }
  }
  impl->draws = random_draws(spec.random, spec.samples, spec.seed);

  // Fingerprint: the base deck's content (not comments or layout) and every swept value.
  std::string id = serialize(impl->base);
  id += fmt::format("\nmode={}\nanalysis={}\n", spec.mode == SweepMode::zip ? "zip" : "product",
                    to_string(spec.analysis));
  for (const auto& a : spec.axes) {
    id += a.key + "=";
    for (const auto& v : a.values)
      id += fmt::format("{}:{};", v.index(), to_text(v));
    id += "\n";
  }
  for (const auto& r : spec.random)
    id += fmt::format("{}~{}({},{})\n", r.key, r.distribution == Distribution::normal ? "normal" : "uniform",
                      r.a, r.b);
  id += fmt::format("samples={} seed={}\n", spec.samples, spec.seed);
  impl->fingerprint = fmt::format("{:016x}", fnv1a(id));
  return Sweep(std::move(impl));
}

Sweep Sweep::load(const std::filesystem::path& deck, const std::vector<std::string>& set_options,
                  std::optional<SweepMode> mode, std::optional<AnalysisKind> analysis) {
  std::ifstream in(deck, std::ios::binary);
  if (!in) throw DeckError(fmt::format("{}: error: cannot open the deck file", deck.string()));
  std::ostringstream ss;
  ss << in.rdbuf();
  return from_text(ss.str(), deck.string(), set_options, mode, analysis);
}

const SweepSpec& Sweep::spec() const {
  return impl_->spec;
}

const std::string& Sweep::source() const {
  return impl_->source;
}

std::string Sweep::title() const {
  return impl_->base["title"].value<std::string>().value_or("");
}

const std::string& Sweep::fingerprint() const {
  return impl_->fingerprint;
}

std::vector<std::string> Sweep::keys() const {
  std::vector<std::string> k;
  for (const auto& a : impl_->spec.axes)
    k.push_back(a.key);
  for (const auto& r : impl_->spec.random)
    k.push_back(r.key);
  return k;
}

std::size_t Sweep::size() const {
  const long samples = impl_->spec.samples;
  return impl_->grid * static_cast<std::size_t>(samples > 0 ? samples : 1);
}

SweepCase Sweep::case_at(std::size_t index) const {
  const SweepSpec& spec = impl_->spec;
  const std::size_t per_point = static_cast<std::size_t>(spec.samples > 0 ? spec.samples : 1);
  const std::size_t point = index / per_point, sample = index % per_point;
  SweepCase c;
  c.index = index;
  c.values.resize(spec.axes.size());
  if (spec.mode == SweepMode::zip) {
    for (std::size_t i = 0; i < spec.axes.size(); ++i)
      c.values[i] = spec.axes[i].values[point];
  } else {
    std::size_t rest = point; // mixed-radix digits, the last axis fastest
    for (std::size_t i = spec.axes.size(); i-- > 0;) {
      c.values[i] = spec.axes[i].values[rest % impl_->axis_sizes[i]];
      rest /= impl_->axis_sizes[i];
    }
  }
  for (std::size_t r = 0; r < spec.random.size(); ++r)
    c.values.emplace_back(impl_->draws[sample * spec.random.size() + r]);
  return c;
}

Deck Sweep::deck_for(const SweepCase& c) const {
  const toml::table t = impl_->table_for(c);
  return parse_deck_table(t, serialize(t), impl_->source);
}

} // namespace plyimpact
