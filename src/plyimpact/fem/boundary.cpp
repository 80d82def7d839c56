#include "plyimpact/fem/boundary.hpp"

namespace plyimpact {

std::string Restraint::code() const {
  std::string s;
  for (const bool f : fixed)
    s.push_back(f ? '1' : '0');
  return s;
}

std::optional<Restraint> parse_restraint(std::string_view text, Edge edge) {
  const bool x_edge = edge == Edge::x0 || edge == Edge::xa;
  std::string_view code;
  if (text == "free")
    code = "00000";
  else if (text == "clamped")
    code = "11111";
  else if (text == "ss")
    code = x_edge ? "01101" : "10110";
  else if (text == "ss-soft")
    code = "00100";
  else
    code = text;
  if (code.size() != 5) return std::nullopt;
  Restraint r;
  for (std::size_t i = 0; i < 5; ++i) {
    if (code[i] != '0' && code[i] != '1') return std::nullopt;
    r.fixed[i] = code[i] == '1';
  }
  return r;
}

std::string_view to_string(Edge e) {
  switch (e) {
  case Edge::x0:
    return "x0";
  case Edge::xa:
    return "xa";
  case Edge::y0:
    return "y0";
  case Edge::yb:
    return "yb";
  }
  return "?";
}

} // namespace plyimpact
