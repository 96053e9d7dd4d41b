"""Shared fixtures of the PinJoint and PinJointRig FMU harness (the rig's helpers
are in rig_support.py).

The FMU is target/fmu/PinJoint.fmu (or $PINJOINT_FMU), built by
`cargo run --release -p fmu_build`; the library reference is the example binary
target/release/examples/reference_points (`cargo build --release -p pinjoint --example
reference_points`). tests/fmu_harness/run.sh builds both.
"""

import os
import subprocess
from ctypes import byref
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
TARGET = Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))
if not TARGET.is_absolute():
    TARGET = ROOT / TARGET
FMU = Path(os.environ.get("PINJOINT_FMU", TARGET / "fmu" / "PinJoint.fmu"))
REFERENCE = TARGET / "release" / "examples" / "reference_points"

OUTPUTS = [
    "torque", "friction_coefficient", "film_thickness", "lambda_ratio",
    "fluid_load_fraction", "asperity_load_fraction", "mean_pressure",
    "sommerfeld_number", "power_loss", "dissipated_energy",
]
DEFAULT_BAND = 0.01  # rad/s, zero_velocity.speed_band
# zero_velocity.model = band (0): the stateless law, bit for bit the one before the presliding
# model (the default, 1). Tests that compare the torque with the library's stateless value or
# the band's ramp set it.
BAND = {"zero_velocity.model": 0}


def _fmu_fixtures(prefix, locate, tmp_name):
    """The session fixtures of one FMU, named `<prefix>fmu_path` (the archive, which must
    exist), `<prefix>unzipped` (extracted once) and `<prefix>model_description`; `locate()`
    gives the archive's Path."""

    def existing():
        path = locate()
        assert path.is_file(), f"{path} is missing: run `cargo run --release -p fmu_build` (or tests/fmu_harness/run.sh)"
        return str(path)

    def extracted(tmp_path_factory):
        from fmpy import extract
        return extract(existing(), str(tmp_path_factory.mktemp(tmp_name)))

    def described():
        from fmpy import read_model_description
        return read_model_description(existing())

    session = {"scope": "session"}
    return (pytest.fixture(existing, name=prefix + "fmu_path", **session),
            pytest.fixture(extracted, name=prefix + "unzipped", **session),
            pytest.fixture(described, name=prefix + "model_description", **session))


def _rig_fmu():
    from rig_support import RIG_FMU
    return RIG_FMU


fmu_path, unzipped, model_description = _fmu_fixtures("", lambda: FMU, "fmu")
rig_fmu_path, rig_unzipped, rig_model_description = _fmu_fixtures("rig_", _rig_fmu, "rigfmu")


def failed_simulation(path, start_values, stop_time=0.1):
    """Simulate `path` (fmpy) with `start_values`, which must fail: the exception's text
    and every message the FMU logged.

    A logger is passed: fmpy's logger proxy keeps the previous simulation's Python logger
    otherwise, which crashes fmpy 0.3.32 once that one is freed."""
    from fmpy import simulate_fmu
    messages = []
    with pytest.raises(Exception) as e:
        simulate_fmu(path, stop_time=stop_time, start_values=start_values,
                     logger=lambda env, name, status, cat, msg: messages.append(msg.decode()))
    return str(e.value), messages


def reference(load, omega, params=None):
    """The library's values at each (load, omega) pair, from the Rust example binary.

    `params` is a dict of `section.key` -> value written as a TOML parameter file."""
    assert REFERENCE.is_file(), f"{REFERENCE} is missing: cargo build --release -p pinjoint --example reference_points"
    args = [str(REFERENCE)]
    if params:
        sections = {}
        for name, value in params.items():
            section, key = name.split(".")
            sections.setdefault(section, []).append(f"{key} = {float(value)!r}")
        toml = "".join(f"[{s}]\n" + "\n".join(lines) + "\n" for s, lines in sections.items())
        path = Path(os.environ.get("TMPDIR", "/tmp")) / f"pinjoint-params-{os.getpid()}.toml"
        path.write_text(toml)
        args.append(str(path))
    text = "".join(f"{float(p)!r},{float(w)!r}\n" for p, w in zip(load, omega))
    out = subprocess.run(args, input=text, capture_output=True, text=True, check=True).stdout
    return np.genfromtxt(out.splitlines(), delimiter=",", names=True)


def expected_torque(load, omega, band=DEFAULT_BAND, params=None):
    """The FMU's documented torque: the library's -sign(w) T outside |w| < band,
    -T(P, band) * w / band inside, 0 at zero load."""
    load = np.asarray(load, float)
    omega = np.asarray(omega, float)
    loaded = load > 0
    torque = np.zeros_like(omega)
    if loaded.any():
        at = reference(load[loaded], omega[loaded], params)
        edge = reference(load[loaded], np.full(loaded.sum(), band), params)
        inside = np.abs(omega[loaded]) < band
        t = np.where(inside, -edge["torque"] * (omega[loaded] / band) if band > 0 else 0.0, at["signed_torque"])
        torque[loaded] = t
    return torque


# The presliding law's default parameters (zero_velocity.presliding_angle, .elastic_limit,
# .damping_time).
PRESLIDING_ANGLE, ELASTIC_LIMIT, DAMPING_TIME = 1.5e-3, 0.95, 0.01


def presliding_torque(tau, omega, bound):
    """The presliding law's friction torque, written out from its documentation (Dupont et al.
    2002 single-state elasto-plastic law): -clamp(clamp(tau, -T, T) + t_d (T/phi_s) w min(max(g, 0), 1), -T, T)
    (the damping adds up to the sliding torque), with g = 1 while s tau <= beta T (s = sign w),
    else (T - s tau)/(T - beta T); 0 unloaded."""
    tau, omega, bound = (np.asarray(x, float) for x in np.broadcast_arrays(tau, omega, bound))
    held = np.clip(tau, -bound, bound)
    u = np.where(omega < 0, -tau, tau)
    limit = ELASTIC_LIMIT * bound
    with np.errstate(divide="ignore", invalid="ignore"):
        g = np.where(u <= limit, 1.0, (bound - u) / (bound - limit))
    damping = np.where((omega != 0) & (g > 0), DAMPING_TIME * (bound / PRESLIDING_ANGLE) * omega * np.minimum(g, 1.0), 0.0)
    return np.where(bound > 0, -np.clip(held + damping, -bound, bound), 0.0)


def assert_close(actual, expected, rel=1e-12, what=""):
    actual = np.asarray(actual, float)
    expected = np.asarray(expected, float)
    err = np.abs(actual - expected)
    bad = err > rel * np.abs(expected)
    assert not bad.any(), (
        f"{what}: {bad.sum()} of {len(bad)} points differ by more than {rel} relative; "
        f"first at index {np.argmax(bad)}: {actual[bad][0]!r} vs {expected[bad][0]!r}"
    )


class LogCapture:
    """An fmi2 logger that records (status, category, message); fmpy's native proxy
    formats the variadic message before it reaches Python."""

    def __init__(self):
        self.messages = []

    def __call__(self, env, name, status, category, message):
        self.messages.append((status, category.decode(), message.decode()))

    def callbacks(self):
        from fmpy.fmi2 import fmi2CallbackFunctions, fmi2CallbackLoggerTYPE, fmi2CallbackAllocateMemoryTYPE, \
            fmi2CallbackFreeMemoryTYPE, fmi2StepFinishedTYPE
        from fmpy.fmi1 import calloc, free
        from fmpy.logging import addLoggerProxy
        cb = fmi2CallbackFunctions()
        cb.logger = fmi2CallbackLoggerTYPE(self)
        cb.allocateMemory = fmi2CallbackAllocateMemoryTYPE(calloc)
        cb.freeMemory = fmi2CallbackFreeMemoryTYPE(free)
        cb.stepFinished = fmi2StepFinishedTYPE()
        addLoggerProxy(byref(cb))
        self._keep = cb  # the FMU keeps the pointer
        return cb

    def last(self):
        return self.messages[-1][2] if self.messages else ""

    def text(self):
        return "\n".join(m[2] for m in self.messages)
