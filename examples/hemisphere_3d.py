"""A hemisphere (R = 5 cm, tetrahedra) pressed onto the foundation through ContactBody3D_fmi3.fmu,
against 3D Hertz: the contact pressure map over the foundation and a cut through it.

The static start (initial_state = static, F = 0) presses the hemisphere's flat face down by
0.2 mm; the FMI 3.0 edge arrays give each contact node's position (x, z) and pressure. For the
measured load P, Hertz gives a = (3 P R / (4 E*))^(1/3), p0 = 3 P / (2 pi a^2) and
p(r) = p0 sqrt(1 - r^2 / a^2) with E* = E / (1 - nu^2). The mesh (contactbody.meshes.hemisphere,
Gmsh) has 0.5 mm cells at the contact; benchmarks/hertz3d.py measures the convergence under
refinement. Writes OUT/hemisphere_3d.png and OUT/hemisphere_3d.json (what it prints).

    .venv/bin/python examples/hemisphere_3d.py [--out DIR] [--contact-size 5e-4]
"""
import argparse
import json
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402
import numpy as np  # noqa: E402

from contactbody import meshes  # noqa: E402
from contactbody.fmu import simulate_fmi3  # noqa: E402
from scene import FMU, output_argument  # noqa: E402

FMU3D = FMU.with_name("ContactBody3D_fmi3.fmu")
RADIUS, TOP = 0.05, -2e-4
LAMBDA, MU = 300e6, 150e6  # the FMU's defaults
E = MU * (3 * LAMBDA + 2 * MU) / (LAMBDA + MU)
NU = LAMBDA / (2 * (LAMBDA + MU))
E_STAR = E / (1 - NU ** 2)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    output_argument(parser)
    parser.add_argument("--contact-size", type=float, default=5e-4, help="cell size at the contact [m]")
    args = parser.parse_args()
    mesh = meshes.hemisphere(args.out / "hemisphere.msh", radius=RADIUS, contact_size=args.contact_size,
                             far_size=1e-2, fine_distance=4.5e-3, refine_distance=0.025, contact_angle=25)
    r = simulate_fmi3(FMU3D, stop_time=1e-6, output_interval=1e-6,
                      start_values={"mesh": str(mesh), "initial_state": 1, "top_displacement": TOP,
                                    "friction_coefficient": 0.0, "foundation_velocity": 0.0,
                                    "internal_step": 1e-6},
                      output=["normal_force", "edge_x", "edge_z", "edge_pressure"])
    first = r[0]  # the static start
    load = float(first["normal_force"])
    a = (3 * load * RADIUS / (4 * E_STAR)) ** (1 / 3)
    p0 = 3 * load / (2 * math.pi * a ** 2)
    x, z, p = first["edge_x"], first["edge_z"], first["edge_pressure"]
    radius = np.hypot(x, z)
    near = radius < 2 * a

    fig, (left, right) = plt.subplots(1, 2, figsize=(13, 5.4))
    tri = mtri.Triangulation(1e3 * x[near], 1e3 * z[near])
    shaded = left.tripcolor(tri, p[near] / 1e6, shading="gouraud", cmap="magma")
    circle = np.linspace(0, 2 * math.pi, 200)
    left.plot(1e3 * a * np.cos(circle), 1e3 * a * np.sin(circle), "c--", lw=1, label=f"Hertz a = {1e3 * a:.2f} mm")
    left.set_aspect("equal")
    left.set_xlabel("x [mm]")
    left.set_ylabel("z [mm]")
    left.set_title(f"contact pressure, P = {load:.0f} N")
    left.legend(loc="upper right")
    plt.colorbar(shaded, ax=left, label="pressure [MPa]")

    s = np.linspace(-1.3 * a, 1.3 * a, 400)
    right.plot(1e3 * s, p0 * np.sqrt(np.clip(1 - s ** 2 / a ** 2, 0, None)) / 1e6, "k-", label="3D Hertz")
    band = np.abs(z) < 0.3 * args.contact_size * 2  # the nodes within a cell of the cut z = 0
    right.plot(1e3 * x[band & near], p[band & near] / 1e6, "o", ms=4, label="FMU: nodes near z = 0")
    right.plot(1e3 * radius[near], p[near] / 1e6, ".", ms=2, color="0.6", label="FMU: every node, at its radius")
    right.set_xlabel("x (or radius) [mm]")
    right.set_ylabel("pressure [MPa]")
    right.set_title("a cut through the pressure map")
    right.legend()
    fig.tight_layout()
    fig.savefig(args.out / "hemisphere_3d.png", dpi=100)
    plt.close(fig)

    pressed = p > 0
    # The nodes' pressures against Hertz's at their radius, inside 0.9 a (the edge of the patch
    # falls between nodes).
    inner = radius < 0.9 * a
    hertz = p0 * np.sqrt(1 - radius[inner] ** 2 / a ** 2)
    summary = {"contact_size_m": args.contact_size, "contact_nodes": int(len(x)), "load_N": load,
               "hertz_a_mm": 1e3 * a, "hertz_p0_MPa": p0 / 1e6,
               "pressed_nodes": int(pressed.sum()),
               "largest_pressed_radius_over_a": float(radius[pressed].max() / a),
               "peak_pressure_over_p0": float(p.max() / p0),
               "pressure_rms_difference_inside_0_9a_over_p0": float(np.sqrt(np.mean((p[inner] - hertz) ** 2)) / p0)}
    (args.out / "hemisphere_3d.json").write_text(json.dumps(summary, indent=1) + "\n")
    print(json.dumps(summary, indent=1))


if __name__ == "__main__":
    main()
