// Independent closed-form (Navier double sine series) reference solutions for simply supported
// rectangular Mindlin (first-order shear deformation, FSDT) plates. Used only by the tests, to check
// the finite-element code; deliberately depends on nothing but Eigen and the C++ standard library.
//
// ----------------------------------------------------------------------------------------------------
// Conventions (SPEC §1–3)
// ----------------------------------------------------------------------------------------------------
//   * 0 ≤ x ≤ a, 0 ≤ y ≤ b, z points INTO the plate (impact direction); top face z = −h/2.
//   * u = u0 + z θx, v = v0 + z θy, w = w0.  w and the transverse load q are positive along +z.
//   * Curvatures κ = (θx,x, θy,y, θx,y + θy,x); transverse shear γxz = θx + w,x, γyz = θy + w,y.
//   * Resultants: M = D κ (Mx, My, Mxy, N·m/m = N), Qx = F55 γxz, Qy = F44 γyz (N/m),
//     with Mx = ∫ σx z dz, Qx = ∫ τxz dz.  With these signs a plate pushed along +z has its top
//     (z < 0) plies in compression and Mx > 0 at the centre.
//
// Scope: symmetric cross-ply / specially orthotropic / isotropic laminate, i.e. B = 0,
// A16 = A26 = D16 = D26 = 0, F45 = 0, I1 = 0.  Then bending (w, θx, θy) and membrane (u0, v0)
// decouple, and the hard simple support SS-2
//     x = 0, a :  v = w = θy = 0,  Nx = Mx = 0 (natural)
//     y = 0, b :  u = w = θx = 0,  Ny = My = 0 (natural)
// is satisfied term by term by
//     w  = Σ W_mn sin αx sin βy,  θx = Σ X_mn cos αx sin βy,  θy = Σ Y_mn sin αx cos βy,
//     u0 = Σ U_mn cos αx sin βy,  v0 = Σ V_mn sin αx cos βy,      α = mπ/a, β = nπ/b.
//
// ----------------------------------------------------------------------------------------------------
// Derivation of the 3×3 bending system (static, load q = Σ q_mn sin αx sin βy)
// ----------------------------------------------------------------------------------------------------
// Total potential Π = ½∫(κᵀDκ + F55 γxz² + F44 γyz²) dA − ∫ q w dA.  Its first variation, after
// integration by parts (boundary terms vanish with the SS-2 conditions above), gives
//     δw :  Qx,x + Qy,y + q = 0
//     δθx:  Mx,x + Mxy,y − Qx = 0
//     δθy:  Mxy,x + My,y − Qy = 0.
// Insert the series (s = sin, c = cos, arguments αx and βy):
//     κx = −αX s s,  κy = −βY s s,  κxy = (βX + αY) c c,  γxz = (X + αW) c s,  γyz = (Y + βW) s c
//     Mx = −(D11 αX + D12 βY) s s,  My = −(D12 αX + D22 βY) s s,  Mxy = D66 (βX + αY) c c
//     Qx = F55 (X + αW) c s,  Qy = F44 (Y + βW) s c.
// Then, per (m, n):
//     δw :  −α F55 (X + αW) − β F44 (Y + βW) + q_mn = 0
//     δθx:  −α(D11 αX + D12 βY) − β D66 (βX + αY) − F55 (X + αW) = 0
//     δθy:  −α D66 (βX + αY) − β(D12 αX + D22 βY) − F44 (Y + βW) = 0
// i.e. the symmetric positive definite system K_mn (W, X, Y)ᵀ = (q_mn, 0, 0)ᵀ with
//         | F55 α² + F44 β²      F55 α                   F44 β                 |
//     K = | F55 α                D11 α² + D66 β² + F55   (D12 + D66) αβ        |
//         | F44 β                (D12 + D66) αβ          D66 α² + D22 β² + F44 |
// (bending_stiffness()).  Free vibration: K − ω² diag(I0, I2, I2) (each of s s, c s, s c integrates
// to ab/4, so the mass matrix is diagonal).  Buckling under uniform Nx, Ny (tension positive): the
// membrane-force work ½∫(Nx w,x² + Ny w,y²) dA adds (Nx α² + Ny β²) to K(0,0), so the critical
// factor λ makes K − λ(−Nx α² − Ny β²) e_w e_wᵀ singular.
//
// Numerically the 3×3 system is NOT solved as written: for thin plates (F ≫ D α²) the relevant
// quantities (γ, and the Kirchhoff-like stiffness) are small differences of large numbers.  Write
// Db = [[D11α²+D66β², (D12+D66)αβ], [(D12+D66)αβ, D66α²+D22β²]], Fd = diag(F55, F44), g = (α, β)ᵀ.
// Rows 2–3 give (X, Y) = −(Db + Fd)⁻¹ Fd g W, hence γ = (X, Y) + g W = (Db + Fd)⁻¹ Db g W, and row 1
// gives gᵀ Fd γ = q_mn, i.e.  W = q_mn / S0,  S0 = gᵀ Fd (Db + Fd)⁻¹ Db g  (= the Schur complement
// K_ww − K_wθ K_θθ⁻¹ K_θw, free of cancellation).  In the thin limit S0 → D11α⁴ + 2(D12 + 2D66)α²β²
// + D22β⁴ (Kirchhoff); for an isotropic plate exactly 1/S0 = 1/(D k⁴) + 1/(F k²), k² = α² + β².
// The same Schur complement with Db → Db − ω² I2 gives the lowest frequency root (solved by
// bisection, see fundamental_bending_omega2) and the buckling factor λ = S0 / (−Nx α² − Ny β²).
//
// Load coefficients q_mn = (4/ab) ∫∫ q sin αx sin βy dA:
//     uniform q0:                      16 q0 / (π² m n) for m, n odd, 0 otherwise
//     point load P at (x0, y0):        4P/(ab) sin αx0 sin βy0
//     uniform patch q0, cx × cy centred at (x0, y0):
//                                      16 q0/(π² m n) sin αx0 sin βy0 sin(α cx/2) sin(β cy/2)
//     sinusoidal q0 sin(πx/a) sin(πy/b): q_11 = q0
// NOTE (point load): for a Mindlin plate w under a point load is logarithmically singular; the
// shear part of the series for w(x0, y0) grows like P ln(N)/(2π F) with the truncation index N, so
// the value at the load point depends on the number of terms (it does not converge).  Qx, Qy are
// singular (∼1/r) there as well.  Away from the load point everything converges.
#pragma once

#include <Eigen/Dense>

#include <vector>

namespace plyimpact::test::navier {

// Plate data. Only the entries allowed by the scope are read (A11, A12, A22, A66, D11, D12, D22, D66);
// the constructor-like helpers and every entry point throw std::invalid_argument if A16, A26, D16, D26
// are not negligible, or if a, b, D11, D22, D66, F44, F55 (and, where inertia or membrane terms are
// used, I0, A11, A22, A66) are not positive.
struct Plate {
  double a = 0.0;                              // length along x, m
  double b = 0.0;                              // length along y, m
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero(); // membrane stiffness, Pa·m (N/m)
  Eigen::Matrix3d D = Eigen::Matrix3d::Zero(); // bending stiffness, Pa·m³ (N·m)
  double F44 = 0.0;                            // transverse shear stiffness yz (with correction factor), N/m
  double F55 = 0.0;                            // transverse shear stiffness xz (with correction factor), N/m
  double I0 = 0.0;                             // mass per unit area, kg/m²
  double I2 = 0.0;                             // rotary inertia per unit area, kg (= kg·m²/m²)
};

// One ply for the laminate helper and the through-thickness shear recovery. Plate axes (Q̄), Pa.
// z_top < z_bottom (z points into the plate); plies listed top (impacted face) to bottom, contiguous.
struct Ply {
  double z_top = 0.0;    // m
  double z_bottom = 0.0; // m
  double Q11 = 0.0, Q12 = 0.0, Q22 = 0.0, Q66 = 0.0;
  double Q16 = 0.0, Q26 = 0.0; // only used by the shear recovery; must be 0 for the Navier solution
  double Q44 = 0.0, Q55 = 0.0; // only used by plate_from_plies (F = K Σ Q̄ t)
  double rho = 0.0;            // kg/m³, only used by plate_from_plies
};

// Isotropic plate: D = E h³/(12(1−ν²)), A = E h/(1−ν²) (plane-stress form), F44 = F55 = k_shear G h,
// I0 = ρ h, I2 = ρ h³/12.
Plate isotropic_plate(double a, double b, double h, double E, double nu, double rho,
                      double k_shear = 5.0 / 6.0);

// Laminate integration of a ply list (the textbook formulas, written here independently of src/):
// A, D, F = k_shear Σ Q̄44,55 t, I0, I2.  Throws if the layup gives B ≠ 0 or I1 ≠ 0 (not symmetric) or
// coupling terms A16, A26, D16, D26 ≠ 0.
Plate plate_from_plies(double a, double b, const std::vector<Ply>& plies, double k_shear = 5.0 / 6.0);

// ---------------------------------------------------------------------------------------------------
// Loads
// ---------------------------------------------------------------------------------------------------
enum class LoadKind { Uniform, Point, Patch, Sinusoidal };

struct Load {
  LoadKind kind = LoadKind::Uniform;
  double value = 0.0;        // q0 in Pa (Uniform, Patch, Sinusoidal) or P in N (Point); positive along +z
  double x0 = 0.0, y0 = 0.0; // load point / patch centre, m
  double cx = 0.0, cy = 0.0; // patch size along x, y, m
};

Load uniform_load(double q0);                                           // q0: Pa
Load sinusoidal_load(double q0);                                        // q0 sin(πx/a) sin(πy/b), Pa
Load point_load(double P, double x0, double y0);                        // P: N at (x0, y0) m
Load patch_load(double q0, double x0, double y0, double cx, double cy); // q0: Pa on cx × cy, m

// q_mn in Pa (see the table above). m, n ≥ 1.
double load_coefficient(const Plate& p, const Load& load, int m, int n);

// ---------------------------------------------------------------------------------------------------
// Single-term (m, n) quantities
// ---------------------------------------------------------------------------------------------------
// K_mn of the derivation above (row 1 in N/m³, rows 2–3 in N/m); m, n ≥ 0.
Eigen::Matrix3d bending_stiffness(const Plate& p, int m, int n);
// diag(I0, I2, I2)
Eigen::Matrix3d bending_mass(const Plate& p);
// Membrane 2×2 for (U, V): [[A11α² + A66β², (A12+A66)αβ], [(A12+A66)αβ, A66α² + A22β²]], N/m³
Eigen::Matrix2d inplane_stiffness(const Plate& p, int m, int n);

struct BendingAmplitudes {
  double W = 0.0;            // m
  double X = 0.0, Y = 0.0;   // rad (θx, θy amplitudes)
  double Gx = 0.0, Gy = 0.0; // rad (γxz = X + αW, γyz = Y + βW, computed without cancellation)
};
// Solution of K_mn (W, X, Y) = (q_mn, 0, 0), m, n ≥ 1, q_mn in Pa.
BendingAmplitudes static_amplitudes(const Plate& p, int m, int n, double q_mn);

// ---------------------------------------------------------------------------------------------------
// Static series solution
// ---------------------------------------------------------------------------------------------------
struct SeriesOptions {
  // Sum all m, n in 1..max_index (terms with q_mn = 0, e.g. even m or n for a uniform load, vanish).
  int max_index = 199;
  // If > 0, sum shell by shell (max(m, n) = 1, 2, ...) and stop early once two successive non-empty
  // shells change each of w, θx, θy, κx, κy, κxy by less than rel_tol × Σ|amplitudes of that field|
  // (trigonometric factors set to 1, so fields that vanish by symmetry pass).  0: always sum to
  // max_index.  The shear-type fields (γ, Q, ∂κ, ∂M, hence the equilibrium τ) are NOT in the test:
  // their series converge only like 1/N (e.g. Qx at an edge midpoint has relative error ≈ 0.6/N for
  // a uniform load); control them with max_index.
  double rel_tol = 0.0;
};

struct StaticField {
  double w = 0.0;                                                  // m
  double theta_x = 0.0, theta_y = 0.0;                             // rad
  Eigen::Vector3d kappa = Eigen::Vector3d::Zero();                 // (κx, κy, κxy), 1/m
  Eigen::Vector3d dkappa_dx = Eigen::Vector3d::Zero();             // ∂κ/∂x, 1/m²
  Eigen::Vector3d dkappa_dy = Eigen::Vector3d::Zero();             // ∂κ/∂y, 1/m²
  double gamma_xz = 0.0, gamma_yz = 0.0;                           // rad
  double Mx = 0.0, My = 0.0, Mxy = 0.0;                            // N·m/m
  double Qx = 0.0, Qy = 0.0;                                       // N/m
  double dMx_dx = 0.0, dMxy_dy = 0.0, dMxy_dx = 0.0, dMy_dy = 0.0; // N/m (Mx,x + Mxy,y = Qx in statics)
  int max_index_used = 0;
  bool converged = false; // true if rel_tol > 0 and the criterion was met before max_index
};

// Fields at (x, y) in m. The in-plane ply strain at depth z is ε = z κ (membrane strain is zero for a
// symmetric laminate under transverse load), so σ = Q̄(z) z κ.
StaticField static_field(const Plate& p, const Load& load, double x, double y, const SeriesOptions& opt = {});

// σ = (σx, σy, τxy) in Pa at depth z (m) from ply stiffness (Q̄11, Q̄12, Q̄22, Q̄66, Q̄16, Q̄26): Q̄ z κ.
Eigen::Vector3d inplane_stress(const Ply& ply, double z, const StaticField& f);

struct TransverseShear {
  double tau_xz = 0.0; // Pa
  double tau_yz = 0.0; // Pa
};
// Equilibrium recovery of the transverse shear stresses at depth z (m):
//     ∂τxz/∂z = −(∂σx/∂x + ∂τxy/∂y),  ∂τyz/∂z = −(∂τxy/∂x + ∂σy/∂y),  τ(z_top of ply 0) = 0,
// with σ = Q̄(z) z κ(x, y) (piecewise quadratic in z). For plies consistent with the plate's D (and
// B = 0) τ vanishes on the bottom face too and ∫ τxz dz = Mx,x + Mxy,y = Qx, ∫ τyz dz = Qy.
TransverseShear equilibrium_transverse_shear(const std::vector<Ply>& plies, const StaticField& f, double z);

// ---------------------------------------------------------------------------------------------------
// Free vibration (rad/s)
// ---------------------------------------------------------------------------------------------------
// Lowest root ω² (rad²/s²) of det(K_mn − ω² diag(I0, I2, I2)) = 0, m, n ≥ 1, computed to full relative
// precision from the Schur complement (well conditioned even for a/h = 10⁴).
double fundamental_bending_omega2(const Plate& p, int m, int n);
// All roots of the bending family (m, n), ascending, rad/s. m, n ≥ 1: 3 roots (the flexural one and
// two thickness-shear ones). m = 0, n ≥ 1: the single thickness-shear mode θx = X sin βy,
// ω² = (D66β² + F55)/I2; n = 0, m ≥ 1: θy = Y sin αx, ω² = (D66α² + F44)/I2.
std::vector<double> bending_frequencies(const Plate& p, int m, int n);
// In-plane (u0, v0) family, ascending, rad/s. m, n ≥ 1: 2 roots of (K_in − ω² I0 I). m = 0: only
// u0 = U sin βy (ω² = A66β²/I0); n = 0: only v0 = V sin αx (ω² = A66α²/I0).
std::vector<double> inplane_frequencies(const Plate& p, int m, int n);

enum class ModeFamily { Bending, InPlane };
struct NaturalFrequency {
  double omega = 0.0; // rad/s
  ModeFamily family = ModeFamily::Bending;
  int m = 0, n = 0;
  int root = 0; // index within bending_frequencies / inplane_frequencies of (m, n), 0 = lowest
};
// The k lowest natural frequencies of the plate over all families (bending: all roots; in-plane),
// ascending. Enumerates m, n ≤ N and doubles N until the k-th value lies below every mode with
// max(m, n) = N + 1 (exact if frequencies increase with each index, as they do for these plates).
std::vector<NaturalFrequency> lowest_frequencies(const Plate& p, int k);

// ---------------------------------------------------------------------------------------------------
// Buckling under uniform in-plane loads Nx, Ny (N/m, tension positive, compression negative)
// ---------------------------------------------------------------------------------------------------
// Load factor λ of mode (m, n) ≥ 1: the plate buckles at (λ Nx, λ Ny). +infinity if the mode is not
// compressed (Nx α² + Ny β² ≥ 0). Shear deformation included.
double buckling_factor(const Plate& p, double Nx, double Ny, int m, int n);

struct BucklingMode {
  double lambda = 0.0;
  int m = 0, n = 0;
};
// Smallest positive λ over 1 ≤ m, n ≤ max_index.
BucklingMode lowest_buckling_factor(const Plate& p, double Nx, double Ny, int max_index = 30);

} // namespace plyimpact::test::navier
