"""Partial slip of a pressed half-cylinder against Cattaneo-Mindlin (issue 43): after the normal
load (static start, as benchmarks/hertz.py, with friction or frictionless), the foundation creeps along x (V = 2 mm/s,
stiffness damping): the friction force Q grows to F P, and the contact splits into a central stick zone
and two slip zones. The 2D partial-slip solution (Cattaneo, Mindlin; uncoupled normal and
tangential problems) gives the stick zone's half-width

    c = a sqrt(1 - Q / (F P)),

which is compared with the edge history's node states (the sticking nodes' extent), record by
record. The uncoupled solution neglects the coupling of an elastic body on a rigid one (Dundurs'
beta = (1 - 2 nu) / (2 (1 - nu)) = 0.25 here); what the FMU computes includes it.

Writes benchmarks/results/cattaneo_mindlin.json, .md and .png.

    .venv/bin/python benchmarks/cattaneo_mindlin.py
"""
import json
import math
import pathlib
import tempfile
import time

import numpy as np

from contactbody import edge, find_fmu, meshes

ROOT = pathlib.Path(__file__).resolve().parents[1]
OUT = ROOT / "benchmarks" / "results"
RADIUS, TOP, FRICTION, SPEED = 0.05, -2.5e-4, 0.3, 0.002
A_EXPECTED = 2.63e-3  # m: Hertz's half-width at TOP (benchmarks/results/hertz.json)
SIZE = A_EXPECTED / 32
STOP, INTERVAL, SUBSTEP = 0.1, 2e-3, 1e-5
# Contact at the end of the step (mass_matrix = 4): with the midpoint contact (variant 1) and
# 1e-5 s substeps the pressed nodes alternate between contact and separation from substep to
# substep (measured: no node is in contact at the end of a step while the step's average
# pressure is Hertz's), so no stick zone can be read from the node states.
# Quasi-static: stiffness damping of 2e-4 s (critical for the body's lowest modes, 0.2 % of the
# elastic stress at this loading rate), no mass damping, which would resist the sticking nodes'
# motion with the foundation.
BETA = 2e-4
# The contact group: the arc within 10 degrees of the bottom (8.7 mm either side, 3.3 a), all
# that can touch. (The whole arc, graded from SIZE to 5 mm, could not carry M_r's least change
# when this benchmark was written; it now takes the least relative change, docs/meshes.md. The
# group is kept so that the results stay comparable.)
CONTACT_ANGLE = 20.0


def stick_half_width(x, state):
    """Half the extent of the sticking nodes (0 where none sticks)."""
    stick = x[state == 1]
    return 0.5 * (stick.max() - stick.min()) if len(stick) else 0.0


MU = 150e6  # the FMU's default shear modulus; lambda from nu


def elastic(nu):
    """(lambda, E*) for shear modulus MU and Poisson's ratio nu, plane strain."""
    lam = 2 * MU * nu / (1 - 2 * nu)
    return lam, 2 * MU * (1 + nu) / (1 - nu ** 2)


def run(nu, frictionless_normal_load=False):
    """One creep run. With frictionless_normal_load the static start presses the body with
    F = 0 (no tangential traction is locked in by the normal load), and F is set to FRICTION
    (a tunable parameter) before the first step."""
    from contactbody.fmu import Model
    lam, e_star = elastic(nu)
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        path = meshes.half_disk(tmp / "roller.msh", radius=RADIUS, contact_size=SIZE,
                                far_size=RADIUS / 10, fine_distance=1.5 * A_EXPECTED,
                                refine_distance=8 * A_EXPECTED, contact_angle=CONTACT_ANGLE)
        t0 = time.perf_counter()
        names = ["normal_force", "friction_force", "active_contact_nodes", "slipping_contact_nodes"]
        with Model(find_fmu(), name="cattaneo_mindlin") as model:
            model.start({"mesh": str(path), "initial_state": 1, "mass_matrix": 4, "lambda": lam,
                         "friction_coefficient": 0.0 if frictionless_normal_load else FRICTION,
                         "top_displacement": TOP, "foundation_velocity": SPEED,
                         "damping_stiffness": BETA, "internal_step": SUBSTEP,
                         "result_directory": str(tmp / "out"), "edge_output_interval": INTERVAL})
            inst = model.instance
            if frictionless_normal_load:
                inst.setReal([model.variable("friction_coefficient").valueReference], [FRICTION])
            refs = [model.variable(n).valueReference for n in names[:2]]
            values = [inst.getReal(refs)]
            steps = int(round(STOP / INTERVAL))
            for k in range(steps):
                inst.doStep(k * INTERVAL, INTERVAL)
                values.append(inst.getReal(refs))
            inst.terminate()
        result = {n: np.array([v[j] for v in values]) for j, n in enumerate(names[:2])}
        seconds = time.perf_counter() - t0
        e = edge.load(tmp / "out" / "contactbody_edge.npy")
    rows = []
    for k, record in enumerate(e):
        P, Q = float(result["normal_force"][k]), float(result["friction_force"][k])
        x, p, state = record["x"], record["pressure"], record["state"]
        if P <= 0 or not (p > 0).any():
            continue
        pressed = x[p > 0]
        a = 0.5 * (pressed.max() - pressed.min())
        a_hertz = math.sqrt(4 * P * RADIUS / (math.pi * e_star))
        ratio = abs(Q) / (FRICTION * P)
        c = stick_half_width(x, state)
        c_theory = a_hertz * math.sqrt(max(0.0, 1 - ratio))
        rows.append({"time": float(record["time"]), "P": P, "Q": Q, "Q_over_FP": ratio,
                     "a_nodes": a, "a_hertz": a_hertz, "c": c, "c_theory": c_theory,
                     "c_error_over_a": (c - c_theory) / a_hertz,
                     "stick_nodes": int(np.sum(state == 1)), "slip_nodes": int(np.sum(state == 2))})
    partial = [r for r in rows if 0.1 <= r["Q_over_FP"] <= 0.9]
    return {"nu": nu, "dundurs_beta": (1 - 2 * nu) / (2 * (1 - nu)), "run_seconds": seconds,
            "normal_load": "frictionless" if frictionless_normal_load else "with friction",
            "rows": rows, "partial_slip": {
                "records": len(partial),
                "max_abs_c_error_over_a": max(abs(r["c_error_over_a"]) for r in partial),
                "mean_c_error_over_a": float(np.mean([r["c_error_over_a"] for r in partial]))}}


def main():
    # The FMU's default material (nu = 1/3), and a nearly incompressible one (nu = 0.49), for
    # which the normal and tangential problems nearly uncouple (Dundurs' beta -> 0) as
    # Cattaneo-Mindlin assumes.
    # Each with the normal load applied with friction (the static start at F = 0.3: tangential
    # tractions are locked in as the contact grows) and frictionless (F = 0.3 set after it).
    cases = {"nu_1_3": run(1 / 3), "nu_0_49": run(0.49),
             "nu_1_3_frictionless_normal_load": run(1 / 3, True),
             "nu_0_49_frictionless_normal_load": run(0.49, True)}
    result_file = {"radius": RADIUS, "top_displacement": TOP, "friction": FRICTION, "speed": SPEED,
                   "element_size": SIZE, "cases": cases}
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / "cattaneo_mindlin.json").write_text(json.dumps(result_file, indent=1) + "\n")
    (OUT / "cattaneo_mindlin.md").write_text(report(result_file))
    plot(result_file, OUT / "cattaneo_mindlin.png")
    print(report(result_file))


def report(r):
    lines = ["# A half-cylinder in partial slip against Cattaneo-Mindlin", "",
             f"`.venv/bin/python benchmarks/cattaneo_mindlin.py`: R = {r['radius']} m, static start at "
             f"{r['top_displacement']} m, F = {r['friction']}, the foundation at {r['speed']} m/s, "
             f"element size {1e3 * r['element_size']:.3f} mm at the contact, mass_matrix = 4; the stick "
             "zone's half-width c from the sticking nodes' extent, c_theory = a sqrt(1 - Q / (F P)) "
             "with Hertz's a for the measured P.", ""]
    for name, case in r["cases"].items():
        ps = case["partial_slip"]
        lines += [f"## nu = {case['nu']:.4g}, normal load {case['normal_load']} (Dundurs' beta = "
                  f"{case['dundurs_beta']:.3f}; run {case['run_seconds']:.1f} s)", "",
                  f"Partial slip (0.1 <= Q / (F P) <= 0.9): {ps['records']} records, largest "
                  f"|c - c_theory| / a = {ps['max_abs_c_error_over_a']:.3f}, mean {ps['mean_c_error_over_a']:+.3f}.", "",
                  "| t [ms] | Q / (F P) | a nodes [mm] | a Hertz [mm] | c [mm] | c theory [mm] | (c - c theory) / a | stick | slip |",
                  "|---|---|---|---|---|---|---|---|---|"]
        for x in case["rows"]:
            lines.append(f"| {1e3 * x['time']:.1f} | {x['Q_over_FP']:.3f} | {1e3 * x['a_nodes']:.3f} | "
                         f"{1e3 * x['a_hertz']:.3f} | {1e3 * x['c']:.3f} | {1e3 * x['c_theory']:.3f} | "
                         f"{x['c_error_over_a']:+.3f} | {x['stick_nodes']} | {x['slip_nodes']} |")
        lines.append("")
    return "\n".join(lines)


def plot(r, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.5, 4.4))
    q = np.linspace(0, 1, 200)
    ax.plot(q, np.sqrt(1 - q), "k-", label="Cattaneo-Mindlin: c / a = sqrt(1 - Q / (F P))")
    for (name, case), marker in zip(r["cases"].items(), ["o", "s", "^", "v"]):
        ax.plot([x["Q_over_FP"] for x in case["rows"]], [x["c"] / x["a_hertz"] for x in case["rows"]],
                marker, ms=4, fillstyle="none" if case["normal_load"] == "frictionless" else "full",
                label=f"FMU, nu = {case['nu']:.3g} (beta = {case['dundurs_beta']:.2f}), "
                      f"normal load {case['normal_load']}")
    ax.set_xlabel("Q / (F P)")
    ax.set_ylabel("c / a (sticking nodes' half-extent)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


if __name__ == "__main__":
    main()
