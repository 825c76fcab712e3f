#!/usr/bin/env bash
# Sets up everything on a fresh Debian 12 machine (as root): system packages, the pinned
# Python environment in .venv, and the build of ContactBody.fmu in build/.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(build-essential cmake ninja-build libeigen3-dev libgtest-dev valgrind
          python3 python3-venv python3-dev
          # only benchmarks/portable_benchmark.py's build of the FMU before the portable one
          libsuitesparse-dev patchelf
          python3-getfem  # the work-precision benchmark's GetFEM series and its test
          locales  # a decimal-comma locale, below
          # the gmsh wheel's libgmsh (contactbody.meshes writes the test meshes with it)
          libglu1-mesa libgl1 libxcursor1 libxft2 libxinerama1 libgomp1)
install_missing() {
    local missing=()
    for p in "$@"; do
        dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
    done
    if [ ${#missing[@]} -gt 0 ]; then
        export DEBIAN_FRONTEND=noninteractive
        apt-get update -qq
        apt-get install -y -qq "${missing[@]}"
    fi
}
install_missing "${packages[@]}"
# A locale whose decimal point is a comma: tests_cpp/test_text_files.cpp checks that the FMU's
# numbers keep '.' under a host that sets one.
locale -a 2>/dev/null | grep -qx 'de_DE.utf8' || localedef -i de_DE -f UTF-8 de_DE.UTF-8
# What each platform of platforms.json needs to be built and tested here (win64: MinGW-w64, and
# wine to run it through fmpy's remoting).
read -r -a platform_packages <<< "$(/usr/bin/python3 -c 'import json; print(" ".join(a for p in json.load(open("platforms.json"))["platforms"] for a in p["apt_packages"]))')"
install_missing "${platform_packages[@]}"

# Debian's interpreter, not whatever python3 comes first on PATH.
if [ ! -x .venv/bin/python ] || ! cmp -s requirements.txt .venv/requirements.installed; then
    /usr/bin/python3 -m venv .venv
    .venv/bin/pip install -q --disable-pip-version-check -r requirements.txt
    cp requirements.txt .venv/requirements.installed
fi
# The contactbody package (examples, tests, contactbody-study), editable from this checkout.
.venv/bin/pip install -q --disable-pip-version-check --no-deps --no-build-isolation -e .

# wine's prefix, made once here rather than inside the first Windows test.
if [ ! -f "${WINEPREFIX:-$HOME/.wine}/system.reg" ]; then
    WINEDEBUG=-all /usr/lib/wine/wine64 wineboot --init >/dev/null 2>&1 || true
fi

# zig (requirements.txt's pin) outside the clone, in the user's cache folder: zig keeps the
# libc++ it builds for each target (about 100 s of 2 cores each, five zig platforms) under
# the path of its own installation, so a zig inside .venv builds them anew in every fresh
# clone, and one at a path that stays builds them once per machine.
zig_version=$(sed -n 's/^ziglang==//p' requirements.txt)
zig_home="${XDG_CACHE_HOME:-$HOME/.cache}/contactbody/ziglang-$zig_version"
if [ ! -x "$zig_home/ziglang/zig" ]; then
    rm -rf "$zig_home.partial"
    .venv/bin/pip install -q --disable-pip-version-check --no-deps --target "$zig_home.partial" \
        "ziglang==$zig_version"
    rm -rf "$zig_home"
    mv "$zig_home.partial" "$zig_home"
fi

# fmpy's wheel also ships a cmake: use Debian's. The build makes the portable FMUs: their
# Linux and macOS binaries with zig, their win64 ones with MinGW-w64 (CMakeLists.txt).
/usr/bin/cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DPython3_EXECUTABLE="$PWD/.venv/bin/python" -DZIG="$zig_home/ziglang/zig" >/dev/null
build_start=$SECONDS
/usr/bin/cmake --build build
echo "== setup: the build took $((SECONDS - build_start)) s =="
