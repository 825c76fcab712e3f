"""The contact solver's Newton step with Eigen's blocked LU (issue 44) against reference
LAPACK's dgetrf before it, in one run: how far the full body's outputs moved, beside how far
before's own outputs move when the initial top displacement is one ulp off. Where the two are
alike the change is round-off, amplified as the scheme amplifies any round-off.

"Before" is commit BEFORE, built with the machine's gcc in build-before/ (build_commit.py);
"after" is build/ContactBody.fmu. Scenes: the undamped reference runs of
python_tests/test_energy_balance.py (10 x 10, 1 ms, variants 0-3, F = 0 and 1.2), the Figs. 7-8
runs (20 x 20, F = 1.2, 20 ms, 4 variants x 5 dt) and test_portable.py's two scenes (the
paper's, 20 ms; 120 x 120 with F = 0.3, 0.3 ms, whose contact systems exceed 64 unknowns).
Per scene: the largest |after - before| over the run and the outputs, relative to the output's
largest value, the same for before's one-ulp twin, and whether the counts are equal.

With --write-references it writes the bit-for-bit references the tests compare with from
"after": python_tests/data/reference_outputs_undamped.json and figures_7_8.sha256.json from
build/ContactBody.fmu, and outputs_native_build.json from a native gcc build of NATIVE (the
commit that carries the change).

    .venv/bin/python benchmarks/lu_change.py [--write-references NATIVE]
"""
import argparse
import hashlib
import json
import pathlib
import sys

import fmpy
import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from build_commit import build_commit  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[1]
DATA = ROOT / "python_tests" / "data"
BEFORE = "f571f79"
AFTER = ROOT / "build" / "ContactBody.fmu"
TOP = -2.5e-5


def scenes():
    ref = json.loads((DATA / "reference_outputs_undamped.json").read_text())
    out = {}
    for key in ref["runs"]:
        variant, friction = key.split("/")
        out[f"undamped {key}"] = dict(stop_time=1e-3, output_interval=1e-4, start_values={
            "mass_matrix": int(variant), "nx": 10, "ny": 10, "friction_coefficient": float(friction)})
    for key in json.loads((DATA / "figures_7_8.sha256.json").read_text()):
        variant, dt = key.split("/")
        out[f"figs 7-8 {key}"] = dict(stop_time=0.02, output_interval=8e-5, start_values={
            "mass_matrix": int(variant), "internal_step": float(dt), "nx": 20, "ny": 20,
            "friction_coefficient": 1.2, "max_energy_ratio": 0})
    out["paper"] = dict(stop_time=0.02, output_interval=1e-4, start_values={})
    out["metis"] = dict(stop_time=3e-4, output_interval=1e-4,
                        start_values={"nx": 120, "ny": 120, "friction_coefficient": 0.3})
    return out


def outputs(fmu):
    return [v.name for v in fmpy.read_model_description(str(fmu)).modelVariables
            if v.causality == "output" and v.type in ("Real", "Integer")]


def simulate(fmu, scene, top=TOP):
    values = dict(scene["start_values"], top_displacement=top)
    r = fmpy.simulate_fmu(str(fmu), stop_time=scene["stop_time"],
                          output_interval=scene["output_interval"], start_values=values,
                          output=outputs(fmu))
    return {name: r[name] for name in r.dtype.names if name != "time"}


def difference(a, b):
    """Largest |a - b| / max |a| over the real outputs, and whether the integer ones agree."""
    worst, counts_equal = 0.0, True
    for name, x in a.items():
        if x.dtype.kind == "f":
            scale = np.abs(x).max()
            worst = max(worst, float(np.abs(b[name] - x).max() / scale) if scale > 0 else 0.0)
        else:
            counts_equal = counts_equal and bool(np.array_equal(x, b[name]))
    return worst, counts_equal


def compare(before_fmu):
    rows = []
    for name, scene in scenes().items():
        before, after = simulate(before_fmu, scene), simulate(AFTER, scene)
        twin = simulate(before_fmu, scene, np.nextafter(TOP, 0))
        change, counts = difference(before, after)
        ulp, ulp_counts = difference(before, twin)
        rows.append({"scene": name, "after_minus_before": change, "counts_equal": counts,
                     "before_one_ulp": ulp, "one_ulp_counts_equal": ulp_counts})
        print(rows[-1], flush=True)
    return rows


def write_references(native_commit):
    ref = json.loads((DATA / "reference_outputs_undamped.json").read_text())
    all_scenes = scenes()
    for key in ref["runs"]:
        r = simulate(AFTER, all_scenes[f"undamped {key}"])
        ref["runs"][key] = {name: [float(x).hex() for x in r[name]] for name in ref["outputs"]}
    (DATA / "reference_outputs_undamped.json").write_text(json.dumps(ref))
    digests = {}
    for key in json.loads((DATA / "figures_7_8.sha256.json").read_text()):
        r = simulate(AFTER, all_scenes[f"figs 7-8 {key}"])
        text = "".join(float(x).hex() for name in ("energy", "energy_minus_friction_work")
                       for x in r[name])
        digests[key] = hashlib.sha256(text.encode()).hexdigest()
    (DATA / "figures_7_8.sha256.json").write_text(json.dumps(digests, indent=1))
    native = build_commit(native_commit, ["ContactBody_fmu"]) / "ContactBody.fmu"
    names = [v.name for v in fmpy.read_model_description(
        str(ROOT / "modelDescription" / "modelDescription.xml")).modelVariables if v.causality == "output"]
    recorded = {}
    for scene in ("paper", "metis"):
        s = all_scenes[scene]
        r = fmpy.simulate_fmu(str(native), stop_time=s["stop_time"], output_interval=s["output_interval"],
                              start_values=s["start_values"], output=names)
        recorded["default" if scene == "paper" else scene] = {n: [float(x).hex() for x in r[n]] for n in names}
    (DATA / "outputs_native_build.json").write_text(json.dumps(recorded))


def report(rows):
    lines = ["# The contact solver's Newton step: Eigen's blocked LU against reference dgetrf", "",
             f"`.venv/bin/python benchmarks/lu_change.py`; before = {BEFORE} (reference LAPACK's "
             "dgetrf/dgetrs, the explicit part's product by rows of W), after = Eigen's blocked "
             "partial-pivoting LU on the same buffer and the product by W's nonzero columns. The "
             "full body's outputs: the largest |after − before| over the run, relative to each "
             "output's largest value, beside before against itself with the initial "
             "top_displacement one ulp off.", "",
             "| scene | after − before | counts equal | before's one-ulp twin | counts equal |",
             "|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['scene']} | {r['after_minus_before']:.2e} | "
                     f"{'yes' if r['counts_equal'] else 'no'} | {r['before_one_ulp']:.2e} | "
                     f"{'yes' if r['one_ulp_counts_equal'] else 'no'} |")
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--write-references", metavar="NATIVE")
    parser.add_argument("--out", type=pathlib.Path, default=ROOT / "benchmarks" / "results")
    args = parser.parse_args()
    before = build_commit(BEFORE, ["ContactBody_fmu"]) / "ContactBody.fmu"
    rows = compare(before)
    (args.out / "lu_change.json").write_text(json.dumps(rows, indent=1))
    (args.out / "lu_change.md").write_text(report(rows))
    if args.write_references:
        write_references(args.write_references)


if __name__ == "__main__":
    main()
