"""Paper Fig. 10: the friction force density at (0, 0) (output corner_friction) over
[0, 5 ms] for the Table 2 ladder, for redistributed_normal and redistributed_both (F = 1.2).

Writes examples/output/figure_10.png and prints a table.

    .venv/bin/python examples/figure_10.py
"""
import argparse
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from scene import output_argument, TABLE2, VARIANTS, cells, simulate  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    output_argument(parser)
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.2), sharey=True)
    print(f"{'mass_matrix':<22} {'h [cm]':>7} {'dt [s]':>8} {'mean [MPa]':>11} "
          f"{'min [MPa]':>10} {'max [MPa]':>10}")
    for ax, variant in zip(axes, (1, 2)):
        for h, dt in TABLE2:
            n = cells(h)
            # One output per substep of the coarsest run: the output is an average over it.
            r, _ = simulate(5.12e-3, 1.6e-5, mass_matrix=variant, nx=n, ny=n, internal_step=dt,
                            outputs=["corner_friction", "corner_pressure"])
            ax.plot(r["time"] * 1e3, r["corner_friction"] / 1e6, lw=0.9,
                    label=f"h = {h * 100:g} cm, Δt = {dt:g} s")
            cf = r["corner_friction"][1:] / 1e6
            print(f"{VARIANTS[variant]:<22} {h * 100:>7g} {dt:>8.1e} {np.mean(cf):>11.2f} "
                  f"{cf.min():>10.2f} {cf.max():>10.2f}")
        ax.set_title(VARIANTS[variant])
        ax.set_xlabel("t [ms]")
        ax.grid(True, alpha=0.3)
    axes[0].set_ylabel("friction force density at (0, 0) [MPa]")
    axes[0].legend(fontsize=8)
    fig.suptitle("Fig. 10: corner_friction, F = 1.2 (averages over 16 µs output steps)")
    fig.tight_layout()
    fig.savefig(args.out / "figure_10.png", dpi=110)
    print(f"wrote {args.out / 'figure_10.png'}")


if __name__ == "__main__":
    main()
