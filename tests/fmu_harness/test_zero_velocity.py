"""The zero-velocity treatment keeps a host that integrates the joint's inertia
against the FMU's torque stable through reversals.

Host: explicit Euler at h = 1 ms of  J dw/dt = T_drive(t) + torque(w),
with torque from the FMU at the current w (the FMU's torque already opposes w),
T_drive(t) = A sin(2 pi f t) with A above the breakaway torque, so the joint
reverses twice per period. Chatter measure: sign changes of w per drive reversal.
A chatter-free run changes sign once per reversal; without the band (speed_band =
0, a pure sign function) the same host chatters, which shows the test can fail.
This is the band's behaviour: the host sets zero_velocity.model = band (the presliding
default has its own tests)."""

import numpy as np
from fmpy import extract
from fmpy.fmi2 import FMU2Slave

H = 1e-3          # s, host step
J = 50.0          # kg m^2, inertia
LOAD = 60e3       # N: boundary torque mu_c R P = 201.6 N m
A = 300.0         # N m, drive amplitude
F = 0.5           # Hz, drive frequency
PERIODS = 6       # -> 12 drive reversals


def run(unzipped, md, band):
    fmu = FMU2Slave(guid=md.guid, unzipDirectory=unzipped, modelIdentifier="PinJoint", instanceName="host")
    fmu.instantiate()
    fmu.setupExperiment(startTime=0.0)
    fmu.setReal([200], [band])
    model = next(v.valueReference for v in md.modelVariables if v.name == "zero_velocity.model")
    fmu.setInteger([model], [0])  # band
    fmu.enterInitializationMode()
    fmu.setReal([3], [LOAD])
    fmu.exitInitializationMode()
    n = int(PERIODS / F / H)
    w, theta = 0.0, 0.0
    ws = np.empty(n)
    for k in range(n):
        t = k * H
        fmu.setReal([1, 2], [theta, w])
        torque = fmu.getReal([10])[0]
        fmu.doStep(t, H)
        drive = A * np.sin(2 * np.pi * F * t)
        theta += w * H
        w += H / J * (drive + torque)
        ws[k] = w
    energy = fmu.getReal([19])[0]
    fmu.terminate()
    fmu.freeInstance()
    return ws, energy


def sign_changes(ws, floor=1e-9):
    s = np.sign(ws[np.abs(ws) > floor])
    return int(np.sum(s[1:] != s[:-1]))


def test_coupled_host_is_bounded_and_free_of_chatter(unzipped, model_description):
    ws, energy = run(unzipped, model_description, 0.01)
    reversals = 2 * PERIODS - 1  # of the drive inside the run (t = 0 excluded)
    assert np.all(np.isfinite(ws))
    # Bounded: |w| stays below what the drive alone could reach in half a period.
    assert np.max(np.abs(ws)) < A / J / (np.pi * F)
    changes = sign_changes(ws)
    assert changes <= reversals + 1, f"{changes} sign changes of w for {reversals} drive reversals"
    assert changes >= reversals - 1, "the joint must actually reverse"
    assert energy > 0


def test_without_the_band_the_same_host_chatters(unzipped, model_description):
    ws, _ = run(unzipped, model_description, 0.0)
    assert sign_changes(ws) > 10 * (2 * PERIODS), "the pure sign function should chatter"
