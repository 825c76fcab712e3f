"""Stability stress test: random scenes over friction (and on half the frictional scenes a
slip-rate law: a Stribeck drop, a viscous term or both), foundation velocity, substep size,
mesh and aspect ratio, lambda/mu, top load from compression to tension, initial gap, damping
and all five mass_matrix variants. Each scene runs in its own process
(so that a crash or a hang is recorded, not fatal) for STOP seconds at 1e-4 s steps.

Recorded per scene: status (ok, error: the FMU's message, refused at initialization, crash,
timeout), max E against the work put in (E(0) + |clamp_work| + |foundation_work|), the energy
balance error, max penetration, Newton iterations, Gauss-Seidel sweeps and refinements (from
the FMU's log). Blow-up: max E above 1e3 x the work put in. Both top controls (with a force
from tension to compression and plate masses 0.1-10 kg/m), and three motions (MOTIONS): on
the foundation (a quarter from the static initial state), free flight, hanging from the clamp.

A scene with a slip-rate law also runs with the constant law (its twin), for the cost the law
adds. Writes OUT/stress_sweep.json and .md (per variant: the fraction that fails, blows up or
refines, and the worst cases; the slip-rate scenes' CPU time against their twins').

    .venv/bin/python examples/stress_sweep.py [--scenes 200] [--seed 1] [--stop 2e-3] [--out DIR]
"""
import argparse
import json
import pathlib
import subprocess
import sys

import numpy as np

from scene import FMU, ROOT

VARIANTS = ["standard", "redistributed_normal", "redistributed_both",
            "standard_implicit_contact", "redistributed_implicit_contact"]
OUTPUTS = ["energy", "clamp_work", "normal_contact_work", "friction_work", "damping_work",
           "foundation_work", "max_penetration", "contact_iterations", "gauss_seidel_sweeps",
           "substep_refinements"]


MOTIONS = ["on the foundation", "free flight", "hanging"]


def random_scene(rng, variant, motion="on the foundation"):
    """One point of the sweep's box (log-uniform where the range spans decades). motion: the
    body pressed on the foundation (a quarter of these from the static initial state); flying
    with a random velocity 1 mm to 1 m above it, under no top force or under tension (force
    control); or hanging from a lifted clamp (stretched) above a gap, with a random velocity."""
    H = float(np.exp(rng.uniform(np.log(0.01), np.log(0.1))))
    aspect = float(np.exp(rng.uniform(np.log(0.1), np.log(10))))
    mu = float(np.exp(rng.uniform(np.log(1e6), np.log(1e10))))
    ratio = float(rng.choice([0.0, rng.uniform(0, 5), rng.uniform(5, 100)]))
    scene = {
        "mass_matrix": variant,
        "height": H, "width": H * aspect,
        "nx": int(np.exp(rng.uniform(np.log(2), np.log(40)))),
        "ny": int(np.exp(rng.uniform(np.log(2), np.log(40)))),
        "mu": mu, "lambda": ratio * mu,
        "density": float(np.exp(rng.uniform(np.log(100), np.log(10000)))),
        "friction_coefficient": float(rng.choice([0.0, rng.uniform(0, 3)])),
        "foundation_velocity": float(rng.uniform(-40, 40)),
        "internal_step": float(np.exp(rng.uniform(np.log(5e-7), np.log(3.2e-5)))),
        "top_displacement": float(rng.uniform(-1e-3, 2e-4) * H),
        "initial_gap": float(rng.choice([0.0, rng.uniform(0, 1e-4) * H])),
        "damping_stiffness": float(rng.choice([0.0, 0.0, 4e-6])),
        "top_control": int(rng.integers(0, 2)),
        "top_force": float(rng.uniform(-0.2, 1.0) * mu * H * 1e-3),  # tension to compression
        "top_mass": float(np.exp(rng.uniform(np.log(0.1), np.log(10)))),
    }
    velocity = {"initial_velocity_x": float(rng.uniform(-5, 5)),
                "initial_velocity_y": float(rng.uniform(-1, 5))}
    if motion == "free flight":
        scene.update(top_control=1, initial_gap=float(np.exp(rng.uniform(np.log(1e-3), 0))),
                     top_force=float(rng.choice([0.0, rng.uniform(-0.2, 0) * mu * H * 1e-3])),
                     **velocity)
    elif motion == "hanging":
        scene.update(top_control=0, top_displacement=float(rng.uniform(0, 1e-3) * H),
                     initial_gap=float(rng.uniform(0, 1e-3) * H), **velocity)
    elif rng.uniform() < 0.25:
        scene.update(initial_state=1)
        if scene["top_control"] == 1:  # the static state under force control needs a load
            scene["top_force"] = abs(scene["top_force"])
    # A slip-rate law on half the scenes with friction: a Stribeck drop, a viscous term or both.
    if scene["friction_coefficient"] > 0 and rng.uniform() < 0.5:
        kind = rng.integers(0, 3)  # 0: Stribeck, 1: viscous, 2: both
        if kind != 1:
            scene.update(static_friction_ratio=float(rng.uniform(1, 3)),
                         stribeck_velocity=float(np.exp(rng.uniform(np.log(0.01), np.log(1)))))
        if kind != 0:
            scene["viscous_friction"] = float(np.exp(rng.uniform(np.log(1e-3), np.log(0.1))))
    return scene


CONSTANT_LAW = {"stribeck_velocity": 0.0, "viscous_friction": 0.0, "static_friction_ratio": 1.0}


def has_rate_law(scene):
    return scene.get("stribeck_velocity", 0) > 0 or scene.get("viscous_friction", 0) > 0


def energy_floor(scene):
    """Below this (J/m) the balance error is taken absolute: the strain energy of a strain of
    1e-6 over the body, far below any loaded scene's. A body lifted off as a rigid
    translation has E of round-off size and nothing put in: 1e-32 J/m, or 1e-28 J/m for a
    stiff one (mu = 6.5e9 Pa), which a fixed floor of 1e-20 J/m called an error of 1e-8."""
    return 1e-12 * scene["mu"] * scene["width"] * scene["height"]


def run_scene(scene, stop, fmu):
    """In this process: the scene's record (called in a child process by sweep())."""
    from contactbody.fmu import Model, SimulationFailed

    import time

    record = {"scene": scene, "status": "ok", "message": ""}
    with Model(fmu, name="sweep") as model:
        tic = time.process_time()
        try:
            rows, _ = model.run(scene, stop, 1e-4, OUTPUTS)
        except SimulationFailed as e:
            if e.stage == "initialization":
                record.update(status="refused", message=str(e))
                return record
            record.update(status="error", message=str(e))
            rows = e.series
        record["cpu_s"] = time.process_time() - tic
        record["warnings"] = [m[2] for m in model.instance.messages if m[0] == 1]
    energy, last = rows["energy"], {n: rows[n][-1] for n in OUTPUTS}
    put_in = energy[0] + abs(last["clamp_work"]) + abs(last["foundation_work"])
    balance = (last["energy"] - energy[0] - last["clamp_work"] - last["normal_contact_work"]
               - last["friction_work"] + last["damping_work"])
    record.update(
        steps=len(energy) - 1, max_energy=float(energy.max()), work_in=float(put_in),
        blow_up=bool(energy.max() > 1e3 * put_in),
        balance_error=float(abs(balance) / max(abs(last["energy"]), put_in, energy_floor(scene))),
        max_penetration=float(rows["max_penetration"].max()),
        newton_iterations=int(rows["contact_iterations"].sum()),
        sweeps=int(rows["gauss_seidel_sweeps"].sum()),
        refinements=int(rows["substep_refinements"].sum()))
    return record


def run_in_child(scene, stop, fmu, timeout):
    code = (f"import json, sys; sys.path.insert(0, {str(ROOT / 'examples')!r}); "
            f"import stress_sweep; print(json.dumps(stress_sweep.run_scene("
            f"json.loads(sys.argv[1]), {stop!r}, {str(fmu)!r})))")
    try:
        out = subprocess.run([sys.executable, "-c", code, json.dumps(scene)],
                             capture_output=True, text=True, timeout=timeout)
        if out.returncode != 0:
            return {"scene": scene, "status": "crash",
                    "message": out.stderr.strip().splitlines()[-1:] or [""]}
        return json.loads(out.stdout.strip().splitlines()[-1])
    except subprocess.TimeoutExpired:
        return {"scene": scene, "status": "timeout", "message": f"> {timeout} s"}


def sweep(scenes, stop, fmu=FMU, timeout=120, twins=False):
    """Each scene's record; with twins, a scene with a slip-rate law also runs with the
    constant law (its twin), and its record keeps the twin's CPU time."""
    records = []
    for scene in scenes:
        record = run_in_child(scene, stop, fmu, timeout)
        if twins and has_rate_law(scene) and "cpu_s" in record:
            twin = run_in_child({**scene, **CONSTANT_LAW}, stop, fmu, timeout)
            record["twin_status"] = twin["status"]
            if "cpu_s" in twin:
                record["twin_cpu_s"] = twin["cpu_s"]
        records.append(record)
    return records


def cost_table(records, rows=8):
    """The slip-rate scenes' CPU time against their constant-law twins, the costliest first
    (ratios of runs under 0.05 s are mostly the clock's noise)."""
    pairs = [r for r in records if "twin_cpu_s" in r]
    if not pairs:
        return "No scene with a slip-rate law ran with its twin."
    ratio = lambda r: r["cpu_s"] / max(r["twin_cpu_s"], 1e-3)  # noqa: E731
    pairs.sort(key=ratio, reverse=True)
    law = lambda s: ", ".join(f"{k} = {s[k]:.3g}" for k in  # noqa: E731
                              ("static_friction_ratio", "stribeck_velocity", "viscous_friction")
                              if k in s)
    alike = [r for r in pairs if r["status"] == r["twin_status"] == "ok"]
    slowest = max(alike, key=lambda r: r["cpu_s"])
    lines = [f"{len(pairs)} scenes with a slip-rate law, each also run with the constant law "
             f"(its twin). Where both complete ({len(alike)} pairs), CPU time / twin's: median "
             f"{sorted(map(ratio, alike))[len(alike) // 2]:.2f}, largest {max(map(ratio, alike)):.2f}; "
             f"the slowest of them {slowest['cpu_s']:.2f} s against {slowest['twin_cpu_s']:.2f} s. "
             "Where one of the two fails (a blow-up the guard stops, mostly lambda/mu > 5 with the "
             "midpoint contact) the two runs follow different trajectories for different times, "
             "and the ratio compares unlike runs; they are listed with their statuses.", "",
             "| variant | F | law | status | twin's status | CPU [s] | twin's CPU [s] | ratio | halvings | halving warnings |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for r in pairs[:rows]:
        s = r["scene"]
        lines.append(f"| {VARIANTS[s['mass_matrix']]} | {s['friction_coefficient']:.3g} | {law(s)} "
                     f"| {r['status']} | {r['twin_status']} | {r['cpu_s']:.3f} | {r['twin_cpu_s']:.3f} | {ratio(r):.2f} "
                     f"| {r.get('refinements', '')} "
                     f"| {sum('substep halvings' in w for w in r.get('warnings', []))} |")
    return "\n".join(lines)


BALANCE_PROMISE = 1e-9  # docs/contract.md: the balance closes to round-off


def balance_holds(r):
    """Whether a run that produced finite outputs closed its energy balance to the promise."""
    return r["balance_error"] <= BALANCE_PROMISE


def summary(records, key="mass_matrix", names=VARIANTS):
    lines = [f"| {key} | scenes | refused at init | ok | error | crash / timeout | blow-up "
             "| refined | Gauss-Seidel used | max balance error | balance <= 1e-9 |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for v, name in enumerate(names):
        sel = [r for r in records if (r["scene"]["mass_matrix"] if key == "mass_matrix"
                                      else r.get("motion")) == (v if key == "mass_matrix" else name)]
        if not sel:
            continue
        count = lambda f: sum(1 for r in sel if f(r))  # noqa: E731
        ran = [r for r in sel if "balance_error" in r]
        lines.append(
            f"| {name} | {len(sel)} | {count(lambda r: r['status'] == 'refused')} "
            f"| {count(lambda r: r['status'] == 'ok')} | {count(lambda r: r['status'] == 'error')} "
            f"| {count(lambda r: r['status'] in ('crash', 'timeout'))} "
            f"| {count(lambda r: r.get('blow_up'))} | {count(lambda r: r.get('refinements', 0) > 0)} "
            f"| {count(lambda r: r.get('sweeps', 0) > 0)} "
            f"| {max((r['balance_error'] for r in ran), default=0):.1e} "
            f"| {count(lambda r: 'balance_error' in r and balance_holds(r))} of {len(ran)} |")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scenes", type=int, default=200)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--stop", type=float, default=2e-3)
    parser.add_argument("--out", type=pathlib.Path, default=ROOT / "examples" / "output")
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    rng = np.random.default_rng(args.seed)
    motions = [MOTIONS[(k // len(VARIANTS)) % len(MOTIONS)] for k in range(args.scenes)]
    scenes = [random_scene(rng, k % len(VARIANTS), motions[k]) for k in range(args.scenes)]
    records = sweep(scenes, args.stop, twins=True)
    for record, motion in zip(records, motions):
        record["motion"] = motion
    (args.out / "stress_sweep.json").write_text(json.dumps(records, indent=1))
    table = summary(records)
    errors = [r for r in records if r["status"] in ("error", "crash", "timeout")]
    lines = [f"{args.scenes} random scenes, seed {args.seed}, {args.stop:g} s each. The energy "
             "balance error is |E - E(0) - works| / max(|E|, work put in) at the end of every "
             "run that produced finite outputs (a run that fails a step keeps its rows up to "
             "there); below the strain energy of a strain of 1e-6 over the body it is taken "
             "absolute.", "", table, "", summary(records, "motion", MOTIONS), "",
             "Cost of the slip-rate law:", "", cost_table(records), "",
             "Failures and their messages:", ""]
    lines += [f"- {VARIANTS[r['scene']['mass_matrix']]}: {r['status']}: "
              f"{str(r['message'])[:300]}" for r in errors]
    (args.out / "stress_sweep.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
