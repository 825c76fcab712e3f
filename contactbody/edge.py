"""The contact edge over time: reads the FMU's edge history (result_directory/
contactbody_edge.npy, written when edge_output_interval > 0), or takes it from the FMI 3.0
FMU's array outputs in a simulate_fmu result, and plots it.

    import contactbody.edge as edge
    e = edge.load("out/contactbody_edge.npy")       # structured array, one record per time
    e = edge.from_result(simulate_fmu("ContactBody_fmi3.fmu", ...))  # the same records
    edge.plot(e, "edge.png", times=[0.005, 0.01])     # x-t maps and pressure profiles
"""
from __future__ import annotations

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.colors import ListedColormap  # noqa: E402

STATES = ["open", "stick", "slip"]


def load(path):
    """Fields: time (s); per node x (m), pressure and friction (Pa, averaged over the step
    like normal_force and friction_force), slip_velocity (m/s, over the last substep,
    relative to the foundation), gap (m, end of the step), state (0 open, 1 stick, 2 slip)."""
    return np.load(path)


# The FMI 3.0 FMU's array outputs and the history's fields they fill.
ARRAYS = {"x": "edge_x", "pressure": "edge_pressure", "friction": "edge_friction",
          "slip_velocity": "edge_slip_velocity", "gap": "edge_gap", "state": "edge_state"}


def dtype(nodes):
    """The history's record type (the .npy file's) for `nodes` bottom nodes."""
    return np.dtype([("time", "<f8")] + [(field, "i1" if field == "state" else "<f8", (nodes,))
                                         for field in ARRAYS])


def from_result(result):
    """The edge history as load() gives it, from a simulate_fmu result of the FMI 3.0 FMU
    (ContactBody_fmi3.fmu), whose edge_* outputs fmpy records as shaped columns."""
    missing = [name for name in ARRAYS.values() if name not in result.dtype.names]
    if missing:
        raise ValueError(f"the result has no {', '.join(missing)}: simulate the FMI 3.0 FMU "
                         "(ContactBody_fmi3.fmu) and record its edge_* outputs")
    nodes = result["edge_x"].shape[1]
    edge = np.empty(len(result), dtype(nodes))
    edge["time"] = result["time"]
    for field, name in ARRAYS.items():
        edge[field] = result[name]
    return edge


def plot(edge, path, times=None, title=None):
    """Three panels: the pressure and the contact state as x-t maps, and pressure profiles
    at `times` (default: four spread over the run). Written as PNG to path."""
    if isinstance(edge, (str, bytes)) or hasattr(edge, "__fspath__"):
        edge = load(edge)
    t, x = edge["time"] * 1e3, edge["x"][0] * 1e3
    extent = [x[0], x[-1], t[0], t[-1]]
    fig, ax = plt.subplots(1, 3, figsize=(14, 4.6))
    image = ax[0].imshow(edge["pressure"] / 1e6, origin="lower", aspect="auto", extent=extent,
                         cmap="viridis", interpolation="nearest")
    fig.colorbar(image, ax=ax[0], label="pressure [MPa]")
    ax[0].set(title="contact pressure (step average)", xlabel="x [mm]", ylabel="t [ms]")
    states = ax[1].imshow(edge["state"], origin="lower", aspect="auto", extent=extent,
                          cmap=ListedColormap(["white", "tab:blue", "tab:orange"]), vmin=-0.5,
                          vmax=2.5, interpolation="nearest")
    bar = fig.colorbar(states, ax=ax[1], ticks=[0, 1, 2])
    bar.ax.set_yticklabels(STATES)
    ax[1].set(title="contact state (last substep)", xlabel="x [mm]", ylabel="t [ms]")
    if times is None:
        times = np.linspace(edge["time"][0], edge["time"][-1], 6)[1:-1]
    for when in times:
        k = int(np.argmin(np.abs(edge["time"] - when)))
        ax[2].plot(x, edge["pressure"][k] / 1e6, label=f"t = {edge['time'][k] * 1e3:.2f} ms")
    ax[2].set(title="pressure profiles", xlabel="x [mm]", ylabel="pressure [MPa]")
    ax[2].legend(fontsize=7)
    if title:
        fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)
