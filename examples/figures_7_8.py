"""Paper Figs. 7 and 8: the energy E(t) and E - xi(t) over [0, 0.02 s] at h = 0.5 cm for
dt in {1.6e-5, 8e-6, 4e-6, 2e-6, 1e-6}, one panel per mass_matrix variant.

Writes OUT/figure_7.png, figure_8.png and figures_7_8.json (the rows of the table that
docs/paper_results.md generates from it) and prints that table.

    .venv/bin/python examples/figures_7_8.py [--stop-time 0.02] [--friction 1.2]
"""
import argparse
import json

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from scene import output_argument, DT_LADDER, VARIANTS, simulate  # noqa: E402


def drift(r):
    """Largest |(E - xi)(t) - (E - xi)(0)| over the run [J/m]."""
    e = r["energy_minus_friction_work"]
    return float(np.max(np.abs(e - e[0])))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--stop-time", type=float, default=0.02)
    parser.add_argument("--friction", type=float, default=1.2)
    output_argument(parser)
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)

    runs = {}
    rows = []
    print(f"{'mass_matrix':<27} {'dt [s]':>8} {'max E [J/m]':>12} {'E(end)':>11} "
          f"{'max|E-xi - E0|':>15} {'wall [s]':>9}")
    for v, name in enumerate(VARIANTS):
        for dt in DT_LADDER:
            r, wall = simulate(args.stop_time, 8e-5, mass_matrix=v, internal_step=dt, nx=20, ny=20,
                               friction_coefficient=args.friction, max_energy_ratio=0,
                               outputs=["energy", "energy_minus_friction_work", "friction_work"])
            runs[name, dt] = r
            rows.append({"mass_matrix": name, "dt": dt, "max_energy": float(r["energy"].max()),
                         "end_energy": float(r["energy"][-1]), "drift": drift(r),
                         "initial_energy": float(r["energy"][0]), "wall": wall})
            print(f"{name:<27} {dt:>8.1e} {r['energy'].max():>12.4g} {r['energy'][-1]:>11.4g} "
                  f"{drift(r):>15.4g} {wall:>9.2f}")

    (args.out / "figures_7_8.json").write_text(json.dumps(
        {"friction": args.friction, "stop_time": args.stop_time, "rows": rows}, indent=1) + "\n")

    for key, label, filename in [("energy", "E [J/m]", "figure_7.png"),
                                 ("energy_minus_friction_work", "E - ξ [J/m]", "figure_8.png")]:
        fig, axes = plt.subplots(2, 2, figsize=(12, 8), sharex=True)
        for ax, name in zip(axes.flat, VARIANTS):
            for dt in DT_LADDER:
                r = runs[name, dt]
                ax.plot(r["time"] * 1e3, r[key], lw=0.9, label=f"Δt = {dt:g} s")
            ax.set_title(name)
            ax.set_yscale("symlog" if key != "energy" else "log", **(
                {"linthresh": 1e-2} if key != "energy" else {}))
            ax.set_ylabel(label)
            ax.grid(True, alpha=0.3)
        for ax in axes[1]:
            ax.set_xlabel("t [ms]")
        axes[0, 0].legend(fontsize=8)
        fig.suptitle(f"{'Fig. 7' if key == 'energy' else 'Fig. 8'}: h = 0.5 cm, "
                     f"F = {args.friction:g}")
        fig.tight_layout()
        fig.savefig(args.out / filename, dpi=110)
        print(f"wrote {args.out / filename}")


if __name__ == "__main__":
    main()
