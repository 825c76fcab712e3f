"""Energy growth without friction: the default scene with F = 0 and the top held,
so that no work enters the body and E should stay at E(0), over lambda/mu x the Courant number
c_p dt / h, for each mass_matrix variant, through the FMU.

With F = 0 and the clamp at rest, E - E(0) = normal_contact_work exactly (the energy balance of
the FMU's outputs), so the growth is measured together with its cause: the work of the normal
contact forces. Reported per cell: max E / E(0) over the run, E(end) / E(0), and the normal
contact work at the end relative to E(0), and max kinetic energy / E(0): the paper's scheme
extrapolates the massless normal dofs to the integer steps (2 u^{k+1/2} - u^k), which do not
feed back into its motion, so growth in E with a bounded kinetic energy is in those values
only, while growth of the kinetic energy is growth of the motion.

Writes OUT/frictionless_stability.png, .json and .md.

    .venv/bin/python examples/frictionless_stability.py [--stop 0.02] [--out DIR] [--fmu FMU]
"""
import argparse
import json
import math
import pathlib

import matplotlib
import numpy as np
from fmpy.fmi1 import FMICallException

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from scene import FMU, ROOT, simulate  # noqa: E402

VARIANTS = ["standard", "redistributed_normal", "redistributed_both",
            "standard_implicit_contact", "redistributed_implicit_contact"]
RATIOS = [0.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0]  # lambda / mu
COURANT = [0.1, 0.3, 1.0, 3.0, 10.0, 20.0]  # c_p dt / h
MU, RHO, H = 150e6, 1000.0, 0.005  # the paper's mu and rho, h = 0.5 cm (nx = ny = 20)


def run(variant, ratio, courant, stop, fmu=FMU):
    c_p = math.sqrt((ratio + 2) * MU / RHO)
    dt = courant * H / c_p
    # Outputs every whole number of substeps near 1e-4 s, so that every substep is exactly dt.
    interval = dt * max(1, round(1e-4 / dt))
    stop = interval * math.ceil(stop / interval - 1e-9)
    try:
        r, wall = simulate(stop, interval, fmu=fmu,
                           outputs=["energy", "normal_contact_work", "kinetic_energy"],
                           friction_coefficient=0.0, mass_matrix=variant,
                           **{"lambda": ratio * MU}, internal_step=dt,
                           max_energy_ratio=0.0)  # measures the growth: no guard
    except FMICallException:  # the energy overflowed: the FMU ends the run with fmi2Error
        return {"variant": variant, "lambda_over_mu": ratio, "courant": courant, "dt": dt,
                "completed": False, "max_E_ratio": math.inf}
    e = r["energy"]
    finite = np.isfinite(e)
    return {"variant": variant, "lambda_over_mu": ratio, "courant": courant, "dt": dt,
            "completed": bool(abs(r["time"][-1] - stop) < 1e-9 and finite.all()),
            "E0": float(e[0]), "max_E_ratio": float(np.nanmax(e) / e[0]),
            "end_E_ratio": float(e[-1] / e[0]),
            "max_kinetic_ratio": float(np.nanmax(r["kinetic_energy"]) / e[0]),
            "normal_contact_work_ratio": float(r["normal_contact_work"][-1] / e[0]),
            "wall": wall}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--stop", type=float, default=0.02)
    parser.add_argument("--fmu", type=pathlib.Path, default=FMU)
    parser.add_argument("--out", type=pathlib.Path, default=ROOT / "examples" / "output")
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    rows = []
    for v in range(len(VARIANTS)):
        for ratio in RATIOS:
            for c in COURANT:
                rows.append(run(v, ratio, c, args.stop, args.fmu))
                print(json.dumps(rows[-1]), flush=True)
    (args.out / "frictionless_stability.json").write_text(json.dumps(rows, indent=1))

    lines = [f"max E / E(0) over {args.stop:g} s, F = 0, top held (E should stay at E(0)); "
             "in brackets E(end) / E(0), then max kinetic energy / E(0)", ""]
    for v, name in enumerate(VARIANTS):
        lines += [f"### {name} (mass_matrix = {v})", "",
                  "| λ/μ \\ c_p Δt / h | " + " | ".join(f"{c:g}" for c in COURANT) + " |",
                  "|---|" + "---|" * len(COURANT)]
        for ratio in RATIOS:
            cells = []
            for c in COURANT:
                r = next(r for r in rows if r["variant"] == v and r["lambda_over_mu"] == ratio
                         and r["courant"] == c)
                cells.append(f"{r['max_E_ratio']:.3g} ({r['end_E_ratio']:.2g}), "
                             f"{r['max_kinetic_ratio']:.2g}"
                             if r["completed"] else "overflow")
            lines.append(f"| {ratio:g} | " + " | ".join(cells) + " |")
        lines.append("")
    (args.out / "frictionless_stability.md").write_text("\n".join(lines))
    print("\n".join(lines))

    fig, axes = plt.subplots(1, len(VARIANTS), figsize=(3.3 * len(VARIANTS), 3.4), sharey=True)
    for ax, (v, name) in zip(axes, enumerate(VARIANTS)):
        grid = np.array([[next(r for r in rows if r["variant"] == v and r["lambda_over_mu"] == ratio
                                and r["courant"] == c)["max_E_ratio"] for c in COURANT]
                         for ratio in RATIOS])
        image = ax.imshow(np.log10(np.where(np.isfinite(grid), grid, 1e300)), origin="lower",
                          cmap="magma_r", vmin=0, vmax=6, aspect="auto")
        ax.set_xticks(range(len(COURANT)), [f"{c:g}" for c in COURANT])
        ax.set_yticks(range(len(RATIOS)), [f"{r:g}" for r in RATIOS])
        ax.set_title(name, fontsize=9)
        ax.set_xlabel("c_p Δt / h")
        for i in range(len(RATIOS)):
            for j in range(len(COURANT)):
                ax.text(j, i, f"{grid[i, j]:.2g}", ha="center", va="center", fontsize=6,
                        color="w" if grid[i, j] > 100 else "k")
    axes[0].set_ylabel("λ / μ")
    fig.colorbar(image, ax=axes, label="log10(max E / E(0))")
    fig.suptitle(f"F = 0, top held: energy growth over {args.stop:g} s (0 = none)")
    fig.savefig(args.out / "frictionless_stability.png", dpi=110, bbox_inches="tight")
    print(f"wrote {args.out / 'frictionless_stability.png'}")


if __name__ == "__main__":
    main()
