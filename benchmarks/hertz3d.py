"""A hemisphere pressed onto the foundation against 3D Hertz (issue 55): tetrahedra, F = 0, the
static start under a clamp displacement, the flat face clamped. From the measured load P,
Hertz gives, against a rigid flat,

    a = (3 P R / (4 E*))^(1/3),  p0 = 3 P / (2 pi a^2),  p(r) = p0 sqrt(1 - r^2 / a^2),
    E* = E / (1 - nu^2).

The contact nodes' pressures (the static start's multipliers over each node's share of the
foundation) are fitted by p^2 = p0^2 (1 - r^2 / a^2) over the active nodes, which gives the
measured a and p0; the same fit over each of eight 45-degree sectors gives a radius per
direction (the patch is round if they agree). The mesh (contactbody.meshes.hemisphere, Gmsh) is
refined near the contact over a ladder of element sizes. The body is solved by the solver's own
program (build/bench_hertz3d): the FMU holds 2D bodies until ContactBody3D is built.

Writes benchmarks/results/hertz3d.json, hertz3d.md and hertz3d.png.

    .venv/bin/python benchmarks/hertz3d.py [--build build] [--levels N]
"""
import argparse
import json
import math
import pathlib
import subprocess
import tempfile

import numpy as np

from contactbody import meshes

ROOT = pathlib.Path(__file__).resolve().parents[1]
OUT = ROOT / "benchmarks" / "results"
RADIUS = 0.05
LAMBDA, MU = 300e6, 150e6  # the FMU's defaults
E = MU * (3 * LAMBDA + 2 * MU) / (LAMBDA + MU)
NU = LAMBDA / (2 * (LAMBDA + MU))
E_STAR = E / (1 - NU ** 2)
TOP = -2e-4  # m: the clamp's displacement
EXPECTED_A = 3.3e-3  # m: about the contact radius at TOP (sizes the refined zone)
SIZES = [1e-3, 7e-4, 5e-4, 3.5e-4]
SECTORS = 8


def hertz(load):
    a = (3 * load * RADIUS / (4 * E_STAR)) ** (1 / 3)
    return a, 3 * load / (2 * math.pi * a * a)


def fit(r, p):
    """(a, p0) of p^2 = p0^2 - (p0^2 / a^2) r^2 over the nodes that press."""
    active = p > 0
    if np.sum(active) < 3:
        return math.nan, math.nan
    slope, intercept = np.polyfit(r[active] ** 2, p[active] ** 2, 1)
    if not (slope < 0 < intercept):
        return math.nan, math.nan
    return math.sqrt(-intercept / slope), math.sqrt(intercept)


def run_level(program, contact_size, folder):
    path = meshes.hemisphere(folder / f"hemisphere_{contact_size:.3g}.msh", radius=RADIUS,
                             contact_size=contact_size, far_size=RADIUS / 5,
                             fine_distance=1.35 * EXPECTED_A, refine_distance=7.5 * EXPECTED_A,
                             contact_angle=25.0)
    out = subprocess.run([str(program), str(path), repr(TOP), repr(LAMBDA), repr(MU)],
                         check=True, capture_output=True, text=True).stdout
    d = json.loads(out)
    x, z, p = (np.array(d[k]) for k in ("x", "z", "pressure"))
    r = np.hypot(x, z)
    load = d["load"]
    a_fit, p0_fit = fit(r, p)
    a_h, p0_h = hertz(load)
    angle = np.arctan2(z, x)
    radii = []
    for k in range(SECTORS):
        sector = ((angle + math.pi) // (2 * math.pi / SECTORS)).astype(int) % SECTORS == k
        radii.append(fit(r[sector], p[sector])[0])
    return {"contact_size": contact_size, "a_over_h": a_h / contact_size, "nodes": d["nodes"],
            "contact_nodes": d["contact_nodes"], "active_nodes": int(np.sum(p > 0)),
            "P": load, "a_hertz": a_h, "p0_hertz": p0_h, "a_fit": a_fit, "p0_fit": p0_fit,
            "a_error": a_fit / a_h - 1, "p0_error": p0_fit / p0_h - 1,
            "sector_radii": radii, "roundness": (max(radii) - min(radii)) / a_h,
            "sector_errors": [s / a_h - 1 for s in radii],
            "start_seconds": d["start_seconds"], "peak_mb": d["peak_mb"], "contact_path": d["contact_path"],
            "mass_redistribution": ("least relative change" if any("least relative change" in n for n in d["notes"])
                                    else "least change in the Frobenius norm"), "notes": d["notes"],
            "r": r.tolist(), "x": x.tolist(), "z": z.tolist(), "pressure": p.tolist()}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--build", default=str(ROOT / "build"))
    parser.add_argument("--levels", type=int, default=len(SIZES))
    args = parser.parse_args()
    program = pathlib.Path(args.build) / "bench_hertz3d"
    with tempfile.TemporaryDirectory() as tmp:
        rows = [run_level(program, h, pathlib.Path(tmp)) for h in SIZES[:args.levels]]
    finest = rows[-1]
    result = {"radius": RADIUS, "E": E, "nu": NU, "E_star": E_STAR, "top_displacement": TOP,
              "levels": rows,
              "finest": {**{k: finest[k] for k in ("a_error", "p0_error", "a_over_h", "nodes", "roundness")},
                         "max_abs_error": max(abs(finest["a_error"]), abs(finest["p0_error"])),
                         "max_sector_error": max(abs(e) for e in finest["sector_errors"])}}
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / "hertz3d.json").write_text(json.dumps(result, indent=1) + "\n")
    (OUT / "hertz3d.md").write_text(report(result))
    plot(result, OUT / "hertz3d.png")
    print(report(result))


def report(r):
    lines = ["# A hemisphere against 3D Hertz", "",
             f"`.venv/bin/python benchmarks/hertz3d.py`: R = {r['radius']} m, E = {r['E'] / 1e6:.0f} MPa, "
             f"nu = {r['nu']:.4f}, tetrahedra, F = 0, static start under a clamp displacement of "
             f"{r['top_displacement']} m; a and p0 fitted to the nodal pressures (p^2 linear in r^2), "
             f"Hertz's from the measured P; the radius fitted in each of {SECTORS} sectors of 45 degrees "
             "(roundness: their spread over Hertz's a).", "",
             "| element size at the contact [mm] | a / h | nodes | active nodes | P [N] | a [mm] (Hertz) "
             "| p0 [MPa] (Hertz) | a error | p0 error | sector radii: spread / a | static start [s] | peak memory [MB] | M_r |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for x in r["levels"]:
        lines.append(f"| {1e3 * x['contact_size']:.3g} | {x['a_over_h']:.1f} | {x['nodes']} | {x['active_nodes']} | "
                     f"{x['P']:.1f} | {1e3 * x['a_fit']:.4f} ({1e3 * x['a_hertz']:.4f}) | "
                     f"{x['p0_fit'] / 1e6:.3f} ({x['p0_hertz'] / 1e6:.3f}) | {100 * x['a_error']:+.2f} % | "
                     f"{100 * x['p0_error']:+.2f} % | {100 * x['roundness']:.2f} % | {x['start_seconds']:.1f} | "
                     f"{x['peak_mb']:.0f} | {x['mass_redistribution']} |")
    f = r["finest"]
    lines += ["", f"Finest mesh: a {100 * f['a_error']:+.2f} %, p0 {100 * f['p0_error']:+.2f} %, "
                  f"every sector's radius within {100 * f['max_sector_error']:.2f} % of Hertz's a."]
    return "\n".join(lines) + "\n"


def plot(r, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (left, middle, right) = plt.subplots(1, 3, figsize=(15, 4.4))
    finest = r["levels"][-1]
    a, p0 = finest["a_hertz"], finest["p0_hertz"]
    x, z, p = (np.array(finest[k]) for k in ("x", "z", "pressure"))
    near = np.hypot(x, z) < 1.6 * a
    sc = left.tricontourf(1e3 * x[near], 1e3 * z[near], p[near] / 1e6, levels=20, cmap="viridis")
    fig.colorbar(sc, ax=left, label="contact pressure [MPa]")
    t = np.linspace(0, 2 * np.pi, 200)
    left.plot(1e3 * a * np.cos(t), 1e3 * a * np.sin(t), "w--", lw=1, label="Hertz's a")
    left.set_aspect("equal")
    left.set_xlabel("x [mm]")
    left.set_ylabel("z [mm]")
    left.set_title("pressure over the contact face")
    left.legend(loc="upper right")
    s = np.linspace(0, a, 300)
    middle.plot(1e3 * s, p0 * np.sqrt(1 - s ** 2 / a ** 2) / 1e6, "k-", label="Hertz (from the measured P)")
    middle.plot(1e3 * np.hypot(x, z), p / 1e6, "o", ms=2.5, alpha=0.6, label="nodal pressures, every direction")
    middle.set_xlim(0, 1.6 * 1e3 * a)
    middle.set_xlabel("r [mm]")
    middle.set_ylabel("contact pressure [MPa]")
    middle.set_title(f"finest mesh: a/h = {finest['a_over_h']:.1f}, {finest['nodes']} nodes")
    middle.legend()
    h = np.array([1e3 * x["contact_size"] for x in r["levels"]])
    right.loglog(h, [abs(x["a_error"]) for x in r["levels"]], "o-", label="|a error|")
    right.loglog(h, [abs(x["p0_error"]) for x in r["levels"]], "s-", label="|p0 error|")
    right.loglog(h, [x["roundness"] for x in r["levels"]], "^-", label="sector radii spread / a")
    right.axhline(0.02, color="grey", ls=":", label="2 %")
    right.set_xlabel("element size at the contact [mm]")
    right.set_ylabel("relative to Hertz")
    right.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=120)


if __name__ == "__main__":
    main()
