"""pinjoint.Presliding: the PinJoint FMU's presliding law as a Python object. Held bit for
bit to the core library (examples/presliding_reference.rs, which the FMU is held to in
tests/fmu_harness/test_presliding_agreement.py), and checked for the law's properties."""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

import pinjoint

ROOT = Path(__file__).resolve().parents[2]
TARGET = Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))
REFERENCE = (TARGET if TARGET.is_absolute() else ROOT / TARGET) / "release" / "examples" / "presliding_reference"


def scene(seed, n=400):
    rng = np.random.default_rng(seed)
    h = 1e-3
    rows, angle = [], 0.0
    for k in range(n):
        omega = 0.05 * np.sin(2 * np.pi * 0.7 * k * h) * rng.uniform(0.5, 2)
        angle += h * omega
        rows.append((float(angle), float(omega), float(20e3 * rng.uniform(0.8, 1.2)), h, 1 if k % 50 < 40 else 0))
    return rows


@pytest.mark.parametrize("seed", range(3))
def test_the_object_steps_the_librarys_law_bit_for_bit(seed):
    # Always asked for: a no-op when up to date, a rebuild when the library changed (a stale
    # reference binary would compare the package with an older law).
    subprocess.run(["cargo", "build", "--release", "-q", "-p", "pinjoint", "--example", "presliding_reference"], cwd=ROOT, check=True)
    rows = scene(seed)
    text = "".join(f"{a!r},{w!r},{p!r},{h!r},{s}\n" for a, w, p, h, s in rows)
    out = subprocess.run([str(REFERENCE)], input=text, capture_output=True, text=True, check=True).stdout
    ref = np.array([[float(x) for x in line.split(",")] for line in out.splitlines()])
    j = pinjoint.Presliding()
    driven, got = False, []
    for angle, omega, load, h, sets in rows:
        driven |= sets == 1
        ref_angle = j.state[1]
        before = j.torque(angle if driven else ref_angle, omega, load)
        if driven:
            j.commit(angle, omega, load)
        else:
            j.advance(omega, load, h)
        after = j.torque(j.state[1], omega, load)
        got.append((before, after, j.state[0]))
    got = np.array(got)
    assert np.array_equal(got.view(np.int64), ref.view(np.int64))


def test_hold_breakaway_and_sliding():
    j = pinjoint.Presliding()
    # The sliding torque at rest: mu_c R P, plus the grease's yield torque in the complete model.
    ts = float(pinjoint.Joint().evaluate(20e3, 0.0)["torque"])
    assert 0.12 * 0.028 * 20e3 < ts < 1.01 * 0.12 * 0.028 * 20e3
    phi, beta, _ = j.law
    # Elastic: the torque is -k*angle below the elastic limit, and returns exactly.
    k = ts / phi
    assert j.torque(0.5 * phi, 0.0, 20e3) == pytest.approx(-0.5 * ts, rel=1e-12)
    j.commit(0.5 * phi, 0.0, 20e3)
    j.commit(0.0, 0.0, 20e3)
    assert j.state[0] == pytest.approx(0.0, abs=1e-12 * ts)
    # Beyond breakaway it slides at the model's torque exactly.
    slide = pinjoint.Joint().evaluate(20e3, 0.3)["torque"]
    j.commit(0.1, 0.3, 20e3)
    assert j.torque(0.1, 0.3, 20e3) == -float(slide)
    # Sliding: no stiffness in the direction of motion; the unloading direction is elastic.
    assert j.partials(0.1, 0.3, 20e3)["angle"] == 0.0
    assert j.partials(0.1, -0.3, 20e3)["angle"] == pytest.approx(-k * float(slide) / ts, rel=1e-6)
    # At rest, nothing held: the elastic stiffness -k (the torque opposes the deflection).
    assert pinjoint.Presliding().partials(0.0, 0.0, 20e3)["angle"] == pytest.approx(-k, rel=1e-12)


def test_bad_inputs_name_the_quantity():
    with pytest.raises(ValueError, match="zero_velocity.presliding_angle = -1 rad"):
        pinjoint.Presliding(presliding_angle=-1.0)
    with pytest.raises(ValueError, match="zero_velocity.elastic_limit = 1 "):
        pinjoint.Presliding(elastic_limit=1.0)
    j = pinjoint.Presliding()
    with pytest.raises(ValueError, match="angular_velocity = nan rad/s|angular_velocity = NaN rad/s"):
        j.torque(0.0, float("nan"), 20e3)
    with pytest.raises(ValueError, match="load"):
        j.torque(0.0, 0.0, 1e300)
