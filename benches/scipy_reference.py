"""The pin-joint model written independently with NumPy/SciPy: the baseline of `pinjoint bench`.

It follows the paper's equations and docs/model.md (errata included) directly, not the Rust
code's logarithmic forms:
  Hertz (eq. 6), E' with the plus sign (erratum 1), R' = R R_b / (R_b - R);
  Greenwood-Williamson F_3/2(t) by quadrature (scipy.integrate.quad) of its definition;
  Moes' central film (eq. 12) and its load-sharing form (eq. 13 with errata 2, 3: eq. 12 at
  E'/g1 and P/g1, times g1^(1/2));
  the asperity side (eq. 19) in the Gelinck-Schipper form with n -> n g2, E' -> E'/g2,
  P -> P/g2; the shares 1/g1 + 1/g2 = 1 (eq. 9) found by scipy.optimize.brentq on the
  logit y = ln(x1/x2);
  mu = tau_L/p_m (1 - exp(-eta u / (tau_L h_c))) + mu_c/g2 (eqs. 3-5, 8, 10), T = mu R P.
Default parameters (Tables 1-3) only.

Usage (by `pinjoint bench`, or by hand):
  python benches/scipy_reference.py SWEEP_OUTPUT.csv [--limit N]
reads a `pinjoint sweep` output (load, speed and the library's results), evaluates the
first N rows here, and prints one JSON object: seconds per point, and the largest relative
difference from the library in mu, torque, h_c and the shares.
  python benches/scipy_reference.py --self-test
checks F_3/2 and eq. 12 against the check values of docs/model.md and the parabolic-cylinder
closed form.
"""

import csv
import json
import math
import sys
import time

import numpy as np
from scipy import integrate, optimize, special

# Tables 1-3 (SI).
R, R_B, B = 0.028, 0.028025, 0.0594
E1, NU1, E2, NU2 = 205e9, 0.28, 117e9, 0.34
N_S, BETA, SIGMA_S, SIGMA, SIGMA_B, D_D = 7.15e9, 3.4e-6, 1.09e-6, 8.3e-7, 1.35e-6, 1.25e-6
ETA0, ETA_INF, C_P, Z, ALPHA, TAU0, TAU_SLOPE = 0.01245, 6.31e-5, 1.96e8, 0.63, 1.69e-8, 2.28e6, 0.047
MU_C = 0.12
A1, A2, A3, A4 = 1.558, 0.0337, -0.442, -1.7

R_RED = R * R_B / (R_B - R)
E_EFF = 2.0 / ((1 - NU1**2) / E1 + (1 - NU2**2) / E2)


def ln_f32(t):
    """ln F_3/2(t), F_3/2(t) = (2 pi)^-1/2 int_t^inf (s - t)^3/2 exp(-s^2/2) ds, with s = t + x
    and exp(-t^2/2) taken out of the integral (no underflow for large t)."""
    val, _ = integrate.quad(lambda x: x**1.5 * math.exp(-t * x - 0.5 * x * x), 0.0, np.inf, epsabs=0.0, epsrel=1e-13, limit=200)
    return -0.5 * t * t + math.log(val) - 0.5 * math.log(2 * math.pi)


def f32_closed_form(t):
    """Gamma(5/2)/sqrt(2 pi) exp(-t^2/4) D_{-5/2}(t) (docs/model.md)."""
    return special.gamma(2.5) / math.sqrt(2 * math.pi) * math.exp(-t * t / 4) * special.pbdv(-2.5, t)[0]


def moes(m, l):
    """Eq. 12: H_C = h_c/R' U^-1/2 from M and L; returns (H, s)."""
    hri, hei = 3.0 / m, 2.621 * m ** -0.2
    hrp, hep = 1.287 * l ** (2 / 3), 1.311 * m ** -0.125 * l**0.75
    s = (7 + 8 * math.exp(-2 * hei / hri)) / 5
    h = ((hri ** (7 / 3) + hei ** (7 / 3)) ** (3 * s / 7) + (hrp**-3.5 + hep**-3.5) ** (-2 * s / 7)) ** (1 / s)
    return h, s


def film(p, u, x1):
    """Eq. 13 with the corrected exponents: eq. 12 at E'/g1 and P/g1 (g1 = 1/x1)."""
    g1 = 1.0 / x1
    e, load = E_EFF / g1, p / g1
    w, uu, g = load / (e * R_RED * B), ETA0 * u / (e * R_RED), ALPHA * e
    h, _ = moes(w * uu**-0.5, g * uu**0.25)
    return h * R_RED * math.sqrt(uu)


def asperity_ln_f32_required(p, x2):
    """Eq. 19: ln F_3/2((h_c - d_d)/sigma_s) that lets the asperities carry P x2, from the
    Gelinck-Schipper load relation with n -> n g2, E' -> E'/g2, P -> P/g2."""
    # In logarithms: in full film x2 reaches 1e-30 and below, and n g2, E'/g2 leave floats.
    ln_g2 = -math.log(x2)
    ln_n, ln_e, ln_load = math.log(N_S) + ln_g2, math.log(E_EFF) - ln_g2, math.log(p) - ln_g2
    ln_w = ln_load - ln_e - math.log(R_RED * B)
    ln_p0 = 0.5 * (ln_load + ln_e - math.log(2 * math.pi * B * R_RED))
    ln_k = (math.log(A1) + A2 * ln_n + (1.5 * A2 - A3) * math.log(R_RED) + 0.5 * A2 * math.log(BETA)
            + A3 * math.log(SIGMA_S) + (A2 - A3) * ln_w)
    ln_p_asp = ln_p0 + np.logaddexp(0.0, A4 * ln_k) / A4  # p0 (1 + K^A4)^(1/A4)
    # GW: p_asp = 2/3 n sqrt(beta) sigma^3/2 E' F_3/2 (eq. 17)
    return ln_p_asp - (math.log(2 / 3) + ln_n + 0.5 * math.log(BETA) + 1.5 * math.log(SIGMA_S) + ln_e)


def shares(y):
    return special.expit(y), special.expit(-y)


def evaluate(p, omega):
    """Every output at load p (N) and angular velocity omega (rad/s)."""
    u = abs(omega) * R
    a = math.sqrt(8 * p * R_RED / (math.pi * E_EFF * B))
    p_m = p / (2 * a * B)
    if u == 0.0:
        target = asperity_ln_f32_required(p, 1.0)
        t = optimize.brentq(lambda t: ln_f32(t) - target, -30, 30, xtol=1e-15, rtol=4 * np.finfo(float).eps, maxiter=500)
        return {"mu": MU_C, "torque": MU_C * R * p, "h": D_D + t * SIGMA_S, "x1": 0.0, "x2": 1.0}

    def r(y):
        x1, x2 = shares(y)
        h = film(p, u, x1)
        return ln_f32((h - D_D) / SIGMA_S) - asperity_ln_f32_required(p, x2)

    lo, hi = -4.0, 4.0
    while r(lo) > 0:
        lo *= 2
    while r(hi) < 0:
        hi *= 2
    y = optimize.brentq(r, lo, hi, xtol=1e-13, rtol=4 * np.finfo(float).eps, maxiter=500)
    x1, x2 = shares(y)
    h = film(p, u, x1)
    eta = ETA0 * math.exp(math.log(ETA_INF / ETA0) * (1 - (1 + p_m / C_P) ** Z))
    tau_l = TAU0 + TAU_SLOPE * p_m
    mu = tau_l / p_m * -math.expm1(-eta * u / (tau_l * h)) + MU_C * x2
    return {"mu": mu, "torque": mu * R * p, "h": h, "x1": x1, "x2": x2}


def self_test():
    checks = {-3: 5.418377276511698, 0: 0.4300199936622599, 0.5: 0.19520360374379062, 1: 0.07566817739097503,
              2: 0.006648177623587, 3: 2.639675542694661e-4, 4: 4.4391559585389115e-6}
    worst = 0.0
    for t, v in checks.items():
        worst = max(worst, abs(math.exp(ln_f32(t)) / v - 1), abs(f32_closed_form(t) / v - 1))
    for m, l, h, s in [(1, 1, 4.05598902635954, 1.678780734472748), (10, 10, 5.464316870977172, 1.4000260648115448),
                       (100, 10, 4.296808913149384, 1.4), (1000, 5, 2.110980706283332, 1.4)]:
        hh, ss = moes(m, l)
        worst = max(worst, abs(hh / h - 1), abs(ss / s - 1))
    # Boundary torque check values: mu_c R P = 67.2 N m at 20 kN.
    worst = max(worst, abs(evaluate(20e3, 0.0)["torque"] / 67.2 - 1))
    print(json.dumps({"self_test_worst_relative_error": worst}))
    return worst < 1e-9


def main(argv):
    if "--self-test" in argv:
        return 0 if self_test() else 1
    path = argv[0]
    limit = int(argv[argv.index("--limit") + 1]) if "--limit" in argv else 200
    rows = []
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            rows.append(row)
            if len(rows) >= limit:
                break
    pts = [(float(r["load"]), float(r["speed"])) for r in rows]
    t0 = time.perf_counter()
    res = [evaluate(p, w) for p, w in pts]
    seconds = (time.perf_counter() - t0) / len(pts)
    worst = {"mu": 0.0, "torque": 0.0, "h": 0.0, "x1": 0.0, "x2": 0.0}
    cols = {"mu": "friction_coefficient", "torque": "torque", "h": "film_thickness", "x1": "fluid_load_fraction",
            "x2": "asperity_load_fraction"}
    for r, lib in zip(res, rows):
        for k, c in cols.items():
            ref = float(lib[c])
            if k in ("x1", "x2"):
                d = abs(r[k] - ref)  # shares: absolute (they may be ~0)
            else:
                d = abs(r[k] - ref) / abs(ref)
            worst[k] = max(worst[k], d)
    print(json.dumps({"points": len(pts), "seconds_per_point": seconds, "scipy": __import__("scipy").__version__,
                      "numpy": np.__version__, "python": sys.version.split()[0], "max_difference": worst}))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
