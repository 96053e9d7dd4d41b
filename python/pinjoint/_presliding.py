"""Presliding: the joint at rest, as a stateful object (the PinJoint FMU's zero-velocity law)."""

from __future__ import annotations

from typing import Any, Dict, Optional, Tuple

from ._coerce import ParamsLike, as_params
from ._native import _Presliding

#: Defaults of the law: presliding angle (rad), elastic limit (1), damping time (s).
DEFAULT_PRESLIDING = (1.5e-3, 0.95, 0.01)


class Presliding:
    """The pin joint at and near rest: the presliding law of the PinJoint FMU, stepped the
    way the FMU steps it (the same library code, bit for bit at fidelity full).

    A single-state elasto-plastic friction law (Dupont, Hayward, Armstrong, Altpeter,
    IEEE Trans. Automatic Control 47(5), 2002). The state is the elastic presliding torque
    tau (N*m), committed at a reference angle. Below breakaway the joint holds it
    elastically (stiffness k = T/presliding_angle, no drift under any drive below
    elastic_limit*T); it breaks away at the sliding torque T = mu(P, |omega|)*R*|P| and
    slides with exactly the model's torque.

    >>> import pinjoint
    >>> j = pinjoint.Presliding()
    >>> j.torque(angle=1e-4, angular_velocity=0.0, load=20e3)   # elastic: -k*1e-4
    >>> j.commit(angle=1e-4, angular_velocity=0.0, load=20e3)   # as the FMU's doStep

    A host that integrates a body J*domega/dt = T_drive + torque calls, at each step,
    ``torque(angle, omega, load)`` (the friction torque at the body's angle) and then
    ``commit`` with the same arguments; a host without an angle calls ``advance``.
    ``rate`` is the Model Exchange derivative d(tau)/dt.

    Inputs: angle (rad), angular_velocity (rad/s), load (N, its magnitude is the load);
    a non-finite value raises ValueError naming it.

    The host's conventions, as in the FMU: the angle is taken modulo 2*pi (the increment
    since the reference is the 2*pi-equivalent closest to angular_velocity*step of the last
    ``commit(..., step=h)``, or closest to 0 when no step was given), so a host may wrap its
    angle into (-pi, pi]. ``angle=None`` makes the first angle given the reference (no
    deflection there). ``host_inertia`` (kg*m^2, 0 = not given) damps the presliding mode near
    critically (zeta = 0.7), capped for an explicit host at the step given to ``commit``.

    A Presliding pickles (parameters, law and state): the copy continues bit for bit.
    """

    def __init__(
        self,
        params: ParamsLike = None,
        presliding_angle: float = DEFAULT_PRESLIDING[0],
        elastic_limit: float = DEFAULT_PRESLIDING[1],
        damping_time: float = DEFAULT_PRESLIDING[2],
        angle: Optional[float] = 0.0,
        host_inertia: float = 0.0,
    ) -> None:
        self._params = as_params(params)
        self._native = _Presliding(self._params, float(presliding_angle), float(elastic_limit), float(damping_time),
                                   None if angle is None else float(angle), float(host_inertia))

    def __reduce__(self) -> Any:
        return (_restore, (self._params, self.law, self.host_inertia, self._native.full_state))

    def torque(self, angle: float, angular_velocity: float, load: float) -> float:
        """The friction torque on the pin (N*m) at these inputs; the state is not changed."""
        return self._native.torque(float(angle), float(angular_velocity), float(load))

    def commit(self, angle: float, angular_velocity: float, load: float, step: Optional[float] = None) -> None:
        """Make the presliding torque at ``angle`` the state (the FMU's step when the host sets the angle).

        ``step`` (s): the host's step just taken, as the FMU's doStep knows it: the next angle
        is read modulo 2*pi against angular_velocity*step, and the host-inertia damping is
        capped at it. None: not known."""
        self._native.commit(float(angle), float(angular_velocity), float(load), None if step is None else float(step))

    def advance(self, angular_velocity: float, load: float, step: float) -> None:
        """Drive the state by angular_velocity*step (the FMU's step when the host does not set the angle)."""
        self._native.advance(float(angular_velocity), float(load), float(step))

    def rate(self, angular_velocity: float, load: float) -> float:
        """d(tau)/dt (N*m/s) at the committed state: the Model Exchange derivative."""
        return self._native.rate(float(angular_velocity), float(load))

    def partials(self, angle: float, angular_velocity: float, load: float) -> Dict[str, float]:
        """The torque and its partial derivatives with respect to angle, angular_velocity and load."""
        return dict(self._native.partials(float(angle), float(angular_velocity), float(load)))

    @property
    def state(self) -> Tuple[float, float]:
        """(presliding torque tau in N*m, reference angle in rad)."""
        return self._native.state

    def set_state(self, torque: float, angle: float) -> None:
        """Replace the state (presliding torque in N*m, reference angle in rad)."""
        self._native.set_state(float(torque), float(angle))

    @property
    def law(self) -> Tuple[float, float, float]:
        """(presliding_angle in rad, elastic_limit, damping_time in s)."""
        return self._native.law

    @property
    def host_inertia(self) -> float:
        """The host's inertia on the pin (kg*m^2, 0 = not given)."""
        return self._native.host_inertia

    def __repr__(self) -> str:
        tau, ref = self.state
        return f"Presliding(tau={tau!r} N*m, reference_angle={ref!r} rad, law={self.law!r})"


def _restore(params: Any, law: Tuple[float, float, float], host_inertia: float, state: Tuple[float, float, float, float, bool]) -> Presliding:
    """A Presliding from its pickled parts (``Presliding.__reduce__``)."""
    j = Presliding(params, *law, angle=0.0, host_inertia=host_inertia)
    j._native.set_full_state(*state)
    return j
