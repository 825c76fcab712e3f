"""The reduced body's two contact edges (issue 42): `reduced_edge` = massless (every contact dof
a massless residual coordinate) against tangential_mass (the contact x dofs kept with their
mass), beside the full body, in one run:

1. build/bench_reduced_edge on the paper's scene (nx = 20, 200 substeps of 1e-5 s, and 800 of
   2.5e-6 s) and on damped sliding from the static start (F = 0.3, beta = 4e-6 s, 1250 substeps
   of 4e-6 s): the normal force's L2 error against the full body, how far the edge's
   end-of-step x velocity departs from its motion over the step, and how much a 1e-14 change
   of the initial displacement changes the normal force.
2. build/stribeck_bifurcation (docs/slip_rate_friction.md): substeps with several solutions in
   the bifurcation scene (F(v) = 0.5 + 0.5 exp(-|v| / 0.1 m/s), V = 0.2 m/s, nx = 10,
   redistributed_normal), full body and 20 modes with each edge.
3. Issue 42's class A scene through the FMU (a decreasing slip-rate law, variant 4, nx = 4):
   which body runs it to 4 ms.

Writes benchmarks/results/reduced_edge.json and .md.

    .venv/bin/python benchmarks/reduced_edge.py [--out benchmarks/results]
"""
import argparse
import json
import pathlib
import subprocess
import sys

import fmpy

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
from contactbody.fmu import find_fmu  # noqa: E402

EDGES = ("massless", "tangential_mass")
SCENES = [  # name, nx, dt, steps, scene, variants, modes
    ("paper", 20, 1e-5, 200, "paper", "0,1,3,4", "8,32,128,256"),
    ("paper, dt / 4", 20, 2.5e-6, 800, "paper", "1", "32,128"),
    ("sliding", 20, 4e-6, 1250, "sliding", "0,1,3,4", "8,20,80"),
]
BIFURCATION = {"F_d": 0.5, "ratio": 2.0, "v_s": 0.1, "V": 0.2, "beta": 4e-6}
CLASS_A = {"nx": 4, "ny": 5, "mass_matrix": 4, "width": 0.02916, "height": 0.06328,
           "density": 564.5, "mu": 4.641e10, "lambda": 8.020e11, "friction_coefficient": 0.786,
           "static_friction_ratio": 2.997, "stribeck_velocity": 0.0397,
           "internal_step": 2.574e-5, "foundation_velocity": 7.433, "top_displacement": -2.324e-4}


def edge_runs():
    out = []
    for name, nx, dt, steps, scene, variants, modes in SCENES:
        text = subprocess.run([str(ROOT / "build" / "bench_reduced_edge"), str(nx), repr(dt),
                               str(steps), scene, variants, modes],
                              check=True, capture_output=True, text=True).stdout
        out += [dict(r, scene=name, dt=dt) for r in json.loads(text)["runs"]]
    return out


def bifurcation_runs():
    out = []
    for dt in (4e-6, 1e-6):
        for modes, edge in ((0, 0), (20, 1), (20, 2)):
            args = [str(ROOT / "build" / "stribeck_bifurcation"), "1", "10", repr(dt),
                    str(round(8e-4 / dt)), *(repr(BIFURCATION[k]) for k in ("F_d", "ratio", "v_s", "V", "beta"))]
            if modes:
                args += [str(modes), str(edge)]
            out.append(json.loads(subprocess.run(args, check=True, capture_output=True, text=True).stdout))
    return out


def class_a_runs():
    out = []
    for modes, edge in ((0, 0), (1, 1), (20, 1), (1, 2), (20, 2)):
        messages = []

        def logger(_env, _name, _status, _category, message):
            messages.append(message.decode(errors="replace"))

        try:
            fmpy.simulate_fmu(str(find_fmu()), stop_time=4e-3, output_interval=3.83e-4, logger=logger,
                              start_values=dict(CLASS_A, modes=modes, reduced_edge=edge),
                              output=["normal_force"])
            ran = True
        except Exception:  # noqa: BLE001 - the failure is the measurement
            ran = False
        out.append({"modes": modes, "edge": ("full", "massless", "tangential_mass")[edge],
                    "ran": ran, "warned": any("reduced_edge = tangential_mass keeps" in m for m in messages)})
    return out


def report(edges, bifurcation, class_a):
    lines = ["# The reduced body's contact edges", "",
             "`benchmarks/reduced_edge.py`: `reduced_edge` = massless against tangential_mass, "
             "beside the full body at the same substep, nx = 20. *error*: relative L2 error of "
             "the substeps' normal force; *departure*: the largest |v_x(end of step) − mean "
             "over the step| of a contact node [m/s]; *perturbation*: the largest change of the "
             "normal force, relative to its largest value, from a 1e-14 relative change of the "
             "initial displacement; µs: wall time per substep.", ""]
    for name, *_ in SCENES:
        rows = [r for r in edges if r["scene"] == name]
        dt = rows[0]["dt"]
        lines += [f"## {name} (substep {dt:g} s)", "",
                  "| variant | modes | massless: error | departure | perturbation | µs "
                  "| tangential mass: error | departure | perturbation | µs |",
                  "|---|---|---|---|---|---|---|---|---|---|"]
        for v in sorted({r["variant"] for r in rows}):
            full = next(r for r in rows if r["variant"] == v and r["edge"] == "full")
            lines.append(f"| {v} | full body | – | {full['departure']:.3g} | "
                         f"{full['perturbation']:.2g} | {full['us_per_substep']:.0f} | | | | |")
            for m in sorted({r["modes"] for r in rows if r["modes"] > 0}):
                cells = []
                for e in EDGES:
                    r = next((r for r in rows if r["variant"] == v and r["edge"] == e and r["modes"] == m), None)
                    cells.append("– | – | – | –" if r is None else
                                 ("failed | | |" if r["failure"] else
                                  f"{r['error_normal_force']:.2g} | {r['departure']:.3g} | "
                                  f"{r['perturbation']:.2g} | {r['us_per_substep']:.0f}"))
                lines.append(f"| {v} | {m} | " + " | ".join(cells) + " |")
        lines.append("")
    lines += ["## Substeps with several solutions (the bifurcation scene, nx = 10)", "",
              "| body | dt [s] | substeps | with several solutions | most | E(0.8 ms) [J/m] |",
              "|---|---|---|---|---|---|"]
    for r in bifurcation:
        body = "full" if r["modes"] == 0 else f"{r['modes']} modes, " + EDGES[r["reduced_edge"] - 1]
        lines.append(f"| {body} | {r['dt']:g} | {r['steps']} | {r['substeps_with_several']} | "
                     f"{r['most_solutions']} | {r['energy_end']:.5f} |")
    lines += ["", "## Issue 42's class A scene (decreasing slip-rate law, variant 4), to 4 ms", "",
              "| body | edge | runs | warned at initialization |", "|---|---|---|---|"]
    for r in class_a:
        lines.append(f"| {'full' if r['modes'] == 0 else str(r['modes']) + ' modes'} | {r['edge']} | "
                     f"{'yes' if r['ran'] else 'no'} | {'yes' if r['warned'] else 'no'} |")
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=pathlib.Path, default=ROOT / "benchmarks" / "results")
    args = parser.parse_args()
    edges, bifurcation, class_a = edge_runs(), bifurcation_runs(), class_a_runs()
    args.out.mkdir(parents=True, exist_ok=True)
    (args.out / "reduced_edge.json").write_text(json.dumps(
        {"edges": edges, "bifurcation": bifurcation, "class_a": class_a}, indent=1))
    (args.out / "reduced_edge.md").write_text(report(edges, bifurcation, class_a))
    print(report(edges, bifurcation, class_a))


if __name__ == "__main__":
    main()
