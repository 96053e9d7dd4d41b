#!/usr/bin/env bash
# The cross-platform builds of the FMU binary, each one run (or, for macOS, inspected):
#
#  1. installs the tools (Debian: MinGW-w64 gcc, wine, aarch64 gcc and glibc, qemu-user;
#     rustup targets; cargo-zigbuild and ziglang from PyPI into target/platforms/venv);
#  2. `fmu_build --platforms all`: target/fmu/PinJoint.fmu and PinJointRig.fmu with
#     binaries/linux64 (glibc 2.17, no libgcc_s), win64 and darwin64 (universal), and
#     the FMI 3.0 platform set in target/fmu/platforms/;
#  3. fmu_build/tests/platform_binaries.rs: exports, needed libraries, glibc versions,
#     Mach-O load commands of every binary;
#  4. tests/platforms/host.c (with the C hosts' shared tests/c/fmi2_host.h), compiled natively, for Windows and for aarch64 Linux, drives
#     PinJoint and PinJointRig through FMI 2.0 with the native build (reference), the
#     FMU's linux64 binary, the FMU's win64 DLL under wine and the aarch64 library under
#     qemu-aarch64; compare.py checks them against the reference and the library.
#
# Set PINJOINT_SKIP_APT=1 to skip the apt step. Prints the time of each stage.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cd "$ROOT"
TARGET="${CARGO_TARGET_DIR:-$ROOT/target}"
[[ "$TARGET" = /* ]] || TARGET="$ROOT/$TARGET"
WORK="$TARGET/platforms"
mkdir -p "$WORK"
stage_start=$SECONDS
stage() { echo "platforms: $1 ($((SECONDS - stage_start)) s since the previous stage)"; stage_start=$SECONDS; }

# --- 1. tools ----------------------------------------------------------------------
debs=()
command -v x86_64-w64-mingw32-gcc >/dev/null || debs+=(gcc-mingw-w64-x86-64)
command -v wine >/dev/null || debs+=(wine wine64)
command -v aarch64-linux-gnu-gcc >/dev/null || debs+=(gcc-aarch64-linux-gnu libc6-dev-arm64-cross)
command -v qemu-aarch64 >/dev/null || debs+=(qemu-user)
if [[ ${#debs[@]} -gt 0 && -z "${PINJOINT_SKIP_APT:-}" ]]; then
    SUDO=""; [[ "$(id -u)" -eq 0 ]] || SUDO="sudo"
    $SUDO apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${debs[@]}" >/dev/null
fi
rustup target add x86_64-unknown-linux-gnu aarch64-unknown-linux-gnu x86_64-pc-windows-gnu \
    x86_64-apple-darwin aarch64-apple-darwin 2>/dev/null || rustup target add x86_64-unknown-linux-gnu \
    aarch64-unknown-linux-gnu x86_64-pc-windows-gnu x86_64-apple-darwin aarch64-apple-darwin
VENV="$WORK/venv"
if ! "$VENV/bin/cargo-zigbuild" --version >/dev/null 2>&1 || ! "$VENV/bin/python" -m ziglang version >/dev/null 2>&1; then
    python3 -m venv "$VENV"
    "$VENV/bin/pip" install -q -r tests/platforms/requirements.txt
fi
export PATH="$VENV/bin:$PATH"
stage "tools installed"

# --- 2. builds ---------------------------------------------------------------------
cargo run --locked --release -q -p fmu_build -- --platforms all
cargo build --locked --release -q --lib -p pinjoint-fmu       # the native reference build (target/release)
cargo build --locked --release -q -p pinjoint --example reference_points
stage "built the FMU binary for every platform"

# --- 3. what the binaries export and need -------------------------------------------
cargo test --locked --release -q -p fmu_build --test platform_binaries -- --ignored --nocapture
stage "binaries inspected"

# --- 4. run each binary --------------------------------------------------------------
run="$WORK/run"
rm -rf "$run"; mkdir -p "$run"/{fmu,rig,native,win64,aarch64}
python3 -m zipfile -e "$TARGET/fmu/PinJoint.fmu" "$run/fmu"
python3 -m zipfile -e "$TARGET/fmu/PinJointRig.fmu" "$run/rig"
guid() { python3 -c 'import sys, xml.etree.ElementTree as E; print(E.parse(sys.argv[1]).getroot().get("guid"))' "$1"; }
PJ_GUID="$(guid "$run/fmu/modelDescription.xml")"
RIG_GUID="$(guid "$run/rig/modelDescription.xml")"
# The FMUs carry the libraries the inspection test read.
cmp "$run/fmu/binaries/linux64/PinJoint.so" "$TARGET/fmu/platforms/x86_64-linux/libpinjoint_fmu.so"
cmp "$run/fmu/binaries/win64/PinJoint.dll" "$TARGET/fmu/platforms/x86_64-windows/pinjoint_fmu.dll"
cmp "$run/fmu/binaries/darwin64/PinJoint.dylib" "$TARGET/fmu/platforms/universal-darwin/libpinjoint_fmu.dylib"

CFLAGS=(-std=c99 -O2 -Wall -Wextra -Werror)
cc "${CFLAGS[@]}" -D_POSIX_C_SOURCE=200809L -o "$run/native/host" tests/platforms/host.c -ldl -lm
x86_64-w64-mingw32-gcc "${CFLAGS[@]}" -o "$run/win64/host.exe" tests/platforms/host.c
x86_64-w64-mingw32-gcc -O2 -Wall -Werror -shared -o "$run/win64/bcryptprimitives.dll" tests/platforms/bcryptprimitives.c -ladvapi32
aarch64-linux-gnu-gcc "${CFLAGS[@]}" -D_POSIX_C_SOURCE=200809L -o "$run/aarch64/host" tests/platforms/host.c -ldl -lm
cp "$run/fmu/binaries/win64/PinJoint.dll" "$run/win64/PinJoint.dll"
cp "$run/rig/binaries/win64/PinJointRig.dll" "$run/win64/PinJointRig.dll"
cp "$TARGET/fmu/platforms/aarch64-linux/libpinjoint_fmu.so" "$run/aarch64/PinJoint.so"
cp "$TARGET/fmu/platforms/aarch64-linux/libpinjoint_fmu.so" "$run/aarch64/PinJointRig.so"
stage "hosts compiled"

# Reference: the native build of this machine (cargo build, target/release).
"$run/native/host" "$TARGET/release/libpinjoint_fmu.so" "$PJ_GUID" "$TARGET/release/libpinjoint_fmu.so" "$RIG_GUID" > "$run/native.txt"
# The FMU's linux64 binary (glibc 2.17, zig-linked).
"$run/native/host" "$run/fmu/binaries/linux64/PinJoint.so" "$PJ_GUID" "$run/rig/binaries/linux64/PinJointRig.so" "$RIG_GUID" > "$run/linux64.txt"
stage "native runs"

# The FMU's win64 DLL under wine, in a private prefix (created on first use: wineboot).
export WINEPREFIX="$WORK/wineprefix" WINEDEBUG=-all WINEDLLOVERRIDES="mscoree,mshtml="
if [[ ! -f "$WINEPREFIX/system.reg" ]]; then
    wineboot --init >/dev/null 2>&1 || true
    wineserver -w || true
    stage "wine prefix created (wineboot)"
fi
(cd "$run/win64" && wine host.exe PinJoint.dll "$PJ_GUID" PinJointRig.dll "$RIG_GUID") | tr -d '\r' > "$run/win64.txt"
stage "win64 run under wine"

# The aarch64 library under qemu-user, with Debian's aarch64 glibc.
qemu-aarch64 -L /usr/aarch64-linux-gnu "$run/aarch64/host" "$run/aarch64/PinJoint.so" "$PJ_GUID" "$run/aarch64/PinJointRig.so" "$RIG_GUID" > "$run/aarch64.txt"
stage "aarch64 run under qemu"

python3 tests/platforms/compare.py --reference "$run/native.txt" --library "$TARGET/release/examples/reference_points" \
    linux64="$run/linux64.txt" win64="$run/win64.txt" aarch64-linux="$run/aarch64.txt"
echo "platforms: every binary built; linux64, win64 (wine) and aarch64-linux (qemu) run and agree; darwin64 inspected, not run"
