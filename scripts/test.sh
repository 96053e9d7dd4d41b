#!/usr/bin/env bash
# Every test of the project, from a fresh machine: installs what it needs (Debian
# packages, rustup targets, pinned Python virtualenvs), runs the Rust tests, lints and
# docs, the Python package's tests, builds the FMUs for every platform and runs them
# (natively, under wine and qemu), drives them from Python (fmpy) and under valgrind.
start=$SECONDS
step() { echo "== test.sh: $1 ($((SECONDS - start)) s so far)"; }
set -euo pipefail
cd "$(dirname "$0")/.."

# --- system packages -------------------------------------------------------------
debs=()
dpkg -s libclang-dev >/dev/null 2>&1 || debs+=(libclang-dev)   # bindgen for the `fmi` crate (2nd importer)
command -v valgrind >/dev/null 2>&1 || debs+=(valgrind)          # memory check of the FMU
python3 -c 'import ensurepip' >/dev/null 2>&1 || debs+=(python3-venv)
ldconfig -p | grep -q 'libtbb\.so\.12' || debs+=(libtbb12)        # Ecos (ecospy), the 3rd importer
if [ ${#debs[@]} -gt 0 ]; then
  SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${debs[@]}" >/dev/null
fi

# --- Rust: unit, integration, property and doc tests (every test binary runs, then the
# first failure stops the script)
step "cargo test"
cargo test --locked --workspace --release --no-fail-fast

# --- lints and API docs of every crate: no warnings (clippy's lints: [workspace.lints])
step "clippy, rustdoc"
cargo clippy --locked --workspace --all-targets --release -- -D warnings
RUSTDOCFLAGS="-D warnings" cargo doc --locked --workspace --no-deps --quiet
python3 tests/docs/check_docs.py --api-docs      # every crate's API front page is there
python3 tests/module_graph.py                    # no import cycle inside a crate; roots list modules in dependency order

# --- the Python package (python/): pinned venv, `pip install ./python`, pytest (incl. a Dask LocalCluster)
step "python package"
bash python/run_tests.sh

# --- the FMU binary cross-built for every platform (fmu_build --platforms all: Linux glibc
# 2.17, Windows, macOS, aarch64 Linux), each run: natively, under wine, under qemu-aarch64
# (macOS: exports and load commands inspected only). Installs its own tools (apt, rustup
# targets, cargo-zigbuild and ziglang from PyPI). Leaves the all-platform FMUs in target/fmu/.
step "platforms"
bash tests/platforms/run.sh

# --- the Python harness (fmpy) and the Rust `fmi` crate on those FMUs (linux64 = the
# shipped glibc-2.17 binary; PINJOINT_KEEP_FMUS: do not rebuild them host-only)
step "fmpy harness"
PINJOINT_KEEP_FMUS=1 PINJOINT_SKIP_APT=1 bash tests/fmu_harness/run.sh

# --- the docs: every relative link and anchor of README.md and docs/*.md resolves, every
# example marked <!-- runnable --> runs on what the steps above built, quoted numbers match;
# the numbers of docs/cold-day.md, journal-bearing.md and validity.md against the built
# `pinjoint` and examples/doc_numbers (tests/docs/numbers_spec.py)
step "docs"
cargo build --locked --release -p pinjoint --example doc_numbers
python3 tests/docs/check_docs.py --run

# --- the SciPy reference of `pinjoint bench` against the check values of docs/model.md, and
# against the library on 50 sweep rows (agreement to 1e-9; measured 2e-14), on the paper's
# model (`[model] paper = true`: the reference implements the paper's equations)
.venv/bin/python benches/scipy_reference.py --self-test
printf 'load,speed\n' > target/scipy_check.csv
.venv/bin/python -c "import math; [print(f'{5e3*12**(i/49)!r},{(-1)**i*1e-3*1e5**((i*7%50)/49)!r}') for i in range(50)]" >> target/scipy_check.csv
printf '[model]\npaper = true\n' > target/paper_model.toml
target/release/pinjoint sweep --input target/scipy_check.csv --output target/scipy_check_out.csv --params target/paper_model.toml
.venv/bin/python - <<'PY'
import json, subprocess, sys
o = json.loads(subprocess.check_output([".venv/bin/python", "benches/scipy_reference.py", "target/scipy_check_out.csv", "--limit", "50"]))
worst = max(o["max_difference"].values())
print("SciPy reference vs library, 50 points: largest difference", worst)
sys.exit(0 if worst < 1e-9 else 1)
PY

# --- Reference-FMUs' fmusim and the FMU Compliance Checker on the FMUs above: neither is on a
# package registry, so this runs only when FMUSIM / FMUCHECK name their binaries (docs/fmu.md,
# "The FMU Compliance Checker and Reference-FMUs' fmusim"); otherwise it says it skipped
step "external checkers"
PINJOINT_KEEP_FMUS=1 bash tests/checkers/run_external.sh

# --- memory: a C host dlopens the packaged FMU, 50 instantiate/step/free cycles under valgrind
# (the issue's 1000-cycle check is `bash tests/valgrind.sh 1000`)
step "valgrind"
bash tests/valgrind.sh 50
step "all passed"
