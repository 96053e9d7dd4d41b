#!/usr/bin/env bash
# The Python package's tests: a virtualenv with the pinned requirements (python/requirements.txt,
# made once in .venv-python, or $PINJOINT_PY_VENV), `pip install ./python` (maturin builds the
# extension; needs cargo), the `pinjoint` CLI the tests compare against, then pytest on
# python/tests (bit for bit against the CLI, broadcasting, bad inputs, pickling, threads,
# the Dask LocalCluster run of examples/monte_carlo_dask.py).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"

VENV="${PINJOINT_PY_VENV:-$ROOT/.venv-python}"
STAMP="$VENV/.requirements"
if ! cmp -s python/requirements.txt "$STAMP" 2>/dev/null; then
    python3 -m venv "$VENV"
    "$VENV/bin/pip" install -q -r python/requirements.txt
    cp python/requirements.txt "$STAMP"
fi
# maturin is pinned in the venv, so the build needs no isolated environment.
PATH="$VENV/bin:$PATH" "$VENV/bin/pip" install -q --no-build-isolation ./python
cargo build --locked --release -q --bin pinjoint
export PINJOINT_CLI="$ROOT/target/release/pinjoint"
"$VENV/bin/python" -m pytest -q python/tests "$@"
