#!/usr/bin/env bash
# Sets everything up and writes the release folder dist/ (or the folder given): the FMUs for
# every platform, the example SSPs, the contactbody wheel that carries the FMUs, the licences
# and SHA256SUMS (contactbody/tools/release.py says what and why).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
.venv/bin/python -m contactbody.tools.release "$@"
