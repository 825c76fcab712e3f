"""A 3D pad (ContactBody3D_fmi3.fmu) pressed onto the foundation, which slides at 0.2 m/s with
a heading that turns from x to z: the friction turns with it, late.

The pad is contactbody.meshes.pad3d: a 60 x 20 x 40 mm block of tetrahedra with two chamfered
bottom edges and a slot across its bottom face, clamped on top. The static start presses it
down by 0.1 mm (foundation at rest, F = 0.5), then the foundation slides along x for 0.2 ms and
its heading turns a right angle, linearly in time (input_interpolation = ramp), until 1.2 ms;
it slides along z to 3 ms. The friction follows the slip, the foundation's velocity less the
contact nodes' own, and while the heading turns the pad's sheared contact face turns with it:
the friction's heading lags the foundation's, the more the slower it slides (measured on the
6 mm mesh: at most 58, 28 and 16 degrees at 0.2, 1 and 4 m/s, with --speed). Damped (damping_stiffness = 2e-6 s), as sliding with friction needs
(docs/contract.md).

The picture: the deformed surface coloured by the von Mises stress at the end (P1: constant in
each tetrahedron, shown on its boundary faces), the contact pressure over the two contact faces,
the stick/slip map with each node's friction direction in mid-turn, and the headings of the
foundation's velocity and of the total friction force over time. Writes OUT/turning_pad_3d.png
and OUT/turning_pad_3d.json (the measured numbers it prints).

    .venv/bin/python examples/turning_pad_3d.py [--out DIR] [--size 4e-3] [--speed 0.2]
"""
import argparse
import json
import math
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

from contactbody import fields, meshes  # noqa: E402
from contactbody.fmu import simulate_fmi3  # noqa: E402
from scene import FMU, output_argument  # noqa: E402

FMU3D = FMU.with_name("ContactBody3D_fmi3.fmu")
LAMBDA, MU, F = 300e6, 150e6, 0.5
SPEED, TURN, STOP = 0.2, (2e-4, 1.2e-3), 3e-3
SLOT = (27.0, 33.0)  # mm: pad3d()'s slot across the bottom face, x from 27 to 33 mm
OUTPUTS = ["normal_force", "friction_force", "friction_force_z", "energy", "clamp_work",
           "normal_contact_work", "friction_work", "damping_work", "friction_dissipation",
           "foundation_work", "edge_x", "edge_z", "edge_pressure", "edge_friction",
           "edge_friction_z", "edge_state"]


def heading(t):
    """The foundation's heading (rad) at time t: 0 until TURN[0], pi/2 from TURN[1]."""
    return 0.5 * math.pi * np.clip((np.asarray(t) - TURN[0]) / (TURN[1] - TURN[0]), 0, 1)


def run(mesh, directory, interval=5e-5):
    times = np.array([0.0, TURN[0], TURN[1], STOP])
    signals = np.array(list(zip(times, SPEED * np.cos(heading(times)), SPEED * np.sin(heading(times)))),
                       dtype=[("time", float), ("foundation_velocity", float),
                              ("foundation_velocity_z", float)])
    started = time.perf_counter()
    result = simulate_fmi3(FMU3D, stop_time=STOP, output_interval=interval, input=signals, output=OUTPUTS,
                           start_values={"mesh": str(mesh), "initial_state": 1, "top_displacement": -1e-4,
                                         "friction_coefficient": F, "damping_stiffness": 2e-6,
                                         "input_interpolation": 1, "foundation_velocity": SPEED,
                                         "result_directory": str(directory), "field_output_interval": STOP})
    return result, time.perf_counter() - started


def draw_surface(ax, vtu, scale):
    points, tets, data = fields.read_solid_field(vtu)
    u = data["displacement"]
    stress = fields.von_mises_solid(points, tets, u, LAMBDA, MU) / 1e6
    faces, owner = fields.boundary_faces(tets)
    deformed = 1e3 * (points + scale * u)[:, [0, 2, 1]]  # x, z across; y up
    norm = plt.Normalize(stress[owner].min(), stress[owner].max())
    colors = plt.cm.viridis(norm(stress[owner]))
    ax.add_collection3d(Poly3DCollection(deformed[faces], facecolors=colors, edgecolors="k", linewidths=0.05))
    lo, hi = deformed.min(0), deformed.max(0)
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_zlim(lo[2], hi[2])
    ax.set_box_aspect(hi - lo)
    ax.view_init(elev=-25, azim=-60)  # from below: the contact faces and the slot
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("z [mm]")
    ax.set_zlabel("y [mm]")
    ax.set_title(f"von Mises stress at t = {1e3 * STOP:g} ms (displacements x{scale:g})")
    plt.colorbar(plt.cm.ScalarMappable(norm=norm, cmap="viridis"), ax=ax, shrink=0.6,
                 label="von Mises stress [MPa]")
    return stress, len(points)


def contact_triangulation(x, z):
    """Delaunay over the contact nodes (mm), without the triangles that bridge the slot."""
    tri = mtri.Triangulation(x, z)
    centroid = x[tri.triangles].mean(1)
    tri.set_mask((centroid > SLOT[0]) & (centroid < SLOT[1]))
    return tri


def main():
    global SPEED
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    output_argument(parser)
    parser.add_argument("--size", type=float, default=4e-3, help="cell size [m] (default 4e-3)")
    parser.add_argument("--speed", type=float, default=SPEED, help="foundation speed [m/s] (default 0.2)")
    args = parser.parse_args()
    SPEED = args.speed
    mesh = meshes.pad3d(args.out / "pad3d.msh", size=args.size)
    result, seconds = run(mesh, args.out / "turning_pad_3d")
    snapshots = fields.read_collection(args.out / "turning_pad_3d" / "contactbody.pvd")

    fig = plt.figure(figsize=(15, 11))
    stress, nodes = draw_surface(fig.add_subplot(2, 2, 1, projection="3d"), snapshots[-1][1], 30)

    last, mid = result[-1], result[np.argmin(np.abs(result["time"] - 0.5 * sum(TURN)))]
    x, z = 1e3 * last["edge_x"], 1e3 * last["edge_z"]
    tri = contact_triangulation(x, z)
    ax = fig.add_subplot(2, 2, 2)
    shaded = ax.tripcolor(tri, last["edge_pressure"] / 1e6, shading="gouraud", cmap="magma")
    ax.set_aspect("equal")
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("z [mm]")
    ax.set_title(f"contact pressure at t = {1e3 * STOP:g} ms (foundation along z)")
    plt.colorbar(shaded, ax=ax, label="pressure [MPa]")

    ax = fig.add_subplot(2, 2, 3)
    state = mid["edge_state"]
    for value, color, label in ((0, "0.7", "open"), (1, "tab:blue", "stick"), (2, "tab:red", "slip")):
        chosen = state == value
        ax.scatter(x[chosen], z[chosen], s=18, color=color, label=f"{label} ({chosen.sum()})")
    magnitude = np.hypot(mid["edge_friction"], mid["edge_friction_z"])
    shown = magnitude > 0
    ax.quiver(x[shown], z[shown], (mid["edge_friction"] / magnitude)[shown],
              (mid["edge_friction_z"] / magnitude)[shown], scale=40, width=0.003)
    ax.set_aspect("equal")
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("z [mm]")
    ax.set_title(f"stick/slip and friction direction at t = {1e3 * mid['time']:.2f} ms "
                 f"(heading {math.degrees(heading(mid['time'])):.0f}°)")
    ax.legend(loc="upper right", fontsize=8)

    ax = fig.add_subplot(2, 2, 4)
    t = result["time"]
    sliding = t >= 1e-4  # the static start's rest state has no friction direction
    friction_heading = np.degrees(np.arctan2(result["friction_force_z"], result["friction_force"]))
    ax.plot(1e3 * t, np.degrees(heading(t)), "k--", label="foundation velocity")
    ax.plot(1e3 * t[sliding], friction_heading[sliding], "tab:red", label="total friction force")
    share = np.hypot(result["friction_force"], result["friction_force_z"]) / (F * result["normal_force"])
    twin = ax.twinx()
    twin.plot(1e3 * t, share, "tab:blue", lw=0.8)
    twin.set_ylabel("|friction| / (F x normal force)", color="tab:blue")
    twin.set_ylim(0, 1.1)
    ax.set_xlabel("t [ms]")
    ax.set_ylabel("heading in the x-z plane [°]")
    ax.set_title(f"the friction turns with the foundation ({SPEED:g} m/s)")
    ax.legend(loc="center right")
    fig.tight_layout()
    fig.savefig(args.out / "turning_pad_3d.png", dpi=100)
    plt.close(fig)

    lag = friction_heading - np.degrees(heading(t))
    balance = (result["energy"] - result["energy"][0] - result["clamp_work"] - result["normal_contact_work"]
               - result["friction_work"] + result["damping_work"])
    works = ["energy", "clamp_work", "normal_contact_work", "friction_work", "damping_work", "foundation_work"]
    summary = {
        "nodes": nodes, "contact_nodes": int(len(x)), "cell_size_m": args.size, "speed_m_per_s": SPEED,
        "run_seconds": seconds,
        "normal_force_N": float(last["normal_force"]),
        "friction_heading_minus_foundation_heading_deg_at_end": float(lag[-1]),
        "largest_heading_lag_during_turn_deg": float(np.abs(lag[(t >= TURN[0]) & (t <= TURN[1])]).max()),
        "friction_over_F_normal_at_end": float(share[-1]),
        "mid_turn_nodes": {"stick": int((state == 1).sum()), "slip": int((state == 2).sum()),
                           "open": int((state == 0).sum())},
        "largest_von_mises_MPa": float(stress.max()),
        "energy_balance_residual": float(np.abs(balance).max() /
                                         max(result["energy"][0], *(np.abs(result[w]).max() for w in works))),
    }
    (args.out / "turning_pad_3d.json").write_text(json.dumps(summary, indent=1) + "\n")
    print(json.dumps(summary, indent=1))


if __name__ == "__main__":
    main()
