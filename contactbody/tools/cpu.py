"""What this machine's CPU has, from the flags Linux reports in /proc/cpuinfo: the tests' and
benchmarks' own reading, independent of the FMU's (solver/linalg/supernodal_dispatch.cpp)."""
import pathlib
import platform

X86_64_V4 = {"avx2", "fma", "avx512f", "avx512dq", "avx512vl", "avx512bw"}


def flags() -> set:
    """The first CPU's flags (empty where /proc/cpuinfo has none, as on aarch64)."""
    for line in pathlib.Path("/proc/cpuinfo").read_text().splitlines():
        if line.startswith("flags"):
            return set(line.split(":")[1].split())
    return set()


def fastest_supernodal_kernels() -> str:
    """The supernodal kernel set an x86_64 binary should pick here: what the log's
    `contact solve:` line names."""
    if platform.machine() != "x86_64":
        return "baseline"
    have = flags()
    if X86_64_V4 <= have:
        return "x86-64-v4 (AVX-512)"
    return "x86-64-v3 (AVX2, FMA)" if {"avx2", "fma"} <= have else "baseline"
