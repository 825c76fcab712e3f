#!/usr/bin/env bash
# Sets everything up (scripts/setup.sh), then runs the C++ solver tests and the pytest suite on
# the FMU users get (build/ContactBody.fmu: its linux64 binary), then the other platforms' jobs
# (platforms.json: the aarch64 binary under qemu-user, the win64 binary under wine through
# fmpy's remoting), then the C++ tests and the pytest suite against a native build with
# AddressSanitizer and UndefinedBehaviorSanitizer.
# SKIP_PLATFORMS=1 and SKIP_SANITIZERS=1 skip those jobs (for a quick local run).
# The two pytest suites run on every core (pytest-xdist, a module's tests on one worker, so that
# its fixtures are made once); the platform jobs run serially (wine's remoting uses one port).
# Each phase prints its time (`== NAME: N s ==`), so that CI's 30 minutes can be accounted for.
set -euo pipefail
cd "$(dirname "$0")/.."
timed() {  # timed NAME COMMAND...: runs the command, then says how long it took
    local name=$1 start=$SECONDS
    shift
    "$@"
    echo "== $name: $((SECONDS - start)) s (CI so far: $SECONDS s) =="
}
timed setup scripts/setup.sh
timed ctest bash -c 'cd build && /usr/bin/ctest --output-on-failure'
timed pytest .venv/bin/python -m pytest -n auto --dist loadscope python_tests "$@"

if [ "${SKIP_PLATFORMS:-0}" != 1 ]; then
    # Each other platform's job, as platforms.json says.
    timed platform-jobs .venv/bin/python -m contactbody.tools.platforms test-jobs "$@"
fi

if [ "${SKIP_SANITIZERS:-0}" != 1 ]; then
    echo "== sanitizer job: ASan + UBSan build, same tests =="
    # Native (gcc), not the portable binaries: the sanitizer runtimes are gcc's.
    /usr/bin/cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DCONTACTBODY_SANITIZE=ON -DCONTACTBODY_PORTABLE=OFF -DPython3_EXECUTABLE="$PWD/.venv/bin/python" >/dev/null
    timed sanitizer-build /usr/bin/cmake --build build-sanitize
    export ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
    timed sanitizer-ctest bash -c 'cd build-sanitize && /usr/bin/ctest --output-on-failure'
    # Python itself is not instrumented: the ASan runtime is preloaded for the FMU, with
    # libstdc++ so that ASan can intercept C++ throws (Python does not load libstdc++ itself).
    # The FMI 2.0 fuzz runs 4000 sequences in the main job and 2000 here, as the FMI 3.0 fuzz
    # runs fewer under the sanitizer: the suite stays within its 15 minutes.
    timed sanitizer-pytest env LD_PRELOAD="$(gcc -print-file-name=libasan.so):$(gcc -print-file-name=libstdc++.so)" \
        CONTACTBODY_SANITIZED=1 FUZZ_EXAMPLES="${FUZZ_EXAMPLES:-2000}" \
        CONTACTBODY_FMU="$PWD/build-sanitize/ContactBody.fmu" \
        .venv/bin/python -m pytest -n auto --dist loadscope python_tests "$@"
fi
