#!/usr/bin/env bash
# Sets everything up (scripts/setup.sh), then runs the C++ solver tests and the pytest suite,
# then the same two against a build with AddressSanitizer and UndefinedBehaviorSanitizer.
# SKIP_SANITIZERS=1 skips that second job (for a quick local run).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
(cd build && /usr/bin/ctest --output-on-failure)
.venv/bin/python -m pytest python_tests "$@"

if [ "${SKIP_SANITIZERS:-0}" != 1 ]; then
    echo "== sanitizer job: ASan + UBSan build, same tests =="
    /usr/bin/cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DCONTACTBODY_SANITIZE=ON -DPython3_EXECUTABLE="$PWD/.venv/bin/python" >/dev/null
    /usr/bin/cmake --build build-sanitize
    export ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
    (cd build-sanitize && /usr/bin/ctest --output-on-failure)
    # Python itself is not instrumented: the ASan runtime is preloaded for the FMU, with
    # libstdc++ so that ASan can intercept C++ throws (Python does not load libstdc++ itself).
    LD_PRELOAD="$(gcc -print-file-name=libasan.so):$(gcc -print-file-name=libstdc++.so)" \
        CONTACTBODY_SANITIZED=1 \
        CONTACTBODY_FMU="$PWD/build-sanitize/ContactBody.fmu" \
        .venv/bin/python -m pytest python_tests "$@"
fi
