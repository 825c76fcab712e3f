"""Bodies from Gmsh meshes (the `mesh` parameter), for a person to look at:

1. a half-disk (a roller's cross-section, R = 5 cm) pressed onto the foundation by its flat
   face (static start, F = 0.3, the foundation at rest, then 2 ms);
2. a pad with chamfered corners and a slot, pressed and dragged by the foundation at 5 cm/s
   with static friction twice the kinetic one (F = 0.5, damped): it goes into stick-slip.

Each picture shows the deformed mesh (displacements magnified) coloured by the von Mises stress,
and the contact pressure along the contact boundary (the roller's against 2D Hertz for the
measured load). The meshes are written by Gmsh (contactbody.meshes). Writes OUT/mesh_roller.png,
OUT/mesh_pad.png and OUT/mesh_bodies.json (what it prints).

    .venv/bin/python examples/mesh_bodies.py [--out DIR]
"""
import argparse
import json
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from fmpy import simulate_fmu  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

from contactbody import edge, fields, meshes  # noqa: E402
from scene import FMU, output_argument  # noqa: E402

LAMBDA, MU = 300e6, 150e6


def run(mesh, directory, stop_time, interval, **values):
    directory.mkdir(parents=True, exist_ok=True)
    result = simulate_fmu(str(FMU), stop_time=stop_time, output_interval=interval, start_values={
        "mesh": str(mesh), "result_directory": str(directory), "field_output_interval": stop_time,
        "edge_output_interval": interval, **values},
        output=["normal_force", "friction_force", "active_contact_nodes", "slipping_contact_nodes"])
    snapshots = fields.read_collection(directory / "contactbody.pvd")
    points, triangles, data = fields.read_field(snapshots[-1][1])
    return result, (points, triangles, data["displacement"]), edge.load(directory / "contactbody_edge.npy")


def draw_body(ax, field, scale, title):
    points, triangles, u = field
    deformed = points + scale * u[:, :2]
    stress = fields.von_mises(points, triangles, u, LAMBDA, MU) / 1e6
    polys = PolyCollection(1e3 * deformed[triangles], array=stress, cmap="viridis", edgecolors="face",
                           linewidths=0.1)
    ax.add_collection(polys)
    ax.autoscale_view()
    ax.set_aspect("equal")
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("y [mm]")
    ax.set_title(f"{title} (displacements x{scale:g})")
    plt.colorbar(polys, ax=ax, label="von Mises stress [MPa]", shrink=0.8)


def roller(out):
    # The contact group: the arc within 10 degrees of the bottom; the whole arc, graded from
    # 0.1 to 4 mm cells, cannot carry M_r (docs/meshes.md).
    mesh = meshes.half_disk(out / "roller.msh", radius=0.05, contact_size=1e-4, far_size=4e-3,
                            fine_distance=4e-3, refine_distance=0.02, contact_angle=20)
    result, field, e = run(mesh, out / "roller", 0.002, 2e-5, initial_state=1, foundation_velocity=0.0,
                           friction_coefficient=0.3, top_displacement=-2.5e-4,
                           damping_stiffness=4e-6)
    fig, (left, right) = plt.subplots(1, 2, figsize=(13, 4.8))
    draw_body(left, field, 20, "half-disk, t = 2 ms")
    x, p = e["x"][-1], e["pressure"][-1]
    load = float(result["normal_force"][-1])
    e_star = MU * (3 * LAMBDA + 2 * MU) / (LAMBDA + MU) / (1 - (LAMBDA / (2 * (LAMBDA + MU))) ** 2)
    a = math.sqrt(4 * load * 0.05 / (math.pi * e_star))
    s = np.linspace(-a, a, 300)
    right.plot(1e3 * s, 2 * load / (math.pi * a) * np.sqrt(1 - s ** 2 / a ** 2) / 1e6, "k-",
               label=f"2D Hertz for P = {load / 1e3:.1f} kN/m")
    right.plot(1e3 * x, p / 1e6, "o", ms=3, label="FMU (nodal pressures)")
    right.set_xlim(-2e3 * a, 2e3 * a)
    right.set_xlabel("x [mm]")
    right.set_ylabel("contact pressure [MPa]")
    right.set_title("pressure along the contact boundary")
    right.legend()
    fig.tight_layout()
    fig.savefig(out / "mesh_roller.png", dpi=110)
    plt.close(fig)
    return {"nodes": int(len(field[0])), "load_kN_per_m": load / 1e3, "hertz_half_width_mm": 1e3 * a,
            "peak_pressure_MPa": float(p.max() / 1e6), "hertz_p0_MPa": 2 * load / (math.pi * a) / 1e6}


def pad(out):
    mesh = meshes.pad(out / "pad.msh", size=1e-3)
    result, field, e = run(mesh, out / "pad", 0.02, 2e-5, initial_state=1, foundation_velocity=0.05,
                           friction_coefficient=0.5, static_friction_ratio=2.0,
                           damping_stiffness=4e-6, internal_step=2e-6, top_displacement=-2e-5)
    fig, axes = plt.subplots(1, 3, figsize=(17, 4.6))
    draw_body(axes[0], field, 100, "pad at 5 cm/s, t = 20 ms")
    late = e["time"] > 0.003
    x = 1e3 * e["x"][0]
    # The two faces apart (no line across the slot).
    faces = np.split(np.arange(len(x)), np.flatnonzero(np.diff(x) > 3 * np.median(np.diff(x))) + 1)
    for k, color in zip(np.linspace(np.flatnonzero(late)[0], len(e) - 1, 4).astype(int), "bgrk"):
        for n, face in enumerate(faces):
            axes[1].plot(x[face], e["pressure"][k][face] / 1e6, ".-", ms=3, color=color,
                         label=f"t = {1e3 * e['time'][k]:.1f} ms" if n == 0 else None)
    axes[1].set_xlabel("x [mm]")
    axes[1].set_ylabel("contact pressure [MPa]")
    axes[1].set_title("pressure along the two contact faces")
    axes[1].legend()
    stick = (e["state"] == 1).sum(1)
    axes[2].plot(1e3 * e["time"], stick, label="sticking nodes")
    axes[2].plot(1e3 * e["time"], (e["state"] == 2).sum(1), label="slipping nodes")
    axes[2].set_xlabel("t [ms]")
    axes[2].set_ylabel("contact nodes")
    axes[2].set_title("stick-slip")
    axes[2].legend()
    fig.tight_layout()
    fig.savefig(out / "mesh_pad.png", dpi=110)
    plt.close(fig)
    all_stick = (stick[late] == (e["state"][late] > 0).sum(1)) & (stick[late] > 0)
    return {"nodes": int(len(field[0])), "contact_nodes": int(e["x"].shape[1]),
            "stick_phases_after_3ms": int(np.sum(np.diff(all_stick.astype(int)) == 1)),
            "mean_friction_over_normal": float(np.mean(result["friction_force"][result["time"] > 0.003]
                                                       / result["normal_force"][result["time"] > 0.003]))}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    output_argument(parser)
    args = parser.parse_args()
    summary = {"roller": roller(args.out), "pad": pad(args.out)}
    (args.out / "mesh_bodies.json").write_text(json.dumps(summary, indent=1) + "\n")
    print(json.dumps(summary, indent=1))


if __name__ == "__main__":
    main()
