"""Speed benchmarks: time per substep against the floor (one bare CHOLMOD solve with
the same factor, measured in the same run), its split, contact iterations, setup and memory,
for the paper scene at nx = ny in {10, 20, 40, 80, 160} with the paper's dt ladder; rows that
show what skipping unneeded work saves; and the default scene through fmpy.simulate_fmu.

Writes benchmarks/results/substep.md, substep.json and substep.png.

    .venv/bin/python benchmarks/run_benchmarks.py [--quick]
"""
import argparse
import json
import pathlib
import subprocess
import tempfile
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from fmpy import simulate_fmu  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[1]
BENCH = ROOT / "build" / "bench_substep"
BENCH_ITERATIVE = ROOT / "build" / "bench_iterative"
BENCH_STEP_SIZES = ROOT / "build" / "bench_step_sizes"
OUT = ROOT / "benchmarks" / "results"


def bench(nx, dt, substeps, friction=1.2, mass_matrix=1, top=-2.5e-5, beta=0.0, alpha=0.0):
    out = subprocess.run([str(BENCH), str(nx), repr(dt), str(substeps), repr(friction),
                          str(mass_matrix), repr(top), repr(beta), repr(alpha)],
                         capture_output=True, text=True, check=True)
    return json.loads(out.stdout)


def run_json(*command):
    out = subprocess.run([str(c) for c in command], capture_output=True, text=True, check=True)
    return json.loads(out.stdout)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--quick", action="store_true", help="fewer substeps, no nx = 160")
    args = parser.parse_args()
    OUT.mkdir(parents=True, exist_ok=True)
    sizes = [10, 20, 40, 80] + ([] if args.quick else [160])
    scale = 0.1 if args.quick else 1.0

    rows = []
    for nx in sizes:
        dt = 8e-6 * 10 / nx  # the paper's ladder: h = 1 cm with 8e-6 s, halving both
        rows.append(bench(nx, dt, max(100, int(scale * 40000 / nx))))
        print(json.dumps(rows[-1]))

    # Target 3: the convergence test's reference run, whole (setup included), against as many
    # bare solves with the same factor, in the same process.
    reference = None if args.quick else bench(160, 5e-7, 10000)

    savings = {
        "F = 1.2 (tangential unknowns)": bench(40, 2e-6, int(scale * 1000) or 100, friction=1.2),
        "F = 0 (no tangential unknowns)": bench(40, 2e-6, int(scale * 1000) or 100, friction=0.0),
        "body lifted off (no contact solve)": bench(40, 2e-6, int(scale * 1000) or 100, top=2.5e-5),
        "tiny mesh nx = 4 (sparse path)": bench(4, 2e-5, int(scale * 20000) or 100),
    }
    # Rayleigh damping: two more sparse products per substep (C u^k in the right-hand side,
    # C (u^{k+1} - u^k) for damping_work), no extra solve. Same scene with and without it.
    damping = {}
    for nx, dt in ((40, 2e-6), (80, 1e-6)):
        n = max(100, int(scale * 40000 / nx))
        damping[nx] = {name: bench(nx, dt, n, friction=0.3, beta=beta, alpha=alpha)
                       for name, beta, alpha in (("undamped", 0.0, 0.0),
                                                 ("beta = 4e-6 s", 4e-6, 0.0),
                                                 ("alpha = 50 /s, beta = 4e-6 s", 4e-6, 50.0))}

    # The factor cache: a master alternating two step sizes against one whose size changes
    # every step (every step refactors), same steps and substeps.
    step_sizes = run_json(BENCH_STEP_SIZES, 40, 4e-6, 100)
    # Target 3's experiment: warm-started preconditioned CG against the direct solve.
    iterative = (run_json(BENCH_ITERATIVE, 80, 1e-6, 50) if args.quick
                 else run_json(BENCH_ITERATIVE, 160, 5e-7, 100))

    fmpy_times = []
    for variant in range(4):
        t = time.perf_counter()
        simulate_fmu(str(ROOT / "build" / "ContactBody.fmu"), stop_time=0.02, output_interval=1e-4,
                     start_values={"mass_matrix": variant})
        fmpy_times.append(time.perf_counter() - t)

    # Field output cost: the default scene with a .vtu every 1e-4 s (201 files) against the same
    # run without; interleaved, best of three each.
    plain, with_fields = [], []
    for _ in range(3):
        for times, extra in ((plain, {}), (with_fields, {"field_output_interval": 1e-4})):
            with tempfile.TemporaryDirectory() as directory:
                if extra:
                    extra = {**extra, "result_directory": directory}
                t = time.perf_counter()
                simulate_fmu(str(ROOT / "build" / "ContactBody.fmu"), stop_time=0.02,
                             output_interval=1e-4, start_values=extra)
                times.append(time.perf_counter() - t)
    field_cost = (min(plain), min(with_fields))

    lines = ["# Substep cost against the floor (paper scene, F = 1.2, redistributed_normal)", "",
             "The floor is one forward + backward solve with the stepper's own factor (simplicial "
             "L L^T, contact dofs ordered last). For comparison, the last column but one is one solve "
             "with CHOLMOD's default factor of the same matrix (Eigen's CholmodDecomposition: "
             "unconstrained ordering, supernodal when CHOLMOD picks it).", "",
             "| nx | dt [s] | unknowns | substep [us] | floor: 1 solve [us] | ratio | solve [us] "
             "| contact [us] | update [us] | Newton it./substep | Newton LUs/substep "
             "| setup assembly [s] | setup factor+Delassus [s] | peak RSS [MB] "
             "| CHOLMOD default solve [us] | nnz(L) |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['nx']} | {r['dt']:g} | {r['unknowns']} | {r['per_substep']*1e6:.1f} "
                     f"| {r['floor_solve']*1e6:.1f} | {r['ratio']:.2f} | {r['split_solve']*1e6:.1f} "
                     f"| {r['split_contact']*1e6:.1f} | {r['split_update']*1e6:.1f} "
                     f"| {r['contact_iterations']:.2f} | {r['newton_factorizations']:.2f} "
                     f"| {r['setup_assembly']:.3f} "
                     f"| {r['setup_factor_delassus']:.3f} | {r['peak_rss_mb']:.0f} "
                     f"| {r['floor_unconstrained']*1e6:.1f} | {r['factor_nonzeros']:.0f} |")
    if reference:
        r = reference
        total = r["setup_assembly"] + r["setup_factor_delassus"] + r["per_substep"] * r["substeps"]
        bare = r["floor_solve"] * r["substeps"]
        lines += ["", "## Reference run of the convergence test (nx = 160, dt = 5e-7, 10,000 substeps)",
                  "", "| whole run incl. setup [s] | 10,000 bare solves [s] | ratio | peak RSS [MB] |",
                  "|---|---|---|---|",
                  f"| {total:.2f} | {bare:.2f} | {total / bare:.3f} | {r['peak_rss_mb']:.0f} |"]
    lines += ["", "## What skipping unneeded work saves (nx = 40, dt = 2e-6)", "",
              "| scene | substep [us] | ratio to floor | contact [us] | contact solves / substep |",
              "|---|---|---|---|---|"]
    for name, r in savings.items():
        lines.append(f"| {name} | {r['per_substep']*1e6:.1f} | {r['ratio']:.2f} "
                     f"| {r['split_contact']*1e6:.1f} | {r['contact_solve_fraction']:.2f} |")
    lines += ["", "## Rayleigh damping cost per substep (F = 0.3, same scene with and without)",
              "", "| nx | dt [s] | damping | substep [us] | ratio to undamped | update [us] "
              "| ratio to its floor | Newton it./substep |", "|---|---|---|---|---|---|---|---|"]
    for nx, by_name in damping.items():
        base = by_name["undamped"]["per_substep"]
        for name, r in by_name.items():
            lines.append(f"| {nx} | {r['dt']:g} | {name} | {r['per_substep'] * 1e6:.1f} "
                         f"| {r['per_substep'] / base:.3f} | {r['split_update'] * 1e6:.1f} "
                         f"| {r['ratio']:.2f} | {r['contact_iterations']:.2f} |")
    r = savings["F = 1.2 (tangential unknowns)"]
    lines += ["", "## Energies only for outputs (nx = 40)", "",
              "| one energy evaluation [us] | substep [us] | share if computed every substep "
              "| share at the default output interval (25 substeps per output) |",
              "|---|---|---|---|",
              f"| {r['energy_evaluation'] * 1e6:.1f} | {r['per_substep'] * 1e6:.1f} "
              f"| {r['energy_evaluation'] / r['per_substep']:.1%} "
              f"| {r['energy_evaluation'] / r['per_substep'] / 25:.2%} |"]
    lines += ["", f"## Factor cache: communication step schedules (nx = {step_sizes['nx']}, "
              f"internal_step = {step_sizes['internal_step']:g} s, {step_sizes['steps']} steps)", "",
              "| schedule | time [s] | factorizations | substeps | per substep [us] |",
              "|---|---|---|---|---|"]
    for r in step_sizes["schedules"]:
        lines.append(f"| {r['schedule']} | {r['seconds']:.3f} | {r['factorizations']} "
                     f"| {r['substeps']} | {r['seconds'] / r['substeps'] * 1e6:.1f} |")
    it = iterative
    lines += ["", f"## Iterative solve experiment (nx = {it['nx']}, dt = {it['dt']:g} s, "
              f"{it['substeps']} substeps of the paper scene)", "",
              "Each substep's final system K u = b solved again, warm-started from the predictor "
              "u^k + dt/2 v^k. The direct solve (the floor) takes "
              f"{it['direct_solve'] * 1e3:.2f} ms (relative error {it['direct_max_error']:.1e}). "
              "`jacobi_two_solves` is what an iterative substep needs: u0 and the contact "
              "correction K^-1 B^T lambda (warm-started from the last one), since the trailing "
              "block of the factor is not available.", "",
              "| method | relative residual | per solve [ms] | ratio to direct | CG iterations "
              "| max relative error | setup [s] |", "|---|---|---|---|---|---|---|"]
    for r in it["iterative"]:
        lines.append(f"| {r['method']} | {r['tolerance']:g} | {r['per_solve'] * 1e3:.2f} "
                     f"| {r['ratio_to_direct']:.2f} | {r['iterations']:.2f} "
                     f"| {r['max_error']:.1e} | {r['setup']:.4f} |")
    lines += ["", "## Default scene through fmpy.simulate_fmu (nx = 20, dt = 4e-6, 0.02 s, "
              "5,000 substeps, output interval 1e-4 s)", "",
              "| mass_matrix | 0 | 1 | 2 | 3 |", "|---|---|---|---|---|",
              "| call time [s] | " + " | ".join(f"{t:.3f}" for t in fmpy_times) + " |",
              "", "## Field output cost (default scene, one .vtu every 1e-4 s: 201 files, best of 3)",
              "", "| without [s] | with [s] | ratio | per file [ms] |", "|---|---|---|---|",
              f"| {field_cost[0]:.3f} | {field_cost[1]:.3f} | {field_cost[1] / field_cost[0]:.2f} "
              f"| {(field_cost[1] - field_cost[0]) / 201 * 1e3:.2f} |"]
    (OUT / "substep.md").write_text("\n".join(lines) + "\n")
    (OUT / "substep.json").write_text(json.dumps({"rows": rows, "savings": savings, "damping": damping,
                                                  "reference_run": reference,
                                                  "step_sizes": step_sizes,
                                                  "iterative": iterative,
                                                  "field_output_s": field_cost,
                                                  "fmpy_default_scene_s": fmpy_times}, indent=1))

    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4))
    n = [r["unknowns"] for r in rows]
    a.loglog(n, [r["per_substep"] for r in rows], "o-", label="substep")
    a.loglog(n, [r["floor_solve"] for r in rows], "s--", label="floor: one bare solve")
    a.set_xlabel("unknowns")
    a.set_ylabel("time [s]")
    a.legend()
    a.grid(True, which="both", alpha=0.3)
    parts = ["split_solve", "split_contact", "split_update"]
    bottom = [0.0] * len(rows)
    for part in parts:
        frac = [r[part] / r["per_substep"] for r in rows]
        b.bar([str(r["nx"]) for r in rows], frac, bottom=bottom, label=part.split("_")[1])
        bottom = [x + y for x, y in zip(bottom, frac)]
    b.set_xlabel("nx = ny")
    b.set_ylabel("share of the substep")
    b.legend()
    fig.tight_layout()
    fig.savefig(OUT / "substep.png", dpi=110)
    print((OUT / "substep.md").read_text())


if __name__ == "__main__":
    main()
