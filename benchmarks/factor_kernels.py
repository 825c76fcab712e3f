"""The refactorable factor's two kernels against each other (issue 55): CHOLMOD's simplicial
Cholesky (LGPL; its supernodal module is GPL) and Eigen's supernodal LU (MPL-2) on the same
fill-reducing order, on 2D rectangles and 3D hemispheres (the sparse contact solve refactors
this factor whenever its held set changes, and solves with it many times a substep). The
TrailingCholesky's automatic choice (supernodal LU from 1e9 flops) is set against the rows'
break-even: the solves per refactorization at which both kernels cost the same (infinite where
the LU is faster at both, negative where the Cholesky is).

Writes benchmarks/results/factor_kernels.json and factor_kernels.md.

    .venv/bin/python benchmarks/factor_kernels.py [--build build]
"""
import argparse
import json
import pathlib
import subprocess
import tempfile

from contactbody import meshes

ROOT = pathlib.Path(__file__).resolve().parents[1]
OUT = ROOT / "benchmarks" / "results"
SWITCH = 1e9  # TrailingCholesky::supernodal_flops
RECTANGLES = [40, 80, 160, 320]
HEMISPHERES = [1e-3, 7e-4, 5e-4, 3.5e-4]  # element size at the contact (benchmarks/hertz3d.py's)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--build", default=str(ROOT / "build"))
    args = parser.parse_args()
    program = pathlib.Path(args.build) / "bench_factor_kernels"
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
    for r in rows:
        s, l = r["simplicial"], r["supernodal_lu"]
        r["factor_ratio"] = s["refactor"] / l["refactor"]  # > 1: the LU factors faster
        r["solve_ratio"] = s["solve"] / l["solve"]
        r["rule_picks"] = "supernodal_lu" if r["flops"] >= SWITCH else "simplicial"
        saved, lost = s["refactor"] - l["refactor"], l["solve"] - s["solve"]
        r["break_even_solves"] = (saved / lost if lost > 0 else (float("inf") if saved >= 0 else float("-inf")))
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / "factor_kernels.json").write_text(json.dumps({"switch_flops": SWITCH, "rows": rows}, indent=1) + "\n")
    lines = ["# The refactorable factor: simplicial Cholesky against supernodal LU", "",
             "`.venv/bin/python benchmarks/factor_kernels.py`: K = A + 4/dt^2 M (dt = 1e-6 s) on the "
             "free dofs, both kernels on CHOLMOD's fill-reducing order; a refactorization and a solve "
             "(mean of 20), one process per body. The rule takes the LU from "
             f"{SWITCH:.0e} flops of factorization.", "",
             "| body | unknowns | flops | nonzeros of L | refactor: simplicial / LU [s] | solve: simplicial / LU [ms] | LU factors x faster | LU solves x faster | break-even [solves per refactor] | rule |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        s, l = r["simplicial"], r["supernodal_lu"]
        lines.append(f"| {r['body']} | {r['unknowns']} | {r['flops']:.3g} | {r['factor_nonzeros']:.3g} | "
                     f"{s['refactor']:.3g} / {l['refactor']:.3g} | {1e3 * s['solve']:.3g} / {1e3 * l['solve']:.3g} | "
                     f"{r['factor_ratio']:.2f} | {r['solve_ratio']:.2f} | {r['break_even_solves']:.0f} | {r['rule_picks']} |")
    (OUT / "factor_kernels.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
