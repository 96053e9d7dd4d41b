#!/usr/bin/env bash
# Where the time goes: callgrind instruction counts of `pinjoint sweep` (20,000 rows, one
# thread) and of the PinJoint FMU step (20,000 steps of the fmpy benchmark's loop, full and
# boundary fidelity, from a plain C host), written to benches/results/ (beside the bench's
# plots, out of the repository's root) as callgrind_sweep.txt, callgrind_fmu_full.txt,
# callgrind_fmu_boundary.txt (the functions with the most instructions, self and inclusive),
# and callgrind_evaluate.txt (instructions per cold and warm library evaluation in the mixed
# regime).
#
#   bash benches/callgrind.sh [OUTDIR]      # default: benches/results
#
# (`sed -n 1,60p` rather than `head`: under pipefail, head closing the pipe early fails the script.)
# Needs valgrind (callgrind_annotate), a C compiler, python3; builds the binaries and FMU.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
OUT="${1:-$ROOT/benches/results}"
mkdir -p "$OUT"
cargo build --locked --release -q --bin pinjoint
cargo build --locked --release -q -p pinjoint --example icount
cargo run --locked --release -q -p fmu_build >/dev/null
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

python3 - "$work/in.csv" <<'PY'
import math, random, sys
random.seed(12)
with open(sys.argv[1], "w") as f:
    f.write("load,speed\n")
    for _ in range(20000):
        p = math.exp(random.uniform(math.log(5e3), math.log(60e3)))
        w = math.exp(random.uniform(math.log(1e-3), math.log(100))) * random.choice([-1, 1])
        f.write(f"{p!r},{w!r}\n")
PY
annotate() { # file title
    { echo "# $2"; echo "# valgrind --tool=callgrind, $(valgrind --version); callgrind_annotate (self, then inclusive)"; echo;
      callgrind_annotate --threshold=99 "$1" | sed -n 1,60p; echo; echo "## inclusive";
      callgrind_annotate --inclusive=yes --threshold=99 "$1" | sed -n 1,60p; } > "$3"
}
RAYON_NUM_THREADS=1 valgrind --tool=callgrind --callgrind-out-file="$work/sweep.out" \
    target/release/pinjoint sweep --input "$work/in.csv" --output "$work/out.csv" 2>/dev/null
annotate "$work/sweep.out" "pinjoint sweep, 20000 rows, RAYON_NUM_THREADS=1" "$OUT/callgrind_sweep.txt"

python3 -m zipfile -e target/fmu/PinJoint.fmu "$work/fmu"
read -r guid vo vl vt vm vf < <(python3 - "$work/fmu/modelDescription.xml" <<'PY'
import sys, xml.etree.ElementTree as E
r = E.parse(sys.argv[1]).getroot()
vr = {v.get("name"): v.get("valueReference") for v in r.iter("ScalarVariable")}
print(r.get("guid"), vr["angular_velocity"], vr["load"], vr["torque"], vr["friction_coefficient"], vr["fidelity"])
PY
)
cc -std=c99 -D_DEFAULT_SOURCE -O1 -o "$work/host" benches/fmu_step_host.c -ldl -lm
for f in full:0 boundary:2; do
    name="${f%%:*}"; code="${f##*:}"
    valgrind --tool=callgrind --callgrind-out-file="$work/fmu_$name.out" \
        "$work/host" "$work/fmu/binaries/linux64/PinJoint.so" "$guid" "$code" 20000 "$vo" "$vl" "$vt" "$vm" "$vf" >/dev/null 2>&1
    annotate "$work/fmu_$name.out" "PinJoint FMU, 20000 steps (set 2 inputs, doStep, get 2 outputs) at fidelity $name, C host" "$OUT/callgrind_fmu_$name.txt"
done
# Instructions per library evaluation in the mixed regime (20 kN, 6 rad/s): (run - empty loop) / N.
total() { valgrind --tool=callgrind --callgrind-out-file="$work/ic.out" target/release/examples/icount "$1" "$2" >/dev/null 2>&1
          callgrind_annotate "$work/ic.out" | awk '/PROGRAM TOTALS/ {gsub(",", "", $1); print $1}'; }
n=20000
none=$(total none $n)
{ echo "# Instructions per Joint evaluation, mixed regime (20 kN, 6 rad/s), examples/icount, N = $n"
  for m in cold warm; do t=$(total $m $n); echo "$m: $(( (t - none) / n )) instructions per evaluation"; done
} > "$OUT/callgrind_evaluate.txt"
cat "$OUT/callgrind_evaluate.txt"
grep -h "PROGRAM TOTALS" "$OUT"/callgrind_sweep.txt "$OUT"/callgrind_fmu_full.txt "$OUT"/callgrind_fmu_boundary.txt
