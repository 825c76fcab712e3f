"""What a refined contact boundary costs today (issue 54's table, the baseline for its work):
a pad (contactbody.meshes.pad, 80 mm wide, its two contact faces 66 mm together) whose cells
along the contact faces shrink so that it has about N contact nodes, growing away from them;
damped sliding at 20 m/s (F = 0.3, beta = 4e-6 s, 1e-6 s substeps) from the static start.
Per N, in a child process of its own: the static start's wall time (instantiation to the end
of initialization), one substep's (the mean over 30 substeps after the first step), and the
process's peak memory. The full body, and the reduced body (40 modes).

Writes benchmarks/results/contact_scaling.json and contact_scaling.md.

    .venv/bin/python benchmarks/contact_scaling.py [--counts 101 201 401 801] [--fmu FMU]
"""
import argparse
import json
import pathlib
import sys
import tempfile

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import child  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[1]
OUT = ROOT / "benchmarks" / "results"
CONTACT_LENGTH = 0.066  # m: the two contact faces of an 80 mm pad with 4 mm chamfers and a 6 mm slot
SCENE = {"initial_state": 1, "friction_coefficient": 0.3, "damping_stiffness": 4e-6,
         "internal_step": 1e-6, "foundation_velocity": 20.0, "top_displacement": -5e-6}
STEP, STEPS = 1e-5, 3  # 10 substeps a step


def measure(fmu, mesh, modes):
    """In this process: the static start, STEPS steps, the peak memory."""
    import resource
    import time

    from contactbody.fmu import Model
    with Model(fmu, name="scaling") as model:
        t0 = time.perf_counter()
        model.start({**SCENE, "mesh": mesh, "modes": modes})
        start = time.perf_counter() - t0
        inst = model.instance
        inst.doStep(0.0, STEP)  # the first step factors what the others reuse
        t0 = time.perf_counter()
        for k in range(1, STEPS + 1):
            inst.doStep(k * STEP, STEP)
        substep = (time.perf_counter() - t0) / (STEPS * round(STEP / SCENE["internal_step"]))
    return {"static_start_seconds": start, "substep_seconds": substep,
            "peak_memory_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024}


def in_child(fmu, mesh, modes):
    return child.in_child("contact_scaling", "measure", fmu, mesh, modes)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--counts", type=int, nargs="+", default=[101, 201, 401, 801])
    parser.add_argument("--fmu", type=pathlib.Path, default=None)
    args = parser.parse_args()
    from contactbody import find_fmu, meshes
    fmu = str(find_fmu(args.fmu))
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for n in args.counts:
            path = meshes.pad(pathlib.Path(tmp) / f"pad_{n}.msh", width=0.08, size=2e-3,
                              contact_size=CONTACT_LENGTH / (n - 2))
            with meshes.session("count") as gmsh:
                gmsh.open(str(path))
                nodes = len(gmsh.model.mesh.getNodes()[0])
                contact = next(tag for dim, tag in gmsh.model.getPhysicalGroups(1)
                               if gmsh.model.getPhysicalName(dim, tag) == "contact")
                contact_nodes = len(gmsh.model.mesh.getNodesForPhysicalGroup(1, contact)[0])
            for modes in (0, 40):
                r = {"contact_nodes": contact_nodes, "nodes": nodes, "modes": modes,
                     **in_child(fmu, str(path), modes)}
                print(r, flush=True)
                rows.append(r)
    full = [r for r in rows if r["modes"] == 0]
    for a, b in zip(full, full[1:]):
        b["substep_ratio_to_previous"] = b["substep_seconds"] / a["substep_seconds"]
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / "contact_scaling.json").write_text(json.dumps({"scene": SCENE, "rows": rows}, indent=1))
    lines = ["# What a refined contact boundary costs", "",
             "`.venv/bin/python benchmarks/contact_scaling.py`: the pad, damped sliding at 20 m/s "
             "(F = 0.3, β = 4e-6 s, 1e-6 s substeps) from the static start; wall times and the "
             "process's peak memory, each case in a process of its own.", "",
             "| contact nodes | nodes | modes | static start [s] | one substep [ms] | × previous | peak memory [MB] |",
             "|---|---|---|---|---|---|---|"]
    for r in rows:
        ratio = r.get("substep_ratio_to_previous")
        lines.append(f"| {r['contact_nodes']} | {r['nodes']} | {r['modes'] or 'full'} | "
                     f"{r['static_start_seconds']:.2f} | {1e3 * r['substep_seconds']:.3g} | "
                     f"{'' if ratio is None else f'{ratio:.1f}'} | {r['peak_memory_mb']:.0f} |")
    (OUT / "contact_scaling.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
