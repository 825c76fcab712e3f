"""Stability of steady sliding with a slip-rate dependent friction coefficient: the
largest growth rate of the linearized semi-discrete problem over F x dF/dv x beta on the
mesh ladder h = 2, 1, 0.5 cm (redistributed_normal, the paper's body, top_displacement
-2.5e-5 m), and two points of it checked against the FMU.

The linearization (top of sliding_stability.cpp): about the admissible steady sliding state
(nodes the full-contact state would pull on are lifted), a slope F' = dF/dv at the sliding
speed adds the interface damping F' p_i on each touching node's x dof, p_i its steady reaction.
p_i scales with the clamp's displacement, so the map's F' axis holds for top_displacement
-2.5e-5 m; at another U it is the same map with F' x U / -2.5e-5 m.

The FMU check: a law whose F is the same at two foundation speeds, F(V1) = F(V2) = 0.5, with
F'(V1) > 0 (stable by the map) and F'(V2) < 0 (unstable): the body settles at V1 (the kinetic
energy's envelope decays at the predicted rate), then the foundation switches to V2, which
keeps the steady state (F unchanged), and what is left of the transient grows at the predicted
rate. Rates from the envelope of the kinetic energy, which goes as e^{2 Re s t}.

Writes OUT/rate_stability.{json,md,png}.

    .venv/bin/python examples/rate_stability.py [--finest NX] [--out DIR]
"""
import argparse
import concurrent.futures
import json
import pathlib
import subprocess

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from damped_stability import draw_growth  # noqa: E402

from contactbody.stability import first_stable  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[1]
PROGRAM = ROOT / "build" / "sliding_stability"
FMU = ROOT / "build" / "ContactBody.fmu"
FRICTIONS = (0.5, 0.8, 1.2)
BETAS = (0.0, 1e-6, 2e-6, 4e-6, 1e-5)
SLOPES = (-0.2, -0.1, -0.05, -0.02, 0.0, 0.02, 0.05, 0.1, 0.2, 0.5, 1.0, 2.0)
# nx = 20: each beta is a dense eigenvalue problem of 1656 unknowns (about 8 s): fewer points.
FINE_BETAS = (0.0, 2e-6, 4e-6, 1e-5)
FINE_SLOPES = (-0.1, -0.05, 0.0, 0.05, 0.1, 0.3, 1.0)


def growth_rates(nx, friction, slope, betas, top=-2.5e-5):
    """Largest Re s [1/s] (and its frequency [Hz]) for each beta, about the admissible steady
    sliding state; the steady normal force and the lifted nodes."""
    out = subprocess.run([str(PROGRAM), "--lift-off", f"--slope={slope!r}", f"--top={top!r}",
                          str(nx), repr(friction), "1", *map(repr, betas)],
                         check=True, capture_output=True, text=True).stdout
    r = json.loads(out)
    return {"nx": nx, "friction": friction, "slope": slope, "top_displacement": top,
            "normal_force": r["normal_force"], "lifted_nodes": r["lifted_nodes"],
            "betas": list(betas), "growth": [d["max_growth_rate"] for d in r["damped"]],
            "frequency_hz": [d["frequency_hz"] for d in r["damped"]]}


def law_through(friction, v1, slope1, v2, slope2):
    """The law F(v) = F_d + (F_s - F_d) exp(-v / v_s) + c_v v with F(v1) = F(v2) = friction and
    F'(v1) = slope1, F'(v2) = slope2 (v1 > v2 > 0, slope1 > slope2), as FMU parameters.
    F'(v1) - F'(v2) fixes (F_s - F_d) / v_s for a given v_s, F(v1) = F(v2) then fixes v_s
    (bisection on a sign change)."""
    def parts(vs):
        a, b = np.exp(-v1 / vs), np.exp(-v2 / vs)
        drop = vs * (slope1 - slope2) / (b - a)
        viscous = slope1 + drop * a / vs
        return drop, viscous, drop * (a - b) + viscous * (v1 - v2)

    grid = np.logspace(-2, 2, 401)
    g = np.array([parts(vs)[2] for vs in grid])
    k = np.flatnonzero(np.sign(g[:-1]) != np.sign(g[1:]))
    if k.size == 0:
        raise ValueError("no Stribeck velocity gives F(v1) = F(v2)")
    lo, hi = grid[k[0]], grid[k[0] + 1]
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if np.sign(parts(mid)[2]) == np.sign(parts(lo)[2]) else (lo, mid)
    vs = 0.5 * (lo + hi)
    drop, viscous, _ = parts(vs)
    dynamic = friction - drop * np.exp(-v1 / vs) - viscous * v1
    if not dynamic > 0:
        raise ValueError(f"F_d = {dynamic:g} <= 0: the slopes are too far apart for F = {friction}")
    return {"friction_coefficient": float(dynamic),
            "static_friction_ratio": float((dynamic + drop) / dynamic),
            "stribeck_velocity": float(vs), "viscous_friction": float(viscous)}


def friction_law(v, friction_coefficient, static_friction_ratio, stribeck_velocity,
                 viscous_friction):
    v = np.abs(v)
    return (friction_coefficient * (1 + (static_friction_ratio - 1) * np.exp(-v / stribeck_velocity))
            + viscous_friction * v)


def envelope_rate(time, kinetic_energy, start, stop, window):
    """Growth rate [1/s] of the amplitude: half the slope of log(max kinetic energy) over
    consecutive windows (each a few periods long) in [start, stop)."""
    edges = np.arange(start, stop - window / 2, window)
    peaks_t, peaks = [], []
    for a in edges:
        m = (time >= a) & (time < a + window)
        k = np.argmax(kinetic_energy[m])
        peaks_t.append(time[m][k])
        peaks.append(kinetic_energy[m][k])
    return float(np.polyfit(peaks_t, np.log(peaks), 1)[0] / 2)


def fmu_check(nx=10, friction=0.5, beta=4e-6, speeds=(5.0, 1.0), slopes=(0.05, -0.15),
              settle=0.06, grow=0.035, fmu=FMU):
    """Runs the FMU at the two points (see the top) and returns predicted and measured rates."""
    import fmpy

    law = law_through(friction, speeds[0], slopes[0], speeds[1], slopes[1])
    predicted = [growth_rates(nx, friction, s, [beta]) for s in slopes]
    signal = np.array([(0.0, speeds[0]), (settle, speeds[0]), (settle, speeds[1]),
                       (settle + grow, speeds[1])],
                      dtype=[("time", float), ("foundation_velocity", float)])
    r = fmpy.simulate_fmu(str(fmu), stop_time=settle + grow, output_interval=2e-5, input=signal,
                          start_values={**law, "nx": nx, "ny": nx, "damping_stiffness": beta,
                                        "initial_state": 1},
                          output=["kinetic_energy", "normal_force", "friction_force",
                                  "active_contact_nodes", "slipping_contact_nodes"])
    t, ke = r["time"], r["kinetic_energy"]
    window = 4 / predicted[0]["frequency_hz"][0]  # four periods of the least stable mode
    # After the stick-to-slip start has died down to the least damped mode, and from one
    # millisecond after the switch, when the growing mode leads.
    decay = envelope_rate(t, ke, settle / 2, settle, window)
    growth = envelope_rate(t, ke, settle + 0.005, settle + grow, window)
    late = (t > settle / 2) & (t <= settle)
    ratio = np.abs(r["friction_force"][late] / r["normal_force"][late])
    return {"nx": nx, "friction": friction, "beta": beta, "speeds": list(speeds),
            "slopes": list(slopes), "law": law,
            "law_at_speeds": [float(friction_law(v, **law)) for v in speeds],
            "predicted": [p["growth"][0] for p in predicted],
            "frequency_hz": [p["frequency_hz"][0] for p in predicted],
            "measured": [decay, growth],
            "steady_normal_force": predicted[0]["normal_force"],
            "fmu_normal_force_before_switch": float(r["normal_force"][t <= settle][-1]),
            "touching_nodes": nx + 1 - len(predicted[0]["lifted_nodes"]),
            "fmu_active_nodes_before_switch": int(r["active_contact_nodes"][t <= settle][-1]),
            "max_friction_ratio_error_before_switch": float(np.max(np.abs(ratio - friction))),
            "kinetic_energy_at": {"settle/2": float(ke[t <= settle / 2][-1]),
                                  "switch": float(ke[t <= settle][-1]),
                                  "end": float(ke[-1])}}


# Constant-F points where the FMU is run from the static start for 0.2 s and compared with the
# admissible steady state and its least stable rate (the full-contact map called the
# first two unstable at every beta <= 1e-5 s; the third is unstable; the fourth has no state).
SETTLE_POINTS = ((0.8, 4e-6), (1.2, 1e-5), (0.4, 4e-6), (1.5, 1e-5))


def settle_run(friction, beta, nx=10, stop=0.2):
    import fmpy

    run = subprocess.run([str(PROGRAM), "--lift-off", str(nx), repr(friction), "1", repr(beta)],
                         capture_output=True, text=True)
    steady = json.loads(run.stdout) if run.returncode == 0 else None
    r = fmpy.simulate_fmu(str(FMU), stop_time=stop, output_interval=2e-5, start_values={
        "friction_coefficient": friction, "nx": nx, "ny": nx, "damping_stiffness": beta,
        "initial_state": 1}, output=["kinetic_energy", "normal_force", "active_contact_nodes"])
    t, ke = r["time"], r["kinetic_energy"]
    last = t > stop - 0.01
    row = {"friction": friction, "beta": beta, "nx": nx, "steady_state": steady is not None,
           "fmu_active_nodes": sorted({int(a) for a in r["active_contact_nodes"][last]}),
           "fmu_normal_force": [float(r["normal_force"][last].min()),
                                float(r["normal_force"][last].max())],
           "fmu_normal_force_at": {f"{a:g}": float(r["normal_force"][t <= a][-1])
                                   for a in (0.03, 0.1, stop)},
           "fmu_kinetic_energy_last_10ms": [float(ke[last].min()), float(ke[last].max())]}
    if steady is not None:
        rate = steady["damped"][0]["max_growth_rate"]
        window = 4 / max(steady["damped"][0]["frequency_hz"], 100.0)
        row.update({"touching_nodes": nx + 1 - len(steady["lifted_nodes"]),
                    "normal_force": steady["normal_force"], "predicted": rate,
                    "measured": envelope_rate(t, ke, stop / 2, stop, window)})
    return row


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--finest", type=int, default=20)
    parser.add_argument("--out", type=pathlib.Path, default=ROOT / "examples" / "output")
    parser.add_argument("--fmu-only", action="store_true",
                        help="keep the map of OUT/rate_stability.json, redo the FMU runs")
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    meshes = [n for n in (5, 10, 20) if n <= args.finest]
    if args.fmu_only:
        rows = json.loads((args.out / "rate_stability.json").read_text())["rows"]
        meshes = sorted({r["nx"] for r in rows})
    else:
        jobs = [(nx, F, s, FINE_BETAS if nx >= 20 else BETAS) for nx in meshes
                for F in FRICTIONS for s in (FINE_SLOPES if nx >= 20 else SLOPES)]
        with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
            rows = list(pool.map(lambda job: growth_rates(*job), jobs))
    check = fmu_check()
    settled = [settle_run(F, beta) for F, beta in SETTLE_POINTS]
    (args.out / "rate_stability.json").write_text(json.dumps(
        {"rows": rows, "fmu_check": check, "settle_runs": settled}, indent=1))

    lines = ["Smallest stabilizing dF/dv [s/m] on the grid (every larger grid value stable; "
             "'-': none up to the largest), top_displacement -2.5e-5 m, redistributed_normal:",
             "", "| F | beta [s] | " + " | ".join(f"h = {10 / n:g} cm" for n in meshes) + " |",
             "|---|---|" + "---|" * len(meshes)]
    for F in FRICTIONS:
        for beta in BETAS:
            cells = []
            for n in meshes:
                sel = sorted((r for r in rows if r["nx"] == n and r["friction"] == F),
                             key=lambda r: r["slope"])
                if beta not in sel[0]["betas"]:
                    cells.append("")
                    continue
                k = sel[0]["betas"].index(beta)
                cs = first_stable([r["slope"] for r in sel], [r["growth"][k] for r in sel])
                cells.append("-" if cs is None else f"{cs:g}")
            lines.append(f"| {F:g} | {beta:g} | " + " | ".join(cells) + " |")
    lines += ["", "Largest growth rate Re s [1/s] at dF/dv = -0.1, 0, 0.05, 0.1 s/m:", "",
              "| F | beta [s] | h [cm] | -0.1 | 0 | 0.05 | 0.1 |", "|---|---|---|---|---|---|---|"]
    for F in FRICTIONS:
        for beta in (0.0, 4e-6, 1e-5):
            for n in meshes:
                cells = []
                for s in (-0.1, 0.0, 0.05, 0.1):
                    r = next(r for r in rows if r["nx"] == n and r["friction"] == F
                             and r["slope"] == s)
                    cells.append(f"{r['growth'][r['betas'].index(beta)]:.4g}")
                lines.append(f"| {F:g} | {beta:g} | {10 / n:g} | " + " | ".join(cells) + " |")
    c = check
    lines += ["", f"FMU check (nx = {c['nx']}, F = {c['friction']}, beta = {c['beta']:g} s, law "
              + ", ".join(f"{k} = {v:.6g}" for k, v in c["law"].items()) + "):", "",
              "| foundation speed [m/s] | dF/dv [s/m] | predicted Re s [1/s] | measured [1/s] "
              "| measured / predicted |", "|---|---|---|---|---|"]
    for v, s, p, m in zip(c["speeds"], c["slopes"], c["predicted"], c["measured"]):
        lines.append(f"| {v:g} | {s:g} | {p:.4g} | {m:.4g} | {m / p:.3f} |")
    lines += ["", "Constant F from the static start, 0.2 s, h = 1 cm: the admissible steady state "
              "against the FMU (rates from the kinetic energy's envelope over [0.1, 0.2] s; "
              "FMU columns over the last 10 ms):", "",
              "| F | beta [s] | touching nodes | FMU active | N [N/m] | FMU N [N/m] "
              "| predicted Re s [1/s] | measured [1/s] | FMU kinetic energy [J/m] |",
              "|---|---|---|---|---|---|---|---|---|"]
    for r in settled:
        active = ", ".join(map(str, r["fmu_active_nodes"]))
        fmu_n = "{:.5g} to {:.5g}".format(*r["fmu_normal_force"])
        ke = "{:.3g} to {:.3g}".format(*r["fmu_kinetic_energy_last_10ms"])
        if r["steady_state"]:
            lines.append(f"| {r['friction']:g} | {r['beta']:g} | {r['touching_nodes']} | {active} "
                         f"| {r['normal_force']:.5g} | {fmu_n} | {r['predicted']:.4g} "
                         f"| {r['measured']:.4g} | {ke} |")
        else:
            at = r["fmu_normal_force_at"]
            lines.append(f"| {r['friction']:g} | {r['beta']:g} | none | {active} | – | "
                         f"{at['0.03']:.3g} at 0.03 s, {at['0.1']:.3g} at 0.1 s, {at['0.2']:.3g} "
                         f"at 0.2 s | – | – | {ke} |")
    table = "\n".join(lines)
    (args.out / "rate_stability.md").write_text(table + "\n")
    print(table)

    fig, axes = plt.subplots(len(FRICTIONS), len(meshes), figsize=(3.6 * len(meshes), 3.0 * len(FRICTIONS)),
                             sharex=True, sharey=True, squeeze=False)
    for i, F in enumerate(FRICTIONS):
        for j, n in enumerate(meshes):
            ax = axes[i, j]
            sel = sorted((r for r in rows if r["nx"] == n and r["friction"] == F),
                         key=lambda r: r["slope"])
            slopes = [r["slope"] for r in sel]
            g = np.array([r["growth"] for r in sel]).T  # beta x slope
            betas = np.array(sel[0]["betas"]) * 1e6
            mesh = draw_growth(ax, slopes, betas, g)
            ax.set_xscale("symlog", linthresh=0.05)
            ax.set_title(f"F = {F:g}, h = {10 / n:g} cm", fontsize=9)
            if i == len(FRICTIONS) - 1:
                ax.set_xlabel("dF/dv [s/m]")
            if j == 0:
                ax.set_ylabel("β [µs]")
    fig.colorbar(mesh, ax=axes, label="sign(Re s)·log10(1 + |Re s|), Re s in 1/s")
    fig.suptitle("Steady sliding with F(v): largest growth rate (black: Re s = 0; blue: stable)")
    fig.savefig(args.out / "rate_stability.png", dpi=110, bbox_inches="tight")
    print(f"\nwrote {args.out / 'rate_stability.png'}")


if __name__ == "__main__":
    main()
