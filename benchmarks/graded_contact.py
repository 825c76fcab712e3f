"""M_r on graded contact groups (issue 53, item 1): the half-disk of contactbody.meshes with its
contact group over an arc of +-15, +-30, +-60 and +-85 degrees (and the whole arc), its cells
growing along the group from CONTACT_SIZE at the bottom to RATIO x CONTACT_SIZE, for RATIO 5 to
50. Each body is initialized in the three variants that build M_r (1, 2, 4): whether it
initializes, and which M_r it got (the least change in the Frobenius norm, or where that is not
positive definite the least relative change, with the largest fraction by which it changed an
entry, from the log). Then the whole arc graded 0.1 -> 4 mm, pressed statically with the default
variant, against Hertz (benchmarks/hertz.py's fit).

Writes benchmarks/results/graded_contact.json and graded_contact.md.

    .venv/bin/python benchmarks/graded_contact.py [--fmu FMU]
"""
import argparse
import json
import pathlib
import re
import sys
import tempfile

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import hertz  # noqa: E402

from contactbody import meshes  # noqa: E402
from contactbody.fmu import Model  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[1]
OUT = ROOT / "benchmarks" / "results"
CONTACT_SIZE = 2e-4
ARCS = [30, 60, 120, 170, 180]  # degrees of the contact group (+-15 ... +-85, the whole arc)
RATIOS = [5, 10, 20, 40, 50]
VARIANTS = {1: "redistributed_normal", 2: "redistributed_both", 4: "redistributed_implicit_contact"}


def initialize(model, values):
    """(initialized, which M_r, largest fraction changed or None, the error if any)."""
    model.instance.setDebugLogging(True, [])
    try:
        model.start(values)
    except Exception as e:  # noqa: BLE001 (the FMU's refusal, kept as text)
        return False, None, None, str(e)
    notes = [m[2] for m in model.instance.messages if "M_r is the least relative change" in m[2]]
    if not notes:
        return True, "least change", None, None
    fraction = float(re.search(r"at most (\S+) of itself", notes[0]).group(1))
    return True, "least relative change", fraction, None


def grading_map(fmu, folder):
    rows = []
    with Model(fmu, name="graded") as model:
        for arc in ARCS:
            for ratio in RATIOS:
                path = meshes.half_disk(folder / f"arc{arc}_ratio{ratio}.msh", contact_size=CONTACT_SIZE,
                                        far_size=ratio * CONTACT_SIZE, fine_distance=4e-3,
                                        refine_distance=0.02, contact_angle=arc)
                for variant, name in VARIANTS.items():
                    ok, which, fraction, error = initialize(
                        model, {"mesh": str(path), "mass_matrix": variant, "foundation_velocity": 0.0})
                    rows.append({"arc_degrees": arc, "ratio": ratio, "variant": name,
                                 "initializes": ok, "m_r": which, "largest_fraction": fraction,
                                 "error": error})
    return rows


def hertz_on_the_graded_arc(fmu, folder):
    """The whole arc graded 0.1 -> 4 mm, pressed by the static start with the default variant."""
    path = meshes.half_disk(folder / "whole_arc.msh", radius=hertz.RADIUS, contact_size=1e-4,
                            far_size=4e-3, fine_distance=1.25 * hertz.EXPECTED_A,
                            refine_distance=8 * hertz.EXPECTED_A, contact_angle=180)
    return {"contact_size": 1e-4, "far_size": 4e-3, "mass_matrix": "redistributed_normal",
            **hertz.pressed(fmu, path, folder / "out")}


def report(result):
    lines = ["# M_r on graded contact groups", "",
             "`.venv/bin/python benchmarks/graded_contact.py`: the half-disk (radius 5 cm) with "
             f"its contact group over the arc shown, cells growing along it from {CONTACT_SIZE * 1e3:g} mm "
             "at the bottom to the ratio times that. Each cell: whether variants 1, 2, 4 initialize, "
             "and which M_r they built (LC: the least change in the Frobenius norm; "
             "RC (f): the least relative change, entries changed by at most the fraction f).", "",
             "| arc | " + " | ".join(f"ratio {r}" for r in RATIOS) + " |",
             "|---|" + "---|" * len(RATIOS)]
    for arc in ARCS:
        cells = []
        for ratio in RATIOS:
            rs = [r for r in result["map"] if r["arc_degrees"] == arc and r["ratio"] == ratio]
            if not all(r["initializes"] for r in rs):
                cells.append("refused")
            elif rs[0]["m_r"] == "least change":
                cells.append("LC")
            else:
                cells.append(f"RC ({rs[0]['largest_fraction']:.2g})")
        label = "whole arc" if arc == 180 else f"±{arc // 2}°"
        lines.append(f"| {label} | " + " | ".join(cells) + " |")
    h = result["hertz"]
    lines += ["", f"Every case initializes: {result['every_case_initializes']}.", "",
              "Hertz, the whole arc graded 0.1 → 4 mm, the default variant, static start "
              f"(P = {h['P']:.4g} N/m): a {100 * h['a_error']:+.2f} %, p0 {100 * h['p0_error']:+.2f} %."]
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--fmu", type=pathlib.Path, default=None)
    parser.add_argument("--out", type=pathlib.Path, default=OUT)
    args = parser.parse_args()
    fmu = str(args.fmu) if args.fmu else None
    with tempfile.TemporaryDirectory() as tmp:
        folder = pathlib.Path(tmp)
        result = {"map": grading_map(fmu, folder), "hertz": hertz_on_the_graded_arc(fmu, folder)}
    result["every_case_initializes"] = all(r["initializes"] for r in result["map"])
    args.out.mkdir(parents=True, exist_ok=True)
    (args.out / "graded_contact.json").write_text(json.dumps(result, indent=1))
    text = report(result)
    (args.out / "graded_contact.md").write_text(text)
    print(text)


if __name__ == "__main__":
    main()
