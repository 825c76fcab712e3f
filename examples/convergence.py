"""Paper Fig. 9 / Table 2: the convergence test, from the FMU's field output.

Experiments (h, dt) = (2 cm, 1.6e-5), (1 cm, 8e-6), (0.5 cm, 4e-6), (0.25 cm, 2e-6) against a
reference (h = 0.0625 cm, dt = 5e-7, 51,520 unknowns), redistributed_normal, on [0, 5.12 ms]
(the first multiple of the 0.16 ms output interval past 5 ms, so that every dt divides it).
The error at each output time is u_ref - u_h on the reference mesh (the meshes nest, so u_h is
exactly a fine P1 field); reported: the maximum over time of its L2(Omega) norm and H1(Omega)
seminorm, and the observed orders log2(e(2h) / e(h)).

Writes examples/output/convergence.md, convergence.json, figure_9.png; with
--damping-stiffness BETA (Rayleigh damping C = beta A, the damping issue's stable sliding)
convergence_damped.md, .json and figure_9_damped.png.

    .venv/bin/python examples/convergence.py [--friction 1.2 0 0.2] [--keep-fields]
    .venv/bin/python examples/convergence.py --friction 0.3 --damping-stiffness 4e-6
"""
import argparse
import json
import resource
import shutil
import subprocess
import sys
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from contactbody import fields  # noqa: E402
from scene import output_argument, REFERENCE, TABLE2, WIDTH, cells, simulate  # noqa: E402

STOP, INTERVAL = 5.12e-3, 1.6e-4


def run_one(h, dt, friction, directory, beta=0.0):
    n = cells(h)
    _, wall = simulate(STOP, INTERVAL, nx=n, ny=n, internal_step=dt, mass_matrix=1,
                       friction_coefficient=friction, damping_stiffness=beta,
                       result_directory=str(directory),
                       field_output_interval=INTERVAL, outputs=["energy"])
    return wall


def snapshots(run_dir):
    """(time, node points, displacement) of each file of a field output collection."""
    out = []
    for t, f in fields.read_collection(run_dir / "contactbody.pvd"):
        points, _, data = fields.read_field(f)
        out.append((t, points, data["displacement"][:, :2]))
    return out


def reference_fields(reference_dir):
    """(time, points, triangles, displacement) of each reference file, read once."""
    out = []
    for t, f in fields.read_collection(reference_dir / "contactbody.pvd"):
        points, triangles, data = fields.read_field(f)
        out.append((t, points, triangles, data["displacement"][:, :2]))
    return out


def errors(reference, run, n):
    """Max over the output times of the L2 norm and H1 seminorm of u_ref - u_h on the
    reference mesh. reference: a field output directory or reference_fields() of one; run:
    a directory or a list of snapshots (nx = ny = n)."""
    if not isinstance(reference, list):
        reference = reference_fields(reference)
    if not isinstance(run, list):
        run = snapshots(run)
    assert len(reference) == len(run), (len(reference), len(run))
    l2, h1 = [], []
    for (t_ref, points, triangles, u_ref), (t, coarse_points, coarse) in zip(reference, run):
        assert abs(t_ref - t) < 1e-12, (t_ref, t)
        u_h = fields.interpolate_nested(coarse_points, coarse, n, n, WIDTH, WIDTH, points)
        e = u_ref - u_h
        l2.append(np.sqrt(fields.l2_squared(points, triangles, e)))
        h1.append(np.sqrt(fields.h1_squared(points, triangles, e)))
    return max(l2), max(h1)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--friction", type=float, nargs="+", default=[1.2, 0.0, 0.2])
    parser.add_argument("--keep-fields", action="store_true")
    parser.add_argument("--damping-stiffness", type=float, default=0.0, metavar="BETA",
                        help="Rayleigh damping beta [s] (C = beta A) for every run")
    parser.add_argument("--single", nargs=4, type=float, help=argparse.SUPPRESS)
    parser.add_argument("--directory", help=argparse.SUPPRESS)
    output_argument(parser)
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    if args.single:  # one run in its own process, so that its peak memory can be measured
        h, dt, friction, beta = args.single
        print(json.dumps({"wall": run_one(h, dt, friction, args.directory, beta)}))
        return

    beta = args.damping_stiffness
    tag = "_damped" if beta > 0 else ""
    base = args.out / f"convergence_fields{tag}"
    report = {}
    for friction in args.friction:
        ref_dir = base / f"F{friction:g}" / "reference"
        shutil.rmtree(ref_dir, ignore_errors=True)
        start = time.perf_counter()
        out = subprocess.run([sys.executable, __file__, "--single", str(REFERENCE[0]),
                              str(REFERENCE[1]), str(friction), repr(beta),
                              "--directory", str(ref_dir)],
                             capture_output=True, text=True, check=True)
        wall_process = time.perf_counter() - start
        reference_wall = json.loads(out.stdout.strip().splitlines()[-1])["wall"]  # after the log
        peak_mb = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
        rows = []
        reference = reference_fields(ref_dir)
        for h, dt in TABLE2:
            run_dir = base / f"F{friction:g}" / f"h{h * 100:g}cm"
            shutil.rmtree(run_dir, ignore_errors=True)
            wall = run_one(h, dt, friction, run_dir, beta)
            l2, h1 = errors(reference, run_dir, cells(h))
            rows.append({"h": h, "dt": dt, "l2": l2, "h1": h1, "wall": wall})
            print(f"F = {friction:g}  h = {h * 100:g} cm  dt = {dt:g}: max L2 = {l2:.3e} m^2, "
                  f"max H1 = {h1:.3e} m, run {wall:.2f} s", flush=True)
        report[f"{friction:g}"] = {
            "reference": {"wall_simulate": reference_wall,
                          "wall_process": wall_process, "peak_rss_mb_children": peak_mb},
            "rows": rows}
        print(f"F = {friction:g}: reference run {reference_wall:.1f} s "
              f"(process {wall_process:.1f} s), peak RSS of the runs so far {peak_mb:.0f} MB",
              flush=True)
        if not args.keep_fields:
            shutil.rmtree(base / f"F{friction:g}", ignore_errors=True)

    damping = f", Rayleigh damping beta = {beta:g} s" if beta > 0 else ""
    lines = ["# Convergence test (Table 2 / Fig. 9), redistributed_normal" + damping +
             ", errors against the reference h = 0.0625 cm, dt = 5e-7, max over t in "
             "[0, 5.12 ms]", ""]
    for friction, r in report.items():
        ref = r["reference"]
        lines += [f"## F = {friction}", "",
                  f"Reference run: {ref['wall_simulate']:.1f} s in fmpy.simulate_fmu "
                  f"({ref['wall_process']:.1f} s for its process), peak RSS "
                  f"{ref['peak_rss_mb_children']:.0f} MB.", "",
                  "| h [cm] | dt [s] | max L2 error [m^2] | order | max H1 error [m] | order | run [s] |",
                  "|---|---|---|---|---|---|---|"]
        prev = None
        for row in r["rows"]:
            o2 = f"{np.log2(prev['l2'] / row['l2']):.2f}" if prev else ""
            o1 = f"{np.log2(prev['h1'] / row['h1']):.2f}" if prev else ""
            lines.append(f"| {row['h'] * 100:g} | {row['dt']:g} | {row['l2']:.3e} | {o2} "
                         f"| {row['h1']:.3e} | {o1} | {row['wall']:.2f} |")
            prev = row
        lines.append("")
    (args.out / f"convergence{tag}.md").write_text("\n".join(lines))
    (args.out / f"convergence{tag}.json").write_text(json.dumps({"damping_stiffness": beta, **report},
                                                          indent=1))

    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for friction, r in report.items():
        h = [row["h"] * 100 for row in r["rows"]]
        axes[0].loglog(h, [row["l2"] for row in r["rows"]], "o-", label=f"F = {friction}")
        axes[1].loglog(h, [row["h1"] for row in r["rows"]], "o-", label=f"F = {friction}")
    for ax, name in zip(axes, ["max_t L2 error [m²]", "max_t H1 error [m]"]):
        ax.set_xlabel("h [cm] (dt = 8e-4 s/m · h)")
        ax.set_ylabel(name)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    fig.suptitle("Fig. 9: convergence against the reference (h = 0.0625 cm, dt = 5e-7 s)"
                 + damping)
    fig.tight_layout()
    fig.savefig(args.out / f"figure_9{tag}.png", dpi=110)
    print("\n".join(lines))


if __name__ == "__main__":
    main()
