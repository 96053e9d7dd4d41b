"""Misuse through fmpy's low-level API (fmpy.fmi2.FMU2Slave): wrong call sequences
and bad arguments return fmi2Error with a message saying what was wrong, the
interpreter survives, and the instance stays usable where the standard allows."""

from ctypes import byref, c_double, c_int, c_size_t, c_uint, c_void_p

import numpy as np
import pytest
from fmpy.fmi2 import FMU2Slave

import host
from conftest import LogCapture
from host import expect_error

VR = {"angle": 1, "angular_velocity": 2, "load": 3, "torque": 10, "dissipated_energy": 19,
      "geometry.pin_radius": 100, "zero_velocity.speed_band": 200}
ERROR = 3


def _first_step(s):
    s.fmu.setReal([VR["angular_velocity"]], [0.3])
    s.fmu.doStep(0.0, 0.1)


def Slave(unzipped, md, state="step", logging_on=False, start_values=None):
    """The shared host (host.py) for PinJoint: "error" is a negative pin radius, "step" one
    step at 0.3 rad/s; `start_values` (by name) are set before initialization too."""
    bad = {"geometry.pin_radius": -1.0} if state == "error" else {}
    return host.Slave(unzipped, md, state, start_values={**(start_values or {}), **bad}, logging_on=logging_on, first_step=_first_step)


# (state, description, call, expected message fragments)
SEQUENCE_CASES = [
    ("instantiated", "doStep before initialization", lambda f: f.doStep(0.0, 0.1), ["fmi2DoStep: illegal call sequence", "instantiated"]),
    ("instantiated", "exitInitializationMode before enter", lambda f: f.exitInitializationMode(), ["fmi2ExitInitializationMode: illegal call sequence"]),
    ("instantiated", "getReal before initialization", lambda f: f.getReal([10]), ["fmi2GetReal: illegal call sequence"]),
    ("instantiated", "terminate before initialization", lambda f: f.terminate(), ["fmi2Terminate: illegal call sequence"]),
    ("init", "setupExperiment in initialization mode", lambda f: f.setupExperiment(startTime=0.0), ["fmi2SetupExperiment: illegal call sequence", "initializationMode"]),
    ("init", "enterInitializationMode twice", lambda f: f.enterInitializationMode(), ["fmi2EnterInitializationMode: illegal call sequence"]),
    ("init", "doStep in initialization mode", lambda f: f.doStep(0.0, 0.1), ["fmi2DoStep: illegal call sequence"]),
    ("init", "terminate in initialization mode", lambda f: f.terminate(), ["fmi2Terminate: illegal call sequence"]),
    ("step", "enterInitializationMode after initialization", lambda f: f.enterInitializationMode(), ["illegal call sequence", "stepComplete"]),
    ("step", "exitInitializationMode after initialization", lambda f: f.exitInitializationMode(), ["illegal call sequence"]),
    ("step", "setupExperiment after initialization", lambda f: f.setupExperiment(startTime=0.0), ["illegal call sequence"]),
    ("terminated", "terminate twice", lambda f: f.terminate(), ["fmi2Terminate: illegal call sequence", "terminated"]),
    ("terminated", "doStep after terminate", lambda f: f.doStep(0.1, 0.1), ["fmi2DoStep: illegal call sequence"]),
    ("terminated", "setReal after terminate", lambda f: f.setReal([3], [1e3]), ["fmi2SetReal: illegal call sequence"]),
    ("error", "doStep in error state", lambda f: f.doStep(0.0, 0.1), ["fmi2DoStep: illegal call sequence", "error"]),
    ("error", "setReal in error state", lambda f: f.setReal([3], [1e3]), ["fmi2SetReal: illegal call sequence"]),
    ("error", "terminate in error state", lambda f: f.terminate(), ["fmi2Terminate: illegal call sequence"]),
]


@pytest.mark.parametrize("state,what,call,fragments", SEQUENCE_CASES, ids=[c[1] for c in SEQUENCE_CASES])
def test_wrong_call_sequence(unzipped, model_description, state, what, call, fragments):
    s = Slave(unzipped, model_description, state)
    expect_error(s, lambda: call(s.fmu), *fragments)
    # The instance is still in its state: what was allowed there still works.
    if state in ("step", "init", "terminated", "error"):
        s.fmu.getReal([VR["load"]])
    if state == "step":
        s.fmu.doStep(0.1, 0.1)
    s.free()


ARGUMENT_CASES = [
    ("unknown value reference in getReal", lambda s: s.fmu.getReal([999]), ["unknown value reference 999"]),
    ("unknown value reference in setReal", lambda s: s.fmu.setReal([3, 12345], [1.0, 2.0]), ["unknown value reference 12345"]),
    ("set an output", lambda s: s.fmu.setReal([10], [5.0]), ["output 'torque'", "cannot be set"]),
    ("set the energy output", lambda s: s.fmu.setReal([19], [0.0]), ["output 'dissipated_energy'"]),
    ("set a fixed parameter after initialization", lambda s: s.fmu.setReal([100], [0.03]), ["'geometry.pin_radius'", "fixed"]),
    ("NaN load", lambda s: s.fmu.setReal([3], [float("nan")]), ["input load = NaN N"]),
    ("infinite load", lambda s: s.fmu.setReal([3], [float("inf")]), ["input load = inf N"]),
    ("NaN speed", lambda s: s.fmu.setReal([2], [float("nan")]), ["input angular_velocity = NaN rad/s"]),
    ("-inf speed", lambda s: s.fmu.setReal([2], [float("-inf")]), ["input angular_velocity = -inf rad/s"]),
    ("NaN angle", lambda s: s.fmu.setReal([1], [float("nan")]), ["input angle = NaN rad"]),
    ("integer getter", lambda s: s.fmu.getInteger([10]), ["Real variable, not Integer"]),
    ("boolean setter", lambda s: s.fmu.setBoolean([2], [True]), ["Real variable, not Boolean"]),
    ("string getter", lambda s: s.fmu.getString([7]), ["unknown value reference 7"]),
    ("NULL vr with nvr > 0", lambda s: s.fmu.fmi2GetReal(s.c, None, 2, (c_double * 2)()), ["vr[] is NULL but its length is 2"]),
    ("NULL value with nvr > 0", lambda s: s.fmu.fmi2SetReal(s.c, (c_uint * 1)(3), 1, None), ["value[] is NULL"]),
    ("negative step", lambda s: s.fmu.doStep(0.1, -0.1), ["communicationStepSize = -0.1 s"]),
    ("zero step", lambda s: s.fmu.doStep(0.1, 0.0), ["communicationStepSize = 0 s"]),
    ("NaN step", lambda s: s.fmu.doStep(0.1, float("nan")), ["communicationStepSize = NaN s"]),
    ("NaN communication point", lambda s: s.fmu.doStep(float("nan"), 0.1), ["currentCommunicationPoint = NaN s"]),
    ("discontinuous communication point", lambda s: s.fmu.doStep(0.5, 0.1), ["currentCommunicationPoint = 0.5 s does not continue", "ended at 0.1 s"]),
    ("communication point in the past", lambda s: s.fmu.doStep(0.0, 0.1), ["does not continue"]),
    ("unknown log category", lambda s: s.fmu.setDebugLogging(True, ["logEverything"]), ["unknown log category 'logEverything'"]),
    ("directional derivative with respect to a parameter", lambda s: s.fmu.getDirectionalDerivative([10], [100], [1.0]),
     ["partials with respect to parameters are not provided"]),
    ("directional derivative of an input", lambda s: s.fmu.getDirectionalDerivative([2], [3], [1.0]), ["continuous Real outputs"]),
    ("real status of an unknown kind", lambda s: s.fmu.fmi2GetRealStatus(s.c, 7, byref(c_double())), ["status kind 7"]),
    ("doStep status (synchronous FMU)", lambda s: s.fmu.fmi2GetStatus(s.c, 0, byref(c_int())), ["fmi2DoStepStatus"]),
    ("setFMUstate with NULL", lambda s: s.fmu.fmi2SetFMUstate(s.c, None), ["FMUstate is NULL"]),
    ("deserialize garbage", lambda s: s.fmu.deSerializeFMUstate(b"\x01\x02\x03" * 40), ["bad magic"]),
]


@pytest.mark.parametrize("what,call,fragments", ARGUMENT_CASES, ids=[c[0] for c in ARGUMENT_CASES])
def test_bad_arguments_leave_the_instance_usable(unzipped, model_description, what, call, fragments):
    s = Slave(unzipped, model_description, "step")
    before = s.fmu.getReal([VR["load"], VR["angular_velocity"], VR["torque"]])
    expect_error(s, lambda: call(s), *fragments)
    assert s.fmu.getReal([VR["load"], VR["angular_velocity"], VR["torque"]]) == before, "nothing changed"
    s.fmu.doStep(0.1, 0.1)
    s.free()


ME_FUNCTIONS = [
    ("fmi2EnterEventMode", []), ("fmi2EnterContinuousTimeMode", []), ("fmi2SetTime", [c_double]),
    ("fmi2NewDiscreteStates", [c_void_p]), ("fmi2CompletedIntegratorStep", [c_int, c_void_p, c_void_p]),
    ("fmi2SetContinuousStates", [c_void_p, c_size_t]), ("fmi2GetDerivatives", [c_void_p, c_size_t]),
    ("fmi2GetEventIndicators", [c_void_p, c_size_t]), ("fmi2GetContinuousStates", [c_void_p, c_size_t]),
    ("fmi2GetNominalsOfContinuousStates", [c_void_p, c_size_t]),
]


@pytest.mark.parametrize("name,argtypes", ME_FUNCTIONS, ids=[m[0] for m in ME_FUNCTIONS])
def test_model_exchange_functions_return_error_on_a_co_simulation_instance(unzipped, model_description, name, argtypes):
    s = Slave(unzipped, model_description, "step")
    args = [0 if t in (c_int, c_size_t, c_double) else None for t in argtypes]
    assert s.raw(name, argtypes, *args) == ERROR
    # Refused by the state mask: a Co-Simulation instance is never in a Model Exchange state.
    assert s.log.last().startswith(name) and "illegal call sequence" in s.log.last()
    s.fmu.doStep(0.1, 0.1)
    s.free()


def test_model_exchange_instantiation_is_accepted_without_warnings(unzipped, model_description):
    """Issue 11: PinJoint is also Model Exchange (nx = 0, nz = 0); NULL-free, clean log."""
    from fmpy.fmi2 import FMU2Model
    log = LogCapture()
    fmu = FMU2Model(guid=model_description.guid, unzipDirectory=unzipped, modelIdentifier="PinJoint", instanceName="me")
    fmu.instantiate(callbacks=log.callbacks())
    fmu.enterInitializationMode()
    fmu.exitInitializationMode()
    fmu.enterContinuousTimeMode()
    assert "fmi2Warning" not in log.text() and "rror" not in log.text()
    fmu.terminate()
    fmu.freeInstance()


def test_wrong_guid_is_refused(unzipped, model_description):
    log = LogCapture()
    fmu = FMU2Slave(guid="{00000000-0000-0000-0000-000000000000}", unzipDirectory=unzipped,
                    modelIdentifier="PinJoint", instanceName="g")
    with pytest.raises(Exception):
        fmu.instantiate(callbacks=log.callbacks())
    assert "matches no model of this binary" in log.text()


def test_reset_then_fresh_run_equals_first_and_free_without_terminate(unzipped, model_description):
    s = Slave(unzipped, model_description, "instantiated")

    def run():
        s.fmu.setupExperiment(startTime=0.0)
        s.fmu.enterInitializationMode()
        s.fmu.exitInitializationMode()
        out = []
        for k in range(100):
            s.fmu.setReal([2, 3], [np.sin(0.1 * k), 1e4 + 100 * k])
            s.fmu.doStep(0.01 * k, 0.01)
            out.append(s.fmu.getReal(list(range(10, 20))))
        return out

    first = run()
    s.fmu.terminate()
    s.fmu.reset()
    assert run() == first
    s.free()  # stepComplete, no terminate


def test_debug_logging_reports_events(unzipped, model_description):
    s = Slave(unzipped, model_description, "instantiated", logging_on=True)
    s.fmu.setupExperiment(startTime=0.0)
    s.fmu.enterInitializationMode()
    s.fmu.exitInitializationMode()
    cats = {m[1] for m in s.log.messages}
    assert "logEvents" in cats and "logAll" in cats
    s.free()
