// Independent modal reference for the impact of a rigid sphere on a simply supported rectangular
// Mindlin laminated plate (issue 16): Navier series for specially orthotropic plates, Ritz series on
// the same trigonometric basis for general symmetric layups (with a Navier tail for small contact
// circles), exact time stepping of the modes (or Newmark) and the SPEC §4 contact law written again
// here. Used only by the tests, to check the finite-element
// program; it depends on Eigen, the standard library and plyimpact/laminate (A, B, D, F, inertias),
// never on src/plyimpact/fem or src/plyimpact/analysis.
//
// ----------------------------------------------------------------------------------------------------
// Plate (SPEC §1–3): 0 ≤ x ≤ a, 0 ≤ y ≤ b, z (and w) along the impact direction. Symmetric laminate
// (B = 0, I1 = 0): bending decouples from membrane, unknowns w, θx, θy. Hard simple support "ss":
// w = 0 and the tangential rotation = 0 on every edge (θy on x = 0, a; θx on y = 0, b).
//
// Basis (each function satisfies the essential conditions; together they are complete in H¹):
//     w   : S_m(x) S_n(y)   m = 1..M, n = 1..N          S_m(x) = sin(mπx/a), C_m(x) = cos(mπx/a)
//     θx  : C_m(x) S_n(y)   m = 0..M, n = 1..N          (m = 0: θx = sin(nπy/b), free on x-edges)
//     θy  : S_m(x) C_n(y)   m = 1..M, n = 0..N
// Strains κ = (θx,x, θy,y, θx,y + θy,x), γ = (γyz, γxz) = (θy + w,y, θx + w,x); energy
//     U = ½ ∫ (κᵀ D κ + γᵀ F γ) dA,  T = ½ ∫ (I0 ẇ² + I2 (θ̇x² + θ̇y²)) dA      (SPEC §3, (2.108)).
// Every strain of a basis function is one separable product X(x)Y(y), so K and M are sums of
// products of the 1-D integrals ∫ S S, ∫ C C, ∫ S C (ritz_matrices).
//
// Edge functions (Ritz only). Every cosine in x has zero slope at x = 0, a, so the series above forces
// κx = θx,x = 0 on the x-edges; with D16 ≠ 0 the natural condition Mx = D11 κx + D16 κxy = 0 needs
// κx ≠ 0 there, and the cosine series then converges only like 1/M in energy (measured on
// [45/90/-45/0]3s: f₁ = 2904.82, 2904.64, 2904.54 Hz at M = 20, 30, 40 without them, 2904.28,
// 2904.25, 2904.24 Hz with them; the program's 15 × 11 mesh gives 2904.25). Adding θx = sin(kπx/a) S_n(y)
// and θy = S_m(x) sin(kπy/b), k = 1, 2 (end slopes of both signs, still zero where the tangential
// rotation is fixed) restores fast convergence; the mass matrix is then no longer diagonal.
//
// Blocks. A 180° rotation about the plate centre, (x, y) → (a − x, b − y) with w → w, θ → −θ, maps
// each basis function onto ± itself (w_mn, θx_mn, θy_mn: sign (−1)^(m+n); edge functions:
// −(−1)^(m+n)) and leaves D and F unchanged (even-order tensors), so symmetric functions never couple
// to antisymmetric ones: the Ritz problem splits into two blocks. For a specially
// orthotropic plate (D16 = D26 = F45 = 0) the 1-D orthogonality decouples further into the 3×3
// Navier blocks {w_mn, θx_mn, θy_mn} (the m = 0 / n = 0 rotations decouple and carry no load).
// Each block's modes come from K φ = ω² M φ (Eigen's GeneralizedSelfAdjointEigenSolver).
//
// Load. The unit-force Hertz pressure p̂(r) = 3/(2πc²) √(1 − r²/c²), r ≤ c, centred at (x0, y0) with
// the circle inside the plate, projected on w_mn, has the closed form
//     ∫ p̂ S_m S_n dA = S_m(x0) S_n(y0) · P(κ c),     κ = √((mπ/a)² + (nπ/b)²),
//     P(q) = 2π ∫₀^c p̂ J0(κr) r dr = 3 j1(q)/q = 3 (sin q − q cos q)/q³
// (S S = ½[cos(k₋·x) − cos(k₊·x)] with |k±| = κ; the radial integral is Sonine's,
// Gradshteyn & Ryzhik 6.567.1 with μ = ½). The point load is the limit c → 0, P = 1. The tests
// check the closed form against polar Gauss–Legendre quadrature.
//
// Time: each mode q_j (unit modal mass) obeys q̈ + ω² q = F(t) s_j(c(t)), the impactor m ẅi = −F.
// Default: exact integration of each mode and of the impactor for a force linear over the step
// (second order in Δt, no period error however high the mode); option: Newmark average acceleration
// (β = 1/4, γ = 1/2), the program's scheme. Either way q_{n+1} = q̂_j + g_j F_{n+1} s_j, so the
// contact-point deflection ws = Σ e_j q_j (e_j = w of mode j at (x0, y0)) is affine in F for a given
// contact radius, ws = ŵs + C(c) F, C(c) = Σ_j e_j g_j s_j(c). Each step solves the scalar equation
//     α = α_free − (λ + C(√(R α))) F(α)          (λ: the impactor's own step compliance)
// for the indentation α by safeguarded Newton (c = √(Rα) taken at the new time, not lagged).
// Contact law (SPEC §4): loading k α^1.5, Tan–Sun unloading, Yang–Sun reloading.
//
// Point load on a Mindlin plate: w under a point force is logarithmically infinite, so with
// LoadModel::point the contact compliance grows like ln(M)/(2π F) with the truncation and the peak
// force drifts down without limit as M, N → ∞ (slowly). Only LoadModel::hertz_pressure converges.
#pragma once

#include "plyimpact/laminate/laminate.hpp"

#include <Eigen/Dense>

#include <optional>
#include <utility>
#include <vector>

namespace plyimpact::test::navier_impact {

// ---------------------------------------------------------------------------------------------------
// Plate and basis
// ---------------------------------------------------------------------------------------------------
struct BendingPlate {
  double a = 0.0;                              // length along x, m
  double b = 0.0;                              // length along y, m
  Eigen::Matrix3d D = Eigen::Matrix3d::Zero(); // bending stiffness (x, y, xy), N·m
  Eigen::Matrix2d F = Eigen::Matrix2d::Zero(); // transverse shear stiffness, order (yz, xz), N/m
  double I0 = 0.0;                             // mass per unit area, kg/m²
  double I2 = 0.0;                             // rotary inertia per unit area, kg
};

// D, F, I0, I2 of a symmetric laminate; throws std::invalid_argument if B ≠ 0 or I1 ≠ 0.
BendingPlate bending_plate(const Laminate& laminate, double a, double b);

// D16 = D26 = 0 and F45 = 0 (relative 1e-12): the Navier blocks decouple.
bool is_specially_orthotropic(const BendingPlate& plate);

enum class Unknown { w, theta_x, theta_y };
struct BasisFunction {
  Unknown unknown = Unknown::w;
  int m = 0;         // half-waves along x
  int n = 0;         // half-waves along y
  bool edge = false; // rotation with sin instead of cos along its free direction (see Expansion::ritz)
};

struct RitzMatrices {
  Eigen::MatrixXd K; // stiffness, SI (w in m, θ in rad)
  Eigen::MatrixXd M; // mass
};
// K and M of the plate on the given basis functions (any selection, any order).
RitzMatrices ritz_matrices(const BendingPlate& plate, const std::vector<BasisFunction>& basis);

// P(q) = 3 j1(q)/q: the 2-D Fourier transform of the unit-force Hertz pressure at q = κ c.
double hertz_transform(double q);
// dP/dq = −3 j2(q)/q.
double hertz_transform_derivative(double q);
// (P(q), P'(q)) with one sine and one cosine.
std::pair<double, double> hertz_transform_and_derivative(double q);
// ∫ p̂ sin(mπx/a) sin(nπy/b) dA for the unit-force Hertz pressure of radius c centred at (x0, y0)
// (c = 0: the point load). Throws if the circle leaves the plate.
double hertz_modal_load(const BendingPlate& plate, int m, int n, double x0, double y0, double c);

// ---------------------------------------------------------------------------------------------------
// Modes of the truncated series
// ---------------------------------------------------------------------------------------------------
struct Truncation {
  int M = 10; // w: m = 1..M
  int N = 10; // w: n = 1..N
};

enum class Expansion {
  automatic,         // navier if is_specially_orthotropic, else ritz
  navier,            // 3×3 blocks per (m, n); throws if the plate is not specially orthotropic
  ritz,              // the two symmetry blocks of the full basis plus edge functions (dense)
  ritz_trigonometric // the same without the edge functions (converges slowly when D16, D26 ≠ 0)
};

// The modes of the plate that a force at (x0, y0) excites: blocks whose w-functions all vanish at
// (x0, y0) (|S_m(x0) S_n(y0)| ≤ 1e-12) are left out.
//
// Ritz expansions with `coupled` = (M1, N1) < (M, N): the dense blocks hold only m ≤ M1, n ≤ N1 and
// every other term up to (M, N) is a Navier block of the plate with D16 = D26 = F45 = 0 (hybrid).
// The local response under a small contact circle needs wavenumbers far beyond what a dense Ritz
// basis can hold (κc ≈ 10: M ≈ 300 for c = 1.3 mm), but at those wavenumbers the compliance is
// shear-dominated (D κ² ≫ F) and D16, D26 enter only through the small bending part; the hybrid
// converges to the full Ritz answer as M1, N1 grow, which the caller checks by refining M1.
class ModalPlate {
public:
  ModalPlate(const BendingPlate& plate, Truncation truncation, double x0, double y0,
             Expansion expansion = Expansion::automatic, std::optional<Truncation> coupled = std::nullopt);

  [[nodiscard]] const BendingPlate& plate() const { return plate_; }
  [[nodiscard]] Truncation truncation() const { return truncation_; }
  [[nodiscard]] double x0() const { return x0_; }
  [[nodiscard]] double y0() const { return y0_; }
  [[nodiscard]] bool ritz() const { return ritz_; }
  [[nodiscard]] int mode_count() const { return static_cast<int>(omega2_.size()); }
  [[nodiscard]] int block_count() const { return static_cast<int>(blocks_.size()); }
  // Natural frequencies of the retained modes, Hz, ascending.
  [[nodiscard]] std::vector<double> frequencies_hz() const;
  // Static w at (x0, y0) per unit force at (x0, y0): point load (c = 0) or Hertz pressure of
  // radius c. m/N.
  [[nodiscard]] double static_compliance(double c = 0.0) const;

  // For the time loop: per w-term, its wavenumber κ and S_m(x0) S_n(y0); per mode, ω² and w at
  // (x0, y0); per block, the w-rows of its M-orthonormal modes (column-major, terms × modes).
  struct Block {
    int first_term = 0, term_count = 0;
    int first_mode = 0, mode_count = 0;
    std::size_t phi_offset = 0;
  };
  [[nodiscard]] const std::vector<Block>& blocks() const { return blocks_; }
  [[nodiscard]] const std::vector<double>& kappa() const { return kappa_; }
  [[nodiscard]] const std::vector<double>& load_point_value() const { return a_; }
  [[nodiscard]] const std::vector<double>& omega2() const { return omega2_; }
  [[nodiscard]] const std::vector<double>& mode_value() const { return e_; }
  [[nodiscard]] const std::vector<double>& phi() const { return phi_; }

private:
  void add_block(const BendingPlate& plate, const std::vector<BasisFunction>& basis);

  BendingPlate plate_;
  Truncation truncation_;
  std::optional<Truncation> coupled_;
  double x0_, y0_;
  bool ritz_ = false;
  std::vector<Block> blocks_;
  std::vector<double> kappa_, a_;  // per w-term
  std::vector<double> omega2_, e_; // per mode
  std::vector<double> phi_;        // per block, w-rows of the modes
};

// ---------------------------------------------------------------------------------------------------
// Impact
// ---------------------------------------------------------------------------------------------------
struct Impactor {
  double mass = 0.0;     // kg
  double radius = 0.0;   // m (contact radius c = √(R α))
  double velocity = 0.0; // m/s towards the plate
};

struct ContactLaw {
  double k = 0.0;           // N/m^1.5
  double q = 2.5;           // Tan–Sun unloading exponent
  double beta = 0.094;      // permanent indentation α0 = β (αm − αcr) when αm > αcr
  double alpha_cr = 1.7e-4; // m
  bool elastic = false;     // unload along the loading curve (q = 1.5, no permanent indentation)
};

enum class LoadModel {
  point,          // point force at (x0, y0); ws = w(x0, y0)
  hertz_pressure, // Hertz pressure of radius √(Rα) at (x0, y0); ws = w(x0, y0) (SPEC §4, the program)
  // The same pressure with ws = ∫ p̂ w dA, the deflection the pressure does work on. With an elastic
  // law and a fixed radius this makes the system conservative; with the radius following α it is not
  // exactly (the load shape changes under a deflected plate). For comparison only.
  hertz_pressure_work_conjugate
};

enum class Integrator {
  exact_modal, // each mode integrated exactly for a force linear over the step (second order in Δt
               // through the force only: no period error, high modes respond correctly)
  newmark      // average acceleration, β = 1/4, γ = 1/2, like the finite-element program
};

struct TimeStepping {
  double dt = 1e-6;          // s
  std::optional<double> end; // s; empty: stop at the first separation
  int history_every = 0;     // keep every k-th step in ImpactResult::history (0: none)
  Integrator integrator = Integrator::exact_modal;
};

struct ImpactSample {
  double t = 0.0;            // s
  double force = 0.0;        // N
  double indentation = 0.0;  // α, m
  double plate_w = 0.0;      // ws, m
  double impactor_w = 0.0;   // m
  double impactor_v = 0.0;   // m/s
  double plate_energy = 0.0; // ½ Σ (q̇² + ω² q²), J
};

struct ImpactResult {
  // First contact, continuous-time estimates: the peak force is k αm^1.5 with αm the maximum of the
  // parabola through the three indentation samples around the largest one (α(t) is smooth there,
  // F(t) is not: the loading and unloading branches meet at the peak); its time is the parabola's
  // vertex; the contact ends where α − α0 crosses zero, interpolated linearly between steps.
  double peak_force = 0.0;       // N
  double time_of_peak = 0.0;     // s
  double contact_duration = 0.0; // s (first contact; 0 if it had not ended)
  double max_indentation = 0.0;  // m
  double permanent_indentation = 0.0;
  double max_contact_radius = 0.0; // √(R αm), m
  // The same quantities as the finite-element program records them (largest sampled force and its
  // step time; duration = last step with F > 0, first contact starting at t = 0).
  double sampled_peak_force = 0.0;
  double sampled_time_of_peak = 0.0;
  double sampled_contact_duration = 0.0;
  double rebound_velocity = 0.0; // −(impactor velocity) at the end, m/s
  bool separated = false;        // the first contact ended within the run
  int contacts = 0;              // contact episodes in the run
  long steps = 0;
  int newton_iterations_max = 0;
  std::vector<ImpactSample> history;
};

ImpactResult simulate_impact(const ModalPlate& plate, const Impactor& impactor, const ContactLaw& law,
                             LoadModel load, const TimeStepping& time);

// Rigid-target Hertz impact (elastic loading and unloading, SPEC §4 with ws = 0):
// peak force (5/4 m v0²)^(3/5) k^(2/5), contact time 2 αm/v0 ∫₀¹ dx/√(1 − x^(5/2)) = 3.21807 (m²/(k²
// v0))^(1/5).
double rigid_target_peak_force(double mass, double velocity, double k);
double rigid_target_contact_time(double mass, double velocity, double k);

} // namespace plyimpact::test::navier_impact
