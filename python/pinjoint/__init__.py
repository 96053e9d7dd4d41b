"""pinjoint: frictional torque of a grease-lubricated aircraft landing-gear pin joint.

The mixed-lubrication model of *Model and Experiments to Determine Lubricant Film
Formation and Frictional Torque in Aircraft Landing Gear Pin Joints*: Greenwood-Williamson
asperity contact, Moes' central film thickness scaled by the load-sharing factors
gamma1/gamma2, Roelands viscosity and Bair-Winer limiting shear give the friction
coefficient, film thickness, lambda and load sharing of the pin in its bush, and from them
the torque T = mu*R*P (eq. 11). The numbers come from the Rust library (the same code as
the ``pinjoint`` command line and FMUs), evaluated over NumPy arrays on every core.

>>> import pinjoint
>>> joint = pinjoint.Joint()                       # the paper's joint (Tables 1-3)
>>> out = joint.evaluate([20e3, 60e3], [0.2, 4.39])  # load (N), speed (rad/s)
>>> out["torque"]                                   # N*m
>>> cycle = pinjoint.simulate_cycle(frequency=1.0, amplitude=0.698, load=20e3, cycles=3)
>>> fit = pinjoint.calibrate([dict(cycle, load=20e3)])  # mu_c from a torque record
>>> fit["parameters"]["friction.boundary_friction_coefficient"]["ci95"]

Everything is in SI units: N, m, Pa, Pa*s, rad, rad/s, N*m.

Public names
------------
Joint            the model at a fidelity level; ``evaluate(load, speed)``
Presliding       the joint at rest (the PinJoint FMU's presliding law), a stateful object
PreslidingBatch  n presliding joints stepped together over NumPy arrays (scenes at scale)
pinjoint.scenes  the free-fall scene on PreslidingBatch and its parameter uncertainty (a module)
Params           the parameter set (the parameter file's keys, validation and messages)
default_params   the paper's parameters
simulate_cycle   whole strokes of the paper's torsion test rig (columns of cycle.csv)
calibrate        fit mu_c (and other parameters) to measured torque cycles, as
                 ``pinjoint calibrate``; returns a Calibration (dict + ``.params``)
param_table, rig_param_table   names, units, ranges, defaults and meanings
RESULT_COLUMNS, CYCLE_COLUMNS, REGIMES, VALIDITIES, MU_C
"""

from ._native import CYCLE_COLUMNS, MU_C, REGIMES, RESULT_COLUMNS, VALIDITIES, Params, param_table, rig_param_table
from ._joint import DEFAULT_ENVELOPE, PAPER_ENVELOPE, Joint, default_envelope, default_params
from ._cycle import simulate_cycle
from ._presliding import DEFAULT_PRESLIDING, Presliding
from ._batch import PreslidingBatch
from ._calibrate import Calibration, calibrate

__all__ = [
    "CYCLE_COLUMNS",
    "Calibration",
    "MU_C",
    "DEFAULT_ENVELOPE",
    "PAPER_ENVELOPE",
    "DEFAULT_PRESLIDING",
    "Joint",
    "Params",
    "default_envelope",
    "Presliding",
    "PreslidingBatch",
    "calibrate",
    "REGIMES",
    "VALIDITIES",
    "RESULT_COLUMNS",
    "default_params",
    "param_table",
    "rig_param_table",
    "simulate_cycle",
]

__version__ = "0.1.0"
