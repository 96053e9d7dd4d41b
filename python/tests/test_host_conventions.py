"""Issue 29 on the Python side: pinjoint.Presliding takes the host's conventions from the core
library (angles modulo 2 pi, the first angle as reference, the host-inertia damping) and
pickles; Joint.evaluate(errors="nan") answers a grid with a few points the model cannot take."""

from __future__ import annotations

import math
import pickle

import numpy as np
import pytest

import pinjoint


def wrap(x: float) -> float:
    w = (x + math.pi) % (2 * math.pi) - math.pi
    return math.pi if w == -math.pi else w


def test_a_wrapped_angle_gives_the_torque_of_a_continuous_one():
    """0.1 rad/s at 20 kN, h = 10 ms, from 3 rad through two wraps: equal torques (1e-9 of T_s),
    the sliding torque opposing the motion at every wrap."""
    a, b = pinjoint.Presliding(angle=3.0), pinjoint.Presliding(angle=wrap(3.0))
    h, w, ts = 1e-2, 0.1, 0.12 * 0.028 * 20e3
    worst = 0.0
    for i in range(1, 2500):
        th = 3.0 + w * h * i
        ta, tb = a.torque(th, w, 20e3), b.torque(wrap(th), w, 20e3)
        worst = max(worst, abs(ta - tb))
        if i > 50:
            assert tb < -0.9 * ts, (i, tb)
        a.commit(th, w, 20e3, step=h)
        b.commit(wrap(th), w, 20e3, step=h)
    assert worst < 1e-9 * ts, worst


def test_without_an_angle_the_first_one_is_the_reference():
    j = pinjoint.Presliding(angle=None)
    assert j.torque(1.4, 0.0, 20e3) == 0.0
    j.commit(1.4, 0.0, 20e3)
    assert j.state == (0.0, 1.4)
    # With a reference, 1.4 rad is far beyond the presliding range: the sliding torque.
    ts = float(pinjoint.Joint().evaluate(20e3, 0.0)["torque"])
    assert pinjoint.Presliding(angle=0.0).torque(1.4, 0.0, 20e3) == -ts


def swing(j: pinjoint.Presliding, inertia: float, load: float, t_end: float, t_from: float, h: float = 1e-3) -> float:
    """Symplectic Euler, a step drive of half the static torque: the angle's range after t_from (rad)."""
    ts = 0.12 * 0.028 * load
    th, w, lo, hi = 0.0, 0.0, math.inf, -math.inf
    for i in range(int(round(t_end / h))):
        tq = j.torque(th, w, load)
        j.commit(th, w, load, step=h)
        w += h * (0.5 * ts + tq) / inertia
        th += h * w
        if i * h >= t_from:
            lo, hi = min(lo, th), max(hi, th)
    return hi - lo


def test_a_heavy_body_settles_with_the_host_inertia():
    """J = 1400 kg m^2 at 6.4 kN: with host_inertia the angle moves < 2e-7 rad (1e-5 deg)
    between 4 and 6 s; without, the presliding ring is still 1e-4 rad there."""
    assert swing(pinjoint.Presliding(host_inertia=1400.0), 1400.0, 6.4e3, 6.0, 4.0) < 2e-7
    assert swing(pinjoint.Presliding(), 1400.0, 6.4e3, 6.0, 4.0) > 1e-4
    assert pinjoint.Presliding(host_inertia=1400.0).host_inertia == 1400.0


def test_a_bad_host_inertia_or_step_is_refused_by_name():
    with pytest.raises(ValueError, match="zero_velocity.host_inertia = -1 kg.m2"):
        pinjoint.Presliding(host_inertia=-1.0)
    with pytest.raises(ValueError, match="step = -0.001 s"):
        pinjoint.Presliding().commit(0.0, 0.0, 20e3, step=-1e-3)


def test_presliding_pickles_state_and_law():
    """A pickled Presliding (parameters, law, host inertia, state, the last step and the pending
    first angle) continues bit for bit."""
    params = pinjoint.Params().with_values({"friction.boundary_friction_coefficient": 0.11})
    j = pinjoint.Presliding(params, presliding_angle=1e-3, elastic_limit=0.9, damping_time=0.02, angle=None, host_inertia=300.0)
    u = pickle.loads(pickle.dumps(j))
    assert u.torque(0.7, 0.0, 20e3) == j.torque(0.7, 0.0, 20e3) == 0.0
    for i in range(200):
        th = 0.7 + 1e-5 * i
        j.commit(th, 0.01, 20e3, step=1e-3)
    c = pickle.loads(pickle.dumps(j))
    assert c.state == j.state and c.law == j.law == (1e-3, 0.9, 0.02) and c.host_inertia == 300.0
    for i in range(200, 400):
        th = 0.7 + 1e-5 * i - 4 * math.pi  # whole turns: the same angle modulo 2 pi
        a, b = j.torque(th, 0.01, 20e3), c.torque(th, 0.01, 20e3)
        assert a == b
        j.commit(th, 0.01, 20e3, step=1e-3)
        c.commit(th, 0.01, 20e3, step=1e-3)
    assert c.state == j.state
    # Another law: the copy has it (the static torque of mu_c = 0.11).
    assert pickle.loads(pickle.dumps(pinjoint.Presliding(params))).torque(1.0, 0.0, 20e3) == pytest.approx(-0.11 * 0.028 * 20e3, rel=1e-3)


def test_evaluate_errors_nan_answers_every_point_it_can():
    joint = pinjoint.Joint()
    load = np.array([[20e3, np.nan, 0.0, 5e3], [60e3, 1e12, 20e3, -20e3]])
    speed = np.array([[1.0, 1.0, 1.0, 1e4], [0.5, 1.0, np.inf, 2.0]])
    with pytest.raises(ValueError):
        joint.evaluate(load, speed)
    with pytest.raises(ValueError, match="errors = 'ignore' is not a choice"):
        joint.evaluate(load, speed, errors="ignore")
    out = joint.evaluate(load, speed, errors="nan")
    refused = out["validity"] == "refused"
    # (5 kN, 1e4 rad/s): the complete model answers it (the journal bearing; the paper's model
    # refused it as a film beyond the clearance).
    assert refused.tolist() == [[False, True, True, False], [False, True, True, False]], out["validity"]
    assert np.array_equal(out["load"], load, equal_nan=True) and np.array_equal(out["speed"], speed)
    for name in pinjoint.RESULT_COLUMNS:
        if name in ("regime", "validity"):
            continue
        col = out[name]
        assert np.all(np.isnan(col[refused])), name
        for idx in zip(*np.nonzero(~refused)):
            alone = joint.evaluate(load[idx], speed[idx])[name]
            assert col[idx] == alone, (name, idx)
    assert np.all(out["regime"][refused] == "refused")
    # A grid the model takes everywhere: the same answers as errors="raise".
    ok = joint.evaluate([5e3, 20e3], [[0.1], [1.0]], errors="nan")
    ref = joint.evaluate([5e3, 20e3], [[0.1], [1.0]])
    for name in ref:
        assert np.array_equal(ok[name], ref[name]), name
