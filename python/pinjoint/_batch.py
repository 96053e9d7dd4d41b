"""PreslidingBatch: n presliding joints stepped together over NumPy arrays (issue 30)."""

from __future__ import annotations

import numbers
from typing import Any, Mapping, Optional, Sequence, Tuple

import numpy as np

from ._coerce import ParamsLike, as_float_array, as_params, short
from ._joint import PAPER_ENVELOPE, default_envelope
from ._native import Params, _PreslidingBatch
from ._presliding import DEFAULT_PRESLIDING


def _is_switch(key: str) -> bool:
    """Whether parameter ``key`` is a switch (``model.paper``, ``grease.enabled``): a bool for
    ``Params``, 0 or 1 as a number."""
    try:
        Params({key: True})
    except Exception:  # noqa: BLE001 - a number (TypeError), or not a key (the library names it)
        return False
    return True


def _is_params_like(x: Any) -> bool:
    import os

    return x is None or isinstance(x, (Params, Mapping, str, os.PathLike))


class PreslidingBatch:
    """n presliding joints stepped together: bit for bit n ``pinjoint.Presliding`` objects
    (the PinJoint FMU's zero-velocity law, the same library code), over NumPy arrays of
    shape (n,), in one call per step on every core, without the GIL.

    PreslidingBatch(n, params=None, presliding_angle=1.5e-3, elastic_limit=0.95,
                    damping_time=0.01, host_inertia=None, fidelity="full", *, angle=0.0,
                    per_joint=None, tolerance=1e-4, envelope=None)

    n           the number of joints (>= 1).
    params      one parameter set for every joint (None, a Params, a mapping or a TOML
                path, as ``Joint``), or a sequence of n of them (one per joint).
    per_joint   {parameter key: array of shape (n,)}: per-joint values of any parameter
                file key (e.g. ``{"friction.boundary_friction_coefficient": mu}``) applied
                over ``params``; each joint's set is validated (an error names the joint).
                A switch (``model.paper``, ``grease.enabled``) takes True/False or 1/0.
    presliding_angle, elastic_limit, damping_time   the law, as ``Presliding``.
    host_inertia  the host's inertia on each pin (kg*m^2, 0 = not given), a number or an
                array (n,), as ``Presliding(host_inertia=...)``: damps each joint's
                presliding mode near critically (zeta = 0.7), capped for an explicit host
                at the step given to ``commit``/``step``. None: 0 for every joint.
    fidelity    "full" (the cold complete solve: equal to ``Presliding`` bit for bit),
                "table", "boundary" or "auto" with ``tolerance`` and ``envelope`` as
                ``Joint`` (inside the envelope the level's answer, outside the complete
                solve: equal to ``Joint(...).evaluate``'s torque bit for bit).
    angle       each joint's initial reference angle (rad), a number or an array (n,);
                None: as ``Presliding(angle=None)``, each joint takes the first angle it
                is given as its reference (no deflection there).

    Calls (each input a number or an array of shape (n,), any integer or float dtype):

    torque(angle, angular_velocity, load[, temperature])   the friction torque (N*m) of
        every joint, shape (n,); the states are not changed.
    commit(angle, angular_velocity, load[, temperature][, step])   commit every state at
        its angle; ``step`` (s, a number or an array (n,), finite >= 0; None: not known) is
        the host's step just taken, as ``Presliding.commit(..., step=h)``: each joint's next
        angle is read modulo 2*pi against angular_velocity*step (a host may wrap its angles
        into (-pi, pi]), and its host-inertia damping is capped at the step.
    step(...)      torque, then commit at the same inputs (one solve per joint), with the
        same ``step`` argument.
    sliding_torque(angular_velocity, load[, temperature])  each joint's sliding torque
        T = mu*R*|P| (N*m); at angular_velocity 0 the breakaway torque.

    angle in rad, angular_velocity in rad/s, load in N (its magnitude; 0: unloaded, no
    torque), temperature in K (the lubricant's; omitted: each parameter set's
    lubricant.temperature). ``torque`` then ``commit`` at the same inputs solve once: the
    sliding torque of each joint is kept until its inputs change.

    Bad input raises as ``Joint.evaluate`` does: an array of another shape is a ValueError
    naming the argument; NaN or infinite values, a load beyond capacity, a temperature out
    of range are a ValueError naming the argument and the first failing index; bool,
    complex, string and object data a TypeError. Nothing is changed by a call that raises.

    A batch of n joints equals n ``Presliding`` objects driven the same way, bit for bit at
    fidelity full: with host_inertia, steps, wrapped angles and angle=None.

    A PreslidingBatch pickles (settings, host inertia and every joint's state: presliding
    torque, reference angle, last step and angular velocity, pending first angle; the rebuilt
    batch steps on bit for bit), so it travels to multiprocessing and Dask workers.

    >>> import numpy as np, pinjoint
    >>> b = pinjoint.PreslidingBatch(3)
    >>> b.step(angle=[1e-4, 0.0, 0.1], angular_velocity=[0.0, 0.0, 0.2], load=2e4)
    """

    __slots__ = ("_n", "_sets", "_per_joint", "_law", "_host_inertia", "_fidelity", "_tolerance", "_envelope", "_native")

    def __init__(
        self,
        n: int,
        params: Any = None,
        presliding_angle: float = DEFAULT_PRESLIDING[0],
        elastic_limit: float = DEFAULT_PRESLIDING[1],
        damping_time: float = DEFAULT_PRESLIDING[2],
        host_inertia: Any = None,
        fidelity: str = "full",
        *,
        angle: Any = 0.0,
        per_joint: Optional[Mapping[str, Any]] = None,
        tolerance: float = 1e-4,
        envelope: Optional[Tuple[float, float, float, float]] = None,
    ) -> None:
        if isinstance(n, bool) or not isinstance(n, numbers.Integral) or n < 1:
            raise ValueError(f"n = {short(n)} is not a number of joints: it must be an integer >= 1")
        n = int(n)
        if _is_params_like(params):
            sets = [as_params(params)]
        elif isinstance(params, Sequence):
            sets = [as_params(p) for p in params]
            if len(sets) != n:
                raise ValueError(f"params has {len(sets)} parameter sets for n = {n} joints: give one set, or one per joint")
        else:
            raise TypeError(f"params must be a parameter set or a sequence of n of them, not {type(params).__name__}")
        if not isinstance(fidelity, str):
            raise TypeError(f"fidelity must be a string (full, table, boundary or auto), not {type(fidelity).__name__}")
        env = None if envelope is None else tuple(float(x) for x in envelope)
        if env is not None and len(env) != 4:
            raise ValueError(f"envelope must be (load_min N, load_max N, speed_min rad/s, speed_max rad/s), got {short(envelope)}")
        keys, values = [], None
        if per_joint:
            keys = [str(k) for k in per_joint]
            cols = []
            for k in keys:
                raw, switch = per_joint[k], _is_switch(k)
                if switch and np.asarray(raw).dtype.kind == "b":
                    raw = np.asarray(raw).astype(np.float64)  # a switch's values: True/False
                col = as_float_array(f"per_joint[{k!r}]", "", raw)
                if col.shape != (n,):
                    raise ValueError(f"per_joint[{k!r}] has shape {col.shape}, the batch has n = {n} joints: give an array of shape ({n},)")
                bad = np.flatnonzero(~np.isfinite(col))
                if bad.size:
                    raise ValueError(f"per_joint[{k!r}] = {col[bad[0]]!r} at index {bad[0]} is not a finite number")
                bad = np.flatnonzero((col != 0.0) & (col != 1.0)) if switch else bad
                if bad.size:
                    raise ValueError(f"per_joint[{k!r}] = {col[bad[0]]!r} at index {bad[0]} is not a switch's value: it must be True or False (1 or 0)")
                cols.append(col)
            values = np.ascontiguousarray(np.stack(cols, axis=1))
        if env is None:
            # The paper's model in any set (or switched on per joint) takes its rig region.
            paper = "model.paper" in keys and bool(np.any(values[:, keys.index("model.paper")] != 0.0))
            env = PAPER_ENVELOPE if paper else default_envelope(*sets)
        law = (float(presliding_angle), float(elastic_limit), float(damping_time))
        self._native = _PreslidingBatch(n, sets, keys, values, law, fidelity, float(tolerance), env)
        self._n = n
        self._sets = sets
        self._per_joint = (keys, values)
        self._law = law
        self._fidelity = fidelity.strip().lower()
        self._tolerance = float(tolerance)
        self._envelope = env
        self._host_inertia = None
        self.host_inertia = host_inertia
        if angle is None:
            z = np.zeros(n)
            self._native.set_full_states(z, z, z, z, np.ones(n, dtype=bool))
            return
        a0 = self._vector("angle", "rad", angle)
        bad = np.flatnonzero(~np.isfinite(a0))
        if bad.size:
            raise ValueError(f"angle = {a0[bad[0]]!r} rad at index {bad[0]} is not a finite number")
        self._native.set_states(np.zeros(n), a0)

    def _vector(self, name: str, unit: str, value: Any) -> np.ndarray:
        """A float64 array of shape (n,) from a number or an array of that shape."""
        arr = as_float_array(name, unit, value)
        if arr.shape == (self._n,):
            return np.ascontiguousarray(arr)
        if arr.ndim == 0:
            return np.full(self._n, float(arr))
        raise ValueError(f"{name} has shape {arr.shape}, the batch has n = {self._n} joints: give a number or an array of shape ({self._n},)")

    def _args(self, angle: Any, angular_velocity: Any, load: Any, temperature: Any):
        a = self._vector("angle", "rad", angle)
        w = self._vector("angular_velocity", "rad/s", angular_velocity)
        p = self._vector("load", "N", load)
        t = None if temperature is None else self._vector("temperature", "K", temperature)
        return a, w, p, t

    @property
    def n(self) -> int:
        """The number of joints."""
        return self._n

    def __len__(self) -> int:
        return self._n

    def torque(self, angle: Any, angular_velocity: Any, load: Any, temperature: Any = None) -> np.ndarray:
        """The friction torque on every pin (N*m), shape (n,), at these inputs; the states are not changed."""
        return self._native.torque(*self._args(angle, angular_velocity, load, temperature))

    def _step(self, step: Any) -> Optional[np.ndarray]:
        return None if step is None else self._vector("step", "s", step)

    def commit(self, angle: Any, angular_velocity: Any, load: Any, temperature: Any = None, step: Any = None) -> None:
        """Make each joint's presliding torque at its ``angle`` its state (the FMU's step when the host sets the angle).

        ``step`` (s, a number or an array (n,)): the host's step just taken, as
        ``Presliding.commit(..., step=h)``: the next angle is read modulo 2*pi against
        angular_velocity*step, and the host-inertia damping is capped at it. None: not known."""
        self._native.commit(*self._args(angle, angular_velocity, load, temperature), self._step(step))

    def step(self, angle: Any, angular_velocity: Any, load: Any, temperature: Any = None, step: Any = None) -> np.ndarray:
        """``torque`` then ``commit`` (with ``step``) at the same inputs (one solve per joint); returns the torque (N*m), shape (n,)."""
        return self._native.step(*self._args(angle, angular_velocity, load, temperature), self._step(step))

    def sliding_torque(self, angular_velocity: Any, load: Any, temperature: Any = None) -> np.ndarray:
        """Each joint's sliding torque T = mu(P, |omega|)*R*|P| (N*m, >= 0), shape (n,): its
        breakaway torque at angular_velocity = 0. The states are not changed."""
        w = self._vector("angular_velocity", "rad/s", angular_velocity)
        p = self._vector("load", "N", load)
        t = None if temperature is None else self._vector("temperature", "K", temperature)
        return self._native.sliding_torque(w, p, t)

    @property
    def state(self) -> Tuple[np.ndarray, np.ndarray]:
        """(presliding torques tau in N*m, reference angles in rad), arrays of shape (n,)."""
        return self._native.states

    def set_state(self, torque: Any, angle: Any) -> None:
        """Replace every state: presliding torques (N*m) and reference angles (rad), numbers or arrays (n,)."""
        self._native.set_states(self._vector("torque", "N*m", torque), self._vector("angle", "rad", angle))

    @property
    def law(self) -> Tuple[float, float, float]:
        """(presliding_angle in rad, elastic_limit, damping_time in s)."""
        return self._law

    @property
    def fidelity(self) -> str:
        """The fidelity level asked for."""
        return self._fidelity

    @property
    def host_inertia(self) -> Optional[np.ndarray]:
        """The host inertia per joint (kg*m^2, 0 = not given), or None (0 for every joint)."""
        return None if self._host_inertia is None else self._host_inertia.copy()

    @host_inertia.setter
    def host_inertia(self, value: Any) -> None:
        if value is None:
            self._native.set_host_inertia(None)
            self._host_inertia = None
            return
        v = self._vector("host_inertia", "kg*m^2", value)
        self._native.set_host_inertia(v)
        self._host_inertia = v

    @property
    def models_held(self) -> int:
        """Models (a parameter set at a temperature and level) held now: joints sharing both share one."""
        return self._native.models_held

    @property
    def tables_held(self) -> int:
        """Models holding a table now: at most 4 at the table and auto levels. Joints beyond
        four parameter sets or temperatures at once (sets or temperatures of their own) are
        answered by the complete solve (as at fidelity "full"), so memory and a step's time stay
        bounded whatever their number."""
        return self._native.tables_held

    @property
    def last_step(self) -> Tuple[np.ndarray, np.ndarray]:
        """(the host's step of each joint's last commit in s, 0 before one or when not given;
        the angular velocity there in rad/s): angular_velocity*step is what the next angle is
        read against."""
        _, _, h, w, _ = self._native.full_states
        return h, w

    @property
    def unreferenced(self) -> np.ndarray:
        """Whether each joint still waits for its first angle (``angle=None``), bool (n,)."""
        return self._native.full_states[4]

    def __reduce__(self):
        keys, values = self._per_joint
        per_joint = {k: values[:, c].copy() for c, k in enumerate(keys)} if keys else None
        params = self._sets[0] if len(self._sets) == 1 else list(self._sets)
        return (
            _rebuild,
            (self._n, params, self._law, self._host_inertia, self._fidelity, self._tolerance, self._envelope, per_joint,
             self._native.full_states),
        )

    def __repr__(self) -> str:
        return f"pinjoint.PreslidingBatch(n={self._n}, fidelity={self._fidelity!r}, law={self._law!r})"


def _rebuild(n, params, law, host_inertia, fidelity, tolerance, envelope, per_joint, states) -> PreslidingBatch:
    """A PreslidingBatch from its pickled parts (``PreslidingBatch.__reduce__``)."""
    b = PreslidingBatch(n, params, *law, host_inertia=host_inertia, fidelity=fidelity, tolerance=tolerance, envelope=envelope, per_joint=per_joint)
    b._native.set_full_states(*states)
    return b
