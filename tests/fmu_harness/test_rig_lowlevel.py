"""PinJointRig through fmpy's low-level API: misuse returns errors with a message,
the interpreter survives, the FMU state round-trips exactly."""

import numpy as np
import pytest

from host import expect_error
from rig_support import RigSlave


CASES = [
    ("instantiated", "doStep before initialization", lambda s: s.fmu.doStep(0.0, 0.1), ["fmi2DoStep: illegal call sequence"]),
    ("step", "NaN load", lambda s: s.set("load", float("nan")), ["input load = NaN N is invalid"]),
    ("step", "NaN command", lambda s: s.set("command_angle", float("nan")), ["input command_angle = NaN rad"]),
    ("step", "Real getter on the Boolean output", lambda s: s.fmu.getReal([s.vr["stuck"]]), ["'stuck'", "Boolean variable, not Real"]),
    ("step", "set the Boolean output", lambda s: s.fmu.setBoolean([s.vr["stuck"]], [True]), ["output 'stuck'", "cannot be set"]),
    ("step", "Integer setter on a Real", lambda s: s.fmu.setInteger([s.vr["frequency"]], [2]), ["Real variable, not Integer"]),
    ("step", "fixed Boolean parameter after initialization", lambda s: s.set("use_command_input", True), ["fixed"]),
    ("step", "discontinuous communication point", lambda s: s.fmu.doStep(0.7, 0.1), ["does not continue"]),
    ("step", "zero step", lambda s: s.fmu.doStep(0.0, 0.0), ["communicationStepSize = 0 s"]),
    ("step", "deserialize a garbage state", lambda s: s.fmu.deSerializeFMUstate(b"\x07" * 64), ["bad magic"]),
]


@pytest.mark.parametrize("state,what,call,fragments", CASES, ids=[c[1] for c in CASES])
def test_misuse_returns_error_and_leaves_the_instance_usable(rig_unzipped, rig_model_description, state, what, call, fragments):
    s = RigSlave(rig_unzipped, rig_model_description, state)
    expect_error(s, lambda: call(s), *fragments)
    if state == "step":
        s.fmu.doStep(0.0, 0.1)
        assert np.isfinite(s.outputs()).all()
    s.free()


@pytest.mark.parametrize("name,value,fragment", [
    ("frequency", -1.0, "frequency = -1 Hz"),
    ("rig.formulation", 7, "rig.formulation = 7"),
    ("rig.inertia", 20.0, "rig.inertia = 20 kg.m2"),
])
def test_bad_parameter_is_named_at_exit_initialization(rig_unzipped, rig_model_description, name, value, fragment):
    s = RigSlave(rig_unzipped, rig_model_description, "init", start_values={name: value})
    expect_error(s, s.fmu.exitInitializationMode, fragment)
    s.free()


def drive(s, t0, n, h=0.013):
    rows = []
    for k in range(n):
        t = t0 + k * h
        s.set("load", 20e3 if (t // 0.4) % 2 == 0 else 45e3)
        s.fmu.doStep(t, h)
        rows.append(s.outputs())
    return rows, t0 + n * h


def test_get_set_state_round_trips_exactly_after_reversals(rig_unzipped, rig_model_description):
    s = RigSlave(rig_unzipped, rig_model_description, "step", start_values={"rig.breakaway_factor": 1.4})
    _, t = drive(s, 0.0, 110)  # 1.43 s: reversals at 0.25, 0.75, 1.25 s
    state = s.fmu.getFMUstate()
    first, _ = drive(s, t, 60)
    s.fmu.setFMUstate(state)
    again, _ = drive(s, t, 60)
    assert again == first
    s.fmu.freeFMUstate(state)
    s.free()


def test_serialized_state_continues_exactly_in_another_instance(rig_unzipped, rig_model_description):
    a = RigSlave(rig_unzipped, rig_model_description, "step", start_values={"frequency": 0.5})
    _, t = drive(a, 0.0, 90)
    blob = a.fmu.serializeFMUstate(a.fmu.getFMUstate())
    expect, _ = drive(a, t, 70)
    b = RigSlave(rig_unzipped, rig_model_description, "instantiated")
    b.fmu.setFMUstate(b.fmu.deSerializeFMUstate(blob))
    got, _ = drive(b, t, 70)
    assert got == expect
    a.free()
    b.free()
