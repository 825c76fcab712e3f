#!/usr/bin/env bash
# Runs build/ContactBody_fmi3.fmu in fmi-sim (crates.io: "A pure Rust FMI simulator"), an FMI
# 3.0 importer other than fmpy that this machine's registries provide (Reference-FMUs' fmusim
# is not in any of them). Not part of CI: building it takes about 10 minutes. It prints the
# importer's own messages; docs/contract.md ("FMI 3.0", importers) quotes them.
#   scripts/fmi_sim_check.sh [PREFIX]     (fmi-sim is installed into PREFIX, default /tmp/fmisim)
set -uo pipefail
cd "$(dirname "$0")/.."
prefix="${1:-/tmp/fmisim}"
if [ ! -x "$prefix/bin/fmi-sim" ]; then
    # its build generates bindings with libclang
    dpkg -s libclang-dev >/dev/null 2>&1 || DEBIAN_FRONTEND=noninteractive apt-get install -y -q libclang-dev
    cargo install --root "$prefix" fmi-sim --version 0.7.0 || exit 1
fi
fmi_sim="$prefix/bin/fmi-sim"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
root=$PWD
echo "== fmi-sim 0.7.0 on build/ContactBody_fmi3.fmu as built"
RUST_BACKTRACE=0 "$fmi_sim" --model build/ContactBody_fmi3.fmu co-simulation --step 1e-4 -f 0.002 2>&1 | head -1
echo "== the same with every unit attribute removed from its modelDescription"
(cd "$tmp" && mkdir fmu && cd fmu && unzip -q "$root/build/ContactBody_fmi3.fmu" &&
 sed -i 's/ unit="[^"]*"//g' modelDescription.xml && zip -qr ../no_units.fmu .)
RUST_BACKTRACE=0 RUST_LOG=error "$fmi_sim" --model "$tmp/no_units.fmu" co-simulation --step 1e-4 -f 0.002 2>&1 | grep -v "^Stack\|^ *[0-9]*:\|^ *at \|^$" | head -3
