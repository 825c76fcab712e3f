#!/usr/bin/env bash
# Sets everything up, simulates the paper's section 7 scene with the four mass matrices
# through fmpy and writes the plots to examples/output/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
.venv/bin/python examples/paper_scene.py "$@"
