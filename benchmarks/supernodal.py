"""The supernodal Cholesky (solver/linalg/supernodal_cholesky) against the body's factor today
(TrailingCholesky: CHOLMOD's simplicial Cholesky and the supernodal LU, both on CHOLMOD's
fill-reducing order) on factor_kernels.py's bodies, all three in the same order and in one
process per body (bench_supernodal), beside the machine's own dense rate in the same process
(Eigen's GEMM at n = 1000, one thread). A factorization is the best of three.

Writes benchmarks/results/supernodal.{json,md}. About two minutes.

    .venv/bin/python benchmarks/supernodal.py [--build DIR]
"""
import argparse
import json
import pathlib
import subprocess
import tempfile

from contactbody import meshes
from factor_kernels import HEMISPHERES, RECTANGLES

ROOT = pathlib.Path(__file__).resolve().parents[1]
OUT = ROOT / "benchmarks" / "results"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=str(ROOT / "build"))
    args = parser.parse_args()
    program = pathlib.Path(args.build) / "bench_supernodal"
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        cases = [(f"rectangle nx = {n}", f"rect:{n}", 2) for n in RECTANGLES]
        for h in HEMISPHERES:
            path = meshes.hemisphere(pathlib.Path(tmp) / f"hemisphere_{h:.3g}.msh", radius=0.05,
                                     contact_size=h, far_size=0.01, fine_distance=0.0045,
                                     refine_distance=0.025, contact_angle=25.0)
            cases.append((f"hemisphere h = {1e3 * h:.3g} mm", str(path), 3))
        for name, mesh, dim in cases:
            out = subprocess.run([str(program), mesh, str(dim)], check=True, capture_output=True,
                                 text=True).stdout
            rows.append({"body": name, "dimension": dim, **json.loads(out)})
            print(json.dumps(rows[-1]), flush=True)
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / "supernodal.json").write_text(json.dumps({"rows": rows}, indent=1))
    lines = ["# The supernodal Cholesky against the body's factor today", "",
             "`benchmarks/supernodal.py`: K = A + 4/dt² M (dt = 1e-6 s) on the free dofs, the three "
             "factors in CHOLMOD's fill-reducing order, one process per body; a factorization the "
             "best of three, a solve the mean of ten. GFlop/s count the Cholesky's flops (CHOLMOD's "
             "count for the simplicial factor and the LU, which does twice as many; the "
             "panels' own, with the amalgamation's zeros, for the supernodal Cholesky). GEMM: "
             "Eigen's at n = 1000, one thread, in the same process.", "",
             "| body | unknowns | supernodes | nonzeros, simplicial / supernodal | factor s: simplicial / LU / supernodal Cholesky | "
             "supernodal over simplicial / over LU | GFlop/s: supernodal / GEMM | solve ms: simplicial / LU / supernodal | solution difference |",
             "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        s, c, lu = r["supernodal_cholesky"], r["simplicial"], r["supernodal_lu"]
        lines.append(
            f"| {r['body']} | {r['unknowns']} | {s['supernodes']} | {r['cholesky_nonzeros']:.3g} / {s['nonzeros']:.3g} | "
            f"{c['factor_seconds']:.3g} / {lu['factor_seconds']:.3g} / {s['factor_seconds']:.3g} | "
            f"{c['factor_seconds'] / s['factor_seconds']:.2f}× / {lu['factor_seconds'] / s['factor_seconds']:.2f}× | "
            f"{s['gflops']:.3g} / {r['gemm_gflops']:.3g} | "
            f"{1e3 * c['solve_seconds']:.3g} / {1e3 * lu['solve_seconds']:.3g} / {1e3 * s['solve_seconds']:.3g} | "
            f"{s['difference']:.1e} |")
    (OUT / "supernodal.md").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
