"""FMU state through fmpy: get/set and serialize/deserialize round-trip exactly."""

import numpy as np
import pytest
from fmpy.fmi1 import FMICallException

from test_lowlevel import Slave

OUT = list(range(10, 20))


def drive(fmu, k0, k1):
    rows = []
    for k in range(k0, k1):
        t = 0.01 * k
        fmu.setReal([1, 2, 3], [-0.3 * np.cos(2 * t), 0.6 * np.sin(2 * t), 5e3 + 200.0 * k])
        fmu.doStep(t, 0.01)
        rows.append(fmu.getReal(OUT))
    return rows


def test_get_set_state_round_trips_exactly_after_reversals(unzipped, model_description):
    s = Slave(unzipped, model_description, "instantiated")
    f = s.fmu
    f.setupExperiment(startTime=0.0)
    f.enterInitializationMode()
    f.exitInitializationMode()
    drive(f, 0, 300)  # two reversals
    state = f.getFMUstate()
    first = drive(f, 300, 450)
    f.setFMUstate(state)
    assert drive(f, 300, 450) == first
    f.freeFMUstate(state)
    s.free()


def test_serialized_state_round_trips_into_another_instance(unzipped, model_description):
    a = Slave(unzipped, model_description, "step")
    drive(a.fmu, 10, 200)
    blob = a.fmu.serializeFMUstate(a.fmu.getFMUstate())
    expect = drive(a.fmu, 200, 300)
    b = Slave(unzipped, model_description, "step")
    b.fmu.setFMUstate(b.fmu.deSerializeFMUstate(blob))
    assert drive(b.fmu, 200, 300) == expect
    assert bytes(b.fmu.serializeFMUstate(b.fmu.getFMUstate()))[:8] == b"FMI2STAT"
    a.free()
    b.free()


@pytest.mark.parametrize("damage", ["truncate", "flip", "version", "extend"])
def test_damaged_serialized_state_is_rejected(unzipped, model_description, damage):
    s = Slave(unzipped, model_description, "step")
    blob = bytearray(s.fmu.serializeFMUstate(s.fmu.getFMUstate()))
    if damage == "truncate":
        blob = blob[:-5]
    elif damage == "flip":
        blob[len(blob) // 2] ^= 0x10
    elif damage == "version":
        blob[8] = 2
    else:
        blob += b"\0"
    with pytest.raises(FMICallException):
        s.fmu.deSerializeFMUstate(bytes(blob))
    assert "serialized FMU state" in s.log.text() or "truncated" in s.log.text()
    s.fmu.doStep(0.1, 0.1)
    s.free()
