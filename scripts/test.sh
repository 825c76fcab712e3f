#!/usr/bin/env bash
# Sets everything up (scripts/setup.sh), then runs the C++ solver tests and the pytest suite.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
(cd build && /usr/bin/ctest --output-on-failure)
.venv/bin/python -m pytest python_tests "$@"
