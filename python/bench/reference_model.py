"""An independent per-point implementation of the pin-joint model in NumPy/SciPy.

Written from the paper's equations and docs/model.md (errata applied), not from the
Rust code's logarithmic forms: direct Hertz/Roelands/Bair-Winer formulas, Moes' eq. 12 with
E' -> E'*x1, P -> P*x1 for the fluid's share x1 = 1/gamma1 (eq. 13), eq. 19 for the asperity
share x2 = 1 - x1, the Greenwood-Williamson integral F_3/2 by quadrature
(scipy.integrate.quad), and the load sharing by Brent's method (scipy.optimize.brentq) in the
logit y = ln(x1/x2). It is the "SciPy-style per-point loop" of the benchmark, and the
independent check of the package to ~1e-9 (python/tests/test_independent.py).
"""

from __future__ import annotations

import math

import numpy as np
from scipy.integrate import quad
from scipy.optimize import brentq

import pinjoint

A1, A2, A3, A4 = 1.558, 0.0337, -0.442, -1.7  # Gelinck-Schipper (eq. 18)
_G52 = math.gamma(2.5)


def ln_f32(t: float) -> float:
    """ln F_3/2(t), F_n(t) = (2 pi)^-1/2 int_t^inf (s - t)^n exp(-s^2/2) ds, by quadrature of
    int_0^inf v^1.5 exp(-v^2/2 - v t) dv (the e^{-t^2/2} factor kept out, so no underflow)."""
    if t > 8.0:
        # Substitute v = w/t: int = t^-2.5 int_0^inf w^1.5 exp(-w - w^2/(2 t^2)) dw.
        val, _ = quad(lambda w: w**1.5 * math.exp(-w - w * w / (2 * t * t)), 0, np.inf, epsabs=0, epsrel=1e-13, limit=200)
        ln_int = math.log(val) - 2.5 * math.log(t)
    else:
        # Peak of the integrand near v = max(0, -t) + O(1); split there for accuracy.
        c = max(0.0, -t)
        f = lambda v: v**1.5 * math.exp(-0.5 * v * v - v * t - (0.5 * c * c))  # scaled by e^{-c^2/2}
        v1, _ = quad(f, 0, c + 1.0, epsabs=0, epsrel=1e-13, limit=200)
        v2, _ = quad(f, c + 1.0, np.inf, epsabs=0, epsrel=1e-13, limit=200)
        ln_int = math.log(v1 + v2) + 0.5 * c * c
    return -0.5 * t * t + ln_int - 0.5 * math.log(2 * math.pi)


def ln_moes_h(ln_m: float, ln_l: float) -> float:
    """ln of Moes' dimensionless central film H_C(M, L), eq. 12:
    H = [(H_RI^(7/3) + H_EI^(7/3))^(3s/7) + (H_RP^(-7/2) + H_EP^(-7/2))^(-2s/7)]^(1/s),
    s = (7 + 8 exp(-2 H_EI/H_RI))/5, with the sums taken as logaddexp (no under/overflow)."""
    ln_hri, ln_hei = math.log(3.0) - ln_m, math.log(2.621) - 0.2 * ln_m
    ln_hrp, ln_hep = math.log(1.287) + 2 / 3 * ln_l, math.log(1.311) - 0.125 * ln_m + 0.75 * ln_l
    s = (7 + 8 * math.exp(-2 * math.exp(ln_hei - ln_hri))) / 5
    first = np.logaddexp(7 / 3 * ln_hri, 7 / 3 * ln_hei)
    second = np.logaddexp(-3.5 * ln_hrp, -3.5 * ln_hep)
    return float(np.logaddexp(3 * s / 7 * first, -2 * s / 7 * second)) / s


class ReferenceJoint:
    """The model at one point at a time (plain floats)."""

    def __init__(self, params: pinjoint.Params | None = None):
        p = params or pinjoint.default_params()
        g = lambda k: p[k]
        self.R, self.Rb, self.B = g("geometry.pin_radius"), g("geometry.bush_radius"), g("geometry.bush_length")
        E, nu = g("materials.pin_elastic_modulus"), g("materials.pin_poisson_ratio")
        Eb, nub = g("materials.bush_elastic_modulus"), g("materials.bush_poisson_ratio")
        self.n, self.beta = g("surface.asperity_density"), g("surface.asperity_radius")
        self.sig_s, self.dd = g("surface.summit_height_std"), g("surface.summit_mean_plane_offset")
        self.rough = math.hypot(g("surface.pin_rms_roughness"), g("surface.bush_rms_roughness"))
        self.eta0, self.eta_inf = g("lubricant.viscosity"), g("lubricant.roelands_viscosity_limit")
        self.cp, self.Z = g("lubricant.roelands_pressure_constant"), g("lubricant.roelands_index")
        self.alpha = g("lubricant.pressure_viscosity_coefficient")
        self.tau0, self.beta0 = g("lubricant.limiting_shear_stress"), g("lubricant.limiting_shear_stress_slope")
        self.mu_c = g("friction.boundary_friction_coefficient")
        self.Rr = self.R * self.Rb / (self.Rb - self.R)  # R'
        self.Ee = 2 / ((1 - nu * nu) / E + (1 - nub * nub) / Eb)  # E', plus sign (erratum 1)

    def point(self, P: float, omega: float) -> dict:
        R, B, Rr, Ee = self.R, self.B, self.Rr, self.Ee
        a = math.sqrt(8 * P * Rr / (math.pi * Ee * B))
        pm = P / (2 * a * B)
        eta = self.eta0 * math.exp(math.log(self.eta_inf / self.eta0) * (1 - (1 + pm / self.cp) ** self.Z))
        tau = self.tau0 + self.beta0 * pm
        u = abs(omega) * R
        W = P / (Ee * Rr * B)
        lnC = math.log(2 * math.sqrt(2 * math.pi) / 3) + 0.5 * math.log(B * Rr * Ee / P) + math.log(self.n) \
            + 0.5 * math.log(self.beta) + 1.5 * math.log(self.sig_s)
        lnK = math.log(A1 * self.n**A2 * Rr ** (1.5 * A2 - A3) * self.beta ** (0.5 * A2) * self.sig_s**A3) + (A2 - A3) * math.log(W)

        def ln_rhs(ln_x2):  # ln[x2 (1 + (K x2^-a2)^a4)^(1/a4)], eq. 19
            return ln_x2 + np.logaddexp(0.0, A4 * (lnK - A2 * ln_x2)) / A4

        if u == 0.0:
            x1, x2 = 0.0, 1.0
            target = ln_rhs(0.0) - lnC
            t = brentq(lambda t: ln_f32(t) - target, -20.0, 40.0, xtol=1e-15, rtol=1e-15, maxiter=500)
            h = self.dd + t * self.sig_s
            mu = self.mu_c
        else:
            U = self.eta0 * u / (Ee * Rr)
            ln_M, ln_L = math.log(W) - 0.5 * math.log(U), math.log(self.alpha * Ee) + 0.25 * math.log(U)

            def film(ln_x1):  # eq. 13: eq. 12 with E' -> E' x1, P -> P x1 (so U -> U/x1, G -> G x1)
                return Rr * math.exp(ln_moes_h(ln_M + 0.5 * ln_x1, ln_L + 0.75 * ln_x1) + 0.5 * (math.log(U) - ln_x1))

            def resid(y):
                ln_x1, ln_x2 = -np.logaddexp(0.0, -y), -np.logaddexp(0.0, y)
                t = (film(ln_x1) - self.dd) / self.sig_s
                return ln_f32(t) - (ln_rhs(ln_x2) - lnC)

            lo, hi = -4.0, 4.0
            while resid(lo) > 0:
                lo *= 2
            while resid(hi) < 0:
                hi *= 2
            y = brentq(resid, lo, hi, xtol=1e-13, rtol=1e-15, maxiter=500)
            ln_x1, ln_x2 = -float(np.logaddexp(0.0, -y)), -float(np.logaddexp(0.0, y))
            x1, x2 = math.exp(ln_x1), math.exp(ln_x2)
            h = film(ln_x1)
            mu = tau / pm * -math.expm1(-eta * u / (tau * h)) + self.mu_c * x2
        PL = P / (2 * R * B)
        S = self.eta0 * abs(omega) / (2 * math.pi * PL) * (R / (self.Rb - self.R)) ** 2
        regime = "boundary" if x1 < 0.01 else ("full-film" if x2 < 0.01 else "mixed")
        return {
            "friction_coefficient": mu, "torque": mu * R * P, "film_thickness": h, "lambda_ratio": h / self.rough,
            "fluid_load_fraction": x1, "asperity_load_fraction": x2, "mean_pressure": pm, "contact_half_width": a,
            "sommerfeld_number": S, "regime": regime,
        }

    def evaluate(self, loads, speeds) -> dict:
        """The per-point loop over arrays (broadcast, flattened)."""
        l, w = np.broadcast_arrays(np.asarray(loads, float), np.asarray(speeds, float))
        rows = [self.point(float(a), float(b)) for a, b in zip(l.ravel(), w.ravel())]
        return {k: np.array([r[k] for r in rows]).reshape(l.shape) for k in rows[0]}
