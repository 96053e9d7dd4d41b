"""calibrate: fit the model to measured torque cycles (``pinjoint calibrate`` in Python)."""

from __future__ import annotations

import json
import os
from typing import Any, Dict, List, Mapping, Optional, Sequence, Union

import numpy as np

from ._coerce import ParamsLike, as_float_array, short
from ._native import MU_C, Params, _calibrate

#: The keys of ``pinjoint calibrate --json``, in its order.
JSON_KEYS = (
    "parameters",
    "rms_residual",
    "points_used",
    "points_excluded",
    "torque_offset",
    "inertia",
    "inertia_fitted",
    "inertia_estimate",
    "temperatures",
    "samples_read",
    "block_length",
    "warnings",
)

_COLUMNS = {"time": "s", "angle": "rad", "angular_velocity": "rad/s", "torque": "N.m", "load": "N", "temperature": "K"}

#: A temperature below this (K) is refused as degrees Celsius given as kelvin (the library's
#: bound, pinjoint_calibrate::record::CELSIUS_SUSPECT).
CELSIUS_SUSPECT = 150.0

#: Largest difference (K) between a record's temperature column and ``temperature=`` beside it.
TEMPERATURE_AGREEMENT = 1.0


class Calibration(dict):
    """The result of :func:`calibrate`: a dict holding the content of ``pinjoint calibrate
    --json`` and more, plus the calibrated parameter set.

    Keys as in the CLI's JSON (values bit for bit equal to it):
      parameters       {key: {"value", "standard_error", "ci95": [lo, hi]}}, mu_c first
      rms_residual     N*m, over the samples used
      points_used, points_excluded
      torque_offset    {"value", "standard_error", "ci95"} of T0 (N*m), when fitted
      inertia          the rotating inertia J used (kg*m^2): fitted, or given
      inertia_fitted   True when J was fitted (no ``inertia`` and no ``rig.inertia`` in params)
      inertia_estimate {"value", "standard_error", "ci95"} of J (kg*m^2), when fitted
      temperatures     the records' distinct temperatures (K, ascending; empty when none given)
      samples_read     samples in the records; block_length: the block averaging of long
                       records to the sample budget (1: none)
      warnings         identifiability and interval warnings (list of str)
    and besides:
      excluded         per record: record, speed_threshold (rad/s), reversals (s), windows
                       [{start, end (s), reason, samples}], low_speed, settling, used
      estimate_details per key (and torque_offset): unit, initial, standard_error_iid,
                       standard_error_cluster, bootstrap_ci95
      strokes, dof, condition, correlation_keys, correlation (rig.inertia among them when
      J is fitted), half_widths (samples), evaluations
      series           per record: time, angle, angular_velocity, load, torque (measured),
                       inertia_torque, fitted_torque (N*m) and used, as arrays

    ``result.params`` is the complete calibrated :class:`Params`; ``result.to_json()`` the
    CLI's JSON text (same keys and numbers).
    """

    params: Params

    def __init__(self, content: Dict[str, Any], params: Params) -> None:
        super().__init__(content)
        self.params = params

    def to_json(self) -> str:
        """The JSON object ``pinjoint calibrate --json`` prints, for the same fit."""
        return json.dumps({k: self[k] for k in JSON_KEYS if k in self})

    def __reduce__(self) -> Any:
        return (Calibration, (dict(self), self.params))


def _column(rec: Any, name: str) -> Any:
    """rec[name] for a mapping (anything with `in` and `[]`), else getattr; None if absent."""
    if hasattr(rec, "__getitem__") and not isinstance(rec, (str, bytes, np.ndarray)):
        try:
            if name in rec:
                return rec[name]
        except (TypeError, KeyError):
            pass
    return getattr(rec, name, None)


def _record(i: int, rec: Any, given_temperature: Optional[float] = None) -> tuple:
    name = _column(rec, "name")
    name = str(i) if name is None else str(name)
    where = f"record {name}"

    def array(col: str, required: bool) -> Optional[np.ndarray]:
        v = _column(rec, col)
        if v is None:
            if required:
                raise ValueError(f"{where}: has no `{col}` ({_COLUMNS[col]}) column")
            return None
        a = as_float_array(f"{where}: {col}", _COLUMNS[col], v)
        if col in ("load", "temperature") and a.ndim == 0:
            return a
        if a.ndim != 1:
            raise ValueError(f"{where}: {col} ({_COLUMNS[col]}) must be one-dimensional, got shape {a.shape}")
        return np.ascontiguousarray(a)

    time = array("time", True)
    torque = array("torque", True)
    angle = array("angle", False)
    omega = array("angular_velocity", False)
    if angle is None and omega is None:
        raise ValueError(f"{where}: needs an `angle` (rad) or an `angular_velocity` (rad/s) column")
    load = array("load", True)
    if load.ndim == 0:
        load = np.full(time.shape, float(load))
    temperature = array("temperature", False)
    if temperature is not None and given_temperature is not None:
        column = np.atleast_1d(temperature)
        bad = np.nonzero(np.abs(column - given_temperature) > TEMPERATURE_AGREEMENT)[0]
        if bad.size:
            t = float(column[bad[0]])
            raise ValueError(
                f"{where}: temperature = {short(t)} K disagrees with temperature={short(given_temperature)} K given beside it: drop one"
            )
    if temperature is None and given_temperature is not None:
        temperature = np.asarray(given_temperature, dtype=np.float64)
    if temperature is not None and temperature.ndim == 0:
        temperature = np.full(time.shape, float(temperature))
    return (name, time, angle, omega, torque, load, temperature)


def _temperatures(temperature: Any, n: int) -> List[Optional[float]]:
    """``temperature=`` as one value per record (K), checked as ``--temperature`` is."""
    if temperature is None:
        return [None] * n
    values = [temperature] if np.ndim(temperature) == 0 else list(temperature)
    out = []
    for v in values:
        if isinstance(v, bool) or not isinstance(v, (int, float, np.integer, np.floating)):
            raise TypeError(f"temperature (K) must be a number or one number per record, got {short(v)}")
        v = float(v)
        if not np.isfinite(v):
            raise ValueError(f"temperature = {short(v)} K is invalid: it must be a finite number of kelvin")
        if v < CELSIUS_SUSPECT:
            hint = (
                f"a temperature must be > 0 K (kelvin? as degrees Celsius it would be {short(v + 273.15)} K)"
                if v <= 0
                else f"below {short(CELSIUS_SUSPECT)} K, colder than any pin joint runs: kelvin? (as degrees Celsius it would be {short(v + 273.15)} K)"
            )
            raise ValueError(f"temperature = {short(v)} K is invalid: {hint}")
        out.append(v)
    if len(out) == 1:
        return out * n
    if len(out) != n:
        raise ValueError(f"{len(out)} temperature values for {n} records: give one temperature for all, or one per record in order")
    return out


def _count(name: str, value: Any, allow_none: bool = True) -> Optional[int]:
    if value is None and allow_none:
        return None
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
        raise TypeError(f"{name} must be an integer, got {short(value)}")
    if value < 0:
        raise ValueError(f"{name} = {value} is invalid: it must be >= 0")
    return int(value)


def calibrate(
    records: Union[Sequence[Any], Mapping[str, Any]],
    params: ParamsLike = None,
    fit: Union[str, Sequence[str]] = (MU_C,),
    model: str = "core",
    *,
    temperature: Any = None,
    inertia: Optional[float] = None,
    fit_offset: bool = True,
    speed_fraction: Optional[float] = None,
    settle_time: Optional[float] = None,
    half_width: Optional[int] = None,
    resamples: Optional[int] = None,
    seed: Optional[int] = None,
    max_samples: Optional[int] = None,
) -> Calibration:
    """Fit the model's parameters to measured torque cycles, as ``pinjoint calibrate`` does.

    records     a list of records (one per test; several loads and frequencies are fitted
                jointly), or one record. A record is a mapping (or any object with
                these attributes) of 1-D arrays with the columns of the CLI's CSV: ``time``
                (s, increasing), ``angle`` (rad) and/or ``angular_velocity`` (rad/s),
                ``torque`` (N*m, the recorded actuator torque, positive in the direction of
                motion, as ``simulate_cycle``'s torque) and ``load`` (N, an array or one
                number); optional ``name`` for messages. Other columns are ignored, so
                ``dict(pinjoint.simulate_cycle(...), load=20e3)`` is a record. An optional
                ``temperature`` (K, an array or one number) evaluates the record by the joint
                at its lubricant temperature (``--temperature``).
    params      start values and fixed parameters: None (the paper's), a Params, a mapping
                or a TOML file; a file's or mapping's ``rig.inertia`` is the given inertia
                when ``inertia`` is None (as with ``--params``)
    fit         the parameter keys fitted (``section.key``); mu_c,
                ``friction.boundary_friction_coefficient``, is always fitted (linear least
                squares on the model's shape); any other key is fitted by Levenberg-Marquardt
                (``--fit``). A comma-separated string works too.
    model       "core": the quasi-static model T = J*alpha + sign(w)*mu*R*P + T0 (the only
                one the calibration library offers; fitting through the rig simulation is
                not available)
    temperature the lubricant temperature (K) of records without a ``temperature`` column: one
                number for all, or one per record (``--temperature``); a column beside it must
                agree within 1 K. With records at 3 or more temperatures and no key named
                besides mu_c, the grease's parameters are fitted too (each dropped with a
                warning when the records cannot determine it); fewer: mu_c (and the named keys)
    inertia     J, kg*m^2, given: J*alpha is subtracted (``--inertia``). Default: params'
                rig.inertia if it has one, else J is fitted with mu_c and T0 (linear least
                squares; result["inertia_estimate"] holds it with its interval)
    fit_offset  fit a torque-sensor offset T0 (default True; ``--no-offset`` is False)
    speed_fraction, settle_time   the exclusion rule (``--speed-fraction``, default 0.3, and
                ``--settle-time``, s, default 0.1): samples slower than the fraction of the
                record's peak speed, and the first settle_time after each reversal, are left out
    half_width  Savitzky-Golay half-width in samples (default 1/40 of a stroke, >= 3)
    resamples   bootstrap resamples over strokes (default 1000; 0: none); seed its seed
    max_samples the most samples, all records together, that enter the fit (``--max-samples``,
                default 1e6, at least 1000); longer records are averaged in blocks of
                m = ceil(samples / max_samples) consecutive samples straight from the arrays

    Returns a :class:`Calibration` (a dict with the CLI's ``--json`` keys, the excluded
    windows, warnings and fitted series; ``.params`` the calibrated Params). A bad record
    or option raises ValueError naming the record, quantity, value, unit and sample index.
    The GIL is released during the fit.
    """
    if model != "core":
        raise ValueError(
            f"model = {short(model)} is not available: the calibration library fits the quasi-static model only (model='core')"
        )
    if isinstance(records, Mapping) or not isinstance(records, (list, tuple)):
        records = [records]
    if len(records) == 0:
        raise ValueError("no records to fit")
    temps = _temperatures(temperature, len(records))
    recs = [_record(i, r, t) for i, (r, t) in enumerate(zip(records, temps))]
    keys = [k.strip() for k in (fit.split(",") if isinstance(fit, str) else list(fit))]
    keys = [k for k in keys if k]
    if MU_C not in keys:
        raise ValueError(f"fit = {short(list(keys))} does not include {MU_C}: mu_c is always fitted; add it")
    if isinstance(params, os.PathLike):
        params = os.fspath(params)

    def real(name: str, unit: str, v: Any) -> Optional[float]:
        if v is None:
            return None
        if isinstance(v, bool) or not isinstance(v, (int, float, np.integer, np.floating)):
            raise TypeError(f"{name} ({unit}) must be a number, got {short(v)}")
        return float(v)

    j = real("inertia", "kg*m^2", inertia)
    sf = real("speed_fraction", "1", speed_fraction)
    st = real("settle_time", "s", settle_time)
    content, calibrated = _calibrate(
        recs,
        params,
        keys,
        j,
        bool(fit_offset),
        sf,
        st,
        _count("half_width", half_width),
        _count("resamples", resamples),
        _count("seed", seed),
        _count("max_samples", max_samples),
    )
    return Calibration(content, calibrated)
