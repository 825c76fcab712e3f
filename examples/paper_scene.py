"""The paper's section 7 scene (Table 1) with the four mass matrices of the paper (docs/contract.md), simulated
through fmpy's own master. Writes examples/output/paper_scene.png and prints a table.

    .venv/bin/python examples/paper_scene.py [--internal-step 4e-6] [--stop-time 0.02]
"""
import argparse
import pathlib
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from fmpy import simulate_fmu  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[1]
VARIANTS = ["standard", "redistributed_normal", "redistributed_both", "standard_implicit_contact"]
OUTPUTS = ["energy", "friction_work", "energy_minus_friction_work", "normal_force",
           "friction_force", "corner_pressure", "corner_friction", "active_contact_nodes",
           "max_penetration"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--fmu", default=str(ROOT / "build" / "ContactBody.fmu"))
    parser.add_argument("--internal-step", type=float, default=4e-6)
    parser.add_argument("--stop-time", type=float, default=0.02)
    parser.add_argument("--output-interval", type=float, default=1e-4)
    parser.add_argument("--out", default=str(ROOT / "examples" / "output"))
    args = parser.parse_args()

    results = {}
    print(f"{'mass_matrix':<27} {'max E [J/m]':>12} {'E - xi at end':>14} "
          f"{'max penetration [m]':>20} {'wall [s]':>9}")
    for value, name in enumerate(VARIANTS):
        start = time.perf_counter()
        r = simulate_fmu(args.fmu, stop_time=args.stop_time, output_interval=args.output_interval,
                         start_values={"mass_matrix": value, "internal_step": args.internal_step},
                         output=OUTPUTS)
        wall = time.perf_counter() - start
        results[name] = r
        print(f"{name:<27} {r['energy'].max():>12.4g} {r['energy_minus_friction_work'][-1]:>14.4g} "
              f"{r['max_penetration'].max():>20.3g} {wall:>9.3f}")

    fig, axes = plt.subplots(2, 2, figsize=(12, 8), sharex=True)
    panels = [("energy", "E [J/m]", "log"), ("energy_minus_friction_work", "E - ξ [J/m]", "symlog"),
              ("normal_force", "normal force [N/m]", "linear"),
              ("corner_friction", "friction density at (0,0) [Pa]", "linear")]
    for ax, (key, label, scale) in zip(axes.flat, panels):
        for name, r in results.items():
            ax.plot(r["time"] * 1e3, r[key], label=name, lw=0.9)
        ax.set_yscale(scale)
        ax.set_ylabel(label)
        ax.grid(True, alpha=0.3)
    for ax in axes[1]:
        ax.set_xlabel("t [ms]")
    axes[0, 0].legend(fontsize=8)
    fig.suptitle(f"Paper section 7 scene, h = {0.1 / 20 * 100:g} cm, Δt = {args.internal_step:g} s")
    fig.tight_layout()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    fig.savefig(out / "paper_scene.png", dpi=120)
    print(f"wrote {out / 'paper_scene.png'}")


if __name__ == "__main__":
    main()
