"""Broadcasting and dtype rules of Joint.evaluate."""

from __future__ import annotations

import numpy as np
import pytest

import pinjoint

J = pinjoint.Joint()


def test_scalars_give_0d_arrays_and_lists_work():
    out = J.evaluate(20e3, 0.2)
    assert out["torque"].shape == () and out["regime"].shape == ()
    assert out["torque"].dtype == np.float64
    lst = J.evaluate([20e3], [0.2])
    assert lst["torque"].shape == (1,)
    assert lst["torque"][0] == out["torque"]


def test_broadcast_shape_and_values_match_pointwise():
    loads = np.array([5e3, 2e4, 6e4])[:, None]
    speeds = np.array([0.0, 0.05, 1.0, 100.0])
    out = J.evaluate(loads, speeds)
    assert set(out) == {"load", "speed", *pinjoint.RESULT_COLUMNS}
    for k, v in out.items():
        assert v.shape == (3, 4), k
    for i in range(3):
        for j in range(4):
            p = J.evaluate(float(loads[i, 0]), float(speeds[j]))
            for k in pinjoint.RESULT_COLUMNS:
                assert p[k] == out[k][i, j], (k, i, j)
    assert out["load"][2, 3] == 6e4 and out["speed"][2, 3] == 100.0


@pytest.mark.parametrize("dtype", [np.int8, np.int32, np.int64, np.uint16, np.uint64, np.float16, np.float32, np.float64])
def test_real_dtypes_are_converted_to_float64_exactly(dtype):
    loads = np.array([1000, 20000, 60000]).astype(dtype) if np.dtype(dtype).itemsize > 1 or np.dtype(dtype).kind == "f" else np.array([100, 110, 120], dtype=dtype)
    # (inside the film bound: 10 N at 1 rad/s would pass the clearance)
    speeds = np.array([1, 2, 1], dtype=dtype)
    out = J.evaluate(loads, speeds)
    ref = J.evaluate(loads.astype(np.float64), speeds.astype(np.float64))
    for k in pinjoint.RESULT_COLUMNS:
        assert np.array_equal(out[k], ref[k]), k
    assert out["load"].dtype == np.float64


def test_non_contiguous_and_reversed_views():
    base = np.linspace(1e3, 6e4, 40).reshape(5, 8)
    view = base[::-1, ::2]
    out = J.evaluate(view, 0.3)
    ref = J.evaluate(np.ascontiguousarray(view), 0.3)
    assert np.array_equal(out["torque"], ref["torque"])


def test_empty_arrays():
    out = J.evaluate(np.zeros((0, 3)), 1.0)
    assert out["torque"].shape == (0, 3) and out["regime"].shape == (0, 3)


def test_mismatched_shapes_are_a_value_error_naming_both():
    with pytest.raises(ValueError, match=r"shape \(3,\).*shape \(2,\)"):
        J.evaluate([1e4, 2e4, 3e4], [1.0, 2.0])
    with pytest.raises(ValueError):
        J.evaluate(np.ones((2, 3)), np.ones((3, 2)))


@pytest.mark.parametrize("bad", [np.array([True]), np.array([1 + 2j]), np.array(["20000"]), [None]])
def test_non_real_inputs_are_a_type_error(bad):
    with pytest.raises(TypeError, match="load"):
        J.evaluate(bad, 1.0)


def test_input_arrays_are_not_modified():
    l = np.array([2e4, 3e4])
    w = np.array([-1.0, 1.0])
    J.evaluate(l, w)
    assert list(l) == [2e4, 3e4] and list(w) == [-1.0, 1.0]
