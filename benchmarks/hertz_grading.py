"""Hertz against how fast the cells coarsen away from the contact (issue 53, item 5): the
half-cylinder of benchmarks/hertz.py, cells of h = a/32 within 1.25 a of the bottom point, then
growing linearly with the distance at a rate g (size h + g (d - 1.25 a), up to R/10), for g
from 0.4 to 0.025; and, at the steepest and the gentlest g, h down to a/128. Static start,
F = 0; a and p0 fitted as hertz.py does.

Writes benchmarks/results/hertz_grading.json and hertz_grading.md.

    .venv/bin/python benchmarks/hertz_grading.py [--fmu FMU]
"""
import argparse
import json
import pathlib
import sys
import tempfile

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import hertz  # noqa: E402

from contactbody import find_fmu, meshes  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[1]
OUT = ROOT / "benchmarks" / "results"
RATES = [0.4, 0.25, 0.1, 0.05, 0.025]
A_OVER_H = [32, 64, 128]


def run(fmu, folder, a_over_h, rate):
    fine, far = hertz.EXPECTED_A / a_over_h, hertz.RADIUS / 10
    inner = 1.25 * hertz.EXPECTED_A
    path = meshes.half_disk(folder / f"h{a_over_h}_g{rate}.msh", radius=hertz.RADIUS,
                            contact_size=fine, far_size=far, fine_distance=inner,
                            refine_distance=inner + (far - fine) / rate)
    result = hertz.pressed(fmu, path, folder / f"out_{a_over_h}_{rate}")
    with meshes.session("count") as gmsh:
        gmsh.open(str(path))
        nodes = len(gmsh.model.mesh.getNodes()[0])
    return {"a_over_h": a_over_h, "growth_rate": rate, "nodes": nodes, "P": result["P"],
            "a_error": result["a_error"], "p0_error": result["p0_error"]}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--fmu", type=pathlib.Path, default=None)
    args = parser.parse_args()
    fmu = str(find_fmu(args.fmu))
    with tempfile.TemporaryDirectory() as tmp:
        folder = pathlib.Path(tmp)
        rows = [run(fmu, folder, 32, g) for g in RATES]
        rows += [run(fmu, folder, n, g) for g in (RATES[0], RATES[-1]) for n in A_OVER_H[1:]]
    for r in rows:
        print(r)
    record = {"rows": rows, "by_rate": {str(r["growth_rate"]): r for r in rows if r["a_over_h"] == 32}}
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / "hertz_grading.json").write_text(json.dumps(record, indent=1))
    lines = ["# Hertz against the grading away from the contact", "",
             "`.venv/bin/python benchmarks/hertz_grading.py`: the half-cylinder of hertz.py, cells "
             "of a/h at the contact within 1.25 a, growing at the rate g with the distance beyond.", "",
             "| a / h | growth rate g | nodes | a error | p0 error |", "|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['a_over_h']} | {r['growth_rate']} | {r['nodes']} | "
                     f"{100 * r['a_error']:+.2f} % | {100 * r['p0_error']:+.2f} % |")
    (OUT / "hertz_grading.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
