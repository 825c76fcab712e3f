"""Where the supernodal Cholesky pays over CHOLMOD's simplicial one, on whole substeps (issue 70):
the rule `TrailingCholesky::supernodal_flops` (a refactorable factor of that many flops or more
is the supernodal one) measured as users run it, not on factorizations alone. Two builds of
build/bench_contact_scaling from this tree (native, the fastest kernel set this CPU has), one
whose rule makes every refactorable factor simplicial (CONTACTBODY_SUPERNODAL_FLOPS=1e300) and
one that makes it supernodal (0), in build-crossover/ (gitignored). Bodies on both sides of the
rule: the hemispheres of supernodal.py at h = 1, 0.7 and 0.5 mm (the last is cost3d.py's
2.7k-node one), the paper's rectangle at nx = 80, 160 and 320 and contact_scaling.py's 2D pad
at 801 and 3201 contact nodes (ContactBody3D takes 2D bodies too). Scenes: pressed (F = 0) and sliding (F = 0.3), damped (beta = 4e-6 s), from the
static start, the foundation at 20 m/s, 1e-6 s substeps; the contact solve as the FMU picks it.
Per case the two builds alternate, REPEAT runs each, the best of each: the set-up (the
discretization, the factors and the static start) and the mean substep over SUBSTEPS after the
first step; the held solves and the normal force must agree (the same solve, to round-off).

Writes benchmarks/results/factor_crossover.{json,md}.

    .venv/bin/python benchmarks/factor_crossover.py [--repeat 2] [--substeps 100]
"""
import argparse
import json
import pathlib
import subprocess
import sys
import tempfile

import contact_scaling
from contactbody import meshes

ROOT = pathlib.Path(__file__).resolve().parents[1]
OUT = ROOT / "benchmarks" / "results"
BUILDS = {"simplicial": "1e300", "supernodal": "0"}
HEMISPHERES = [1e-3, 7e-4, 5e-4]
RECTANGLES = [80, 160, 320]
PADS = [801, 3201]  # contact nodes of contact_scaling.py's 2D pad
SCENES = {"pressed": "0", "sliding": "0.3"}  # F


def build(name, flops):
    folder = ROOT / "build-crossover" / name
    subprocess.run(["/usr/bin/cmake", "-S", str(ROOT), "-B", str(folder), "-G", "Ninja",
                    "-DCMAKE_BUILD_TYPE=Release", "-DCONTACTBODY_PORTABLE=OFF",
                    f"-DPython3_EXECUTABLE={sys.executable}",
                    f"-DCONTACTBODY_SUPERNODAL_FLOPS={flops}"], check=True, stdout=subprocess.DEVNULL)
    subprocess.run(["/usr/bin/cmake", "--build", str(folder), "--target", "bench_contact_scaling"],
                   check=True, stdout=subprocess.DEVNULL)
    return folder / "bench_contact_scaling"


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--repeat", type=int, default=2)
    parser.add_argument("--substeps", type=int, default=100)
    parser.add_argument("--tables", action="store_true", help="rewrite the .md from the .json")
    args = parser.parse_args()
    if args.tables:
        write_tables(json.loads((OUT / "factor_crossover.json").read_text()))
        return
    programs = {name: build(name, flops) for name, flops in BUILDS.items()}
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        bodies = []
        for h in HEMISPHERES:
            path = meshes.hemisphere(pathlib.Path(tmp) / f"hemisphere_{h:.3g}.msh", radius=0.05,
                                     contact_size=h, far_size=0.01, fine_distance=0.0045,
                                     refine_distance=0.025, contact_angle=25.0)
            bodies.append((f"hemisphere h = {1e3 * h:.3g} mm", str(path), "3", "-2e-4"))
        bodies += [(f"rectangle nx = {n}", f"rect:{n}", "2", "-5e-6") for n in RECTANGLES]
        bodies += [(f"2D pad, {n} contact nodes", str(contact_scaling.pad_mesh(tmp, n)), "2", "-5e-6")
                   for n in PADS]
        for body, mesh, dimension, top in bodies:
            for scene, friction in SCENES.items():
                runs = {name: [] for name in programs}
                for _ in range(args.repeat):
                    for name, program in programs.items():
                        out = subprocess.run([str(program), mesh, "0", "automatic", str(args.substeps),
                                              friction, dimension, top, "0", "1e-5", "0", "4e-6"],
                                             check=True, capture_output=True, text=True).stdout
                        runs[name].append(json.loads(out))
                row = {"body": body, "scene": scene}
                for name, results in runs.items():
                    first = results[0]
                    for r in results[1:]:  # deterministic: the same counts and forces
                        assert r["held_solves"] == first["held_solves"], (body, scene, name)
                    row[name] = {"kernel": first["factor_kernel"], "contact_solve":
                                 "sparse" if first["sparse"] else "condensed",
                                 "setup_seconds": min(r["static_start_seconds"] for r in results),
                                 "substep_seconds": min(r["substep_seconds"] for r in results),
                                 "solve_seconds": min(r["sparse_solve_seconds"] for r in results),
                                 "held_solves_per_substep": first["held_solves_per_substep"],
                                 "held_refactorizations": first["held_refactorizations"],
                                 "normal_force": first["normal_force"],
                                 "peak_memory_mb": max(r["peak_memory_mb"] for r in results)}
                # The body's own (the same analysis in both builds), from the supernodal one's run.
                first = runs["supernodal"][0]
                row.update(unknowns=first["unknowns"], contact_nodes=first["contact_nodes"],
                           factor_flops=first["factor_flops"], factor_nonzeros=first["factor_nonzeros"])
                s, p = row["simplicial"], row["supernodal"]
                row["normal_force_difference"] = abs(s["normal_force"] - p["normal_force"]) / max(
                    abs(s["normal_force"]), 1e-300)
                row["substep_supernodal_over_simplicial"] = p["substep_seconds"] / s["substep_seconds"]
                row["setup_supernodal_over_simplicial"] = p["setup_seconds"] / s["setup_seconds"]
                rows.append(row)
                print(json.dumps(row), flush=True)
    results = {"repeat": args.repeat, "substeps": args.substeps, "rows": rows}
    (OUT / "factor_crossover.json").write_text(json.dumps(results, indent=1) + "\n")
    write_tables(results)


def write_tables(results):
    lines = ["# Where the supernodal factor pays, on whole substeps", "",
             "`.venv/bin/python benchmarks/factor_crossover.py` (the docstring says what it runs): "
             "every refactorable factor simplicial (CHOLMOD's) or supernodal (ours, the fastest "
             f"kernel set this CPU has), the best of {results['repeat']} alternated runs each, the "
             f"substep the mean over {results['substeps']} substeps after the first step. *Ratio*: "
             "supernodal over simplicial (below 1: the supernodal factor is faster).", "",
             "| body | unknowns | factor flops | flops per nonzero | scene | contact solve | "
             "set-up s: simplicial / supernodal | set-up ratio | substep ms: simplicial / supernodal "
             "| substep ratio | held solves a substep: simplicial / supernodal | normal force difference |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in results["rows"]:
        s, p = r["simplicial"], r["supernodal"]
        lines.append(
            f"| {r['body']} | {r['unknowns']} | {r['factor_flops']:.2g} | "
            f"{r['factor_flops'] / r['factor_nonzeros']:.0f} | {r['scene']} | {s['contact_solve']} | "
            f"{s['setup_seconds']:.3g} / {p['setup_seconds']:.3g} | "
            f"{r['setup_supernodal_over_simplicial']:.2f} | "
            f"{1e3 * s['substep_seconds']:.3g} / {1e3 * p['substep_seconds']:.3g} | "
            f"{r['substep_supernodal_over_simplicial']:.2f} | "
            f"{s['held_solves_per_substep']:.2f} / {p['held_solves_per_substep']:.2f} | "
            f"{r['normal_force_difference']:.1e} |")
    (OUT / "factor_crossover.md").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
