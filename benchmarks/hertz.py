"""A half-cylinder pressed onto the foundation against the 2D Hertz solution (issue 43): plane
strain, F = 0, the static start (initial_state = static) under a clamp displacement, the flat
face clamped. From the measured load P (normal_force) Hertz gives, against a rigid flat,

    a^2 = 4 P R / (pi E*),  p0 = 2 P / (pi a),  p(x) = p0 sqrt(1 - x^2 / a^2),  E* = E / (1 - nu^2).

The FMU's contact pressures (the edge history's record at t = 0) are fitted by p^2 = p0^2 (1 -
x^2 / a^2) (least squares over the active nodes), which gives the measured a and p0; the mesh
is refined near the contact (contactbody.meshes.half_disk, Gmsh) over a ladder of element sizes.

Writes benchmarks/results/hertz.json, hertz.md and hertz.png.

    .venv/bin/python benchmarks/hertz.py [--levels N]
"""
import argparse
import json
import math
import pathlib
import tempfile
import time

import numpy as np
from fmpy import simulate_fmu

from contactbody import edge, find_fmu, meshes

ROOT = pathlib.Path(__file__).resolve().parents[1]
OUT = ROOT / "benchmarks" / "results"
RADIUS = 0.05
LAMBDA, MU = 300e6, 150e6  # the FMU's defaults
E = MU * (3 * LAMBDA + 2 * MU) / (LAMBDA + MU)
NU = LAMBDA / (2 * (LAMBDA + MU))
E_STAR = E / (1 - NU ** 2)
TOP = -2.5e-4  # m: the clamp's displacement
EXPECTED_A = 2.6e-3  # m: about the half-width at TOP (sizes the ladder)


def hertz(load):
    a = math.sqrt(4 * load * RADIUS / (math.pi * E_STAR))
    return a, 2 * load / (math.pi * a)


def fit(x, p):
    """(a, p0) of p^2 = p0^2 - (p0^2 / a^2) x^2 over the nodes that press."""
    active = p > 0
    slope, intercept = np.polyfit(x[active] ** 2, p[active] ** 2, 1)
    p0 = math.sqrt(intercept)
    return math.sqrt(-intercept / slope), p0


def pressed(fmu, path, out):
    """The static start of the mesh at `path` pressed by TOP with F = 0 (the edge history in
    the folder `out`): its load and the fitted a and p0 against Hertz's."""
    from contactbody.fmu import Model
    with Model(fmu, name="hertz") as model:
        rows, _ = model.run({"mesh": str(path), "initial_state": 1, "mass_matrix": 1,
                             "friction_coefficient": 0.0, "foundation_velocity": 0.0,
                             "top_displacement": TOP, "internal_step": 1e-7,
                             "result_directory": str(out), "edge_output_interval": 1e-7},
                            1e-7, 1e-7, ["normal_force"])
    record = edge.load(pathlib.Path(out) / "contactbody_edge.npy")[0]
    load = float(rows["normal_force"][0])
    a_fit, p0_fit = fit(record["x"], record["pressure"])
    a_h, p0_h = hertz(load)
    return {"P": load, "a_error": a_fit / a_h - 1, "p0_error": p0_fit / p0_h - 1,
            "active_nodes": int(np.sum(record["pressure"] > 0))}


def run_level(contact_size, folder):
    path = meshes.half_disk(folder / f"half_disk_{contact_size:.3g}.msh", radius=RADIUS,
                            contact_size=contact_size, far_size=RADIUS / 10,
                            fine_distance=1.25 * EXPECTED_A, refine_distance=8 * EXPECTED_A)
    out = folder / f"out_{contact_size:.3g}"
    t0 = time.perf_counter()
    result = simulate_fmu(str(find_fmu()), stop_time=1e-7, output_interval=1e-7,
                          start_values={"mesh": str(path), "initial_state": 1, "mass_matrix": 0,
                                        "friction_coefficient": 0.0, "foundation_velocity": 0.0,
                                        "top_displacement": TOP, "internal_step": 1e-7,
                                        "result_directory": str(out), "edge_output_interval": 1e-7},
                          output=["normal_force", "active_contact_nodes"])
    seconds = time.perf_counter() - t0
    record = edge.load(out / "contactbody_edge.npy")[0]  # t = 0: the static state
    x, p = record["x"], record["pressure"]
    load = float(result["normal_force"][0])
    a_fit, p0_fit = fit(x, p)
    a_h, p0_h = hertz(load)
    with meshes.session("count") as gmsh:
        gmsh.open(str(path))
        nodes = len(gmsh.model.mesh.getNodes()[0])
    return {"contact_size": contact_size, "a_over_h": a_h / contact_size, "nodes": nodes,
            "contact_nodes": int(len(x)), "active_nodes": int(np.sum(p > 0)),
            "P": load, "a_hertz": a_h, "p0_hertz": p0_h, "a_fit": a_fit, "p0_fit": p0_fit,
            "p_max": float(p.max()),
            "a_error": a_fit / a_h - 1, "p0_error": p0_fit / p0_h - 1, "seconds": seconds,
            "x": x.tolist(), "pressure": p.tolist()}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--levels", type=int, default=7)
    args = parser.parse_args()
    sizes = [EXPECTED_A / 2 ** k for k in range(1, args.levels + 1)]
    with tempfile.TemporaryDirectory() as tmp:
        rows = [run_level(h, pathlib.Path(tmp)) for h in sizes]
    result = {"radius": RADIUS, "E": E, "nu": NU, "E_star": E_STAR, "top_displacement": TOP,
              "levels": rows, "finest": {**{k: rows[-1][k] for k in ("a_error", "p0_error", "a_over_h", "nodes")},
                                         "max_abs_error": max(abs(rows[-1]["a_error"]), abs(rows[-1]["p0_error"]))}}
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / "hertz.json").write_text(json.dumps(result, indent=1) + "\n")
    (OUT / "hertz.md").write_text(report(result))
    plot(result, OUT / "hertz.png")
    print(report(result))


def report(r):
    lines = ["# A half-cylinder against 2D Hertz", "",
             f"`.venv/bin/python benchmarks/hertz.py`: R = {r['radius']} m, E = {r['E'] / 1e6:.0f} MPa, "
             f"nu = {r['nu']:.4f}, plane strain, F = 0, static start under a clamp displacement of "
             f"{r['top_displacement']} m; a and p0 fitted to the nodal pressures (p^2 linear in x^2), "
             "Hertz's from the measured P.", "",
             "| element size at the contact [mm] | a / h | nodes | active nodes | P [kN/m] | a [mm] (Hertz) | p0 [MPa] (Hertz) | a error | p0 error | run [s] |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for x in r["levels"]:
        lines.append(f"| {1e3 * x['contact_size']:.4g} | {x['a_over_h']:.1f} | {x['nodes']} | {x['active_nodes']} | "
                     f"{x['P'] / 1e3:.2f} | {1e3 * x['a_fit']:.4f} ({1e3 * x['a_hertz']:.4f}) | "
                     f"{x['p0_fit'] / 1e6:.3f} ({x['p0_hertz'] / 1e6:.3f}) | {100 * x['a_error']:+.2f} % | "
                     f"{100 * x['p0_error']:+.2f} % | {x['seconds']:.1f} |")
    return "\n".join(lines) + "\n"


def plot(r, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
    finest = r["levels"][-1]
    x = np.array(finest["x"])
    a, p0 = finest["a_hertz"], finest["p0_hertz"]
    s = np.linspace(-a, a, 400)
    left.plot(1e3 * s, p0 * np.sqrt(1 - s ** 2 / a ** 2) / 1e6, "k-", label="Hertz (from the measured P)")
    left.plot(1e3 * x, np.array(finest["pressure"]) / 1e6, "o", ms=3, label="FMU, nodal pressures")
    left.set_xlim(-2 * 1e3 * a, 2 * 1e3 * a)
    left.set_xlabel("x [mm]")
    left.set_ylabel("contact pressure [MPa]")
    left.set_title(f"finest mesh: a/h = {finest['a_over_h']:.0f}, {finest['nodes']} nodes")
    left.legend()
    h = np.array([1e3 * x["contact_size"] for x in r["levels"]])
    right.loglog(h, [abs(x["a_error"]) for x in r["levels"]], "o-", label="|a error|")
    right.loglog(h, [abs(x["p0_error"]) for x in r["levels"]], "s-", label="|p0 error|")
    right.axhline(0.02, color="grey", ls=":", label="2 %")
    right.set_xlabel("element size at the contact [mm]")
    right.set_ylabel("relative error against Hertz")
    right.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=120)


if __name__ == "__main__":
    main()
