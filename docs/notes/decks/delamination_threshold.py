#!/usr/bin/env python3
"""Energy release rate of central circular delaminations in a clamped circular plate under a central
point load (docs/notes/delamination-threshold.md). The plate is solved as two Kirchhoff regions: inside
r < a the n + 1 sub-plates (n equally spaced delaminations, frictionless) bend each about its own
mid-plane, D/(n+1)^2 together, and, tied to the intact plate at the front r = a, carry the uniform
in-plane stretches that its rotation there imposes (a moment (1 - 1/(n+1)^2) D (1+nu) phi(a)/a); outside,
the intact plate D, clamped at R. The 3 x 3 system of the slope's continuity, the moment's continuity
and the clamp is solved by Cramer's rule, the centre deflection integrated exactly, G = (P^2/2) dC/dA
by central differences (A = n pi a^2: the area of all n delaminations).

Checks, exit status non-zero if any fails (relative 1e-6):
  * tied front: G pi^2 D / P^2 = (n + 2)/32 for every a/R and nu (Davies-Zhang for n = 1, Suemasu's
    (n + 2) for n delaminations): P_c^2 = 32 pi^2 D G_IIc / (n + 2), whatever the delamination radius;
  * free front (the sub-plates allowed to slide at r = a, no stretch): the closed form of the note,
    3/32 + 3(1+nu)/(8 k^2) [(5 - 3 nu) L^2 - k L], L = ln(R/a), k = 5 - 3 nu + 3 (1+nu)(a/R)^2, which grows
    without bound as a -> 0: what a model that forgets the front's compatibility predicts."""
import math
import sys


def det3(m):
    return (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))


def solve3(A, b):
    d = det3(A)
    return [det3([[b[i] if j == k else A[i][j] for j in range(3)] for i in range(3)]) / d for k in range(3)]


def compliance(a, n=1, tied=True, nu=0.3, R=1.0, D=1.0, P=1.0):
    """Centre deflection / P of the clamped plate with n delaminations of radius a."""
    s = 1.0 / (n + 1) ** 2                # bending stiffness of the sub-plates together, / D
    Di = s * D
    m = (1.0 - s) * D * (1 + nu) if tied else 0.0   # membrane couple per unit phi(a)/a
    # slope phi_k(r) = P/(4 pi D_k) (r ln r - r/2) + c_k r/2 + d_k / r  (d = 0 inside)
    f = lambda Dk, r: P / (4 * math.pi * Dk) * (r * math.log(r) - r / 2)
    fp = lambda Dk, r: P / (4 * math.pi * Dk) * (math.log(r) + 0.5)
    M = lambda Dk, r: Dk * (fp(Dk, r) + nu * f(Dk, r) / r)    # particular part of D_k (phi' + nu phi/r)
    # unknowns (c_i, c_o, d_o)
    A = [[a / 2, -a / 2, -1 / a],
         [Di * (1 + nu) / 2 + m / 2, -D * (1 + nu) / 2, D * (1 - nu) / a**2],
         [0.0, R / 2, 1 / R]]
    b = [f(D, a) - f(Di, a),
         M(D, a) - M(Di, a) - m * f(Di, a) / a,
         -f(D, R)]
    ci, co, do = solve3(A, b)
    F = lambda Dk, r: P / (4 * math.pi * Dk) * (r * r / 2 * math.log(r) - r * r / 2)   # integral of f
    inner = F(Di, a) + ci * a * a / 4
    outer = F(D, R) - F(D, a) + co * (R * R - a * a) / 4 + do * math.log(R / a)
    return -(inner + outer) / P


def g_numerical(rho, n, tied, nu):
    h = 1e-5 * rho
    dC = (compliance(rho + h, n, tied, nu) - compliance(rho - h, n, tied, nu)) / (2 * h)
    return 0.5 * dC / (n * 2 * math.pi * rho) * math.pi**2        # G pi^2 D / P^2 with D = P = R = 1


def g_free(rho, nu):
    L = math.log(1.0 / rho)
    k = 5 - 3 * nu + 3 * (1 + nu) * rho**2
    return 3 / 32 + 3 * (1 + nu) / (8 * k * k) * ((5 - 3 * nu) * L * L - k * L)


worst = 0.0
print("  n   nu     a/R   tied front  (n+2)/32   free front  its closed form   P_c free / P_c tied")
for n in (1, 2, 3):
    for nu in (0.0, 0.3):
        for rho in (0.01, 0.05, 0.1, 0.2, 0.5, 0.8):
            tied = g_numerical(rho, n, True, nu)
            worst = max(worst, abs(tied / ((n + 2) / 32) - 1))
            free = g_numerical(rho, n, False, nu)
            line = f"{n:3d} {nu:4.1f} {rho:7.3f} {tied:11.6f} {(n + 2) / 32:9.6f} {free:12.6f}"
            if n == 1:
                worst = max(worst, abs(free / g_free(rho, nu) - 1))
                line += f" {g_free(rho, nu):16.6f} {math.sqrt(tied / free):19.3f}"
            print(line)
print(f"largest relative difference from the closed forms: {worst:.1e}")
sys.exit(0 if worst < 1e-6 else 1)
