"""simulate_cycle: whole strokes of the paper's torsion test rig."""

from __future__ import annotations

import os
from typing import Any, Dict, Mapping, Union

import numpy as np

from ._coerce import magnitude, short
from ._native import Params, _simulate_cycle


def simulate_cycle(
    frequency: float,
    amplitude: float,
    load: float,
    cycles: int = 3,
    samples_per_cycle: int = 2000,
    params: Union[Params, Mapping[str, Any], str, "os.PathLike[str]", None] = None,
    fidelity: str = "full",
    tolerance: float = 1e-4,
    **rig: Any,
) -> Dict[str, np.ndarray]:
    """Simulate whole sine strokes of the paper's torsion rig, from rest at t = 0.

    The rig (section 4): a servo-hydraulic torsional actuator in angle control drives the
    pin through A*sin(2*pi*f*t) strokes; the joint's friction comes from the model at each
    speed, and at each stroke end the joint sticks while |T_a| <= breakaway_factor*mu_c*R*P.
    The same computation as ``pinjoint cycle`` (bit for bit, its cycle.csv columns).

    frequency          f, Hz (> 0)
    amplitude          A, rad (>= 0; the CLI's --amplitude is in degrees: use np.radians(40))
    load               P, N: a magnitude (a negative value is taken as |P|: -P gives the
                       answer at +P); |P| must be > 0
    cycles             whole strokes to simulate (1..100000)
    samples_per_cycle  samples written per stroke (>= 8; cycles*samples <= 2e7)
    params             model parameters: None, a Params, a mapping, or a TOML file path; a
                       mapping or file may hold a "rig" section too
    fidelity, tolerance  the friction's fidelity level, as `pinjoint cycle --fidelity`:
                       table/boundary/auto are built over the stroke's envelope (load +-10 %,
                       1e-3 rad/s to twice the peak command speed)
    **rig              any other [rig] key: inertia (kg*m^2), position_gain (N*m/rad),
                       velocity_gain (N*m*s/rad), servo_time_constant (s), torque_limit (N*m),
                       breakaway_factor, regularisation_speed (rad/s), rtol, atol,
                       rk4_step (s), event_tolerance (s), segment_length (s),
                       formulation ("hybrid" | "regularised"), method ("dopri5" | "dop853" |
                       "rk4"). See pinjoint.rig_param_table().

    Returns a dict of arrays, one entry per sample: time (s), command_angle (rad), angle
    (rad), angular_velocity (rad/s), torque (N*m, the actuator's transducer), friction_torque
    (N*m, on the pin, signed), friction_coefficient (-), film_thickness (m),
    fluid_load_fraction (-), stuck (bool). Invalid values raise ValueError naming the
    parameter, value and unit. The GIL is released while it runs.
    """
    overrides: Dict[str, Any] = {"frequency": frequency, "amplitude": amplitude, "load": magnitude(load)}
    overrides.update(rig)
    if isinstance(params, os.PathLike):
        params = os.fspath(params)
    for name, value in (("cycles", cycles), ("samples_per_cycle", samples_per_cycle)):
        if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
            raise TypeError(f"{name} must be an integer, got {short(value)}")
        if value < 0:
            raise ValueError(f"{name} = {value} is invalid: it must be >= 1")
    return _simulate_cycle(params, overrides, int(cycles), int(samples_per_cycle), str(fidelity), float(tolerance))
