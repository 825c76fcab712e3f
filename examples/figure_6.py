"""Paper Fig. 6: the deformed mesh with the contact pressure along the bottom edge at a few
times, rendered from the FMU's field output (.pvd + .vtu read with meshio).

Writes examples/output/figure_6.png.

    .venv/bin/python examples/figure_6.py [--magnify 200] [--mass-matrix 1]
"""
import argparse
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402
import numpy as np  # noqa: E402

from contactbody import fields  # noqa: E402
from scene import output_argument, simulate  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--magnify", type=float, default=None,
                        help="displacement scale (default: largest displacement drawn as 1 cm)")
    parser.add_argument("--mass-matrix", type=int, default=1)
    parser.add_argument("--times", type=float, nargs="+", default=[0, 1e-3, 2e-3, 4e-3])
    output_argument(parser)
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory() as directory:
        simulate(max(args.times) + 1e-4, 1e-4, mass_matrix=args.mass_matrix,
                 result_directory=directory, field_output_interval=1e-4)
        snapshots = fields.read_collection(f"{directory}/contactbody.pvd")
        chosen = [min(snapshots, key=lambda s: abs(s[0] - t)) for t in args.times]
        frames = [(t, fields.read_field(path)) for t, path in chosen]

    if args.magnify is None:
        largest = max(np.abs(f[2]["displacement"]).max() for _, f in frames)
        args.magnify = float(f"{0.01 / largest:.2g}")
    fig, axes = plt.subplots(2, len(frames), figsize=(4 * len(frames), 7),
                             gridspec_kw={"height_ratios": [3, 1]})
    pmax = max(f[2]["contact_pressure"].max() for _, f in frames) / 1e6
    for k, (t, (points, triangles, data)) in enumerate(frames):
        u = data["displacement"][:, :2]
        deformed = points + args.magnify * u
        speed = np.linalg.norm(data["velocity"][:, :2], axis=1)
        tri = mtri.Triangulation(deformed[:, 0] * 100, deformed[:, 1] * 100, triangles)
        ax = axes[0, k]
        shade = ax.tripcolor(tri, speed, shading="gouraud", cmap="viridis")
        ax.triplot(tri, lw=0.2, color="k", alpha=0.5)
        bottom = np.where(points[:, 1] == 0)[0]
        bottom = bottom[np.argsort(points[bottom, 0])]
        segments = np.stack([deformed[bottom[:-1]], deformed[bottom[1:]]], axis=1) * 100
        line = LineCollection(segments, cmap="inferno", lw=4)
        line.set_array(data["contact_pressure"][bottom[:-1]] / 1e6)
        line.set_clim(0, pmax)
        ax.add_collection(line)
        ax.set_aspect("equal")
        ax.set_title(f"t = {t * 1e3:.1f} ms (displacement × {args.magnify:g})")
        ax.set_xlabel("x [cm]")
        fig.colorbar(shade, ax=ax, shrink=0.6, label="|v| [m/s]")
        axes[1, k].plot(points[bottom, 0] * 100, data["contact_pressure"][bottom] / 1e6, ".-")
        axes[1, k].set_xlabel("x [cm]")
        axes[1, k].grid(True, alpha=0.3)
    axes[0, 0].set_ylabel("y [cm]")
    axes[1, 0].set_ylabel("contact pressure [MPa]")
    fig.tight_layout()
    fig.savefig(args.out / "figure_6.png", dpi=110)
    print(f"wrote {args.out / 'figure_6.png'}")


if __name__ == "__main__":
    main()
