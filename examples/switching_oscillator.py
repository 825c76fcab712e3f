"""One degree of freedom with a switching stiffness: the smallest model of what the
paper's scheme does without friction. With M_r the normal contact dofs are massless, so the
semi-discrete problem is M q'' + grad Phi(q) = 0 for the massive dofs q, with Phi the strain
energy condensed over the contact dofs under the unilateral condition: convex and piecewise
quadratic, stiffer where contact is closed. Near incompressibility, closing a node stiffens
the body more. Here a unit mass q hangs on a spring 1 to the ground and on a spring k - 1 to
a massless node p with the unilateral condition p <= 0 and contact force f = (k-1)(p - q) <= 0:
  Phi(q) = min_{p <= 0} 1/2 q^2 + 1/2 (k - 1)(q - p)^2 = 1/2 q^2 + 1/2 (k - 1) max(q, 0)^2,
stiffness 1 open and k closed. Started at q = 1, v = 0 and advanced 20,000 midpoint steps of
size dt (omega_open dt = dt), with the condition on
  midpoint:  p^{k+1/2} (redistributed_normal, the paper's scheme);
  end:       p^{k+1} = 2 p^{k+1/2} - p^k (redistributed_implicit_contact): the contact work
             f (p^{k+1} - p^k) = f (0 - p^k) <= 0, so E cannot grow.
E is 1/2 v^2 + Phi(q) at the integer steps (the massless node at its static value).
Prints, and writes OUT/switching_oscillator.md and .png: max E / E(0) and E(end) / E(0).

    .venv/bin/python examples/switching_oscillator.py [--out DIR]
"""
import argparse
import pathlib

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

RATIOS = [1, 2, 5, 10, 20, 50]
STEPS_DT = [0.03, 0.1, 0.3, 1.0, 3.0, 10.0]
STEPS = 20000


def energy(q, v, k):
    return 0.5 * v * v + 0.5 * q * q + 0.5 * (k - 1) * max(q, 0.0) ** 2


def step(q, v, p, k, dt, scheme):
    """One midpoint step of (q, v, p); the piecewise linear problem is solved branch by
    branch: open (f = 0, p = q) or closed (p at its bound: 0, or p^k / 2 for `end`)."""
    ks = k - 1
    bound = 0.0 if scheme == "midpoint" else 0.5 * p  # on p^{k+1/2}
    # closed: 4/dt^2 (qh - q) - 2/dt v + qh + ks (qh - bound) = 0, valid if f <= 0 (qh >= bound)
    qh = (4 / dt**2 * q + 2 / dt * v + ks * bound) / (4 / dt**2 + 1 + ks)
    ph = bound
    if qh < bound:  # open: p follows q (no force), valid if the bound holds
        qh = (4 / dt**2 * q + 2 / dt * v) / (4 / dt**2 + 1)
        ph = qh
    return 2 * qh - q, 4 / dt * (qh - q) - v, 2 * ph - p


def run(k, dt, scheme):
    q, v, p = 1.0, 0.0, 0.0
    e0 = energy(q, v, k)
    e_max = e0
    for _ in range(STEPS):
        q, v, p = step(q, v, p, k, dt, scheme)
        e = energy(q, v, k)
        if not np.isfinite(e) or e > 1e100:
            return np.inf, np.inf
        e_max = max(e_max, e)
    return e_max / e0, e / e0


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=pathlib.Path,
                        default=pathlib.Path(__file__).resolve().parent / "output")
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    results = {s: np.array([[run(k, dt, s) for dt in STEPS_DT] for k in RATIOS])
               for s in ("midpoint", "end")}
    lines = [f"max E / E(0) over {STEPS} steps (E(end) / E(0) in brackets)", ""]
    for scheme, r in results.items():
        lines += [f"### {scheme}", "", "| k \\ omega dt | " + " | ".join(f"{d:g}" for d in STEPS_DT)
                  + " |", "|---|" + "---|" * len(STEPS_DT)]
        for i, k in enumerate(RATIOS):
            lines.append(f"| {k} | " + " | ".join(f"{r[i, j, 0]:.3g} ({r[i, j, 1]:.2g})"
                                                  for j in range(len(STEPS_DT))) + " |")
        lines.append("")
    (args.out / "switching_oscillator.md").write_text("\n".join(lines))
    print("\n".join(lines))

    fig, axes = plt.subplots(1, 2, figsize=(9, 3.6), sharey=True)
    for ax, (scheme, r) in zip(axes, results.items()):
        grid = np.log10(np.minimum(r[:, :, 0], 1e300))
        image = ax.imshow(grid, origin="lower", cmap="magma_r", vmin=0, vmax=6, aspect="auto")
        ax.set_xticks(range(len(STEPS_DT)), [f"{d:g}" for d in STEPS_DT])
        ax.set_yticks(range(len(RATIOS)), [str(k) for k in RATIOS])
        ax.set_xlabel("ω_open Δt")
        ax.set_title(f"{scheme}: max E / E(0)")
        for i in range(len(RATIOS)):
            for j in range(len(STEPS_DT)):
                ax.text(j, i, f"{r[i, j, 0]:.2g}", ha="center", va="center", fontsize=7,
                        color="w" if r[i, j, 0] > 100 else "k")
    axes[0].set_ylabel("stiffness ratio closed / open")
    fig.colorbar(image, ax=axes, label="log10(max E / E(0))")
    fig.savefig(args.out / "switching_oscillator.png", dpi=110, bbox_inches="tight")


if __name__ == "__main__":
    main()
