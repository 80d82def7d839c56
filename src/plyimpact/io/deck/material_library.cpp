#include "plyimpact/io/deck/material_library.hpp"

#include <stdexcept>

namespace plyimpact {

namespace {

// SI units; fracture_angle in degrees. Every value is its source's; where a source gives no value the
// card has none, and `note` says so (docs/deck.md, "Material library").
constexpr std::string_view library_text = R"toml(
[thesis-3-6]
source = "the thesis plyimpact implements (README), Table 3.1: the material of the section 3.6 impact validation"
note = "the thesis gives G12 only: G13 and G23 take plyimpact's default, G12 (docs/deck.md)"
E1 = 129.0e9
E2 = 7.5e9
G12 = 3.5e9
nu12 = 0.33
rho = 1540.0

[T300-976]
source = "the thesis plyimpact implements (README), Table 4.2 and Annex 2: graphite/epoxy T300/976, elastic constants, density and the strengths of its damage analysis (Yt, Yc, S_L = S12, S_T = S23, Da)"
note = "no fibre strengths (Xt, Xc) nor fracture toughnesses in the thesis: a deck that uses progressive damage gives them with their source"
E1 = 144.8e9
E2 = 9.65e9
G12 = 7.10e9
G13 = 7.10e9
G23 = 5.92e9
nu12 = 0.30
rho = 1389.2
Yt = 55.2e6
Yc = 294.0e6
S12 = 101.1e6
S23 = 32.94e6
Da = 1.8

[AS4-PEEK]
source = "Camanho, Davila & de Moura 2003 (J. Compos. Mater. 37), AS4/PEEK properties as read in docs/delamination.md: E11 = 122.7 GPa, E22 = 10.1 GPa, G12 = G13 = 5.5 GPa, nu12 = 0.25, nu23 = 0.45 (G23 = E22 / (2 (1 + nu23))); density 1.59 g/cm^3 from a CF/PEEK unidirectional laminate's data sheet (ASTM D792), as examples/impact-delamination.toml"
note = "the interface's toughnesses and strengths (G_Ic 969, G_IIc 1719 J/m^2, eta 2.284, N 80, S 100 MPa) belong to [delamination] (docs/delamination.md)"
E1 = 122.7e9
E2 = 10.1e9
G12 = 5.5e9
G13 = 5.5e9
G23 = 3.4828e9
nu12 = 0.25
rho = 1590.0

[IM7-8552]
source = "NASA CompDam_DGD, tests/IM7-8552.props (github.com/nasa/CompDam_DGD, commit 346cc80), IM7/8552 190 gsm: E1, E2, G12, nu12, Xt, Yt, Yc, S12 from Camanho, Maimi & Davila 2007 (Compos. Sci. Technol. 67:2715); Xc, G_fc, G_mt, G_ms, bk_exponent, nu23 = 0.52 from Camanho, Bessa, Catalanotti, Vogler & Rolfes 2013 (Mech. Mater. 59:36); G_ft from Catalanotti et al. 2010 (Compos. Sci. Technol. 70:1986); fracture_angle alpha0 = 0.925 rad (52.998 deg)"
note = "Yt and S12 are in-situ values. G23 = E2 / (2 (1 + nu23)) and G13 = G12 (transverse isotropy); G_mc is the mode II value GSL, as docs/progressive_damage.md takes it for transverse compression. No density in the file: a deck gives rho with its source"
E1 = 171.42e9
E2 = 9.08e9
G12 = 5.29e9
G13 = 5.29e9
G23 = 2.9868e9
nu12 = 0.32
Xt = 2326.2e6
Xc = 1200.1e6
Yt = 62.3e6
Yc = 199.8e6
S12 = 92.3e6
G_ft = 133.3e3
G_fc = 47.5e3
G_mt = 277.0
G_mc = 788.0
G_ms = 788.0
bk_exponent = 1.634
fracture_angle = 52.998

[AS4-3501-6]
source = "the World-Wide Failure Exercise's lamina data (Soden, Hinton & Kaddour 1998, Compos. Sci. Technol. 58:1011), as two public files give it (we could not read the paper): wrinkleFE (github.com/elhajjar1/wrinkleFE, src/wrinklefe/core/material.py, commit 11b2634, cited there to Soden et al. 1998) and, for E1, E2, G12, nu12 and the five strengths, the same values in github.com/sanjayg0/ims MainBook/ex23_2.m (commit 2623413, a textbook example of AS4/3501-6): E1 126, E2 11, G12 6.6 GPa, nu12 0.28, nu23 0.4; Xt 1950, Xc 1480, Yt 48, Yc 200, S12 79 MPa"
note = "G13 = G12 and G23 = E2 / (2 (1 + nu23)) (transverse isotropy, as the files take them). No density and no fracture toughnesses in these data: a deck gives rho, and G_ft ... G_ms for progressive damage, with their sources"
E1 = 126.0e9
E2 = 11.0e9
G12 = 6.6e9
G13 = 6.6e9
G23 = 3.9286e9
nu12 = 0.28
Xt = 1950.0e6
Xc = 1480.0e6
Yt = 48.0e6
Yc = 200.0e6
S12 = 79.0e6

[T300-914]
source = "the World-Wide Failure Exercise's lamina data of T300/914C (Soden, Hinton & Kaddour 1998, Compos. Sci. Technol. 58:1011), as wrinkleFE gives it (github.com/elhajjar1/wrinkleFE, src/wrinklefe/core/material.py, commit 11b2634, cited there to Soden et al. 1998, WWFE-I; we could not read the paper): E1 138, E2 11, G12 5.5 GPa, nu12 0.28, nu23 0.4; Xt 1500, Xc 900, Yt 27, Yc 200, S12 80 MPa"
note = "one public file only: check these values against the paper before relying on them. G13 = G12 and G23 = E2 / (2 (1 + nu23)) (transverse isotropy). No density and no fracture toughnesses in these data: a deck gives rho, and G_ft ... G_ms for progressive damage, with their sources"
E1 = 138.0e9
E2 = 11.0e9
G12 = 5.5e9
G13 = 5.5e9
G23 = 3.9286e9
nu12 = 0.28
Xt = 1500.0e6
Xc = 900.0e6
Yt = 27.0e6
Yc = 200.0e6
S12 = 80.0e6

[T700-M21]
source = "Tan, Falzon, Chiu & Price, Composites Part A 71 (2015) 212-226, Table 1 (the Rivallant et al. 2013 coupon, 6.5, 17 and 29.5 J)"
note = "no density in the paper: a deck gives rho with its source. bk_exponent is the paper's interface B-K exponent (1.45; Table 1 gives none for the ply's matrix crack). Not carried: the non-linear shear curve (c1 37 833, c2 16 512, c3 2 334.3 MPa), nu23 0.35 and the interface (G_Ic 500, G_IIc 1600 J/m^2, N 20, S 36 MPa), which belong to [delamination]"
E1 = 130.0e9
E2 = 7.7e9
G12 = 4.8e9
G13 = 4.8e9
G23 = 3.8e9
nu12 = 0.3
Xt = 2080.0e6
Xc = 1250.0e6
Yt = 60.0e6
Yc = 290.0e6
S12 = 110.0e6
G_ft = 133.0e3
G_fc = 10.0e3
G_mt = 500.0
G_mc = 1600.0
G_ms = 1600.0
bk_exponent = 1.45

[T700GC-M21]
source = "Tan, Falzon, Chiu & Price, Composites Part A 71 (2015) 212-226, Table 1, values in parentheses (the 25 J panel of T700GC/M21)"
note = "no density in the paper: a deck gives rho with its source. bk_exponent is the paper's interface B-K exponent (1.45). Not carried: the non-linear shear curve, nu23 0.35 and the interface (G_Ic 600, G_IIc 2100 J/m^2, N 20, S 36 MPa), which belong to [delamination]"
E1 = 130.0e9
E2 = 7.7e9
G12 = 4.8e9
G13 = 4.8e9
G23 = 3.8e9
nu12 = 0.33
Xt = 2080.0e6
Xc = 1250.0e6
Yt = 60.0e6
Yc = 290.0e6
S12 = 110.0e6
G_ft = 133.0e3
G_fc = 40.0e3
G_mt = 600.0
G_mc = 2100.0
G_ms = 2100.0
bk_exponent = 1.45
)toml";

} // namespace

std::string_view material_library_toml() {
  return library_text;
}

toml::table material_library() {
  try {
    return toml::parse(library_text, std::string_view("material library"));
  } catch (const toml::parse_error& e) {
    throw std::logic_error(std::string("the material library does not parse: ") +
                           std::string(e.description()));
  }
}

std::string_view material_key_unit(std::string_view key) {
  for (const std::string_view pa :
       {"E1", "E2", "G12", "G13", "G23", "Xt", "Xc", "Yt", "Yc", "S12", "S23", "Zt"})
    if (key == pa) return "Pa";
  for (const std::string_view j : {"G_ft", "G_fc", "G_mt", "G_mc", "G_ms"})
    if (key == j) return "J/m^2";
  if (key == "nu12" || key == "Da" || key == "bk_exponent") return "-";
  if (key == "rho") return "kg/m^3";
  if (key == "fracture_angle") return "deg";
  return {};
}

std::vector<std::string> material_library_names() {
  std::vector<std::string> names;
  for (auto&& [name, card] : material_library())
    names.emplace_back(name.str());
  return names;
}

} // namespace plyimpact
