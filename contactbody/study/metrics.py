"""What each point yields: the outputs it reads, the metrics computed from them, and one
point's run."""
from __future__ import annotations

import math
import time

import numpy as np

from ..fmu import Model, Profile, SimulationFailed
from ..material import to_fmu
from .schema import Study


# Outputs every point reads (the metrics are computed from them).
OUTPUTS = ["energy", "clamp_work", "normal_contact_work", "friction_work", "damping_work",
           "friction_dissipation", "normal_force", "friction_force", "max_penetration",
           "active_contact_nodes", "slipping_contact_nodes", "substeps", "substep_refinements",
           "contact_iterations", "gauss_seidel_sweeps"]
# Outputs a 3D body's FMU (ContactBody3D) adds, read where the FMU has them.
SOLID_OUTPUTS = ["friction_force_z"]

# Per point, in this order (units: J/m, N/m, W/m, m for a 2D body, J, N, W, m for a 3D one:
# metric_units; counts summed over the run).
METRICS = {
    "energy_final": "E at stop_time",
    "energy_max": "largest E at a communication point",
    "balance_error_max": "max |E - E(0) - (clamp + normal contact + friction - damping work)|",
    "normal_force_mean": "mean of normal_force over the averaging window",
    "friction_force_mean": "mean of friction_force over the averaging window",
    "friction_force_z_mean": "mean of friction_force_z over the averaging window (0 for a 2D body)",
    "apparent_friction_ratio": "friction_force_mean / normal_force_mean; for a 3D body the mean "
                               "friction force's magnitude, hypot(x, z), / normal_force_mean",
    "slip_fraction": "slipping share of the node-steps in contact (averaging window)",
    "stick_fraction": "sticking share of the node-steps in contact (averaging window)",
    "friction_power": "friction_dissipation's growth over the window / its length",
    "damping_power": "damping_work's growth over the window / its length",
    "max_penetration": "largest max_penetration",
    "substeps": "midpoint substeps taken",
    "refinements": "substeps redone as halves after a failed contact solve",
    "contact_iterations": "semi-smooth Newton iterations",
    "iterations_per_substep": "contact_iterations / substeps",
    "gauss_seidel_sweeps": "sweeps of the contact solver's fallback",
}
METRIC_UNITS = {"energy_final": "J/m", "energy_max": "J/m", "balance_error_max": "J/m",
                "normal_force_mean": "N/m", "friction_force_mean": "N/m",
                "friction_force_z_mean": "N/m",
                "friction_power": "W/m", "damping_power": "W/m", "max_penetration": "m",
                "wall_time": "s", "dostep_time": "s"}


def metric_units(units: dict) -> dict:
    """METRIC_UNITS for the FMU whose variables have `units` (name -> unit): per metre of
    thickness for a 2D body's, N, J and W for a 3D body's (ContactBody3D)."""
    if units.get("energy") == "J":
        return {k: {"J/m": "J", "N/m": "N", "W/m": "W"}.get(v, v) for k, v in METRIC_UNITS.items()}
    return dict(METRIC_UNITS)
TIMES = ["wall_time", "dostep_time"]  # s: the whole point on its worker; its doSteps only


def metrics(s: dict, study: Study) -> dict:
    """The per-point metrics (METRICS) from a run's series."""
    t, e = s["time"], s["energy"]
    balance = (e - e[0]) - (s["clamp_work"] + s["normal_contact_work"] + s["friction_work"] -
                            s["damping_work"])
    # Rows after t0 whose step ends after average_from (row 0 holds the initial reactions).
    window = np.flatnonzero((t > study.average_from) & (np.arange(len(t)) > 0))
    first = max(window[0] - 1, 0) if len(window) else 0
    span = t[-1] - t[first]
    normal = s["normal_force"][window].mean() if len(window) else math.nan
    friction = s["friction_force"][window].mean() if len(window) else math.nan
    solid = "friction_force_z" in s
    friction_z = (s["friction_force_z"][window].mean() if len(window) else math.nan) if solid else 0.0
    tangential = math.hypot(friction, friction_z) if solid else friction
    active = s["active_contact_nodes"][window].sum()
    slipping = s["slipping_contact_nodes"][window].sum()
    substeps = int(s["substeps"].sum())
    iterations = int(s["contact_iterations"].sum())
    return {
        "energy_final": float(e[-1]),
        "energy_max": float(e.max()),
        "balance_error_max": float(np.abs(balance).max()),
        "normal_force_mean": float(normal),
        "friction_force_mean": float(friction),
        "friction_force_z_mean": float(friction_z),
        "apparent_friction_ratio": float(tangential / normal) if normal > 0 else math.nan,
        "slip_fraction": float(slipping / active) if active > 0 else math.nan,
        "stick_fraction": float((active - slipping) / active) if active > 0 else math.nan,
        "friction_power": float((s["friction_dissipation"][-1] -
                                 s["friction_dissipation"][first]) / span) if span > 0 else math.nan,
        "damping_power": float((s["damping_work"][-1] - s["damping_work"][first]) / span)
        if span > 0 else math.nan,
        "max_penetration": float(s["max_penetration"].max()),
        "substeps": substeps,
        "refinements": int(s["substep_refinements"].sum()),
        "contact_iterations": iterations,
        "iterations_per_substep": iterations / substeps if substeps else math.nan,
        "gauss_seidel_sweeps": int(s["gauss_seidel_sweeps"].sum()),
    }


def failed_metrics() -> dict:
    return {name: math.nan for name in METRICS}


def run_point(model: Model, point: dict, study: Study):
    """Runs one point on `model` (reset first). Returns (record, series): series is None
    unless the study keeps series and the run succeeded."""
    tic = time.perf_counter()
    values = {k: v for k, v in point.items() if not isinstance(v, Profile)}
    inputs = {k: v for k, v in point.items() if isinstance(v, Profile)}
    try:
        values = to_fmu(values)  # youngs_modulus, poisson_ratio, loss_factor, ...
    except ValueError as e:
        return ({"status": "failed", "message": str(e), **failed_metrics(),
                 "wall_time": math.nan, "dostep_time": math.nan}, None)
    solid = [n for n in SOLID_OUTPUTS if n in model.variables]
    outputs = list(dict.fromkeys(OUTPUTS + solid + list(study.series)))
    series, dostep = None, math.nan
    try:
        s, dostep = model.run(values, study.stop_time, study.output_interval, outputs, inputs)
        record = {"status": "ok", "message": "", **metrics(s, study)}
        if study.series:
            series = {k: s[k] for k in ["time"] + list(study.series)}
    except (SimulationFailed, ValueError, KeyError) as e:
        record = {"status": "failed", "message": str(e), **failed_metrics()}
    record["wall_time"] = time.perf_counter() - tic
    record["dostep_time"] = dostep
    return record, series
