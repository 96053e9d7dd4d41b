"""Shared fixtures: the `pinjoint` command line (the reference: the Rust library through its
own CSV front end) and helpers to run `sweep` and `cycle` on it."""

from __future__ import annotations

import csv
import importlib.util
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]


def load_example(name: str):
    """examples/<name>.py imported as the module `name` (registered in sys.modules, so that
    the worker processes of a Dask cluster find its functions by name)."""
    spec = importlib.util.spec_from_file_location(name, ROOT / "examples" / f"{name}.py")
    mod = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = mod
    spec.loader.exec_module(mod)
    return mod


@pytest.fixture(scope="session")
def cli() -> Path:
    """target/release/pinjoint (or $PINJOINT_CLI), built with cargo when missing."""
    path = Path(os.environ.get("PINJOINT_CLI", ROOT / "target" / "release" / "pinjoint"))
    if not path.exists():
        subprocess.run(["cargo", "build", "--release", "-q", "--bin", "pinjoint"], cwd=ROOT, check=True)
    assert path.exists(), path
    return path


def read_csv(path: Path) -> dict:
    """Columns of a CSV file; numeric ones as float64 arrays (exact: the CLI prints the
    shortest text that reads back as the same double)."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    out = {}
    for j, name in enumerate(header):
        col = [r[j] for r in body]
        try:
            out[name] = np.array([float(x) for x in col])
        except ValueError:
            out[name] = np.array(col)
    return out


@pytest.fixture
def sweep(cli, tmp_path):
    """sweep(loads, speeds, *flags) -> the CLI's output columns."""

    def run(loads, speeds, *flags):
        src, dst = tmp_path / "in.csv", tmp_path / "out.csv"
        with open(src, "w") as f:
            f.write("load,speed\n")
            for l, w in zip(loads, speeds):
                f.write(f"{float(l)!r},{float(w)!r}\n")
        subprocess.run([str(cli), "sweep", "--input", str(src), "--output", str(dst), *flags], check=True, capture_output=True)
        return read_csv(dst)

    return run


@pytest.fixture
def cycle_cli(cli, tmp_path):
    """cycle_cli(*flags) -> the columns of the CLI's cycle.csv."""

    def run(*flags):
        out = tmp_path / "cycle"
        subprocess.run([str(cli), "cycle", "--output", str(out), *flags], check=True, capture_output=True)
        return read_csv(out / "cycle.csv")

    return run


def inside_film_bound(joint, loads, speeds):
    """Mask of the points the model answers: False where the fluid's film would pass the
    diametral clearance (the ValueError naming it, docs/conventions.md), True elsewhere."""
    keep = []
    for load, speed in zip(np.ravel(loads), np.ravel(speeds)):
        try:
            joint.evaluate(load, speed)
            keep.append(True)
        except ValueError as e:
            assert "diametral clearance" in str(e), str(e)
            keep.append(False)
    return np.array(keep, dtype=bool)
