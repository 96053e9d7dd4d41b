"""Scenes built on ``PreslidingBatch``: the cold-day free-fall extension of a main landing gear,
n scenes stepped together, and the uncertainty of its answer (time to lock, lock margin) over
scattered parameters.

The free-fall scene (the project's shared specification; every number ILLUSTRATIVE of a
narrow-body main gear, assumed, not from a specific aircraft): the leg is released from the up
position and swings down about its trunnion under gravity, slowed by the retraction actuator
throttled as a damper; near the down position a lock spring drives the lock links over centre.
CS 25.729 asks the analysis to include the mechanism's friction and the temperature range.

Equations (phi the leg's angle from down-locked, omega = dphi/dt, positive = up):

* gravity  T_g = -m g l sin(phi);  damper  T_d = -c1 omega - c2 omega |omega|;
  lock spring  T_s = -T_l where phi < phi_e;
* trunnion friction  T_f = trunnion_joints x (the presliding joint's torque at phi, omega, the
  pin load P and the temperature), from ``PreslidingBatch`` (host_inertia = J / trunnion_joints,
  each commit with the step h: the presliding damping near critical, capped for this explicit
  host at h);
* pin load from the leg's dynamics, the cg at l(sin phi, -cos phi):
  a_cg = l [alpha (cos phi, sin phi) + omega^2 (-sin phi, cos phi)] with alpha of the previous
  step (0 at the first: lagged one step), F = m a_cg + (0, m g), P = trunnion_load_share |F|;
* semi-implicit Euler at step h: the joints' torque at (phi_n, omega_n, P_n, T) and their commit,
  alpha_n = (T_g + T_d + T_s + T_f)/J, omega_n+1 = omega_n + h alpha_n, phi_n+1 = phi_n + h omega_n+1;
* locked at the first step with phi_n+1 <= 0: time_to_lock = n h + h phi_n/(phi_n - phi_n+1) (linear
  interpolation inside the step), speed_at_lock = |omega_n+1|; not locked by end_time: inf and NaN;
* lock margin (static, at the lock) = lock_link_torque / (lock_link_pivots x T_break) - 1, T_break
  the joint's breakaway torque at lock_link_load and the temperature: its sliding torque as
  omega -> 0+, the larger of the values at omega = 0 and at BREAKAWAY_SPEED (with a grease
  model, its yield torque included);
* friction energy = sum over the steps of -T_f (phi_n+1 - phi_n), up to phi = 0 in the step that
  locks (J).

>>> from pinjoint import scenes
>>> out = scenes.free_fall(3, temperature=[293.15, 273.15, 253.15])
>>> out["time_to_lock"], out["lock_margin"]
"""

from __future__ import annotations

import dataclasses
import math
import re
from typing import Any, Dict, Mapping, Optional, Sequence, Tuple, Union

import numpy as np

from ._batch import PreslidingBatch
from ._coerce import short
from ._native import MU_C, Params


#: The angular velocity (rad/s) standing for omega -> 0+ in the breakaway torque: far below any
#: speed at which the film carries load in the joint model.
BREAKAWAY_SPEED = 1e-9


@dataclasses.dataclass(frozen=True)
class FreeFall:
    """The free-fall scene's parameters (SI units; defaults ILLUSTRATIVE, assumed)."""

    leg_mass: float = 600.0  #: m, kg: the leg (strut, wheels, brakes)
    cg_distance: float = 1.5  #: l, m: trunnion to centre of gravity
    inertia: float = 1500.0  #: J, kg*m^2 about the trunnion (>= m l^2)
    gravity: float = 9.81  #: g, m/s^2
    up_angle: float = 1.4  #: phi_up, rad: release angle
    damper_linear: float = 2000.0  #: c1, N*m*s/rad
    damper_quadratic: float = 4000.0  #: c2, N*m*s^2/rad^2
    lock_spring_angle: float = 0.087  #: phi_e, rad: the lock spring acts for phi < phi_e
    lock_spring_torque: float = 300.0  #: T_l, N*m
    trunnion_load_share: float = 0.5  #: each pin carries share x |F|
    trunnion_joints: int = 2  #: trunnion pins, each with the same friction torque
    lock_link_torque: float = 40.0  #: N*m: the lock spring's torque about the lock-link pivots
    lock_link_load: float = 1500.0  #: N: radial load on each lock-link pivot
    lock_link_pivots: int = 2  #: pivots the lock spring must turn
    temperature: float = 293.15  #: K: one temperature for the joints' grease (the damper's is not modelled)
    step: float = 1e-3  #: h, s
    end_time: float = 30.0  #: s: not locked if phi > 0 then

    def __post_init__(self) -> None:
        for f in dataclasses.fields(self):
            v = getattr(self, f.name)
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
                raise ValueError(f"scene {f.name} = {short(v)} is not a finite number")
        positive = ("leg_mass", "cg_distance", "inertia", "gravity", "up_angle", "step", "end_time", "trunnion_joints",
                    "lock_link_load", "lock_link_pivots", "temperature")
        for name in positive:
            if not getattr(self, name) > 0:
                raise ValueError(f"scene {name} = {short(getattr(self, name))} must be > 0")
        for name in ("damper_linear", "damper_quadratic", "lock_spring_angle", "lock_spring_torque", "trunnion_load_share", "lock_link_torque"):
            if getattr(self, name) < 0:
                raise ValueError(f"scene {name} = {short(getattr(self, name))} must be >= 0")

    def with_values(self, **values: Any) -> "FreeFall":
        """A copy with some values changed (validated)."""
        return dataclasses.replace(self, **values)


def free_fall(
    n: int = 1,
    scene: Optional[FreeFall] = None,
    params: Any = None,
    per_joint: Optional[Mapping[str, Any]] = None,
    temperature: Any = None,
    fidelity: str = "full",
    record: bool = False,
    **batch_options: Any,
) -> Dict[str, Any]:
    """n free-fall scenes stepped together (one ``PreslidingBatch`` of n trunnion joints).

    scene        FreeFall (default: the specification's defaults).
    params       the joints' parameter set (as ``PreslidingBatch``), shared by the scenes;
    per_joint    {parameter key: array (n,)}: per-scene values over it (e.g. sampled mu_c).
    temperature  K, a number or an array (n,); default scene.temperature.
    record       also return the time series (t, phi, omega, P, T_f as arrays (steps, n)).
    batch_options  more ``PreslidingBatch`` settings (presliding_angle, tolerance, envelope...).

    Returns a dict of arrays (n,): time_to_lock (s; inf: not locked by end_time),
    speed_at_lock (rad/s, |omega|; NaN if not locked), lock_margin (-), breakaway_torque (N*m,
    one lock-link pivot's), friction_energy (J, both trunnion pins, until the lock), locked
    (bool); with record=True also "series".
    """
    s = FreeFall() if scene is None else scene
    m, l, g, J, h = s.leg_mass, s.cg_distance, s.gravity, s.inertia, s.step
    temp = np.broadcast_to(np.asarray(s.temperature if temperature is None else temperature, dtype=np.float64), (n,)).copy()
    phi = np.full(n, float(s.up_angle))
    omega = np.zeros(n)
    alpha = np.zeros(n)
    batch = PreslidingBatch(n, params, per_joint=per_joint, host_inertia=J / s.trunnion_joints, fidelity=fidelity, angle=phi, **batch_options)
    # The breakaway torque: the sliding torque as omega -> 0+ (at rest and just above it: a
    # model whose rest point differs from its limit gives the larger).
    t_break = np.maximum(batch.sliding_torque(0.0, s.lock_link_load, temp), batch.sliding_torque(BREAKAWAY_SPEED, s.lock_link_load, temp))
    steps = int(round(s.end_time / h))
    t_lock = np.full(n, np.inf)
    w_lock = np.full(n, np.nan)
    energy = np.zeros(n)
    active = np.ones(n, dtype=bool)
    series = {"time": [], "angle": [], "angular_velocity": [], "load": [], "friction_torque": []} if record else None
    for k in range(steps):
        sn, cs = np.sin(phi), np.cos(phi)
        w2 = omega * omega
        fx = m * (l * (alpha * cs - w2 * sn))
        fy = m * (l * (alpha * sn + w2 * cs)) + m * g
        load = s.trunnion_load_share * np.hypot(fx, fy)
        tf = s.trunnion_joints * batch.step(phi, omega, load, temp, step=h)
        torque = -m * g * l * sn - s.damper_linear * omega - s.damper_quadratic * omega * np.abs(omega)
        torque = torque - np.where(phi < s.lock_spring_angle, s.lock_spring_torque, 0.0) + tf
        alpha_new = torque / J
        omega_new = omega + h * alpha_new
        phi_new = phi + h * omega_new
        if series is not None:
            series["time"].append(k * h)
            series["angle"].append(phi.copy())
            series["angular_velocity"].append(omega.copy())
            series["load"].append(load)
            series["friction_torque"].append(tf)
        newly = active & (phi_new <= 0.0)
        # The friction's work until the lock: over the whole step, or up to phi = 0 in the
        # step that locks.
        energy += np.where(active, -tf * (np.where(newly, 0.0, phi_new) - phi), 0.0)
        if newly.any():
            p0, p1 = phi[newly], phi_new[newly]
            t_lock[newly] = k * h + h * p0 / (p0 - p1)
            w_lock[newly] = np.abs(omega_new[newly])
            active &= ~newly
        # A locked scene's inputs stay as they were: its joint sees the same inputs each step
        # (the batch keeps its sliding torque: no solve).
        phi = np.where(active, phi_new, phi)
        omega = np.where(active, omega_new, omega)
        alpha = np.where(active, alpha_new, alpha)
        if not active.any():
            break
    out: Dict[str, Any] = {
        "time_to_lock": t_lock,
        "speed_at_lock": w_lock,
        "lock_margin": s.lock_link_torque / (s.lock_link_pivots * t_break) - 1.0,
        "breakaway_torque": t_break,
        "friction_energy": energy,
        "locked": np.isfinite(t_lock),
    }
    if series is not None:
        out["series"] = {"time": np.array(series["time"]), **{k: np.array(v) for k, v in series.items() if k != "time"}}
    return out


# ---------------------------------------------------------------------------------------------
# Parameter uncertainty

#: Scatter used when the caller gives none: mu_c uniform over 0.10-0.14 (the boundary friction
#: coefficient's spread across greases and batches, as examples/monte_carlo_dask.py), and a
#: log-normal scatter (sigma of ln) of the grease's rheology about its default, applied to the
#: keys the installed model has (none before the grease model; then they join without a change
#: here). Low-temperature torque tests scatter widely; these spreads are ASSUMED, not fitted.
DEFAULT_SCATTER: Dict[str, Tuple[str, float, float]] = {
    MU_C: ("uniform", 0.10, 0.14),
    "grease.yield_stress": ("lognormal", float("nan"), 0.3),
    "grease.consistency": ("lognormal", float("nan"), 0.3),
}

Distribution = Union[Tuple[str, float, float], str]


def parse_distribution(text: str) -> Tuple[str, Tuple[str, float, float]]:
    """``KEY=KIND:A,B`` (kind normal: mean, sd; lognormal: median (or "default"), sigma of ln;
    uniform: low, high) -> (key, (kind, a, b))."""
    m = re.fullmatch(r"\s*([A-Za-z_][\w.]*)\s*=\s*(normal|lognormal|uniform)\s*:\s*([^,]+),\s*([^,]+)\s*", text)
    if not m:
        raise ValueError(f"{short(text)} is not KEY=KIND:A,B with KIND normal, lognormal or uniform (e.g. {MU_C}=normal:0.12,0.01)")
    a = float("nan") if m.group(3).strip() == "default" else float(m.group(3))
    return m.group(1), (m.group(2), a, float(m.group(4)))


def _from_calibration(calibration: Mapping[str, Any]) -> Tuple[list, np.ndarray, np.ndarray]:
    """(keys, estimates, covariance) from a fit result (``pinjoint.calibrate``'s dict or
    ``pinjoint calibrate --json``): the parameters' values and standard errors with their
    correlation matrix (the torque offset and the inertia are not parameters of the joint)."""
    params = calibration["parameters"]
    keys = [k for k in params]
    est = np.array([float(params[k]["value"]) for k in keys])
    se = np.array([float(params[k]["standard_error"]) for k in keys])
    corr = np.eye(len(keys))
    ck = list(calibration.get("correlation_keys") or [])
    if ck:
        full = np.asarray(calibration["correlation"], dtype=np.float64)
        idx = [ck.index(k) for k in keys]
        corr = full[np.ix_(idx, idx)]
    return keys, est, corr * np.outer(se, se)


def sample_parameters(
    n: int,
    seed: int,
    calibration: Optional[Mapping[str, Any]] = None,
    estimates: Optional[Mapping[str, float]] = None,
    covariance: Any = None,
    distributions: Optional[Mapping[str, Distribution]] = None,
    base: Optional[Params] = None,
) -> Dict[str, np.ndarray]:
    """n samples of parameters by key, reproducible from ``seed``: {key: array (n,)}.

    * ``calibration``: a fit result (its estimates and covariance = standard errors x their
      correlation), sampled as a multivariate normal; or ``estimates`` ({key: value}) with
      ``covariance`` (matrix in the keys' order);
    * ``distributions``: {key: (kind, a, b) or "kind:a,b"} for further keys (normal mean, sd;
      lognormal median, sigma of ln, a NaN median = the base value; uniform low, high).
    * Neither: ``DEFAULT_SCATTER`` for the keys the model has.

    Any parameter file key works (``pinjoint.Params.keys()``); an unknown key is a ValueError.
    """
    rng = np.random.default_rng(seed)
    base = Params() if base is None else base
    known = set(Params.keys())
    out: Dict[str, np.ndarray] = {}
    if calibration is not None:
        keys, mean, cov = _from_calibration(calibration)
    elif estimates is not None:
        keys = list(estimates)
        mean = np.array([float(estimates[k]) for k in keys])
        cov = np.asarray(covariance, dtype=np.float64).reshape(len(keys), len(keys))
    else:
        keys, mean, cov = [], np.zeros(0), np.zeros((0, 0))
    for k in keys:
        if k not in known:
            raise ValueError(f"{short(k)} is not a parameter key (see pinjoint.param_table())")
    if keys:
        draws = rng.multivariate_normal(mean, cov, size=n, method="cholesky" if np.all(np.linalg.eigvalsh(cov) > 0) else "svd")
        for c, k in enumerate(keys):
            out[k] = draws[:, c].copy()
    if distributions is None and not keys:
        distributions = {k: v for k, v in DEFAULT_SCATTER.items() if k in known}
    for k, spec in (distributions or {}).items():
        if k in out:
            continue
        if k not in known:
            raise ValueError(f"{short(k)} is not a parameter key (see pinjoint.param_table())")
        if isinstance(spec, str):
            _, spec = parse_distribution(f"{k}={spec}")
        kind, a, b = spec
        if kind == "normal":
            out[k] = rng.normal(a, b, n)
        elif kind == "lognormal":
            med = base[k] if math.isnan(a) else a
            out[k] = med * np.exp(rng.normal(0.0, b, n))
        elif kind == "uniform":
            out[k] = rng.uniform(a, b, n)
        else:
            raise ValueError(f"distribution {short(kind)} of {k} is not normal, lognormal or uniform")
    return out


#: Percentiles the summaries report.
PERCENTILES = (1, 5, 25, 50, 75, 95, 99)


def percentiles(x: np.ndarray, q: Sequence[float] = PERCENTILES) -> Dict[float, float]:
    """Percentiles of ``x`` as observed values (no interpolation: an infinite time to lock,
    not locked, stays inf)."""
    return {float(p): float(v) for p, v in zip(q, np.percentile(np.asarray(x, dtype=np.float64), q, method="inverted_cdf"))}


def free_fall_chunk(scene: FreeFall, values: Mapping[str, np.ndarray], temperature: float, fidelity: str = "full", params: Any = None) -> Dict[str, np.ndarray]:
    """One task of an uncertainty study: the scenes of ``values`` (per-scene parameter values by
    key), stepped together. A function of its arguments alone (the same bits on any worker)."""
    n = len(next(iter(values.values()))) if values else 1
    out = free_fall(n, scene, params=params, per_joint=values or None, temperature=temperature, fidelity=fidelity)
    return {k: v for k, v in out.items() if k != "series"}
