#!/usr/bin/env bash
# The FMU harness: builds target/fmu/PinJoint.fmu and PinJointRig.fmu (FMI 2.0) and
# target/fmu/fmi3/*.fmu (FMI 3.0; test_interfaces.py validates and simulates all four,
# Co-Simulation and Model Exchange, against the library) and the library
# reference binaries (reference_points, rig_reference),
# installs requirements-test.txt into .venv (once), runs pytest on tests/fmu_harness and
# the Rust `fmi` crate importer against the packaged FMU.
#
# Needs: cargo, python3 with venv (Debian: python3-venv), for the fmi crate's
# bindgen step Debian's libclang-dev, and for Ecos (ecospy) Debian's libtbb12. libcosim
# (libcosimpy), pythonfmu and fmu-manipulation-toolbox are pinned in requirements-test.txt
# (tests/fmu_harness/test_cosim_masters.py: about 20 s).
# Set PINJOINT_SKIP_APT=1 to skip the apt step, PINJOINT_KEEP_FMUS=1 to keep target/fmu/*.fmu.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cd "$ROOT"

if [[ -z "${PINJOINT_SKIP_APT:-}" ]] && { ! ls /usr/lib/llvm-*/lib/libclang*.so* >/dev/null 2>&1 || ! ldconfig -p | grep -q 'libtbb\.so\.12'; }; then
    if command -v apt-get >/dev/null && [[ "$(id -u)" == 0 ]]; then
        apt-get update -qq && apt-get install -y -qq libclang-dev python3-venv libtbb12 >/dev/null
    else
        echo "run.sh: libclang-dev or libtbb12 is missing (needed by the fmi crate's bindgen, by ecospy)" >&2
    fi
fi

# PINJOINT_KEEP_FMUS=1: test the FMUs already in target/fmu (e.g. the all-platform ones of
# tests/platforms/run.sh) instead of rebuilding them for this host only.
if [[ -z "${PINJOINT_KEEP_FMUS:-}" || ! -f target/fmu/PinJoint.fmu || ! -f target/fmu/PinJointRig.fmu ]]; then
    cargo run --locked --release -q -p fmu_build
fi
cargo build --locked --release -q -p pinjoint --example reference_points --example rig_reference --example presliding_reference

VENV="${PINJOINT_VENV:-$ROOT/.venv}"
if ! "$VENV/bin/python" -c "import fmpy, numpy, pytest, ecospy, scipy, libcosimpy, pythonfmu, fmu_manipulation_toolbox" 2>/dev/null; then
    python3 -m venv "$VENV"
    "$VENV/bin/pip" install -q -r requirements-test.txt
fi

export PINJOINT_FMU="$ROOT/target/fmu/PinJoint.fmu"
export PINJOINT_RIG_FMU="$ROOT/target/fmu/PinJointRig.fmu"
# The co-simulation masters (libcosim, Ecos, the toolbox's container) load native libraries
# into the test process: their scenes run in a pytest process of their own, so that nothing
# they leave behind reaches the other tests (a later fmi2SetReal segfaulted in one CI run of
# the whole directory in one process).
"$VENV/bin/python" -m pytest -q tests/fmu_harness --ignore=tests/fmu_harness/test_cosim_masters.py "$@"
"$VENV/bin/python" -m pytest -q tests/fmu_harness/test_cosim_masters.py "$@"
cargo test --locked --release -q -p pinjoint-fmu --test fmi_crate_importer --test fmi_crate_rig_importer --test fmi_crate_misuse
