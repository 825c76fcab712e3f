"""Stability map of steady sliding with Rayleigh damping C = beta A: the
largest growth rate of the linearized semi-discrete problem over F x beta, for h = 2, 1, 0.5
and 0.25 cm (redistributed_normal, the paper's scene). build/sliding_stability computes the
undamped eigenvalues once per (h, F); the damped rates follow exactly from them (see the top
of sliding_stability.cpp), so the beta axis costs nothing.

The steady state linearized about is the admissible one (--lift-off: the nodes that the full
contact state would pull on are lifted); --full-contact gives the earlier map, which
linearized about every node touching. Where no admissible steady sliding state
exists (F >= 1.3 here: the clamped body wedges) the row has no growth rates.
About 30 min on 2 cores (the nx = 40 eigenvalues dominate).

Writes OUT/damped_stability.png, .json and .md (the table of the smallest stabilizing beta);
with --full-contact OUT/damped_stability_full_contact.* (docs/paper_results.md generates its
full-contact table from the .json: --full-contact --friction 0.3,0.5,1.2, 15 min).

    .venv/bin/python examples/damped_stability.py [--finest NX] [--friction F,...] [--out DIR]
"""
import argparse
import concurrent.futures
import json
import pathlib
import subprocess

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from contactbody.stability import first_stable  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[1]
PROGRAM = ROOT / "build" / "sliding_stability"
BETAS = np.linspace(0, 1e-5, 101)


def analyse(nx, friction, variant=1, lift_off=True):
    run = subprocess.run([str(PROGRAM), *(["--lift-off"] if lift_off else []), str(nx),
                          repr(friction), str(variant), *(repr(float(b)) for b in BETAS)],
                         capture_output=True, text=True)
    if run.returncode == 1 and "no admissible steady contact set" in run.stderr:
        return {"nx": nx, "h": 0.1 / nx, "friction": friction, "steady_state": False,
                "growth": None}
    if run.returncode != 0:
        raise RuntimeError(f"sliding_stability {nx} {friction}: {run.stderr.strip()}")
    r = json.loads(run.stdout)
    return {"nx": nx, "h": r["h"], "friction": friction, "seconds": r["seconds"],
            "steady_state": True, "lifted_nodes": r["lifted_nodes"],
            "normal_force": r["normal_force"],
            "growth": [d["max_growth_rate"] for d in r["damped"]]}


def critical_beta(growth):
    """Smallest beta of the grid from which every larger one is stable."""
    return first_stable(BETAS, growth)


def draw_growth(ax, x, y, growth):
    """The growth rates (y x x) as a signed log colour map with the Re s = 0 contour."""
    level = np.sign(growth) * np.log10(1 + np.abs(growth))
    mesh = ax.pcolormesh(x, y, level, cmap="RdBu_r", vmin=-5, vmax=5, shading="nearest")
    ax.contour(x, y, growth, levels=[0], colors="k", linewidths=1.5)
    return mesh


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--finest", type=int, default=40, help="finest nx (dense eigenvalues)")
    parser.add_argument("--out", type=pathlib.Path, default=ROOT / "examples" / "output")
    parser.add_argument("--full-contact", action="store_true",
                        help="linearize about every node touching (the full-contact map)")
    parser.add_argument("--friction", help="only these F, comma-separated (default 0 ... 2)")
    parser.add_argument("--replot", action="store_true",
                        help="redo the table and figure from OUT/damped_stability.json")
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    name = "damped_stability_full_contact" if args.full_contact else "damped_stability"
    if args.replot:
        rows = json.loads((args.out / f"{name}.json").read_text())["rows"]
    else:
        frictions = {n: np.round(np.arange(0, 2.0001, 0.1), 2) for n in (5, 10, 20)}
        # nx = 40 (3239 dofs) takes 2-4 min per F: up to F = 1.5 (none beyond 1.25 has a
        # steady state on the coarser meshes).
        frictions[40] = np.round(np.arange(0, 1.5001, 0.1), 2)
        if args.friction:
            chosen = [float(f) for f in args.friction.split(",")]
            frictions = {n: chosen for n in frictions}
        jobs = [(nx, float(F)) for nx in frictions if nx <= args.finest for F in frictions[nx]]
        with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
            rows = list(pool.map(lambda job: analyse(*job, lift_off=not args.full_contact),
                                 jobs))
        for r in rows:
            r["critical_beta"] = critical_beta(r["growth"])
        (args.out / f"{name}.json").write_text(json.dumps(
            {"betas": BETAS.tolist(), "lift_off": not args.full_contact, "rows": rows}, indent=1))

    sizes = sorted({r["nx"] for r in rows})
    lines = ["Smallest stabilizing beta [s] (grid step 1e-7; '-' = unstable up to 1e-5 s; "
             "'none' = no admissible steady sliding state), redistributed_normal, alpha = 0:", "",
             "| F | " + " | ".join(f"h = {100 * 0.1 / n:g} cm" for n in sizes) + " |",
             "|---|" + "---|" * len(sizes)]
    for F in sorted({r["friction"] for r in rows}):
        cells = []
        for n in sizes:
            match = [r for r in rows if r["nx"] == n and r["friction"] == F]
            if not match:
                cells.append("")
                continue
            cb = match[0]["critical_beta"]
            cells.append("none" if match[0]["growth"] is None else
                         "-" if cb is None else f"{cb:.1e}")
        lines.append(f"| {F:g} | " + " | ".join(cells) + " |")
    table = "\n".join(lines)
    (args.out / f"{name}.md").write_text(table + "\n")
    print(table)

    fig, axes = plt.subplots(1, len(sizes), figsize=(3.6 * len(sizes), 3.6), sharey=True)
    for ax, n in zip(np.atleast_1d(axes), sizes):
        sel = sorted((r for r in rows if r["nx"] == n and r["growth"] is not None),
                     key=lambda r: r["friction"])
        F = [r["friction"] for r in sel]
        g = np.array([r["growth"] for r in sel]).T  # beta x F
        mesh = draw_growth(ax, F, BETAS * 1e6, g)
        ax.set_title(f"h = {100 * 0.1 / n:g} cm")
        ax.set_xlabel("F")
    np.atleast_1d(axes)[0].set_ylabel("β [µs]")
    fig.colorbar(mesh, ax=axes, label="sign(Re s)·log10(1 + |Re s|), Re s in 1/s")
    fig.suptitle("Damped steady sliding: largest growth rate (black: Re s = 0; blue: stable)")
    fig.savefig(args.out / f"{name}.png", dpi=110, bbox_inches="tight")
    print(f"\nwrote {args.out / f'{name}.png'}")


if __name__ == "__main__":
    main()
