"""Host-inertia scenes for PinJoint: a rigid body of inertia J on the pin,

    J dw/dt = T_d(t) + torque(angle, w, P),      d angle/dt = w,

integrated by a host the way a system simulation would, with the FMU (FMI 2.0 or 3.0,
Co-Simulation or Model Exchange, through fmpy) or a Python reference law as the joint.

Hosts
- explicit(): symplectic Euler, the joint's torque held over the step. Each step sets the
  inputs (angle_n, w_n, P), reads the torque, calls doStep(t_n, h) (order="read-step"; or
  doStep first, then reads the torque: order="step-read"), then
  w_{n+1} = w_n + h (T_d(t_n) + torque) / J,  angle_{n+1} = angle_n + h w_{n+1}.
- implicit(): linearly implicit Euler with the joint's directional derivatives
  T_a = d torque/d angle, T_w = d torque/d angular_velocity at (angle_n, w_n):
  (J - h T_w - h^2 T_a) dw = h (T_d(t_n) + T_n + h T_a w_n), w_{n+1} = w_n + dw,
  angle_{n+1} = angle_n + h w_{n+1}; then doStep.
- model_exchange(): SciPy's BDF (scipy.integrate.BDF, the integrator solve_ivp uses for
  method="BDF", stepped by hand so that completedIntegratorStep is called after every
  accepted step) over the states [angle, w, x...] where x are the FMU's continuous states
  (presliding_torque under the presliding model, none under the band model); optionally
  with the Jacobian from the directional derivatives.

Each host returns a Run (t, angle, w, torque, drive arrays); the metrics below read it.

Zero dead-band of the sign-change counts: |w| < W_ZERO = 1e-9 rad/s counts as zero and
neither makes nor breaks a sign change. Motion at that speed for the longest scene (100 s)
is below 1e-7 rad (6e-6 deg), four decades under every angle tolerance of the scenes, so
no motion that matters is hidden; and it is far above the round-off left in w when a
stuck body's increments cancel (|h (T_d + torque)/J| ~ 1e-16 relative of T_s h / J).
"""

import atexit
import math
import os
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

W_ZERO = 1e-9  # rad/s, see the module doc

ROOT = Path(__file__).resolve().parents[2]
_TARGET = Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))
TARGET = _TARGET if _TARGET.is_absolute() else ROOT / _TARGET
FMI2_PATH = Path(os.environ.get("PINJOINT_FMU", TARGET / "fmu" / "PinJoint.fmu"))
FMI3_PATH = TARGET / "fmu" / "fmi3" / "PinJoint.fmu"

# Names of the presliding interface (issue 22).
MODEL = "zero_velocity.model"
BAND, PRESLIDING = 0, 1
PRESLIDING_PARAMETERS = ("zero_velocity.presliding_angle", "zero_velocity.elastic_limit",
                         "zero_velocity.damping_time")
STATE = "presliding_torque"
MU_C_NAME = "friction.boundary_friction_coefficient"
RADIUS_NAME = "geometry.pin_radius"


class MissingInterface(AssertionError):
    """The FMU lacks a variable or capability the scene needs (an AssertionError, so a test
    fails with its message rather than erroring or skipping)."""


# ----------------------------------------------------------------------------- FMU access

_EXTRACTED = {}


def _remove_extracted():
    import shutil
    for d in _EXTRACTED.values():
        shutil.rmtree(d, ignore_errors=True)


atexit.register(_remove_extracted)


class _Fmu:
    """Common part of the fmpy wrappers: variables by name, version-independent get/set."""

    def __init__(self, path, kind, start_values=None, instance="scene"):
        from fmpy import extract, read_model_description
        path = Path(path)
        if not path.is_file():
            raise MissingInterface(f"{path} is missing: run `cargo run --release -p fmu_build`")
        self.path = path
        self.md = read_model_description(str(path))
        self.fmi3 = self.md.fmiVersion.startswith("3")
        self.vars = {v.name: v for v in self.md.modelVariables}
        iface = self.md.coSimulation if kind == "cs" else self.md.modelExchange
        if iface is None:
            raise MissingInterface(f"{path.name} (FMI {self.md.fmiVersion}) has no {kind.upper()} interface")
        self.iface = iface
        key = (str(path.resolve()), path.stat().st_mtime_ns)
        if key not in _EXTRACTED:  # once per archive and process
            _EXTRACTED[key] = extract(str(path))
        self.unzipped = _EXTRACTED[key]
        self.start_values = dict(start_values or {})
        for name in self.start_values:
            self.require(name)
        self.vr_angle, self.vr_omega, self.vr_load, self.vr_torque = (
            self.require(n).valueReference for n in ("angle", "angular_velocity", "load", "torque"))
        self.instance = instance
        self.provides_directional = self._provides_directional(kind)

    def _provides_directional(self, kind):
        """The interface's providesDirectionalDerivative (FMI 2) / providesDirectionalDerivatives
        (FMI 3) read from modelDescription.xml: fmpy 0.3.32 parses only the FMI 2 spelling,
        so its attribute is always False for an FMI 3 FMU."""
        import xml.etree.ElementTree as ET
        root = ET.parse(os.path.join(self.unzipped, "modelDescription.xml")).getroot()
        element = root.find("CoSimulation" if kind == "cs" else "ModelExchange")
        name = "providesDirectionalDerivatives" if self.fmi3 else "providesDirectionalDerivative"
        return element is not None and element.get(name, "false") in ("true", "1")

    def require(self, name, why=""):
        v = self.vars.get(name)
        if v is None:
            raise MissingInterface(
                f"{self.path.name} (FMI {self.md.fmiVersion}) has no variable {name!r}"
                + (f": {why}" if why else "")
                + (" -- the presliding zero-velocity model of issue 22 is not in this FMU"
                   if name in (MODEL, STATE, f"der({STATE})") + PRESLIDING_PARAMETERS else ""))
        return v

    def parameter(self, name):
        """The start value of a parameter (float), or the override given."""
        if name in self.start_values:
            return float(self.start_values[name])
        return float(self.require(name).start)

    def static_torque(self, load):
        """T_s = mu_c R |P| (N.m) with this FMU's parameters."""
        return self.parameter(MU_C_NAME) * self.parameter(RADIUS_NAME) * abs(load)

    def set_value(self, name, value):
        v = self.require(name)
        t = v.type
        if t == "Boolean":
            (self.fmu.setBoolean)([v.valueReference], [bool(value)])
        elif t in ("Integer", "Enumeration", "Int32", "Int64"):
            if self.fmi3:
                if t == "Int32":
                    self.fmu.setInt32([v.valueReference], [int(value)])
                else:
                    self.fmu.setInt64([v.valueReference], [int(value)])
            else:
                self.fmu.setInteger([v.valueReference], [int(value)])
        else:
            self.set_reals([v.valueReference], [float(value)])

    def set_reals(self, vrs, values):
        (self.fmu.setFloat64 if self.fmi3 else self.fmu.setReal)(vrs, values)

    def get_reals(self, vrs):
        return (self.fmu.getFloat64 if self.fmi3 else self.fmu.getReal)(vrs)

    def enter_initialization(self, start=0.0):
        """Initialization mode from the instantiated (or reset) state, starting at `start` s:
        enterInitializationMode(startTime) in FMI 3, setupExperiment(startTime) then
        enterInitializationMode() in FMI 2."""
        if self.fmi3:
            self.fmu.enterInitializationMode(startTime=start)
        else:
            self.fmu.setupExperiment(startTime=start)
            self.fmu.enterInitializationMode()

    def directional(self, unknowns, knowns, seed):
        if not self.provides_directional:
            raise MissingInterface(f"{self.path.name} (FMI {self.md.fmiVersion}) does not provide directional "
                                   "derivatives (providesDirectionalDerivative(s) is not true), which this host needs")
        return self.fmu.getDirectionalDerivative(unknowns, knowns, seed)

    def close(self):
        try:
            self.fmu.terminate()
        finally:
            self.fmu.freeInstance()


class CoSimJoint(_Fmu):
    """PinJoint as a Co-Simulation FMU (FMI 2 or 3). `start_values`: parameters by name."""

    def __init__(self, path, start_values=None, load=20e3, instance="scene"):
        super().__init__(path, "cs", start_values, instance)
        from fmpy.fmi2 import FMU2Slave
        from fmpy.fmi3 import FMU3Slave
        kw = dict(guid=self.md.guid, unzipDirectory=self.unzipped, modelIdentifier=self.iface.modelIdentifier,
                  instanceName=instance)
        self.fmu = (FMU3Slave if self.fmi3 else FMU2Slave)(**kw)
        self.fmu.instantiate()
        self.enter_initialization()
        for name, value in self.start_values.items():
            self.set_value(name, value)
        self.set_reals([self.vr_load], [float(load)])
        self.fmu.exitInitializationMode()
        self._io = [self.vr_angle, self.vr_omega, self.vr_load]

    @property
    def provides_partials(self):
        return self.provides_directional

    def set_inputs(self, theta, omega, load):
        self.set_reals(self._io, [theta, omega, load])

    def torque(self):
        return self.get_reals([self.vr_torque])[0]

    def do_step(self, t, h):
        self.fmu.doStep(t, h)

    def step(self, t, h, theta, omega, load):
        """One step of a host that reads the torque before stepping: set the inputs (angle,
        angular velocity, load), read the torque, doStep(t, h); returns the torque read."""
        self.set_inputs(theta, omega, load)
        torque = self.torque()
        self.do_step(t, h)
        return torque

    def partials(self):
        """(d torque/d angle, d torque/d angular_velocity) from the FMU's directional derivatives."""
        return (self.directional([self.vr_torque], [self.vr_angle], [1.0])[0],
                self.directional([self.vr_torque], [self.vr_omega], [1.0])[0])


class MEJoint(_Fmu):
    """PinJoint as a Model Exchange FMU (FMI 2 or 3); its continuous states (presliding_torque
    under the presliding model, none in an FMU without it) are states of the host's ODE."""

    def __init__(self, path, start_values=None, load=20e3, instance="scene"):
        super().__init__(path, "me", start_values, instance)
        from fmpy.fmi2 import FMU2Model
        from fmpy.fmi3 import FMU3Model
        kw = dict(guid=self.md.guid, unzipDirectory=self.unzipped, modelIdentifier=self.iface.modelIdentifier,
                  instanceName=instance)
        self.fmu = (FMU3Model if self.fmi3 else FMU2Model)(**kw)
        self.fmu.instantiate()
        self.enter_initialization()
        for name, value in self.start_values.items():
            self.set_value(name, value)
        self.set_reals([self.vr_load], [float(load)])
        self.fmu.exitInitializationMode()
        while True:  # event iteration at the start
            if self.fmi3:
                needed = self.fmu.updateDiscreteStates()[0]
            else:
                needed = self.fmu.newDiscreteStates()[0]
            if not needed:
                break
        self.fmu.enterContinuousTimeMode()
        self.state_vrs, self.der_vrs = [], []
        for d in self.md.derivatives:
            dv = d.variable
            self.der_vrs.append(dv.valueReference)
            sv = dv.derivative
            self.state_vrs.append(sv.valueReference)
        self.n_states = len(self.state_vrs)
        import ctypes
        self._x = (ctypes.c_double * max(self.n_states, 1))()
        self._dx = (ctypes.c_double * max(self.n_states, 1))()
        if self.n_states:
            self.fmu.getContinuousStates(self._x, self.n_states)
        self.x0 = list(self._x[:self.n_states])
        self._io = [self.vr_angle, self.vr_omega, self.vr_load]

    @property
    def provides_partials(self):
        return self.provides_directional

    def _set(self, t, theta, omega, load, x):
        self.fmu.setTime(t)
        self.set_reals(self._io, [theta, omega, load])
        if self.n_states:
            self._x[:self.n_states] = list(x)
            self.fmu.setContinuousStates(self._x, self.n_states)

    def evaluate(self, t, theta, omega, load, x):
        self._set(t, theta, omega, load, x)
        dx = []
        if self.n_states:
            if self.fmi3:
                self.fmu.getContinuousStateDerivatives(self._dx, self.n_states)
            else:
                self.fmu.getDerivatives(self._dx, self.n_states)
            dx = list(self._dx[:self.n_states])
        return self.get_reals([self.vr_torque])[0], dx

    def partials(self, t, theta, omega, load, x):
        self._set(t, theta, omega, load, x)
        tq = [self.vr_torque]
        t_w = self.directional(tq, [self.vr_omega], [1.0])[0]
        t_x = [self.directional(tq, [s], [1.0])[0] for s in self.state_vrs]
        d_w = self.directional(self.der_vrs, [self.vr_omega], [1.0]) if self.n_states else []
        d_x = [self.directional(self.der_vrs, [s], [1.0]) for s in self.state_vrs]
        d_x = [[d_x[j][i] for j in range(self.n_states)] for i in range(self.n_states)]  # row i: d xdot_i/d x_j
        return t_w, t_x, d_w, d_x

    def completed_step(self):
        """fmi2CompletedIntegratorStep; returns whether the FMU asks for a step event."""
        r = self.fmu.completedIntegratorStep()
        return bool(r[0]) if isinstance(r, (tuple, list)) else False

    def event(self, t, theta, omega, load, x):
        """Event mode at (t, inputs, states): the event iteration, back to continuous time;
        returns the states afterwards (changed if the FMU says valuesOfContinuousStatesChanged)."""
        self._set(t, theta, omega, load, x)
        self.fmu.enterEventMode()
        changed = False
        while True:
            r = self.fmu.updateDiscreteStates() if self.fmi3 else self.fmu.newDiscreteStates()
            # FMI 2: (newDiscreteStatesNeeded, terminate, nominalsChanged, valuesChanged, ...);
            # FMI 3: (discreteStatesNeedUpdate, terminate, nominalsChanged, valuesChanged, ...).
            changed |= bool(r[3])
            if not r[0]:
                break
        self.fmu.enterContinuousTimeMode()
        if changed and self.n_states:
            self.fmu.getContinuousStates(self._x, self.n_states)
            return list(self._x[:self.n_states]), True
        return list(x), False


def open_cosim(path, model=None, params=None, load=20e3, instance="scene"):
    """A CoSimJoint with `zero_velocity.model` = model (None: the FMU's default) and params."""
    sv = dict(params or {})
    if model is not None:
        sv[MODEL] = model
    return CoSimJoint(path, sv, load=load, instance=instance)


def open_me(path, model=None, params=None, load=20e3, instance="scene"):
    """An MEJoint with `zero_velocity.model` = model (None: the FMU's default) and params."""
    sv = dict(params or {})
    if model is not None:
        sv[MODEL] = model
    joint = MEJoint(path, sv, load=load, instance=instance)
    if model == PRESLIDING and joint.n_states == 0:
        joint.close()
        raise MissingInterface(f"{Path(path).name}: the presliding model has no continuous state "
                               f"({STATE!r}) under Model Exchange")
    return joint


# ----------------------------------------------------------------------------- drives

class Drive:
    """A drive torque T_d(t) (N.m); `reversals(t_end, threshold)`: the number of times the
    drive goes beyond +threshold after having been beyond -threshold or back (the reversals
    of sliding it commands when threshold is the breakaway torque)."""

    def __call__(self, t):
        raise NotImplementedError

    def reversals(self, t_end, threshold, dt=1e-3):
        t = np.arange(0.0, t_end, dt)
        d = np.vectorize(self.__call__)(t)
        side = np.where(d > threshold, 1, np.where(d < -threshold, -1, 0))
        side = side[side != 0]
        return int(np.sum(side[1:] != side[:-1]))

    def time_reaching(self, level, t_end, dt=1e-4):
        """The first time the drive reaches `level` (inf if never before t_end)."""
        t = np.arange(0.0, t_end, dt)
        d = np.vectorize(self.__call__)(t)
        hit = np.nonzero(d >= level)[0]
        return float(t[hit[0]]) if len(hit) else math.inf


@dataclass
class Hold(Drive):
    """A constant drive `level`, optionally reached by a cosine ramp over `rise` seconds."""
    level: float
    rise: float = 0.0

    def __call__(self, t):
        if self.rise > 0 and t < self.rise:
            return self.level * 0.5 * (1 - math.cos(math.pi * t / self.rise))
        return self.level


@dataclass
class Ramp(Drive):
    """T_d = rate t (N.m/s) up to `top`, then held."""
    rate: float
    top: float = math.inf

    def __call__(self, t):
        return min(self.rate * t, self.top)


@dataclass
class Sine(Drive):
    """T_d = bias + amplitude sin(2 pi f t), the whole multiplied by a cosine rise from 0 to
    1 over `rise` seconds if rise > 0."""
    amplitude: float
    frequency: float
    bias: float = 0.0
    rise: float = 0.0

    def __call__(self, t):
        g = 0.5 * (1 - math.cos(math.pi * t / self.rise)) if self.rise > 0 and t < self.rise else 1.0
        return g * (self.bias + self.amplitude * math.sin(2 * math.pi * self.frequency * t))


# ----------------------------------------------------------------------------- hosts

@dataclass
class Run:
    """A recorded scene: times (s), angle (rad), angular velocity (rad/s), torque (N.m, the
    joint's, as used by the host over the step that starts at t) and drive (N.m)."""
    t: np.ndarray
    angle: np.ndarray
    omega: np.ndarray
    torque: np.ndarray
    drive: np.ndarray
    info: dict = field(default_factory=dict)


def _load_fn(load):
    return load if callable(load) else (lambda t, p=float(load): p)


def explicit(joint, J, drive, load, h, t_end, order="read-step", theta0=0.0, omega0=0.0):
    """Symplectic Euler with the torque held over the step (see the module doc)."""
    n = int(round(t_end / h))
    P = _load_fn(load)
    t_ = np.empty(n + 1)
    a_, w_, tq_, d_ = np.empty(n + 1), np.empty(n + 1), np.empty(n + 1), np.empty(n + 1)
    theta, omega = theta0, omega0
    for i in range(n):
        t = i * h
        joint.set_inputs(theta, omega, P(t))
        if order == "read-step":
            tq = joint.torque()
            joint.do_step(t, h)
        elif order == "step-read":
            joint.do_step(t, h)
            tq = joint.torque()
        else:
            raise ValueError(f"order = {order!r}: 'read-step' or 'step-read'")
        td = drive(t)
        t_[i], a_[i], w_[i], tq_[i], d_[i] = t, theta, omega, tq, td
        omega = omega + h * (td + tq) / J
        theta = theta + h * omega
    t = n * h
    joint.set_inputs(theta, omega, P(t))
    t_[n], a_[n], w_[n], tq_[n], d_[n] = t, theta, omega, joint.torque(), drive(t)
    return Run(t_, a_, w_, tq_, d_, {"host": f"explicit {order}", "h": h, "J": J})


def implicit(joint, J, drive, load, h, t_end, theta0=0.0, omega0=0.0, relinearize=True):
    """Linearly implicit Euler with the joint's partials (see the module doc).

    relinearize: the presliding tangent d torque/d angle is one-sided (k backwards from the
    sliding branch, ~0 forwards), taken by the joint in the direction of the angular_velocity
    input. When the step predicts a reversal (sign of w_{n+1} opposite to w_n's), the
    partials are asked again with angular_velocity = w_{n+1} (the angle unchanged, so
    nothing is committed), the step is solved again with them (the torque T_n stays the one
    at w_n), and the inputs are set back to (angle_n, w_n) before doStep. Without it, a body
    stopping within a 100 ms step is linearized on the soft sliding branch, overshoots
    through the whole elastic range (2 phi_s) and limit-cycles (seen at 50 kg m^2, 60 kN)."""
    n = int(round(t_end / h))
    P = _load_fn(load)
    t_ = np.empty(n + 1)
    a_, w_, tq_, d_ = np.empty(n + 1), np.empty(n + 1), np.empty(n + 1), np.empty(n + 1)
    theta, omega = theta0, omega0
    for i in range(n):
        t = i * h
        joint.set_inputs(theta, omega, P(t))
        tq = joint.torque()
        ta, tw = joint.partials()
        td = drive(t)
        dw = h * (td + tq + h * ta * omega) / (J - h * tw - h * h * ta)
        if relinearize and omega * (omega + dw) < 0:
            joint.set_inputs(theta, omega + dw, P(t))
            ta, tw = joint.partials()
            dw = h * (td + tq + h * ta * omega) / (J - h * tw - h * h * ta)
            joint.set_inputs(theta, omega, P(t))
        joint.do_step(t, h)
        t_[i], a_[i], w_[i], tq_[i], d_[i] = t, theta, omega, tq, td
        omega = omega + dw
        theta = theta + h * omega
    t = n * h
    joint.set_inputs(theta, omega, P(t))
    t_[n], a_[n], w_[n], tq_[n], d_[n] = t, theta, omega, joint.torque(), drive(t)
    return Run(t_, a_, w_, tq_, d_, {"host": "implicit", "h": h, "J": J})


def fixed_step_me(joint, J, drive, load, h, t_end, method="euler", theta0=0.0, omega0=0.0, events=True):
    """A fixed-step explicit Model Exchange host over [angle, w, x...]: explicit Euler
    (method="euler") or classic Runge-Kutta 4 ("rk4") at step h, the drive and load sampled at
    each stage's time. After each step: fmi2CompletedIntegratorStep, and when it asks for a
    step event (events=True), event mode: the event iteration, and the states read back if the
    FMU changed them. Run.info: "events" (their number), "x_max" (max |x| seen)."""
    P = _load_fn(load)
    nx = joint.n_states
    n = int(round(t_end / h))
    y = np.array([theta0, omega0] + list(getattr(joint, "x0", [0.0] * nx)), float)

    def f(t, y):
        tq, dx = joint.evaluate(t, y[0], y[1], P(t), y[2:])
        return np.array([y[1], (drive(t) + tq) / J] + list(dx)), tq

    t_ = np.empty(n + 1)
    a_, w_, tq_, d_ = np.empty(n + 1), np.empty(n + 1), np.empty(n + 1), np.empty(n + 1)
    n_events, x_max = 0, 0.0
    for i in range(n):
        t = i * h
        k1, tq = f(t, y)
        t_[i], a_[i], w_[i], tq_[i], d_[i] = t, y[0], y[1], tq, drive(t)
        if method == "euler":
            y = y + h * k1
        elif method == "rk4":
            k2, _ = f(t + h / 2, y + h / 2 * k1)
            k3, _ = f(t + h / 2, y + h / 2 * k2)
            k4, _ = f(t + h, y + h * k3)
            y = y + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        else:
            raise ValueError(f"method = {method!r}: 'euler' or 'rk4'")
        joint.evaluate(t + h, y[0], y[1], P(t + h), y[2:])
        if joint.completed_step() and events:
            x, _ = joint.event(t + h, y[0], y[1], P(t + h), y[2:])
            y[2:] = x
            n_events += 1
        if nx:
            x_max = max(x_max, float(np.abs(y[2:]).max()))
    t = n * h
    tq, _ = joint.evaluate(t, y[0], y[1], P(t), y[2:])
    t_[n], a_[n], w_[n], tq_[n], d_[n] = t, y[0], y[1], tq, drive(t)
    return Run(t_, a_, w_, tq_, d_, {"host": f"ME {method}", "h": h, "J": J, "events": n_events, "x_max": x_max})


def model_exchange(joint, J, drive, load, t_end, rtol=1e-6, atol=None, jacobian=True, max_step=np.inf,
                   theta0=0.0, omega0=0.0, x0=None):
    """SciPy BDF over [angle, w, x...] (see the module doc). atol: per state (default 1e-10 rad,
    1e-10 rad/s -- a decade under the sign-change dead band W_ZERO, so that the solver's noise
    about a held w = 0 does not count as sign changes -- and 1e-6 N.m)."""
    from scipy.integrate import BDF
    P = _load_fn(load)
    nx = joint.n_states
    x0 = list(x0 if x0 is not None else getattr(joint, "x0", [0.0] * nx))
    y0 = np.array([theta0, omega0] + x0, float)
    if atol is None:
        atol = np.array([1e-10, 1e-10] + [1e-6] * nx)

    def rhs(t, y):
        tq, dx = joint.evaluate(t, y[0], y[1], P(t), y[2:])
        return np.array([y[1], (drive(t) + tq) / J] + list(dx))

    def jac(t, y):
        t_w, t_x, d_w, d_x = joint.partials(t, y[0], y[1], P(t), y[2:])
        m = np.zeros((2 + nx, 2 + nx))
        m[0, 1] = 1.0
        m[1, 1] = t_w / J
        for j in range(nx):
            m[1, 2 + j] = t_x[j] / J
            m[2 + j, 1] = d_w[j]
            for i in range(nx):
                m[2 + i, 2 + j] = d_x[i][j]
        return m

    solver = BDF(rhs, 0.0, y0, t_end, rtol=rtol, atol=atol, max_step=max_step,
                 jac=jac if jacobian else None)
    ts, ys = [0.0], [y0.copy()]
    while solver.status == "running":
        msg = solver.step()
        if solver.status == "failed":
            raise RuntimeError(f"BDF failed at t = {solver.t:.6g} s: {msg}")
        joint.completed_step()
        ts.append(solver.t)
        ys.append(solver.y.copy())
    ys = np.array(ys)
    t_ = np.array(ts)
    tq = np.array([joint.evaluate(t, y[0], y[1], P(t), y[2:])[0] for t, y in zip(t_, ys)])
    d = np.array([drive(t) for t in t_])
    return Run(t_, ys[:, 0], ys[:, 1], tq, d,
               {"host": "ME BDF", "rtol": rtol, "J": J, "nfev": solver.nfev, "njev": solver.njev,
                "steps": len(t_) - 1, "states": ys[:, 2:]})


# ----------------------------------------------------------------------------- metrics

def signs(omega, zero=W_ZERO):
    """sign(w) with |w| < zero counted as 0."""
    w = np.asarray(omega)
    return np.where(w > zero, 1, np.where(w < -zero, -1, 0))


def sign_changes(omega, zero=W_ZERO):
    """Sign changes of w, zeros (|w| < zero) skipped: a stop followed by motion the same way
    is no change, a stop followed by motion the other way is one."""
    s = signs(omega, zero)
    s = s[s != 0]
    return int(np.sum(s[1:] != s[:-1]))


def chatter(omega, zero=W_ZERO, spacing=2, window=10):
    """Numerical chatter: sign changes of w that land at most `spacing` samples after the
    previous one (a half-period of at most two host steps -- h times the angular frequency
    >= pi/2, which no motion the host resolves has: symplectic Euler is unstable beyond
    2), counted only where such close changes repeat (at least three within `window`
    samples either side). That is the signature of a stiff law sampled too coarsely: w
    flips every step or dips below zero for one step every few (the band law at
    20 kg m^2, 60 kN, 10 ms: +++-+++-...). A resolved elastic ring, and a lone +-+ blip
    where a smooth motion touches zero (two close changes), are not counted."""
    s = signs(omega, zero)
    idx = np.nonzero(s)[0]
    v = s[idx]
    flips = idx[1:][v[1:] != v[:-1]]  # sample index at which each sign change lands
    if len(flips) < 3:
        return 0
    close = flips[1:][np.diff(flips) <= spacing]
    if len(close) < 3:
        return 0
    lo = np.searchsorted(close, close - window, side="left")
    hi = np.searchsorted(close, close + window, side="right")
    return int(np.sum(hi - lo >= 3))


def turning_points(angle, hysteresis):
    """Reversals of motion: the angle turns back by more than `hysteresis` (rad) from its
    last extremum. Elastic (presliding) rings smaller than the hysteresis do not count."""
    return len(reversal_indices(angle, hysteresis))


def reversal_indices(angle, hysteresis):
    """Indices of the extrema at which the motion reverses (see turning_points)."""
    a = np.asarray(angle)
    out, direction = [], 0
    hi = lo = a[0]
    ihi = ilo = 0
    for i, x in enumerate(a):
        if direction >= 0:
            if x > hi:
                hi, ihi = x, i
            elif hi - x > hysteresis:
                if direction > 0:
                    out.append(ihi)
                direction, lo, ilo = -1, x, i
                continue
        if direction <= 0:
            if x < lo:
                lo, ilo = x, i
            elif x - lo > hysteresis:
                if direction < 0:
                    out.append(ilo)
                direction, hi, ihi = 1, x, i
    return out


def trend(run, t_from, t_to=None):
    """Least-squares line of the angle over [t_from, t_to]: (slope rad/s, residual peak-to-peak rad)."""
    t_to = run.t[-1] if t_to is None else t_to
    if not t_to > t_from:
        return 0.0, 0.0
    m = (run.t >= t_from) & (run.t <= t_to)
    if m.sum() < 2001:  # a sparse (ME) record: the angle interpolated on a uniform grid
        t = np.linspace(t_from, t_to, 2001)
        a = np.interp(t, run.t, run.angle)
    else:
        t, a = run.t[m], run.angle[m]
    p = np.polyfit(t - t[0], a, 1)
    r = a - np.polyval(p, t - t[0])
    return float(p[0]), float(r.max() - r.min())


def drift_after_settling(run, t_settle):
    """Angle drift (rad) over [t_settle, end]: the slope of the least-squares line times the
    duration (an elastic ring averages out; a creep does not)."""
    slope, _ = trend(run, t_settle)
    return abs(slope) * (run.t[-1] - t_settle)


def oscillation_left(run, tail=0.1):
    """Peak-to-peak (rad) of the angle about its trend over the last `tail` of the run."""
    t0 = run.t[-1] - tail * (run.t[-1] - run.t[0])
    return trend(run, t0)[1]


def displacement(run):
    """max |angle - angle_0| (rad)."""
    return float(np.max(np.abs(run.angle - run.angle[0])))


def peak_torque(run, t_to=None):
    """max |torque| (N.m) up to t_to."""
    m = run.t <= (run.t[-1] if t_to is None else t_to)
    return float(np.max(np.abs(run.torque[m])))


def motion_before(run, t_level):
    """max |angle - angle_0| (rad) up to t_level (e.g. the drive reaching 0.95 T_s)."""
    m = run.t <= t_level
    return float(np.max(np.abs(run.angle[m] - run.angle[0])))


def walk_per_cycle(run, period, skip=1):
    """Mean angle change per drive period (rad): the slope of the least-squares line through
    the angle sampled at the period starts after `skip` periods (a decaying elastic ring
    sampled there averages out better than in an end-to-end difference; a walk does not)."""
    n = int(math.floor(run.t[-1] / period + 1e-9))
    if n - skip < 1:
        return 0.0
    k = np.arange(skip, n + 1)
    marks = np.interp(k * period, run.t, run.angle)
    return float(np.polyfit(k, marks, 1)[0]) if len(k) > 2 else float(marks[-1] - marks[0])


def deg(x):
    return math.degrees(x)


# ----------------------------------------------------------------------------- scenes

DEG = math.pi / 180
HOLD_FRACTION = 0.5          # hold drive / T_s
DRIFT_TOL = 1e-3 * DEG       # rad, angle drift after settling (and oscillation left)
DISPLACEMENT_TOL = 0.5 * DEG  # rad, displacement while held
REVERSAL_HYSTERESIS = 0.5 * DEG  # rad: motion smaller than the holding tolerance is no reversal
PEAK_TOL = 0.02              # relative, breakaway peak torque against T_s
WALK_TOL = 1e-3 * DEG        # rad, total walk under a dither below breakaway


@dataclass
class Host:
    """How a scene is integrated: kind 'explicit' (h, order), 'implicit' (h), 'me' (SciPy BDF:
    rtol, jacobian) or 'me-fixed' (fixed-step Model Exchange honouring step events: h, method
    'euler' or 'rk4')."""
    kind: str
    h: float = 1e-3
    order: str = "read-step"
    rtol: float = 1e-6
    jacobian: bool = True
    method: str = "euler"

    def run(self, joint, J, drive, load, t_end):
        if self.kind == "me-fixed":
            return fixed_step_me(joint, J, drive, load, self.h, t_end, self.method)
        if self.kind == "explicit":
            return explicit(joint, J, drive, load, self.h, t_end, order=self.order)
        if self.kind == "implicit":
            return implicit(joint, J, drive, load, self.h, t_end)
        if self.kind == "me":
            return model_exchange(joint, J, drive, load, t_end, rtol=self.rtol, jacobian=self.jacobian)
        raise ValueError(f"host kind = {self.kind!r}: 'explicit', 'implicit' or 'me'")

    def __str__(self):
        if self.kind == "me":
            return f"ME BDF rtol {self.rtol:g}"
        if self.kind == "me-fixed":
            return f"ME {self.method} h = {self.h * 1e3:g} ms"
        return f"{self.kind} h = {self.h * 1e3:g} ms"


def hold_scene(joint, host, J, load, T_s, fraction=HOLD_FRACTION, t_end=100.0, t_settle=None, rise=0.0):
    """Drive fraction T_s from rest (a step, or a cosine rise over `rise` s) for t_end s.
    Metrics: displacement, drift after settling (t_settle, default t_end/2), oscillation
    left (last 10 %), sign changes and chatter of w after settling; `failures` lists the
    criteria missed."""
    t_settle = t_end / 2 if t_settle is None else t_settle
    run = host.run(joint, J, Hold(fraction * T_s, rise), load, t_end)
    late = run.t >= t_settle
    m = {"displacement_deg": deg(displacement(run)),
         "drift_deg": deg(drift_after_settling(run, t_settle)),
         "oscillation_deg": deg(oscillation_left(run)),
         "sign_changes_late": sign_changes(run.omega[late]),
         "chatter": chatter(run.omega)}
    f = []
    if not np.all(np.isfinite(run.angle)):
        f.append("non-finite angle")
    if m["displacement_deg"] >= deg(DISPLACEMENT_TOL):
        f.append(f"displacement {m['displacement_deg']:.3g} deg >= 0.5 deg")
    if m["drift_deg"] >= deg(DRIFT_TOL):
        f.append(f"drift after settling {m['drift_deg']:.3g} deg >= 1e-3 deg")
    if m["oscillation_deg"] >= deg(DRIFT_TOL):
        f.append(f"oscillation left {m['oscillation_deg']:.3g} deg >= 1e-3 deg")
    if m["chatter"]:
        f.append(f"chatter: {m['chatter']} sign changes of w within two steps of the previous")
    m["failures"] = f
    return run, m


def ramp_scene(joint, host, J, load, T_s, rise_time=5.0, top=1.5):
    """Drive ramped at T_s / rise_time (N.m/s) up to top T_s. Metrics: motion before the
    drive reaches 0.95 T_s, peak |torque| up to the drive reaching 1.1 T_s against T_s,
    breakaway time (w first above 1e-3 rad/s for good), and sliding at the end."""
    drive = Ramp(T_s / rise_time, top * T_s)
    t_end = rise_time * top * 1.2
    run = host.run(joint, J, drive, load, t_end)
    t95 = 0.95 * rise_time
    # the breakaway peak: up to the drive reaching 1.1 T_s or, if later, w first reaching
    # 0.01 rad/s (a heavy body lags the drive; beyond, the sliding torque's own speed
    # dependence is no breakaway error)
    fast = np.nonzero(run.omega >= 0.01)[0]
    t110 = max(1.1 * rise_time, float(run.t[fast[0]]) if len(fast) else run.t[-1])
    moving = np.nonzero(run.omega < 1e-3)[0]
    t_break = math.inf  # w crossing 1e-3 rad/s for good, interpolated between samples
    if len(moving) and moving[-1] + 1 < len(run.t):
        i = moving[-1]
        w0, w1 = run.omega[i], run.omega[i + 1]
        t_break = float(run.t[i] + (run.t[i + 1] - run.t[i]) * (1e-3 - w0) / (w1 - w0))
    m = {"motion_before_deg": deg(motion_before(run, t95)),
         "peak_torque": peak_torque(run, t110),
         "peak_error": peak_torque(run, t110) / T_s - 1,
         "breakaway_time": t_break,
         "final_omega": float(run.omega[-1]),
         "travel_deg": deg(run.angle[-1] - run.angle[0]),
         "chatter": chatter(run.omega)}
    f = []
    if m["motion_before_deg"] >= 0.5:
        f.append(f"motion below 0.95 T_s {m['motion_before_deg']:.3g} deg >= 0.5 deg")
    if abs(m["peak_error"]) > PEAK_TOL:
        f.append(f"peak torque {m['peak_torque']:.4g} N.m is {100 * m['peak_error']:+.2f} % off T_s = {T_s:.4g}")
    if not (m["final_omega"] > 1e-3 and m["travel_deg"] > 2 * m["motion_before_deg"]):
        f.append(f"not sliding above breakaway: final w {m['final_omega']:.3g} rad/s, travel {m['travel_deg']:.3g} deg")
    if m["chatter"]:
        f.append(f"chatter: {m['chatter']} sign changes of w within two steps of the previous")
    m["failures"] = f
    return run, m


def reversal_scene(joint, host, J, load, T_s, amplitude=1.5, frequency=0.5, bias=0.0, periods=3):
    """Drive bias + amplitude sin(2 pi f t) (in T_s) for `periods` periods. Metrics: the
    drive's reversals beyond +-T_s, reversals of motion (turning points of the angle beyond
    the 0.5 deg hysteresis), sign changes of w (dead band W_ZERO), chatter."""
    drive = Sine(amplitude * T_s, frequency, bias * T_s)
    t_end = periods / frequency
    run = host.run(joint, J, drive, load, t_end)
    expected = drive.reversals(t_end, T_s)
    m = {"drive_reversals": expected,
         "reversals": turning_points(run.angle, REVERSAL_HYSTERESIS),
         "sign_changes": sign_changes(run.omega),
         "chatter": chatter(run.omega),
         "peak_omega": float(np.max(np.abs(run.omega)))}
    f = []
    if not np.all(np.isfinite(run.angle)):
        f.append("non-finite angle")
    if m["reversals"] != expected:
        f.append(f"{m['reversals']} reversals of motion for {expected} of the drive")
    # Not a criterion: sign changes of w == the drive's reversals. When the body stops while
    # the drive is still well inside +-T_s (a 1.3 T_s sine), the deflected presliding spring
    # throws it back and it rings about the new equilibrium (damping ratio
    # (t_d/2) sqrt(T_s/(phi_s J)) < 1 over the whole envelope): a physical ring, 28 sign changes
    # of w for 3 reversals at 20 kg m^2, 20 kN with the reference law, within the elastic range
    # (a throw-back of at most 2 phi_s). It is
    # reported (sign_changes); reversals of motion and chatter are the criteria.
    if m["chatter"]:
        f.append(f"chatter: {m['chatter']} sign changes of w within two steps of the previous")
    m["failures"] = f
    return run, m


def dither_scene(joint, host, J, load, T_s, bias=0.3, amplitude=0.4, frequency=1.0, periods=20, rise=0.0):
    """Drive (bias + amplitude sin(2 pi f t)) T_s, below breakaway. Metrics: walk per
    cycle (after the first), total walk from the end of the first period to the end,
    displacement."""
    drive = Sine(amplitude * T_s, frequency, bias * T_s, rise)
    t_end = periods / frequency
    run = host.run(joint, J, drive, load, t_end)
    per = walk_per_cycle(run, 1 / frequency, skip=max(1, math.ceil(rise * frequency)))
    m = {"walk_per_cycle_deg": deg(per),
         "walk_deg": deg(per * (periods - 1)),
         "displacement_deg": deg(displacement(run)),
         "chatter": chatter(run.omega)}
    f = []
    if abs(m["walk_deg"]) >= deg(WALK_TOL):
        f.append(f"walk {m['walk_deg']:.3g} deg over {periods - 1} periods >= 1e-3 deg")
    if m["displacement_deg"] >= 0.5:
        f.append(f"displacement {m['displacement_deg']:.3g} deg >= 0.5 deg")
    if m["chatter"]:
        f.append(f"chatter: {m['chatter']} sign changes of w within two steps of the previous")
    m["failures"] = f
    return run, m


@dataclass
class LoadProfile:
    """A load (N) through cosine transitions between `levels` (N), each transition lasting
    `ramp` s and each level held `dwell` s: levels[0] at t = 0, then levels[1], ..."""
    levels: tuple
    ramp: float = 5.0
    dwell: float = 5.0

    def __call__(self, t):
        seg = self.ramp + self.dwell
        i = int(t // seg)
        if i + 1 >= len(self.levels):
            return float(self.levels[-1])
        a, b = self.levels[i], self.levels[i + 1]
        x = min((t - i * seg) / self.ramp, 1.0)
        return a + (b - a) * 0.5 * (1 - math.cos(math.pi * x))

    def end(self):
        return (len(self.levels) - 1) * (self.ramp + self.dwell)


def load_change_scene(joint, host, J, profile, drive_level, t_settle=2.0):
    """A constant drive `drive_level` (N.m) held while the load follows `profile`
    (LoadProfile), every level's breakaway torque above the drive / 0.95: the joint must
    neither release nor jerk. Metrics: displacement, |w| peak after t_settle, and the drift
    over the run after t_settle (trend)."""
    t_end = profile.end()
    run = host.run(joint, J, Hold(drive_level), profile, t_end)
    late = run.t >= t_settle
    m = {"displacement_deg": deg(displacement(run)),
         "late_peak_omega": float(np.max(np.abs(run.omega[late]))),
         "drift_deg": deg(drift_after_settling(run, t_settle)),
         "chatter": chatter(run.omega)}
    f = []
    if m["displacement_deg"] >= deg(DISPLACEMENT_TOL):
        f.append(f"displacement {m['displacement_deg']:.3g} deg >= 0.5 deg")
    if m["drift_deg"] >= deg(DISPLACEMENT_TOL) / 10:
        f.append(f"drift {m['drift_deg']:.3g} deg >= 0.05 deg while the load changes")
    if m["late_peak_omega"] >= 1e-2:
        f.append(f"jerk: |w| reaches {m['late_peak_omega']:.3g} rad/s after {t_settle} s")
    if m["chatter"]:
        f.append(f"chatter: {m['chatter']} sign changes of w within two steps of the previous")
    m["failures"] = f
    return run, m
