"""The Joint class: the model over NumPy arrays."""

from __future__ import annotations

from typing import Any, Dict, Optional, Tuple

import numpy as np

from ._coerce import ParamsLike, as_float_array, as_params, short
from ._native import DEFAULT_ENVELOPE as _SERVICE_ENVELOPE
from ._native import PAPER_ENVELOPE as _PAPER_ENVELOPE
from ._native import REGIMES, VALIDITIES, Params, _Joint

#: Default envelope of the table/boundary/auto levels (Joint and PreslidingBatch): loads
#: 1-100 kN, speed magnitudes 0.01-100 rad/s, and at the table level the speeds below, down to
#: rest (the library's Envelope::SERVICE: light loads to the paper's joint's load edge, 96.7 kN).
#: Its table at the paper's joint: ~13 MiB, built in ~0.2 s at 20-120 C. The PinJoint FMU's
#: default envelope parameters are narrower (5-60 kN, 0.01-10 rad/s).
DEFAULT_ENVELOPE: Tuple[float, float, float, float] = tuple(_SERVICE_ENVELOPE)

#: Default envelope for the paper's model (``model.paper``): the paper's rig region, 5-60 kN
#: and 0.01-10 rad/s (its line-contact film passes the clearance at light loads and high
#: speeds, at 1 kN and 26 rad/s already, where no table could be built).
PAPER_ENVELOPE: Tuple[float, float, float, float] = tuple(_PAPER_ENVELOPE)


def default_envelope(*params: Params) -> Tuple[float, float, float, float]:
    """The default envelope for these parameter sets: PAPER_ENVELOPE if any is the paper's
    model, else DEFAULT_ENVELOPE (the library's Envelope::default_for_all)."""
    return PAPER_ENVELOPE if any(p["model.paper"] != 0.0 for p in params) else DEFAULT_ENVELOPE

_REGIME_NAMES = np.array(REGIMES)
_VALIDITY_NAMES = np.array(VALIDITIES)


def default_params() -> Params:
    """The paper's joint: Tables 1-3 and mu_c = 0.12 (section 3.1), in SI units."""
    return Params()


class Joint:
    """The pin joint's friction model, evaluated over NumPy arrays.

    Joint(params=None, fidelity="full", tolerance=1e-4, envelope=None)

    params     None (the paper's joint), a pinjoint.Params, a dict with the parameter
               file's keys ({"geometry": {"pin_radius": 0.028}} or
               {"geometry.pin_radius": 0.028}), or the path of a TOML parameter file.
               Validated: an unknown key, a non-finite or out-of-range value raises
               ValueError naming the parameter, its value and unit.
    fidelity   "full" (the complete load-sharing solve, the default), "table" (the
               Stribeck map tabulated over the envelope to `tolerance`), "boundary"
               (mu = mu_c) or "auto" (the cheapest level within `tolerance`).
    tolerance  largest relative error accepted in mu, torque and h_c (absolute in the
               load shares) for table, boundary and auto; dimensionless, > 0.
    envelope   (load_min, load_max, speed_min, speed_max) in N and rad/s: where the table
               and boundary levels answer. Default DEFAULT_ENVELOPE (1-100 kN,
               0.01-100 rad/s; PAPER_ENVELOPE, 5-60 kN and 0.01-10 rad/s, for the
               paper's model). Points outside it are answered by the complete solve,
               as at "full" (counted in `fallbacks`).

    The model: Greenwood-Williamson asperity contact, Moes' central film thickness scaled
    by the load-sharing factors gamma1/gamma2, Roelands viscosity and Bair-Winer limiting
    shear give the friction coefficient mu (eq. 10) and the torque T = mu*R*P (eq. 11),
    its magnitude; it acts against the motion. The model depends on |speed|. At speed 0,
    mu = mu_c exactly. The regime names the negligible carrier: "boundary" when the fluid
    carries under 1 % of the load, "full-film" when the asperities carry under 1 %,
    "mixed" otherwise.

    evaluate(load, speed) broadcasts its two inputs (NumPy rules) and returns a dict of
    arrays of the broadcast shape with the columns of `pinjoint sweep`:
    load (N), speed (rad/s), friction_coefficient (-), torque (N*m), film_thickness (m,
    central h_c), lambda_ratio (-), fluid_load_fraction (1/gamma1), asperity_load_fraction
    (1/gamma2), mean_pressure (Pa), contact_half_width (m), sommerfeld_number (-),
    regime (strings), min_film_thickness (m), min_lambda_ratio (-) and validity (strings:
    "checked" inside the paper's rig conditions, 5-60 kN, |speed|*R up to the 1 Hz +-40 deg
    stroke's peak, 15-25 C; "extrapolation" outside them; "known-wrong" below 0 C, where
    the model's mu and torque are too low: no grease yield stress; "outside" past the model's
    assumptions: |load| above `load_edge`, where the Hertz half-width of eq. 6 reaches the pin
    radius, or the temperature above grease.upper_service_temperature, 394.15 K by default;
    still answered, continuous across the edge). At fidelity "full" each number equals the Rust library's (and the CLI
    sweep's) bit for bit. The GIL is released and large arrays use every core (rayon; set
    RAYON_NUM_THREADS to limit it).

    at_temperature(T) is this joint at lubricant temperature T (K): the same numbers as
    Joint(params with lubricant.temperature = T, ...) bit for bit, at the cost of a few
    logarithms at "full" (a table or boundary level is built and measured again there).

    A Joint pickles (its parameters and fidelity settings; the rebuilt joint gives
    bit-identical results), so it travels to multiprocessing and Dask workers.

    >>> joint = Joint()
    >>> joint.evaluate(20e3, 0.2)["friction_coefficient"]      # 0-d array
    >>> out = joint.evaluate(np.linspace(5e3, 60e3, 12)[:, None], np.logspace(-2, 2, 50))
    >>> out["torque"].shape
    (12, 50)
    """

    __slots__ = ("_params", "_fidelity", "_tolerance", "_envelope", "_native")

    def __init__(
        self,
        params: ParamsLike = None,
        fidelity: str = "full",
        tolerance: float = 1e-4,
        envelope: Optional[Tuple[float, float, float, float]] = None,
    ) -> None:
        p = as_params(params)
        if not isinstance(fidelity, str):
            raise TypeError(f"fidelity must be a string (full, table, boundary or auto), not {type(fidelity).__name__}")
        env = default_envelope(p) if envelope is None else tuple(float(x) for x in envelope)
        if len(env) != 4:
            raise ValueError(f"envelope must be (load_min N, load_max N, speed_min rad/s, speed_max rad/s), got {short(envelope)}")
        self._native = _Joint(p, fidelity, float(tolerance), env)
        self._params = p
        self._fidelity = fidelity.strip().lower()
        self._tolerance = float(tolerance)
        self._envelope = env

    @property
    def params(self) -> Params:
        """The validated parameter set."""
        return self._params

    @property
    def fidelity(self) -> str:
        """The fidelity level asked for: full, table, boundary or auto."""
        return self._fidelity

    @property
    def level(self) -> str:
        """The level in use: full, table or boundary (what auto picked)."""
        return self._native.chosen

    @property
    def tolerance(self) -> float:
        """The tolerance asked for (relative in mu, torque, h_c)."""
        return self._tolerance

    @property
    def envelope(self) -> Tuple[float, float, float, float]:
        """(load_min N, load_max N, speed_min rad/s, speed_max rad/s) of the table/boundary level."""
        return self._envelope  # type: ignore[return-value]

    @property
    def error_bound(self) -> float:
        """The measured error bound of the level in use inside the envelope (full: the solver's)."""
        return self._native.error_bound

    @property
    def fallbacks(self) -> int:
        """Points so far answered by the full solve because they were outside the envelope."""
        return self._native.fallbacks

    @property
    def load_edge(self) -> float:
        """The declared load capacity (N): the load at which the Hertz half-width of eq. 6
        reaches the pin radius, pi E' B R^2/(8 R') (96.7 kN for the paper's joint). Above it the
        answers are flagged "outside" (beyond the model's assumptions), up to `capacity`."""
        return self._native.load_edge

    @property
    def capacity(self) -> float:
        """The largest load (N) the asperity model can take for these parameters: refused at and
        beyond it. The declared load capacity is `load_edge` (answers above it are "outside")."""
        return self._native.capacity

    def evaluate(self, load: Any, speed: Any, errors: str = "raise") -> Dict[str, np.ndarray]:
        """The model at every (load, speed) pair, NumPy-broadcast.

        load   N, a magnitude: a negative value is taken as |load| (-P gives the answer at
               +P); |load| must be > 0 and below `capacity`. Scalar, list or array of
               real numbers.
        speed  rad/s, finite (the angular velocity; the model uses its magnitude).

        Integer and floating dtypes (float16/32/64, any int) are accepted and converted to
        float64; bool, complex, string and object arrays are a TypeError. Shapes that do not
        broadcast are a ValueError. A point the model cannot take (NaN or infinite input,
        load = 0, |load| beyond the asperity model's capacity, a fluid film thicker than the
        diametral clearance 2(R_b - R)) raises ValueError naming the
        index (in the broadcast shape), the quantity, its value and unit, for the first such
        point in C order; nothing is returned then (``errors="raise"``, the default).
        With ``errors="nan"`` every other point is answered (bit for bit as alone) and the points
        the model cannot take are NaN in every float column (load and speed keep the inputs),
        with regime and validity "refused"; a shape or type error still raises.

        Returns a dict of arrays of the broadcast shape: load, speed, then RESULT_COLUMNS
        (float64, SI units; regime as strings "boundary", "mixed", "full-film"; validity as
        strings "checked", "extrapolation", "known-wrong", "outside").
        """
        if errors not in ("raise", "nan"):
            raise ValueError(f'errors = {errors!r} is not a choice: it must be "raise" or "nan"')
        lo = as_float_array("load", "N", load)
        sp = as_float_array("speed", "rad/s", speed)
        try:
            lo_b, sp_b = np.broadcast_arrays(lo, sp)
        except ValueError:
            raise ValueError(
                f"load (shape {lo.shape}) and speed (shape {sp.shape}) do not broadcast to one shape"
            ) from None
        shape = lo_b.shape
        flat_l = np.ascontiguousarray(lo_b).reshape(-1)
        flat_s = np.ascontiguousarray(sp_b).reshape(-1)
        if errors == "raise":
            cols, codes = self._native.evaluate_flat(flat_l, flat_s, list(shape))
            refused = None
        else:
            cols, codes, refused = self._evaluate_or_refuse(flat_l, flat_s)
        out: Dict[str, np.ndarray] = {
            "load": flat_l.copy().reshape(shape),
            "speed": flat_s.copy().reshape(shape),
        }
        for name, arr in cols.items():
            out[name] = arr.reshape(shape)
        regime = _REGIME_NAMES[codes & 3].astype(object)
        validity = _VALIDITY_NAMES[codes >> 2].astype(object)
        if refused is not None and refused.any():
            regime[refused] = "refused"
            validity[refused] = "refused"
        out["regime"] = regime.astype(str).reshape(shape)
        out["validity"] = validity.astype(str).reshape(shape)
        return out

    def _evaluate_or_refuse(self, flat_l: np.ndarray, flat_s: np.ndarray) -> Any:
        """evaluate_flat over the flat arrays, answering every point it can: a failing block is
        halved until the failing points are single (O(bad points * log n) extra calls), those
        are NaN. Returns (columns, codes, refused mask)."""
        n = flat_l.size
        refused = np.zeros(n, dtype=bool)
        cols: Dict[str, np.ndarray] = {}
        codes = np.zeros(n, dtype=np.int64)
        # Points that cannot be taken whatever the model: not finite, zero load.
        bad = ~(np.isfinite(flat_l) & np.isfinite(flat_s)) | (flat_l == 0.0)
        refused |= bad
        blocks = [(0, n)]
        while blocks:
            a, b = blocks.pop()
            idx = np.nonzero(~bad[a:b])[0] + a
            if idx.size == 0:
                continue
            try:
                c, k = self._native.evaluate_flat(flat_l[idx], flat_s[idx], [idx.size])
            except ValueError:
                if idx.size == 1:
                    refused[idx] = True
                else:
                    mid = a + (b - a) // 2
                    blocks += [(mid, b), (a, mid)]
                continue
            for name, arr in c.items():
                col = cols.get(name)
                if col is None:
                    col = cols[name] = np.full(n, np.nan, dtype=arr.dtype if arr.dtype.kind == "f" else np.float64)
                col[idx] = arr
            codes[idx] = np.asarray(k)
        if not cols:
            # Every point refused: the columns' names from a point the model takes.
            c, _ = self._native.evaluate_flat(np.array([20e3]), np.array([1.0]), [1])
            cols = {name: np.full(n, np.nan) for name in c}
        return cols, codes, refused

    def at_temperature(self, temperature: float) -> "Joint":
        """This joint at lubricant temperature `temperature` (K), same fidelity settings.

        Bit for bit the Joint built from the parameters with lubricant.temperature =
        `temperature`; at fidelity "full" it costs a few logarithms (the solve's start table
        and everything independent of temperature are shared), a table or boundary level is
        built and measured again at the new temperature. A temperature outside
        (138.15, 673.15] K, NaN or infinite raises ValueError naming it.
        """
        t = float(temperature)
        p = self._params.with_values({"lubricant.temperature": t})
        j = object.__new__(Joint)
        j._native = self._native.at_temperature(t)
        j._params = p
        j._fidelity = self._fidelity
        j._tolerance = self._tolerance
        j._envelope = self._envelope
        return j

    def __reduce__(self):
        return (_rebuild, (self._params, self._fidelity, self._tolerance, self._envelope))

    def __repr__(self) -> str:
        extra = ""
        if self._fidelity != "full":
            extra = f", fidelity={self._fidelity!r}, tolerance={self._tolerance!r}, envelope={self._envelope!r}"
        return f"pinjoint.Joint({self._params!r}{extra})"


def _rebuild(params: Params, fidelity: str, tolerance: float, envelope: Tuple[float, float, float, float]) -> Joint:
    return Joint(params, fidelity, tolerance, envelope)
