#!/usr/bin/env bash
# The FMUs under two external checkers that are not on any package registry, so the test
# command cannot install them: Reference-FMUs' `fmusim` (FMI 2.0 and 3.0, CS and ME) and the
# FMU Compliance Checker (FMI 2.0). Give their binaries in the environment:
#
#   FMUSIM=/path/to/fmusim FMUCHECK=/path/to/fmuCheck.linux64 bash tests/checkers/run_external.sh
#
# Either may be left out (that checker is skipped); with neither, the script says so and
# exits 0. docs/fmu.md ("Where the FMUs are tested") says how they were
# built and what they reported. Runs:
#   fmusim:   PinJoint FMI 2.0 and 3.0 as CS, ME (CVode) and ME (Euler) with zero_velocity.model
#             = band (the stateless law compared with the library), as CS and ME (CVode) with the
#             default presliding model, and PinJointRig
#             FMI 2.0 and 3.0 as CS (following the command_angle input), each with an input
#             CSV (a stroke at 20 kN, then a slow creep through the zero-speed band), every FMI
#             call logged: passes when fmusim exits 0, prints no message at level warning and
#             every call returned OK;
#   FMUCC:    PinJoint and PinJointRig with its defaults, and with the input CSVs (PinJoint ME
#             and CS, PinJointRig CS): passes when it reports 0 warnings and 0 errors, from the
#             checker and from the FMU. The checker cannot set parameters: PinJoint runs the
#             default presliding model; its ME run (explicit Euler) takes steps of 1e-4 s, inside
#             the explicit stability limit of the presliding state in sliding,
#             |omega| h < 2 (1 - beta) phi_s = 1.5e-4 rad (|omega| <= 0.8 rad/s here; at 0.01 s
#             the state's Euler update would grow its error 106-fold per step);
#   and every result CSV against the library (`pinjoint sweep` at the recorded inputs;
#   compare_torque.py): PinJoint's torque (band runs: every row; presliding runs: within the
#   presliding bound on every row; under CS in steady sliding the library's torque to 1e-12
#   relative; under ME, where the host's integrator owns the state, the law's torque at the
#   recorded presliding_torque on every row to 1e-9 of T: checked here on fmpy's CS and CVode
#   runs of the same input, not under fmusim or FMUCC, which are not installed here),
#   PinJointRig's slipping friction torque and μ, to 1e-12 relative.
# The FMUs are target/fmu/{,fmi3/}PinJoint{,Rig}.fmu, built host-only here unless
# PINJOINT_KEEP_FMUS is set (then they must exist, e.g. the --platforms all ones).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cd "$ROOT"
FMUSIM="${FMUSIM:-}"
FMUCHECK="${FMUCHECK:-}"
if [[ -z "$FMUSIM" && -z "$FMUCHECK" ]]; then
    echo "checkers: SKIPPED (fmusim and the FMU Compliance Checker are not on a package registry;"
    echo "          set FMUSIM and/or FMUCHECK to their binaries to run them, see docs/fmu.md)"
    exit 0
fi
for b in "$FMUSIM" "$FMUCHECK"; do
    [[ -z "$b" || -x "$b" ]] || { echo "checkers: $b is not an executable file"; exit 1; }
done

TARGET="${CARGO_TARGET_DIR:-$ROOT/target}"
[[ "$TARGET" = /* ]] || TARGET="$ROOT/$TARGET"
WORK="$TARGET/checkers"
rm -rf "$WORK"
mkdir -p "$WORK"
cargo build --locked --release -q -p pinjoint-cli
[[ -n "${PINJOINT_KEEP_FMUS:-}" ]] || cargo run --locked --release -q -p fmu_build >/dev/null
PINJOINT="$TARGET/release/pinjoint"
FMU2="$TARGET/fmu"
FMU3="$TARGET/fmu/fmi3"
for f in "$FMU2/PinJoint.fmu" "$FMU2/PinJointRig.fmu" "$FMU3/PinJoint.fmu" "$FMU3/PinJointRig.fmu"; do
    [[ -f "$f" ]] || { echo "checkers: $f is missing"; exit 1; }
done

# Inputs. PinJoint: 0-4 s a stroke at 20 kN, ω = 0.8 sin(πt/2) rad/s (out and back through
# zero at 2 s), then 4-6 s a creep ω = 0.012 sin(π(t-4)), mostly inside the 0.01 rad/s band.
# PinJointRig: 20 kN, command_angle = 0.7 sin(πt/3) rad (40° out and back in 3 s).
python3 - "$WORK" <<'PY'
import math, sys
work = sys.argv[1]
with open(f"{work}/joint_input.csv", "w") as f:
    f.write("time,angular_velocity,load\n")
    for i in range(601):
        t = i / 100
        w = 0.8 * math.sin(math.pi * t / 2) if t <= 4 else 0.012 * math.sin(math.pi * (t - 4))
        f.write(f"{t!r},{w!r},20000.0\n")
with open(f"{work}/rig_input.csv", "w") as f:
    f.write("time,load,command_angle\n")
    for i in range(301):
        t = i / 100
        f.write(f"{t!r},20000.0,{0.7 * math.sin(math.pi * t / 3)!r}\n")
PY

passed=0
failed=0
result() { # name, ok (0/1), text
    if [[ "$2" -eq 0 ]]; then passed=$((passed + 1)); echo "  ok    $1: $3"; else failed=$((failed + 1)); echo "  FAIL  $1: $3"; fi
}
compare() { # name, kind, csv, extra args...
    local out rc=0
    out=$(python3 tests/checkers/compare_torque.py --kind "$2" --pinjoint "$PINJOINT" --label "$1" "$3" "${@:4}") || rc=$?
    result "$1 vs library" "$rc" "${out#*: }"
}

if [[ -n "$FMUSIM" ]]; then
    echo "checkers: $("$FMUSIM" --version)"
    JOINT_OUT=(--output-variable angular_velocity --output-variable load --output-variable temperature
               --output-variable torque --output-variable friction_coefficient)
    RIG_OUT=(--output-variable load --output-variable angular_velocity --output-variable friction_torque
             --output-variable friction_coefficient --output-variable stuck --output-variable torque)
    fmusim_run() { # name, fmu, csv input, stop time, extra args...
        local name=$1 fmu=$2 input=$3 stop=$4 rc=0 msgs calls notok
        shift 4
        "$FMUSIM" --stop-time "$stop" --output-interval 0.01 --input-file "$input" --logging-on \
            --log-level warning --log-fmi-calls --fmi-log-file "$WORK/$name.calls" \
            --output-file "$WORK/$name.csv" "$@" "$fmu" >"$WORK/$name.log" 2>&1 || rc=$?
        msgs=$(grep -c . "$WORK/$name.log" || true)
        calls=$(grep -c ' -> ' "$WORK/$name.calls" || true)
        notok=$(grep ' -> ' "$WORK/$name.calls" | grep -vc ' -> OK$' || true)
        local ok=1
        [[ $rc -eq 0 && $msgs -eq 0 && $notok -eq 0 && $calls -gt 0 ]] && ok=0
        result "fmusim $name" $ok "exit $rc, $msgs messages at level warning, $calls FMI calls of which $notok not OK"
    }
    BAND=(--start-value zero_velocity.model 0)
    for v in 2 3; do
        d=$FMU2; [[ $v = 3 ]] && d=$FMU3
        fmusim_run "fmi${v}_joint_cs" "$d/PinJoint.fmu" "$WORK/joint_input.csv" 6 --interface-type cs "${BAND[@]}" "${JOINT_OUT[@]}"
        fmusim_run "fmi${v}_joint_me_cvode" "$d/PinJoint.fmu" "$WORK/joint_input.csv" 6 --interface-type me --solver cvode "${BAND[@]}" "${JOINT_OUT[@]}"
        fmusim_run "fmi${v}_joint_me_euler" "$d/PinJoint.fmu" "$WORK/joint_input.csv" 6 --interface-type me --solver euler "${BAND[@]}" "${JOINT_OUT[@]}"
        fmusim_run "fmi${v}_joint_cs_presliding" "$d/PinJoint.fmu" "$WORK/joint_input.csv" 6 --interface-type cs "${JOINT_OUT[@]}"
        fmusim_run "fmi${v}_joint_me_cvode_presliding" "$d/PinJoint.fmu" "$WORK/joint_input.csv" 6 --interface-type me --solver cvode "${JOINT_OUT[@]}" --output-variable presliding_torque
        compare "fmusim fmi${v}_joint_cs_presliding" joint-presliding "$WORK/fmi${v}_joint_cs_presliding.csv"
        compare "fmusim fmi${v}_joint_me_cvode_presliding" joint-presliding "$WORK/fmi${v}_joint_me_cvode_presliding.csv" --state --rtol 1e-9
        fmusim_run "fmi${v}_rig_cs" "$d/PinJointRig.fmu" "$WORK/rig_input.csv" 3 --interface-type cs --start-value use_command_input true "${RIG_OUT[@]}"
        for m in cs me_cvode me_euler; do compare "fmusim fmi${v}_joint_$m" joint "$WORK/fmi${v}_joint_$m.csv"; done
        compare "fmusim fmi${v}_rig_cs" rig "$WORK/fmi${v}_rig_cs.csv"
    done
    # The two standards' rig runs follow the same command: their results are identical.
    if cmp -s "$WORK/fmi2_rig_cs.csv" "$WORK/fmi3_rig_cs.csv"; then r=0; else r=1; fi
    result "fmusim rig FMI 2.0 = FMI 3.0" $r "result CSVs byte for byte"
fi

if [[ -n "$FMUCHECK" ]]; then
    echo "checkers: FMU Compliance Checker $("$FMUCHECK" -v 2>&1 | head -n 1)"
    fmucc_run() { # name, fmu, checker args...
        local name=$1 fmu=$2 rc=0 chk fmu_n
        shift 2
        "$FMUCHECK" -l 3 -e "$WORK/fmucc_$name.log" -o "$WORK/fmucc_$name.csv" "$@" "$fmu" >/dev/null 2>&1 || rc=$?
        # The summary: "FMU reported:\n\tN warning(s) and error(s)\nChecker reported:\n\tW Warning(s)\n\tE Error(s)"
        fmu_n=$(awk '/^FMU reported:/ {getline; print $1}' "$WORK/fmucc_$name.log")
        chk=$(awk '/^Checker reported:/ {getline; w=$1; getline; print w " warnings, " $1 " errors"}' "$WORK/fmucc_$name.log")
        local ok=1
        [[ $rc -eq 0 && "$fmu_n" == 0 && "$chk" == "0 warnings, 0 errors" ]] && ok=0
        result "FMUCC $name" $ok "exit $rc, checker: ${chk:-no summary}, FMU: ${fmu_n:-?} warnings and errors"
    }
    fmucc_run joint_default "$FMU2/PinJoint.fmu"
    fmucc_run rig_default "$FMU2/PinJointRig.fmu"
    # -f records every variable (the inputs too), -n 0 every step, -h the step size.
    fmucc_run joint_input_me "$FMU2/PinJoint.fmu" -k me -f -n 0 -h 1e-4 -s 6 -i "$WORK/joint_input.csv"
    fmucc_run joint_input_cs "$FMU2/PinJoint.fmu" -k cs -f -n 0 -h 0.01 -s 6 -i "$WORK/joint_input.csv"
    # The checker cannot set parameters: the rig follows its internal sine (use_command_input
    # = false) and takes the load from the file.
    fmucc_run rig_input_cs "$FMU2/PinJointRig.fmu" -k cs -f -n 0 -h 0.01 -s 3 -i "$WORK/rig_input.csv"
    compare "FMUCC joint_input_me" joint-presliding "$WORK/fmucc_joint_input_me.csv" --state --rtol 1e-9
    compare "FMUCC joint_input_cs" joint-presliding "$WORK/fmucc_joint_input_cs.csv"
    compare "FMUCC rig_input_cs" rig "$WORK/fmucc_rig_input_cs.csv"
fi

echo "checkers: $passed passed, $failed failed"
[[ $failed -eq 0 ]]
