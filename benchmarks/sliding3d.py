"""3D sliding with the slipping nodes held in the factor (issue 71), against the slips left to
GCR, in one run: the tetrahedral hemispheres of benchmarks/cost3d.py (2.7k and 12.6k nodes),
F = 0.3, 1e-6 s substeps, the static start under -0.2 mm, then the foundation at 20 m/s, damped
(beta = 4e-6 s) and undamped (beta = 0, the FMU's default: rho reaches 0.26 there, so that
fewer slips are held; on the 2.7k-node mesh only: at 12.6k nodes an undamped substep took
8.7 s in a run of 20, docs/decisions.md). Each mesh and damping runs
build/bench_contact_scaling once for each solve, one process each:

* "in the factor": the FMU's contact solve (automatic): a slipping node's tangential rows
  K_j - F t_j K_y held in the factor (an LU on the Cholesky's supernodes) along its slip
  direction t, GCR taking the directions' drift;
* "by GCR": the contact path sparse_gcr, the solve before issue 71 (the factor holds the
  normal dofs; every slip law is GCR's).
* "in the factor, 96 kept directions" (12.6k nodes only, whose factor has 4e6 nonzeros or
  more): the FMU's solve with GCR's kept directions at max_directions, the solve before they
  span the slips (docs/decisions.md, "GCR's kept directions span the slips").

For each: the set-up (discretization, factors, the static start with friction), the held
solves a substep (exact counts), Newton iterations, wall time a substep, the refactorizations
over the run and the share of a whole factorization they redid, and the normal force (the same solution). The substeps timed follow a first
communication step of 10. Then, on each mesh's K, the factor with slipping rows against the
Cholesky (build/bench_supernodal, one repeat: the supernodal Cholesky with the fast kernels and
its LU, factor and solve times).

Writes benchmarks/results/sliding3d.json and sliding3d.md.

    .venv/bin/python benchmarks/sliding3d.py [--build build] [--meshes 0,1] [--substeps 300,200]
        [--only sliding|factors]  (the other part's rows kept from the results file)
"""
import argparse
import json
import pathlib
import subprocess
import tempfile

from contactbody import meshes

ROOT = pathlib.Path(__file__).resolve().parents[1]
OUT = ROOT / "benchmarks" / "results"
MESHES = [(5e-4, 1e-2), (2.5e-4, 1e-2)]  # contact and far element sizes (cost3d.py's)
SOLVES = {"in the factor": "automatic", "by GCR": "sparse_gcr",
          "in the factor, 96 kept directions": "automatic_narrow"}
NARROW_MESHES = (1,)  # where the wide span of kept directions applies (factor nonzeros >= 4e6)
DAMPINGS = {"": 4e-6, ", undamped": 0.0}  # the rows' slips label: its suffix, and beta [s]
UNDAMPED_MESHES = (0,)  # indices into MESHES


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--build", default=str(ROOT / "build"))
    parser.add_argument("--meshes", default="0,1", help="indices into MESHES, smallest first")
    parser.add_argument("--substeps", default="300,200", help="timed substeps, per mesh chosen")
    parser.add_argument("--only", choices=["sliding", "factors"])
    parser.add_argument("--out", default=str(OUT))
    args = parser.parse_args()
    program = pathlib.Path(args.build) / "bench_contact_scaling"
    chosen = [int(i) for i in args.meshes.split(",")]
    substeps = [int(s) for s in args.substeps.split(",")]
    kept = json.loads((pathlib.Path(args.out) / "sliding3d.json").read_text()) if args.only else {}
    rows = kept.get("rows", []) if args.only == "factors" else []
    factors = kept.get("factors", []) if args.only == "sliding" else []
    with tempfile.TemporaryDirectory() as tmp:
        for index, count in zip(chosen, substeps):
            contact, far = MESHES[index]
            path = meshes.hemisphere(pathlib.Path(tmp) / f"hemisphere_{contact:.3g}.msh", radius=0.05,
                                     contact_size=contact, far_size=far, fine_distance=0.0045,
                                     refine_distance=0.025, contact_angle=25.0)
            nodes = int(path.read_text().split("$Nodes\n")[1].split()[1])
            if args.only != "sliding":
                run = json.loads(subprocess.run(
                    [str(pathlib.Path(args.build) / "bench_supernodal"), str(path), "3", "1", "supernodal"],
                    check=True, capture_output=True, text=True).stdout)
                cholesky, lu = run["supernodal_cholesky_fast"], run["supernodal_lu_fast"]
                factors.append({"nodes": nodes, "unknowns": run["unknowns"], "gemm_gflops": run["gemm_gflops"],
                                "cholesky_seconds": cholesky["factor_seconds"], "cholesky_gflops": cholesky["gflops"],
                                "cholesky_solve_seconds": cholesky["solve_seconds"],
                                "lu_seconds": lu["factor_seconds"], "lu_gflops": lu["gflops"],
                                "lu_solve_seconds": lu["solve_seconds"], "lu_difference": lu["difference"],
                                "lu_over_cholesky": lu["factor_seconds"] / cholesky["factor_seconds"]})
                print(json.dumps(factors[-1]), flush=True)
            if args.only == "factors":
                continue
            for suffix, beta in DAMPINGS.items():
                if beta == 0 and index not in UNDAMPED_MESHES:
                    continue
                for slips, contact_path in SOLVES.items():
                    if contact_path == "automatic_narrow" and index not in NARROW_MESHES:
                        continue
                    case = subprocess.run([str(program), str(path), "0", contact_path, str(count), "0.3", "3",
                                           "-2e-4", "0", "1e-5", "0", str(beta)], check=True,
                                          capture_output=True, text=True).stdout
                    row = {"nodes": nodes, "slips": slips + suffix, "beta": beta, "substeps": count,
                           **json.loads(case)}
                    rows.append(row)
                    print(json.dumps(row), flush=True)
    for r in rows:
        if "substep_speedup" in r:
            continue
        gcr = next(g for g in rows if g["nodes"] == r["nodes"] and g["slips"].startswith("by GCR")
                   and g.get("beta", 4e-6) == r.get("beta", 4e-6))
        r["substep_speedup"] = gcr["substep_seconds"] / r["substep_seconds"]
        r["solves_ratio"] = gcr["held_solves_per_substep"] / r["held_solves_per_substep"]
        r["static_start_speedup"] = gcr["static_start_seconds"] / r["static_start_seconds"]
        r["normal_force_difference"] = abs(r["normal_force"] - gcr["normal_force"]) / abs(gcr["normal_force"])
    write(rows, factors, pathlib.Path(args.out))


def refactored_share(row):
    """The refactorizations' flops over as many whole factorizations' (the supernodal factor redoes
    only the supernodes whose values changed and their ancestors)."""
    count = row["held_refactorizations"]
    return f"{row['held_refactored_work'] / count:.2f}" if count and "held_refactored_work" in row else "–"


def write(rows, factors, out):
    out.mkdir(parents=True, exist_ok=True)
    (out / "sliding3d.json").write_text(json.dumps({"rows": rows, "factors": factors}, indent=1) + "\n")
    lines = ["# 3D sliding: the slipping nodes in the factor", "",
             "`.venv/bin/python benchmarks/sliding3d.py`: tetrahedral hemispheres (R = 50 mm), "
             "F = 0.3, beta = 4e-6 s (and 0 where the slips say *undamped*), 1e-6 s substeps, "
             "static start under -0.2 mm, then the "
             "foundation at 20 m/s; the substeps timed follow a first communication step of 10. "
             "*In the factor*: the FMU's contact solve, the slipping rows held in the factor's LU "
             "along their slip directions; *by GCR*: every slip law left to GCR (the contact path "
             "`sparse_gcr`, the solve before); *96 kept directions* (12.6k nodes): the FMU's solve with "
             "GCR keeping 96 directions, as before they spanned the slips. Held solves are exact counts; the refactored share is "
             "the refactorizations' flops over as many whole factorizations'; times are wall "
             "times of one process each, in one run.", "",
             "| nodes | contact nodes | slips | substeps | held solves / substep | Newton iterations / substep | substep [ms] | one solve [ms] | refactorizations | refactored share | static start [s] | substep speed-up | normal force difference |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['nodes']} | {r['contact_nodes']} | {r['slips']} | {r['substeps']} | "
                     f"{r['held_solves_per_substep']:.2f} | {r['newton_iterations_per_substep']:.2f} | "
                     f"{1e3 * r['substep_seconds']:.3g} | {1e3 * r['sparse_solve_seconds']:.3g} | "
                     f"{r['held_refactorizations']} | {refactored_share(r)} | {r['static_start_seconds']:.3g} | "
                     f"{r['substep_speedup']:.2f} | {r['normal_force_difference']:.1e} |")
    lines += ["", "The factor with slipping rows: on each mesh's K (`bench_supernodal`, one repeat), "
              "the supernodal Cholesky with the fast kernels and its LU without pivoting (twice "
              "the flops), beside the GEMM rate of the bench's own Eigen (its build's flags, not the kernels'), in the same run.", "",
              "| nodes | unknowns | GEMM [GFlop/s] | Cholesky [s] | Cholesky [GFlop/s] | LU [s] | LU [GFlop/s] | LU / Cholesky | Cholesky solve [ms] | LU solve [ms] |",
              "|---|---|---|---|---|---|---|---|---|---|"]
    for f in factors:
        lines.append(f"| {f['nodes']} | {f['unknowns']} | {f['gemm_gflops']:.3g} | {f['cholesky_seconds']:.3g} | "
                     f"{f['cholesky_gflops']:.3g} | {f['lu_seconds']:.3g} | {f['lu_gflops']:.3g} | "
                     f"{f['lu_over_cholesky']:.2f} | {1e3 * f['cholesky_solve_seconds']:.3g} | "
                     f"{1e3 * f['lu_solve_seconds']:.3g} |")
    (out / "sliding3d.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
