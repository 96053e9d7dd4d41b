"""One adversarial case, run in a child process by test_adversarial.py (so a crash, an
abort or a hang of the FMU kills or stalls only this process, never pytest).

    python adversarial_host.py HOST UNZIPPED_FMU_DIR CASE_JSON

HOST is `ctypes` (a minimal FMI 2.0 co-simulation host written here with ctypes, no
importer library in between) or `fmpy` (fmpy's FMU2Slave). CASE_JSON is a list of
operations; the result, printed as one JSON line on standard output, is the status of
every call and every message the FMU logged.

Operations: ["set", name, value] (Real/Integer/Boolean by the variable's type),
["init"] (setupExperiment, enter and exit initialization), ["step", t, h], ["get", name],
["save"] (get and serialize the FMU state), ["patch", kind, value] (rewrite one value of
the saved state, fix its CRC, deserialize it and set it), ["restore"].
"""

import ctypes as C
import json
import struct
import sys
import xml.etree.ElementTree as ET
import zlib
from pathlib import Path


class Variables:
    def __init__(self, unzipped):
        root = ET.parse(Path(unzipped) / "modelDescription.xml").getroot()
        self.guid = root.get("guid")
        self.identifier = root.find("CoSimulation").get("modelIdentifier")
        self.vars = {}
        for sv in root.iter("ScalarVariable"):
            kind = next(c.tag for c in sv if c.tag in ("Real", "Integer", "Boolean", "String", "Enumeration"))
            self.vars[sv.get("name")] = (int(sv.get("valueReference")), kind)


LOGGER = C.CFUNCTYPE(None, C.c_void_p, C.c_char_p, C.c_int, C.c_char_p, C.c_char_p, C.c_char_p)
ALLOC = C.CFUNCTYPE(C.c_void_p, C.c_size_t, C.c_size_t)
FREE = C.CFUNCTYPE(None, C.c_void_p)


class Callbacks(C.Structure):
    _fields_ = [("logger", LOGGER), ("allocateMemory", ALLOC), ("freeMemory", FREE),
                ("stepFinished", C.c_void_p), ("componentEnvironment", C.c_void_p)]


class CtypesHost:
    """FMI 2.0 co-simulation through ctypes only."""

    def __init__(self, unzipped, log):
        self.v = Variables(unzipped)
        lib = Path(unzipped) / "binaries" / "linux64" / f"{self.v.identifier}.so"
        self.dll = C.CDLL(str(lib))
        libc = C.CDLL(None)
        libc.calloc.restype = C.c_void_p
        libc.calloc.argtypes = [C.c_size_t, C.c_size_t]
        libc.free.argtypes = [C.c_void_p]

        def logger(env, name, status, category, fmt, msg):
            log.append((msg or fmt or b"").decode("utf-8", "replace"))

        self._keep = (LOGGER(logger), ALLOC(lambda n, s: libc.calloc(n, s)), FREE(lambda p: libc.free(p)))
        self.cb = Callbacks(self._keep[0], self._keep[1], self._keep[2], None, None)
        d = self.dll
        d.fmi2Instantiate.restype = C.c_void_p
        d.fmi2Instantiate.argtypes = [C.c_char_p, C.c_int, C.c_char_p, C.c_char_p, C.POINTER(Callbacks), C.c_int, C.c_int]
        for f in ("fmi2SetupExperiment", "fmi2EnterInitializationMode", "fmi2ExitInitializationMode", "fmi2DoStep",
                  "fmi2SetReal", "fmi2GetReal", "fmi2SetInteger", "fmi2SetBoolean", "fmi2GetFMUstate", "fmi2SetFMUstate",
                  "fmi2SerializedFMUstateSize", "fmi2SerializeFMUstate", "fmi2DeSerializeFMUstate", "fmi2FreeFMUstate",
                  "fmi2Terminate"):
            getattr(d, f).restype = C.c_int
        d.fmi2SetupExperiment.argtypes = [C.c_void_p, C.c_int, C.c_double, C.c_double, C.c_int, C.c_double]
        d.fmi2DoStep.argtypes = [C.c_void_p, C.c_double, C.c_double, C.c_int]
        d.fmi2FreeInstance.argtypes = [C.c_void_p]
        d.fmi2FreeInstance.restype = None
        uri = Path(unzipped, "resources").resolve().as_uri().encode()
        self.c = d.fmi2Instantiate(b"adversary", 1, self.v.guid.encode(), uri, C.byref(self.cb), 0, 1)
        assert self.c, "fmi2Instantiate returned NULL"
        self.state = C.c_void_p()

    def set(self, name, value):
        vr, kind = self.v.vars[name]
        r = (C.c_uint * 1)(vr)
        if kind == "Real":
            return self.dll.fmi2SetReal(C.c_void_p(self.c), r, C.c_size_t(1), (C.c_double * 1)(value))
        if kind in ("Integer", "Enumeration"):
            return self.dll.fmi2SetInteger(C.c_void_p(self.c), r, C.c_size_t(1), (C.c_int * 1)(int(value)))
        return self.dll.fmi2SetBoolean(C.c_void_p(self.c), r, C.c_size_t(1), (C.c_int * 1)(int(value)))

    def get(self, name):
        vr, _ = self.v.vars[name]
        out = (C.c_double * 1)()
        st = self.dll.fmi2GetReal(C.c_void_p(self.c), (C.c_uint * 1)(vr), C.c_size_t(1), out)
        return st, out[0]

    def init(self):
        c = C.c_void_p(self.c)
        for st in (self.dll.fmi2SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0), self.dll.fmi2EnterInitializationMode(c)):
            if st:
                return st
        return self.dll.fmi2ExitInitializationMode(c)

    def step(self, t, h):
        return self.dll.fmi2DoStep(C.c_void_p(self.c), t, h, 1)

    def save(self):
        c = C.c_void_p(self.c)
        st = self.dll.fmi2GetFMUstate(c, C.byref(self.state))
        n = C.c_size_t()
        st = st or self.dll.fmi2SerializedFMUstateSize(c, self.state, C.byref(n))
        buf = C.create_string_buffer(n.value)
        st = st or self.dll.fmi2SerializeFMUstate(c, self.state, buf, n)
        return st, buf.raw

    def load_state(self, data):
        c = C.c_void_p(self.c)
        s = C.c_void_p()
        st = self.dll.fmi2DeSerializeFMUstate(c, data, C.c_size_t(len(data)), C.byref(s))
        if st:
            return st
        st = self.dll.fmi2SetFMUstate(c, s)
        self.dll.fmi2FreeFMUstate(c, C.byref(s))
        return st

    def free(self):
        self.dll.fmi2FreeInstance(C.c_void_p(self.c))


class FmpyHost:
    """The same operations through fmpy's FMU2Slave (statuses from its exceptions)."""

    def __init__(self, unzipped, log):
        from fmpy import read_model_description
        from fmpy.fmi2 import FMU2Slave
        self.v = Variables(unzipped)
        md = read_model_description(unzipped)

        from ctypes import byref
        from fmpy.fmi1 import calloc, free
        from fmpy.fmi2 import (fmi2CallbackAllocateMemoryTYPE, fmi2CallbackFreeMemoryTYPE, fmi2CallbackFunctions,
                               fmi2CallbackLoggerTYPE, fmi2StepFinishedTYPE)
        from fmpy.logging import addLoggerProxy

        def logger(env, name, status, category, message):
            log.append(message.decode("utf-8", "replace"))

        cb = fmi2CallbackFunctions()
        cb.logger = fmi2CallbackLoggerTYPE(logger)
        cb.allocateMemory = fmi2CallbackAllocateMemoryTYPE(calloc)
        cb.freeMemory = fmi2CallbackFreeMemoryTYPE(free)
        cb.stepFinished = fmi2StepFinishedTYPE()
        addLoggerProxy(byref(cb))  # fmpy's native proxy formats the variadic message
        self._keep = cb
        self.fmu = FMU2Slave(guid=md.guid, unzipDirectory=unzipped, modelIdentifier=md.coSimulation.modelIdentifier,
                             instanceName="adversary")
        self.fmu.instantiate(loggingOn=True, callbacks=cb)

    def _call(self, f, *a):
        from fmpy.fmi1 import FMICallException
        try:
            r = f(*a)
            return 0, r
        except FMICallException as e:
            return int(e.status), None

    def set(self, name, value):
        vr, kind = self.v.vars[name]
        f = {"Real": self.fmu.setReal, "Integer": self.fmu.setInteger, "Enumeration": self.fmu.setInteger, "Boolean": self.fmu.setBoolean}[kind]
        v = float(value) if kind == "Real" else (int(value) if kind in ("Integer", "Enumeration") else bool(value))
        return self._call(f, [vr], [v])[0]

    def get(self, name):
        st, r = self._call(self.fmu.getReal, [self.v.vars[name][0]])
        return st, (r[0] if r else None)

    def init(self):
        for f in (lambda: self.fmu.setupExperiment(startTime=0.0), self.fmu.enterInitializationMode, self.fmu.exitInitializationMode):
            st = self._call(f)[0]
            if st:
                return st
        return 0

    def step(self, t, h):
        return self._call(self.fmu.doStep, t, h)[0]

    def save(self):
        st, s = self._call(self.fmu.getFMUstate)
        if st:
            return st, b""
        st, data = self._call(self.fmu.serializeFMUstate, s)
        return st, bytes(data or b"")

    def load_state(self, data):
        st, s = self._call(self.fmu.deSerializeFMUstate, bytes(data))
        if st:
            return st
        st = self._call(self.fmu.setFMUstate, s)[0]
        self._call(self.fmu.freeFMUstate, s)
        return st

    def free(self):
        self.fmu.freeInstance()


# PinJointRig's simulator state (RigState) words after the settings, start time, flag, length.
RIG_WORDS = {"rig:node_time": 0, "rig:time": 9, "rig:held_load": 11}


def patch(data, model_offset, value):
    """Write the f64 `value` at `model_offset` bytes into the model part (or a named
    PinJointRig simulator word, see RIG_WORDS); fix the CRC."""
    b = bytearray(data)
    glen = b[14]
    model_at = 8 + 2 + 4 + 1 + glen + 1 + 16 + 4
    if isinstance(model_offset, str):
        n = struct.unpack("<H", b[model_at + 1:model_at + 3])[0]
        model_offset = 3 + 8 * n + 8 + 1 + 2 + 8 * RIG_WORDS[model_offset]
    at = model_at + model_offset
    b[at:at + 8] = struct.pack("<d", value)
    b[-4:] = struct.pack("<I", zlib.crc32(bytes(b[:-4])) & 0xFFFFFFFF)
    return bytes(b)


def patch_time(data, value):
    """Rewrite the container's time (after magic, version, length, GUID, life-cycle state)."""
    b = bytearray(data)
    glen = b[14]
    at = 8 + 2 + 4 + 1 + glen + 1
    b[at:at + 8] = struct.pack("<d", value)
    b[-4:] = struct.pack("<I", zlib.crc32(bytes(b[:-4])) & 0xFFFFFFFF)
    return bytes(b)


def main():
    host_kind, unzipped, case = sys.argv[1], sys.argv[2], json.loads(sys.argv[3])
    log, results = [], []
    host = (CtypesHost if host_kind == "ctypes" else FmpyHost)(unzipped, log)
    saved = b""
    for op in case:
        kind = op[0]
        if kind == "set":
            results.append(host.set(op[1], op[2]))
        elif kind == "init":
            results.append(host.init())
        elif kind == "step":
            results.append(host.step(op[1], op[2]))
        elif kind == "get":
            st, v = host.get(op[1])
            results.append([st, v])
        elif kind == "save":
            st, saved = host.save()
            results.append(st)
        elif kind == "patch":
            data = patch_time(saved, op[2]) if op[1] == "time" else patch(saved, op[1], op[2])
            results.append(host.load_state(data))
        elif kind == "restore":
            results.append(host.load_state(saved))
        print(json.dumps({"results": results, "log": log}), flush=True)
    host.free()
    print(json.dumps({"results": results, "log": log, "done": True}), flush=True)


if __name__ == "__main__":
    main()
