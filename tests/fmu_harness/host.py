"""The one low-level fmpy host of the Python tests, for any model of the FMU library: an
FMU2Slave with a recording logger, brought to a named state, with variables set by name
through the model's own description (the PinJoint and PinJointRig tests bind it to their
model; crates/test-support/src/fmi2_host.rs is the Rust counterpart)."""

import pytest
from ctypes import c_int, c_void_p
from fmpy.fmi1 import FMICallException
from fmpy.fmi2 import FMU2Slave

from conftest import LogCapture

ERROR = 3


class Slave:
    """An FMU2Slave of the model described by `md` (unzipped in `unzipped`), brought to
    `state`: "instantiated", "init" (in initialization mode), "error" (exit of
    initialization refused, with `start_values` that are invalid), "step" (initialized, then
    `first_step(slave)` if given) or "terminated" (after that, terminated)."""

    def __init__(self, unzipped, md, state="step", start_values=None, logging_on=False, instance_name="misuse", first_step=None):
        self.md = md
        self.vr = {v.name: v.valueReference for v in md.modelVariables}
        self.type = {v.name: v.type for v in md.modelVariables}
        self.log = LogCapture()
        self.fmu = FMU2Slave(guid=md.guid, unzipDirectory=unzipped, modelIdentifier=md.coSimulation.modelIdentifier,
                             instanceName=instance_name)
        self.fmu.instantiate(callbacks=self.log.callbacks(), loggingOn=logging_on)
        self.c = self.fmu.component
        if state == "instantiated":
            return
        self.fmu.setupExperiment(startTime=0.0)
        for name, value in (start_values or {}).items():
            self.set(name, value)
        self.fmu.enterInitializationMode()
        if state == "init":
            return
        if state == "error":
            with pytest.raises(FMICallException):
                self.fmu.exitInitializationMode()
            return
        self.fmu.exitInitializationMode()
        if first_step is not None:
            first_step(self)
        if state == "terminated":
            self.fmu.terminate()

    def set(self, name, value):
        """Set a variable by name through the setter of its type."""
        t = self.type[name]
        if t == "Boolean":
            self.fmu.setBoolean([self.vr[name]], [bool(value)])
        elif t in ("Integer", "Enumeration"):
            self.fmu.setInteger([self.vr[name]], [int(value)])
        else:
            self.fmu.setReal([self.vr[name]], [float(value)])

    def raw(self, name, argtypes, *args):
        """Call an exported function directly (also those FMU2Slave does not load)."""
        f = getattr(self.fmu.dll, name)
        f.argtypes = [c_void_p] + argtypes
        f.restype = c_int
        return f(self.c, *args)

    def free(self):
        self.fmu.freeInstance()


def expect_error(slave, call, *fragments):
    """`call()` fails with fmi2Error and the log holds every fragment."""
    with pytest.raises(FMICallException) as e:
        call()
    assert f"status {ERROR}" in str(e.value), str(e.value)
    for f in fragments:
        assert f in slave.log.text(), f"{f!r} not in log:\n{slave.log.text()}"
