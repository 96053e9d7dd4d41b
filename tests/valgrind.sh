#!/usr/bin/env bash
# Memory check of the packaged FMU: a plain C host (tests/valgrind/fmu_cycles.c, with the
# hosts' shared tests/c/fmi2_host.h)
# dlopens binaries/linux64/PinJoint.so from target/fmu/PinJoint.fmu (or
# $PINJOINT_FMU) and runs instantiate / initialize / 20 steps / FMU state get, set,
# serialize, deserialize (also damaged) / rejected calls / terminate or not / free,
# CYCLES times, under valgrind. Fails on any invalid read or write, use of
# uninitialised memory, or definitely-lost block.
#
#   bash tests/valgrind.sh [CYCLES]     # default 50 (about 30 s); the issue's check is 1000
#
# Needs valgrind, a C compiler and python3 (for unzipping); builds the FMU if missing.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
CYCLES="${1:-50}"
FMU="${PINJOINT_FMU:-$ROOT/target/fmu/PinJoint.fmu}"
[[ -f "$FMU" ]] || cargo run --locked --release -q -p fmu_build >/dev/null

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
python3 -m zipfile -e "$FMU" "$work/fmu"
guid="$(python3 -c 'import sys, xml.etree.ElementTree as E; print(E.parse(sys.argv[1]).getroot().get("guid"))' "$work/fmu/modelDescription.xml")"
cc -std=c99 -D_POSIX_C_SOURCE=200809L -O1 -g -Wall -Werror -o "$work/fmu_cycles" tests/valgrind/fmu_cycles.c -ldl -lm

echo "valgrind: $CYCLES instantiate/step/free cycles of $(basename "$FMU")"
valgrind --error-exitcode=1 --leak-check=full --errors-for-leak-kinds=definite --show-leak-kinds=definite \
    --track-origins=yes --keep-debuginfo=yes --quiet \
    "$work/fmu_cycles" "$work/fmu/binaries/linux64/PinJoint.so" "$guid" "$CYCLES"
