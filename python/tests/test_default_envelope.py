"""The default envelope of the table, boundary and auto levels (Joint and PreslidingBatch).

For the complete model it is DEFAULT_ENVELOPE (the library's Envelope::SERVICE, 1-100 kN and
0.01-100 rad/s): a held, creeping or sliding joint anywhere in it is answered by the table,
never by the complete solve. For the paper's model, whose line-contact film passes the
clearance at light loads and high speeds, it is PAPER_ENVELOPE (the paper's rig region), so
that its table can be built: the levels construct with no envelope given, whichever model.
"""

import numpy as np
import pytest

import pinjoint


def test_the_defaults_are_the_librarys_and_nest():
    lo, hi, wlo, whi = pinjoint.DEFAULT_ENVELOPE
    assert lo <= 1e3 and hi >= 1e5 and wlo <= 0.01 and whi >= 100.0
    p_lo, p_hi, p_wlo, p_whi = pinjoint.PAPER_ENVELOPE
    assert lo <= p_lo < p_hi <= hi and wlo <= p_wlo < p_whi <= whi
    assert pinjoint.default_envelope(pinjoint.Params()) == pinjoint.DEFAULT_ENVELOPE
    assert pinjoint.default_envelope(pinjoint.Params({"model.paper": True})) == pinjoint.PAPER_ENVELOPE
    assert pinjoint.default_envelope(pinjoint.Params(), pinjoint.Params({"model.paper": True})) == pinjoint.PAPER_ENVELOPE


@pytest.mark.parametrize("fidelity", ["table", "boundary", "auto"])
def test_every_model_builds_its_levels_without_an_envelope(fidelity):
    for params, env in [(None, pinjoint.DEFAULT_ENVELOPE), ({"model.paper": True}, pinjoint.PAPER_ENVELOPE),
                        ({"grease.enabled": False}, pinjoint.DEFAULT_ENVELOPE)]:
        j = pinjoint.Joint(params, fidelity=fidelity)
        assert j.envelope == env, (params, fidelity)
        b = pinjoint.PreslidingBatch(3, params, fidelity=fidelity)
        t = b.step(np.zeros(3), np.array([0.0, 0.3, -2.0]), np.full(3, 2e4))
        assert np.all(np.isfinite(t))
    # The paper's model switched on for one joint of a batch: its rig region for the batch.
    b = pinjoint.PreslidingBatch(3, fidelity=fidelity, per_joint={"model.paper": [False, True, False]})
    assert np.all(np.isfinite(b.step(np.zeros(3), np.full(3, 0.3), np.full(3, 2e4))))


def test_the_table_answers_anywhere_in_the_default_envelope():
    rng = np.random.default_rng(39)
    j = pinjoint.Joint(fidelity="table")
    lo, hi, _, whi = j.envelope
    n = 4000
    load = lo * (hi / lo) ** rng.uniform(0, 1, n)
    # From rest and a held joint's creep (1e-14 rad/s) to the envelope's top speed, both ways.
    speed = np.where(rng.uniform(size=n) < 0.05, 0.0, 1e-14 * (whi / 1e-14) ** rng.uniform(0, 1, n)) * rng.choice([-1.0, 1.0], n)
    out = j.evaluate(load, speed)
    assert j.fallbacks == 0
    full = pinjoint.Joint().evaluate(load, speed)
    err = np.abs(out["torque"] / full["torque"] - 1.0)
    assert err.max() <= j.error_bound, err.max()
