#!/usr/bin/env bash
# Sets up everything on a fresh Debian 12 machine (as root): system packages, the pinned
# Python environment in .venv, and the build of ContactBody.fmu in build/.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(build-essential cmake ninja-build libeigen3-dev libsuitesparse-dev patchelf
          libgtest-dev valgrind python3 python3-venv python3-dev
          python3-getfem)  # the work-precision benchmark's GetFEM series and its test
missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    apt-get install -y -qq "${missing[@]}"
fi

# Debian's interpreter, not whatever python3 comes first on PATH.
if [ ! -x .venv/bin/python ] || ! cmp -s requirements.txt .venv/requirements.installed; then
    /usr/bin/python3 -m venv .venv
    .venv/bin/pip install -q --disable-pip-version-check -r requirements.txt
    cp requirements.txt .venv/requirements.installed
fi
# The contactbody package (examples, tests, contactbody-study), editable from this checkout.
.venv/bin/pip install -q --disable-pip-version-check --no-deps --no-build-isolation -e .

# fmpy's wheel also ships a cmake: use Debian's.
/usr/bin/cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DPython3_EXECUTABLE="$PWD/.venv/bin/python" >/dev/null
/usr/bin/cmake --build build
