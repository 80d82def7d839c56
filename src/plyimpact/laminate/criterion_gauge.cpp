#include "plyimpact/laminate/criterion_gauge.hpp"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <initializer_list>

namespace plyimpact {

// Named, not anonymous: the unity batches put this file beside others with their own helpers.
namespace gauge_detail {

using Ramp = GaugeBranch::Ramp;

/// Columns of PlateStressVector.
enum Component : Eigen::Index { s11 = 0, s22 = 1, t12 = 2, t13 = 3, t23 = 4 };

/// One row of a branch: coefficient × component, with its ramp.
struct Row {
  Component component;
  double coefficient;
  Ramp ramp = Ramp::none;
};

GaugeBranch branch(std::initializer_list<Row> rows, bool quadratic = true) {
  GaugeBranch b;
  b.quadratic = quadratic;
  Eigen::Index r = 0;
  for (const Row& row : rows) {
    b.W(r, row.component) = row.coefficient;
    b.ramp[static_cast<std::size_t>(r)] = row.ramp;
    ++r;
  }
  return b;
}

/// A quadratic form σᵀQσ + gᵀσ over (σ11, σ22, τ12) as ‖Lᵀσ + h‖² − ‖h‖² (Q = LLᵀ, h = L⁻¹g/2);
/// nullopt when Q is not positive definite.
std::optional<GaugeBranch> completed_square(const Eigen::Matrix3d& Q, const Eigen::Vector3d& g) {
  const Eigen::LLT<Eigen::Matrix3d> llt(Q);
  if (llt.info() != Eigen::Success) return std::nullopt;
  const Eigen::Matrix3d L = llt.matrixL();
  GaugeBranch b;
  b.W.topLeftCorner<3, 3>() = L.transpose();
  b.h.head<3>() = L.triangularView<Eigen::Lower>().solve(0.5 * g);
  return b;
}

double squared(double x) {
  return x * x;
}

// Hashin (2.37) with σ33 = 0: fibre tension and compression, matrix tension and compression. The
// compression branch completes its linear term a·σ22, a = [(Yc/2S23)² − 1]/Yc, into
// (σ22⁻/(2S23) + S23·a)² − (S23·a)².
std::vector<GaugeBranch> hashin_gauge(const Strengths& st) {
  const double Xt = *st.Xt, Xc = *st.Xc, Yt = *st.Yt, Yc = *st.Yc, S12 = *st.S12, S23 = *st.S23;
  GaugeBranch compression =
      branch({{s22, 0.5 / S23, Ramp::negative}, {t23, 1.0 / S23}, {t12, 1.0 / S12}, {t13, 1.0 / S12}});
  compression.h(0) = S23 * (squared(Yc / (2.0 * S23)) - 1.0) / Yc;
  return {branch({{s11, 1.0 / Xt, Ramp::positive}, {t12, 1.0 / S12}, {t13, 1.0 / S12}}),
          branch({{s11, 1.0 / Xc, Ramp::negative}}),
          branch({{s22, 1.0 / Yt, Ramp::positive}, {t23, 1.0 / S23}, {t12, 1.0 / S12}, {t13, 1.0 / S12}}),
          compression};
}

// Sun (2.39)–(2.41): (σ11/X)² = (σ11⁺/Xt)² + (σ11⁻/Xc)² in one branch; crushing completes
// c·σ22, c = Yc/(4S12²) − 1/Yc, into (σ22⁻/(2S12) + S12·c)² − (S12·c)².
std::vector<GaugeBranch> sun_gauge(const Strengths& st) {
  const double Xt = *st.Xt, Xc = *st.Xc, Yt = *st.Yt, Yc = *st.Yc, S12 = *st.S12, S23 = *st.S23;
  GaugeBranch crushing = branch({{s22, 0.5 / S12, Ramp::negative}, {t12, 1.0 / S12}});
  crushing.h(0) = S12 * (Yc / (4.0 * S12 * S12) - 1.0 / Yc);
  return {branch({{s11, 1.0 / Xt, Ramp::positive},
                  {s11, 1.0 / Xc, Ramp::negative},
                  {t12, 1.0 / S12},
                  {t13, 1.0 / S12}}),
          branch({{s22, 1.0 / Yt, Ramp::positive}, {t12, 1.0 / S12}, {t23, 1.0 / S23}}), crushing};
}

// Maximum stress (2.32): five linear branches, one per ratio.
std::vector<GaugeBranch> max_stress_gauge(const Strengths& st) {
  return {branch({{s11, 1.0 / *st.Xt, Ramp::positive}}, false),
          branch({{s11, 1.0 / *st.Xc, Ramp::negative}}, false),
          branch({{s22, 1.0 / *st.Yt, Ramp::positive}}, false),
          branch({{s22, 1.0 / *st.Yc, Ramp::negative}}, false), branch({{t12, 1.0 / *st.S12}}, false)};
}

// Maximum strain (2.33): the strains are linear in the stresses, so each ratio is one row.
std::vector<GaugeBranch> max_strain_gauge(const Material& m) {
  const StrainAllowables a = strain_allowables(m);
  const auto strain_row = [](double per_s11, double per_s22, double allowable, Ramp ramp) {
    GaugeBranch b;
    b.quadratic = false;
    b.W(0, s11) = per_s11 / allowable;
    b.W(0, s22) = per_s22 / allowable;
    b.ramp[0] = ramp;
    return b;
  };
  const double e11_s11 = 1.0 / m.E1, e11_s22 = -m.nu12 / m.E1; // ε11 = (σ11 − ν12 σ22)/E1
  const double e22_s11 = -m.nu12 / m.E1, e22_s22 = 1.0 / m.E2; // ε22 = σ22/E2 − ν12 σ11/E1
  return {strain_row(e11_s11, e11_s22, a.e1t, Ramp::positive),
          strain_row(e11_s11, e11_s22, a.e1c, Ramp::negative),
          strain_row(e22_s11, e22_s22, a.e2t, Ramp::positive),
          strain_row(e22_s11, e22_s22, a.e2c, Ramp::negative), branch({{t12, 1.0 / (m.G12 * a.g12)}}, false)};
}

std::optional<std::vector<GaugeBranch>> single(std::optional<GaugeBranch> b) {
  if (!b) return std::nullopt;
  return std::vector<GaugeBranch>{*b};
}

// Tsai–Wu (2.36): F11σ11² + 2F12σ11σ22 + F22σ22² + F66τ12² + F1σ11 + F2σ22.
std::optional<std::vector<GaugeBranch>> tsai_wu_gauge(const Strengths& st, double f12_star) {
  const double F11 = 1.0 / (*st.Xt * *st.Xc), F22 = 1.0 / (*st.Yt * *st.Yc), F66 = 1.0 / squared(*st.S12);
  const double F12 = f12_star * std::sqrt(F11 * F22);
  Eigen::Matrix3d Q;
  Q << F11, F12, 0.0, F12, F22, 0.0, 0.0, 0.0, F66;
  return single(completed_square(Q, {1.0 / *st.Xt - 1.0 / *st.Xc, 1.0 / *st.Yt - 1.0 / *st.Yc, 0.0}));
}

// Hoffman (2.38) in plane stress: (σ11² − σ11σ22)/(XtXc) + σ22²/(YtYc) + τ12²/S12² + linear terms.
std::optional<std::vector<GaugeBranch>> hoffman_gauge(const Strengths& st) {
  const double XX = *st.Xt * *st.Xc, YY = *st.Yt * *st.Yc;
  Eigen::Matrix3d Q;
  Q << 1.0 / XX, -0.5 / XX, 0.0, -0.5 / XX, 1.0 / YY, 0.0, 0.0, 0.0, 1.0 / squared(*st.S12);
  return single(completed_square(Q, {1.0 / *st.Xt - 1.0 / *st.Xc, 1.0 / *st.Yt - 1.0 / *st.Yc, 0.0}));
}

// Tsai–Hill (2.35): X and Y follow the signs of σ11 and σ22 inside a form with a cross term, so no
// ramp can select them; each of the four (X, Y) pairs is a branch of its own, positive definite when
// Y < 2X, and the largest of the four bounds the one that holds (loosely where the others are larger).
std::optional<std::vector<GaugeBranch>> tsai_hill_gauge(const Strengths& st) {
  std::vector<GaugeBranch> out;
  for (const double X : {*st.Xt, *st.Xc})
    for (const double Y : {*st.Yt, *st.Yc}) {
      Eigen::Matrix3d Q;
      Q << 1.0 / (X * X), -0.5 / (X * X), 0.0, -0.5 / (X * X), 1.0 / (Y * Y), 0.0, 0.0, 0.0,
          1.0 / squared(*st.S12);
      const auto b = completed_square(Q, Eigen::Vector3d::Zero());
      if (!b) return std::nullopt;
      out.push_back(*b);
    }
  return out;
}

} // namespace gauge_detail

using gauge_detail::squared;

double GaugeBranch::norm_of_image(const Eigen::Matrix<double, 5, 1>& v) const {
  double sum = 0.0;
  for (Eigen::Index r = 0; r < 5; ++r) {
    double x = v(r);
    switch (ramp[static_cast<std::size_t>(r)]) {
    case Ramp::positive:
      x = std::max(x, 0.0);
      break;
    case Ramp::negative:
      x = std::min(x, 0.0);
      break;
    case Ramp::none:
      break;
    }
    sum += squared(x + h(r));
  }
  return std::sqrt(sum);
}

double GaugeBranch::index(const PlateStressVector& s) const {
  const double n = norm(s);
  return quadratic ? n * n - h.squaredNorm() : n;
}

double GaugeBranch::threshold(double index_limit) const {
  return quadratic ? std::sqrt(std::max(index_limit + h.squaredNorm(), 0.0)) : index_limit;
}

std::optional<std::vector<GaugeBranch>> criterion_gauge(Criterion criterion, const Material& m,
                                                        const CriterionOptions& options) {
  if (!missing_strengths(criterion, m.strength).empty()) return std::nullopt;
  switch (criterion) {
  case Criterion::max_stress:
    return gauge_detail::max_stress_gauge(m.strength);
  case Criterion::max_strain:
    return gauge_detail::max_strain_gauge(m);
  case Criterion::hoffman:
    return gauge_detail::hoffman_gauge(m.strength);
  case Criterion::tsai_wu:
    return gauge_detail::tsai_wu_gauge(m.strength, options.tsai_wu_f12_star);
  case Criterion::hashin:
    return gauge_detail::hashin_gauge(m.strength);
  case Criterion::sun:
    return gauge_detail::sun_gauge(m.strength);
  case Criterion::tsai_hill:
    return gauge_detail::tsai_hill_gauge(m.strength);
  case Criterion::choi_chang_matrix:
  case Criterion::choi_chang_delamination:
    return std::nullopt;
  }
  return std::nullopt;
}

} // namespace plyimpact
