"""The supernodal Cholesky (solver/linalg/supernodal_cholesky) against the body's factor today
(TrailingCholesky: CHOLMOD's simplicial Cholesky and the supernodal LU, both on CHOLMOD's
fill-reducing order) on factor_kernels.py's bodies, all three in the same order and in one
process per body (bench_supernodal), beside the machine's own dense rate: Eigen's GEMM at
n = 1000 (the baseline build, in the same process) and numpy's OpenBLAS at n = 2000 (one thread,
just before each body). The supernodal Cholesky runs with the baseline kernels and with the
fastest this CPU has (linalg/supernodal_kernels.hpp). A factorization is the best of three.
--large adds cost3d.py's 111k-node hemisphere, the supernodal Cholesky alone (today's factors
take tens of minutes there). Beside each 3D body, and a box of tetrahedra of 45,000 unknowns:
what a user would pick instead, CHOLMOD's supernodal Cholesky with OpenBLAS on one thread
(cholmod_supernodal.c, built here against Debian's libcholmod3 and libopenblas0-serial:
`apt-get install libsuitesparse-dev libopenblas0-serial`; GPL, so never in an FMU) on the same
K, in its own order and in ours.

Writes benchmarks/results/supernodal.{json,md}. About four minutes; with --large, 32 (2026-12-07).
--tables writes supernodal.md again from supernodal.json.

    .venv/bin/python benchmarks/supernodal.py [--build DIR]
"""
import argparse
import json
import os
import pathlib
import subprocess
import tempfile
import time

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
import numpy as np  # noqa: E402

from contactbody import meshes
from contactbody.tools import cpu
from factor_kernels import HEMISPHERES, RECTANGLES

ROOT = pathlib.Path(__file__).resolve().parents[1]
OUT = ROOT / "benchmarks" / "results"


def openblas_gflops(n=2000, repeats=3):
    """numpy's a @ b at n, one thread: the best of `repeats`."""
    a, b = np.random.rand(n, n), np.random.rand(n, n)
    best = 1e30
    for _ in range(repeats):
        tic = time.perf_counter()
        a @ b
        best = min(best, time.perf_counter() - tic)
    return 2 * n ** 3 / best * 1e-9


def read_bandwidth(megabytes=800, repeats=3):
    """Bytes a second that one core reads from memory: the fastest of numpy's sum, max and dot
    (OpenBLAS's ddot of the array with itself) over an array far larger than the caches, each
    the best of `repeats`. sum alone is not a floor: on 2026-12-07's machine its pairwise
    summation read 8.6 GB/s where max read 14.6 and dot 12.7, and the 111k-node solve streamed
    its factor at 13.7 (docs/decisions.md, "The supernodal factor on several threads")."""
    a = np.ones(megabytes * 2 ** 20 // 8)
    best = 1e30
    for read in (a.sum, a.max, lambda: a.dot(a)):
        for _ in range(repeats):
            tic = time.perf_counter()
            read()
            best = min(best, time.perf_counter() - tic)
    return a.nbytes / best


OPENBLAS = pathlib.Path("/usr/lib/x86_64-linux-gnu/openblas-serial/libopenblas.so.0")


def openblas_core():
    """The OPENBLAS_CORETYPE CHOLMOD's OpenBLAS runs with: Debian's 0.3.21 takes a CPU newer than
    it knows for Prescott (SSE3; 2026-12-07's Xeon, family 6 model 207, factored at 10-13 GFlop/s
    there), so the kernels are named from the CPU's flags: SkylakeX with AVX-512, Haswell with
    AVX2 and FMA."""
    kernels = cpu.fastest_supernodal_kernels()
    return {"x86-64-v4 (AVX-512)": "SkylakeX", "x86-64-v3 (AVX2, FMA)": "Haswell"}.get(kernels, "Prescott")


def build_cholmod(folder):
    """cholmod_supernodal.c against Debian's CHOLMOD, its BLAS calls bound to OpenBLAS serial."""
    header = pathlib.Path("/usr/include/suitesparse/cholmod.h")
    if not header.exists() or not OPENBLAS.exists():
        raise SystemExit("supernodal.py compares with CHOLMOD and OpenBLAS from Debian's packages: "
                         "apt-get install libsuitesparse-dev libopenblas0-serial")
    program = pathlib.Path(folder) / "cholmod_supernodal"
    subprocess.run(["gcc", "-O2", "-o", str(program), str(ROOT / "benchmarks" / "cholmod_supernodal.c"),
                    str(OPENBLAS), "-lcholmod"], check=True)
    return program


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=str(ROOT / "build"))
    parser.add_argument("--large", action="store_true", help="also the 111k-node hemisphere")
    parser.add_argument("--tables", action="store_true",
                        help="only write supernodal.md again from supernodal.json")
    args = parser.parse_args()
    if args.tables:
        write_tables(json.loads((OUT / "supernodal.json").read_text())["rows"])
        return
    program = pathlib.Path(args.build) / "bench_supernodal"
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        cholmod = build_cholmod(tmp)
        cases = [(f"rectangle nx = {n}", f"rect:{n}", 2, []) for n in RECTANGLES]
        for h in HEMISPHERES:
            path = meshes.hemisphere(pathlib.Path(tmp) / f"hemisphere_{h:.3g}.msh", radius=0.05,
                                     contact_size=h, far_size=0.01, fine_distance=0.0045,
                                     refine_distance=0.025, contact_angle=25.0)
            cases.append((f"hemisphere h = {1e3 * h:.3g} mm", str(path), 3, []))
        box = meshes.block(pathlib.Path(tmp) / "box.msh", cells=24)
        cases.append(("box of tetrahedra, 24³ cells", str(box), 3, []))
        if args.large:
            path = meshes.hemisphere(pathlib.Path(tmp) / "hemisphere_111k.msh", radius=0.05,
                                     contact_size=1.25e-4, far_size=3e-3, fine_distance=0.0045,
                                     refine_distance=0.025, contact_angle=25.0)
            cases.append(("hemisphere, 111k nodes", str(path), 3, ["1", "supernodal"]))
        for name, mesh, dim, extra in cases:
            gemm, bandwidth = openblas_gflops(), read_bandwidth()
            prefix = str(pathlib.Path(tmp) / "K")
            out = subprocess.run([str(program), mesh, str(dim), *extra], check=True,
                                 capture_output=True, text=True,
                                 env={**os.environ, "WRITE_K": prefix} if dim == 3 else None).stdout
            rows.append({"body": name, "dimension": dim, "openblas_gflops": gemm,
                         "read_bandwidth_gb": bandwidth * 1e-9, **json.loads(out)})
            if dim == 3:
                core = openblas_core()
                out = subprocess.run([str(cholmod), prefix + ".mtx", prefix + ".perm", extra[0] if extra else "3"],
                                     check=True, capture_output=True, text=True,
                                     env={**os.environ, "OPENBLAS_CORETYPE": core}).stdout
                rows[-1]["cholmod_openblas"] = {**json.loads(out), "openblas_core": core}
            print(json.dumps(rows[-1]), flush=True)
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / "supernodal.json").write_text(json.dumps({"rows": rows}, indent=1))
    write_tables(rows)


def write_tables(rows):
    lines = ["# The supernodal Cholesky against the body's factor today", "",
             "`benchmarks/supernodal.py`: K = A + 4/dt² M (dt = 1e-6 s) on the free dofs, the "
             "factors in CHOLMOD's fill-reducing order, one process per body; a factorization the "
             "best of three (one at 111k nodes), a solve the mean of ten. GFlop/s count the "
             "Cholesky's flops (the panels' own, with the amalgamation's zeros; the supernodal LU "
             "does twice as many). GEMM: Eigen's baseline build at n = 1000 in the same process, "
             "numpy's OpenBLAS at n = 2000 on one thread just before. Supernodal: the baseline "
             "kernels / the fastest this CPU has; then the fastest on two threads (this machine's "
             "two cores), whose solution must equal the one thread's bit for bit. Top share: the "
             "flops of the supernodes above the subtrees that run side by side. Peak MB: the process's "
             "peak before the supernodal LU of the same K that runs after the Cholesky "
             "(`cholesky_peak_memory_mb`); in a row without that field (2026-12-07's run and before) the "
             "whole process's, with that LU's twice as large factor.", "",
             "| body | unknowns | supernodes | factor s: simplicial / LU / supernodal | "
             "supernodal over simplicial / over LU | fast kernels: set, factor s | "
             "GFlop/s: supernodal / fast / Eigen GEMM / OpenBLAS GEMM | "
             "solve ms: simplicial / LU / supernodal | solution difference: to simplicial / fast to baseline | "
             "2 threads: factor s, speed-up over 1, same bits | top share | peak MB |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]

    def seconds(r, key):
        return f"{r[key]['factor_seconds']:.3g}" if key in r else "–"

    def ratio(r, key):
        s = r["supernodal_cholesky"]
        return f"{r[key]['factor_seconds'] / s['factor_seconds']:.2f}×" if key in r else "–"

    def solve(r, key):
        return f"{1e3 * r[key]['solve_seconds']:.3g}" if key in r else "–"

    for r in rows:
        s, fast = r["supernodal_cholesky"], r["supernodal_cholesky_fast"]
        two = r["supernodal_cholesky_fast_2_threads"]
        lines.append(
            f"| {r['body']} | {r['unknowns']} | {s['supernodes']} | "
            f"{seconds(r, 'simplicial')} / {seconds(r, 'supernodal_lu')} / {s['factor_seconds']:.3g} | "
            f"{ratio(r, 'simplicial')} / {ratio(r, 'supernodal_lu')} | "
            f"{fast['kernel_set']}, {fast['factor_seconds']:.3g} | "
            f"{s['gflops']:.3g} / {fast['gflops']:.3g} / {r['gemm_gflops']:.3g} / {r['openblas_gflops']:.3g} | "
            f"{solve(r, 'simplicial')} / {solve(r, 'supernodal_lu')} / {1e3 * s['solve_seconds']:.3g} | "
            f"{s['difference']:.1e} / {fast['difference_to_baseline']:.1e} | "
            f"{two['factor_seconds']:.3g}, {fast['factor_seconds'] / two['factor_seconds']:.2f}×, "
            f"{'yes' if two['same_bits_as_one_thread'] else 'NO'} | {two['top_share']:.2f} | "
            f"{r.get('cholesky_peak_memory_mb', r['peak_memory_mb']):.0f} |")
    lines += ["", "## Against CHOLMOD's supernodal Cholesky with OpenBLAS, and a solve against memory", "",
              "The same K; CHOLMOD (Debian's libcholmod3 with libopenblas0-serial, one thread; OpenBLAS's "
              "kernels named by OPENBLAS_CORETYPE from the CPU's flags, `openblas_core`, where a row has "
              "that field; a row without it ran what OpenBLAS 0.3.21 detected, Prescott (SSE3) on "
              "2026-12-07's Xeon, which it does not know) in its "
              "own order (its analysis picks it; ours is CHOLMOD's simplicial analysis's order, so the "
              "flops may differ), a factorization the best of three (one at 111k nodes). Ours: the "
              "fastest kernels, one thread and two. A solve streams the factor twice (forward and "
              "backward): its floor is 2 × 8 bytes × nonzeros over the read bandwidth measured just "
              "before (the fastest of numpy's sum, max and dot over 800 MB, one core).", "",
              "| body | unknowns | CHOLMOD: analysis s, factor s, GFlop | ours: factor s, GFlop | "
              "ours over CHOLMOD: 1 thread / 2 threads | solve ms: CHOLMOD / ours | "
              "read GB/s | our solve over streaming the factor twice |",
              "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        if "cholmod_openblas" not in r:
            continue
        c, fast = r["cholmod_openblas"]["own_order"], r["supernodal_cholesky_fast"]
        two = r["supernodal_cholesky_fast_2_threads"]
        stream = 2 * 8 * fast["nonzeros"] / (r["read_bandwidth_gb"] * 1e9)
        lines.append(
            f"| {r['body']} | {r['unknowns']} | {c['analysis_seconds']:.3g}, {c['factor_seconds']:.3g}, "
            f"{c['flops'] * 1e-9:.3g} | {fast['factor_seconds']:.3g}, {fast['flops'] * 1e-9:.3g} | "
            f"{fast['factor_seconds'] / c['factor_seconds']:.2f}× / {two['factor_seconds'] / c['factor_seconds']:.2f}× | "
            f"{1e3 * c['solve_seconds']:.3g} / {1e3 * fast['solve_seconds']:.3g} | {r['read_bandwidth_gb']:.3g} | "
            f"{fast['solve_seconds'] / stream:.2f}× |")
    (OUT / "supernodal.md").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
