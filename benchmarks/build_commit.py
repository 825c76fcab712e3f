"""Builds an earlier commit of this project once, for benchmarks that compare against it: a git
worktree in build-before/COMMIT/src, built in build-before/COMMIT/build (gitignored)."""
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]


def build_commit(commit, targets, cmake_options=()):
    """The build folder of `commit` with `targets` built (CMake Release, Ninja)."""
    src = ROOT / "build-before" / commit / "src"
    build = ROOT / "build-before" / commit / "build"
    if not src.exists():
        subprocess.run(["git", "-C", str(ROOT), "worktree", "add", "--detach", str(src), commit],
                       check=True)
    if not (build / "build.ninja").exists():
        subprocess.run(["/usr/bin/cmake", "-S", str(src), "-B", str(build), "-G", "Ninja",
                        "-DCMAKE_BUILD_TYPE=Release", f"-DPython3_EXECUTABLE={sys.executable}",
                        *cmake_options], check=True, stdout=subprocess.DEVNULL)
    subprocess.run(["/usr/bin/cmake", "--build", str(build), "--target", *targets], check=True,
                   stdout=subprocess.DEVNULL)
    return build
