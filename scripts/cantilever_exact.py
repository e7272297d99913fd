#!/usr/bin/env python3
"""Exact continuum tip receptance of a clamped-free beam (Euler-Bernoulli or Timoshenko) under a
tip force F sin(wt) with mass-proportional damping C = alpha M, by a transfer matrix: an
independent check of src/analysis/timoshenko.rs (which uses finite elements and modes).

C = alpha M makes the damped problem the undamped one at the complex "frequency squared"
w^2 - i alpha w, for translation and rotary inertia alike. State y = [w, psi, Q, M]:
  w' = psi + Q/(kGA),  psi' = M/EI,  Q' = -rhoA s w,  M' = -Q - rhoI s psi,  s = w^2 - i alpha w;
clamp w = psi = 0 at x = 0; Q(L) = F, M(L) = 0 at the tip. Euler-Bernoulli: 1/kGA = rhoI = 0.

Prints the figures pinned in src/analysis/timoshenko_tests.rs (`continuum_*`). numpy + scipy.
"""
import numpy as np
import scipy.linalg as sl
from scipy.optimize import brentq

L, h, t = 10.0, 10 * np.sqrt(3) / 18, 1.0
E, nu, rho = 1.2e9, 0.3, 2000.0
A, I = h * t, t * h**3 / 12
G, kappa = E / (2 * (1 + nu)), 10 * (1 + nu) / (12 + 11 * nu)  # Cowper 1966
EI, kGA, rA, rI = E * I, kappa * G * A, rho * A, rho * I


def transfer(s, timoshenko):
    """exp(A L) for the state above at complex s = w^2 - i alpha w."""
    a = np.zeros((4, 4), complex)
    a[0, 1] = 1
    a[0, 2] = 1 / kGA if timoshenko else 0
    a[1, 3] = 1 / EI
    a[2, 0] = -rA * s
    a[3, 2] = -1
    a[3, 1] = -(rI * s if timoshenko else 0)
    return sl.expm(a * L)


def receptance(omega, alpha, timoshenko):
    T = transfer(omega**2 - 1j * alpha * omega, timoshenko)
    q = np.linalg.solve(T[2:4, 2:4], np.array([1, 0], complex))
    return T[0, 2] * q[0] + T[0, 3] * q[1]


def fundamental(timoshenko):
    w_eb = 1.875104068711961**2 * np.sqrt(EI / (rA * L**4))
    f = lambda w: np.linalg.det(transfer(w * w, timoshenko)[2:4, 2:4]).real
    return brentq(f, 0.5 * w_eb, 1.2 * w_eb, xtol=1e-15, rtol=1e-15)


def eb_closed_form(omega, alpha):
    """Euler-Bernoulli tip receptance in closed form, to check the transfer matrix itself."""
    x = (rA * (omega**2 - 1j * alpha * omega) / EI) ** 0.25 * L
    num = np.cosh(x) * np.sin(x) - np.sinh(x) * np.cos(x)
    return num * L**3 / (EI * x**3 * (1 + np.cosh(x) * np.cos(x)))


if __name__ == "__main__":
    w1_eb, w1_t = fundamental(False), fundamental(True)
    omega = 0.2 * w1_t
    alpha = 2 * 0.10 * omega
    for w, a in [(omega, alpha), (3 * w1_t, 0.3 * w1_t)]:
        rel = abs(receptance(w, a, False) / eb_closed_form(w, a) - 1)
        print(f"transfer matrix vs EB closed form at w = {w:.6f}: {rel:.1e}")
    print(f"static tip flexibility (Timoshenko) {receptance(0, 0, True).real:.16e} "
          f"vs {L**3 / (3 * EI) + L / kGA:.16e}")
    print(f"w1 EB         {w1_eb:.15f} rad/s (analytic {1.875104068711961**2 * np.sqrt(EI / (rA * L**4)):.15f})")
    print(f"w1 Timoshenko {w1_t:.15f} rad/s")
    print(f"sample: omega = {omega:.15f} rad/s, alpha = {alpha:.15f} 1/s, F = 1 kN")
    for name, timo in [("EB", False), ("Timoshenko", True)]:
        print(f"  tip amplitude {name:11s} {1e3 * abs(receptance(omega, alpha, timo)):.15e} m")
    w, a = 1.5 * w1_t, 0.05 * w1_t
    print(f"above resonance: omega = 1.5 w1, alpha = 0.05 w1: Timoshenko "
          f"{1e3 * abs(receptance(w, a, True)):.15e} m")
