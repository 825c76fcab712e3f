"""Tables in docs/ that reshape a results file (pivot, combine, round): generated from it.

A generated table carries, on the line before it, the marker

    <!-- table convergence from examples/results/convergence.json -->

`contactbody.tools.quotes` checks that the table below the marker is what the named generator makes
of that file today; `--write` rewrites every marked table from its file:

    .venv/bin/python -m contactbody.tools.doc_tables --write

A table copied unchanged from a results .md uses `<!-- rows of FILE -->` instead.
"""
import json
import math
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]


def documents():
    """Every Markdown file of the repository outside build trees and environments."""
    skip = {".venv", "build", "build-before", "third_party", ".git", "dist"}
    return sorted(p for p in ROOT.rglob("*.md")
                  if not skip & set(p.relative_to(ROOT).parts))


GENERATORS = {}
DERIVED = {}  # a value that prose quotes as `FILE.json: =NAME`, computed from the file
MARKER = re.compile(r"<!-- table (?P<name>\w+) from (?P<file>[\w./-]+\.json) -->\n"
                    r"(?P<table>(?:\|.*\n?)*)")


def generator(function):
    GENERATORS[function.__name__] = function
    return function


def derived(function):
    DERIVED[function.__name__] = function
    return function


def _critical_betas(data):
    """{(nx, F): smallest stabilizing beta} of the damped stability map, where it has one."""
    return {(r["nx"], round(r["friction"], 6)): r["critical_beta"] for r in data["rows"]
            if r.get("critical_beta") is not None}


def _largest_change(data, coarse, fine):
    betas = _critical_betas(data)
    return max(abs(betas[fine, f] - betas[coarse, f]) for n, f in betas
               if n == coarse and (fine, f) in betas)


@derived
def largest_refinement_change(data):
    """The largest change of the smallest stabilizing beta from nx = 20 to 40."""
    return _largest_change(data, 20, 40)


@derived
def largest_coarse_change(data):
    """The largest change of the smallest stabilizing beta from nx = 5 to 10."""
    return _largest_change(data, 5, 10)


@derived
def worst_balance_error(data):
    """The stress sweep's largest energy balance error over the runs with finite outputs."""
    return max(r["balance_error"] for r in data if "balance_error" in r)


@derived
def step_errors(data):
    """How many stress-sweep runs failed a step."""
    return sum(r["status"] == "error" for r in data)


@derived
def stick_share_beyond_50mm(data):
    """The edge history's largest share of time stuck among the nodes beyond x = 50 mm."""
    return max(share for x, share in zip(data["x_mm"], data["stick_share_after_3ms"]) if x > 50)


def _getfem_pairs(data):
    """(GetFEM row, the FMU's standard row) of the work-precision run at the same settings."""
    key = lambda r: (r["scene"], r["ladder"], r["h"], r["dt"])  # noqa: E731
    fmu = {key(r): r for r in data["rows"] if r["variant"] == "standard"}
    return [(r, fmu[key(r)]) for r in data["rows"] if r["variant"].startswith("GetFEM")]


def _getfem(statistic):
    values = {
        "ratio": lambda g, f: g["time"] / f["time"],
        "getfem_ms": lambda g, f: 1e3 * g["time"] / g["substeps"],
        "fmu_us": lambda g, f: 1e6 * f["time"] / f["substeps"]}[statistic]
    return lambda data: [values(g, f) for g, f in _getfem_pairs(data)]


def _register_extremes(name, values):
    DERIVED[f"{name}_min"] = lambda data: min(values(data))
    DERIVED[f"{name}_max"] = lambda data: max(values(data))


for _statistic in ("ratio", "getfem_ms", "fmu_us"):
    _register_extremes(f"getfem_{_statistic}", _getfem(_statistic))
_register_extremes("getfem_ms_at_nx20", lambda data: [
    1e3 * g["time"] / g["substeps"] for g, _ in _getfem_pairs(data) if g["h"] == 0.005])


def sci(value, digits=2):
    """1.2e5, 4.82e-3: `digits` significant digits, exponent without padding."""
    if value == 0:
        return "0"
    mantissa, exponent = f"{value:.{digits - 1}e}".split("e")
    return f"{mantissa}e{int(exponent)}"


def short(value):
    """A step or size as written by hand: 1.6e-5, 8e-6, 0.5, 2."""
    text = f"{value:.6g}"
    if "e" in text:
        mantissa, exponent = text.split("e")
        return f"{mantissa}e{int(exponent)}"
    return text


def rate(value):
    """A growth rate: whole numbers below 1e3, three digits above."""
    if value is None:
        return "–"
    return f"{value:.0f}" if abs(value) < 1e3 else sci(value, 3)


def table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(str(cell) for cell in row) + " |" for row in rows]
    return "\n".join(lines) + "\n"


def orders(rows, key):
    """The observed convergence orders along a ladder of halvings of h."""
    return [math.log(a[key] / b[key]) / math.log(a["h"] / b["h"]) for a, b in zip(rows, rows[1:])]


def _order(rows, i, key):
    return f" ({orders(rows, key)[i - 1]:.2f})" if i else ""


@derived
def damped_l2_order_min(data):
    """The smallest L2 order of the damped F = 0.3 ladder (examples/convergence.py)."""
    return min(orders(data["0.3"]["rows"], "l2"))


@derived
def damped_l2_order_max(data):
    return max(orders(data["0.3"]["rows"], "l2"))


@generator
def figures_7_8(data):
    """Max E and the drift of E − ξ per variant and Δt (examples/figures_7_8.py)."""
    variants = ["standard", "redistributed_normal", "redistributed_both",
                "standard_implicit_contact"]
    cell = {(r["mass_matrix"], r["dt"]): r for r in data["rows"]}
    steps = sorted({r["dt"] for r in data["rows"]}, reverse=True)
    header = ["Δt [s]", "standard: max E"] + [f"{v}: max E / drift" for v in variants[1:]]
    rows = [[short(dt), sci(cell["standard", dt]["max_energy"])]
            + [f"{sci(cell[v, dt]['max_energy'])} / {sci(cell[v, dt]['drift'])}"
               for v in variants[1:]] for dt in steps]
    return table(header, rows)


def _convergence(data, frictions, orders):
    ladders = {f: data[f]["rows"] for f in frictions}
    header = ["h [cm]", "Δt [s]"]
    for f in frictions:
        suffix = " (order)" if f in orders else ""
        header += [f"F = {f}: L2 [m²]{suffix}", f"H1 [m]{suffix}"]
    rows = []
    for i, first in enumerate(ladders[frictions[0]]):
        row = [short(first["h"] * 100), short(first["dt"])]
        for f in frictions:
            ladder = ladders[f]
            for key in ("l2", "h1"):
                row.append(sci(ladder[i][key], 3) + (_order(ladder, i, key) if f in orders else ""))
        rows.append(row)
    return table(header, rows)


@generator
def convergence(data):
    """The Table 2 ladder, undamped (examples/convergence.py)."""
    return _convergence(data, ["1.2", "0", "0.2"], orders={"0"})


@generator
def convergence_damped(data):
    """The Table 2 ladder with β = 4e-6 s (examples/convergence.py --damping-stiffness 4e-6)."""
    return _convergence(data, ["0.3", "0"], orders={"0.3", "0"})


@generator
def sliding_growth(data, test_time=5e-3):
    """Largest growth rate about full-contact steady sliding, e-folds over the test's 5 ms
    (examples/sliding_stability.py)."""
    def cell(h, friction, variant):
        found = [r for r in data if math.isclose(r["h"], h) and r["friction"] == friction
                 and r["mass_matrix"] == variant]
        if not found:
            return "–"
        growth = found[0]["max_growth_rate"]
        if growth == 0:
            return "0"
        folds = growth * test_time
        return f"{rate(growth)} ({folds:.1f})" if folds < 10 else f"{rate(growth)} ({folds:.0f})"

    def frictionless(h):
        cells = {cell(h, 0, v) for v in (0, 1, 2)}
        return cells.pop() if len(cells) == 1 else "differs"

    header = ["h [cm]", "F = 0 (all variants)", "redistributed_normal, F = 0.2",
              "redistributed_normal, F = 1.2", "standard, F = 1.2", "redistributed_both, F = 1.2"]
    rows = [[short(h * 100), frictionless(h), cell(h, 0.2, 1), cell(h, 1.2, 1), cell(h, 1.2, 0),
             cell(h, 1.2, 2)] for h in sorted({r["h"] for r in data}, reverse=True)]
    return table(header, rows)


@generator
def full_contact_growth(data):
    """Largest damped growth rate about the full-contact state (examples/damped_stability.py
    --full-contact), at chosen F and β."""
    columns = [(0.3, 0.0), (0.3, 4e-6), (0.5, 4e-6), (0.5, 1e-5), (1.2, 0.0), (1.2, 4e-6),
               (1.2, 1e-5)]
    betas = data["betas"]
    header = ["h [cm]"] + [f"F = {f}, β = {short(b)} s" for f, b in columns]
    rows = []
    for h in sorted({r["h"] for r in data["rows"]}, reverse=True):
        row = [short(h * 100)]
        for friction, beta in columns:
            found = [r for r in data["rows"] if math.isclose(r["h"], h)
                     and math.isclose(r["friction"], friction) and r.get("growth")]
            index = min(range(len(betas)), key=lambda i: abs(betas[i] - beta))
            row.append(rate(found[0]["growth"][index]) if found else "–")
        rows.append(row)
    return table(header, rows)


@generator
def figures_3_5(data):
    """The one-triangle step's solution sets against the closed forms (examples/figures_3_5.py)."""
    cases = [("normal", "normal mass removed (m1 = 0, m2 > 0): Fig. 3"),
             ("tangential", "tangential mass removed (m1 > 0, m2 = 0): Fig. 4"),
             ("both", "both removed (m1 = m2 = 0)"),
             ("critical", "tangential mass removed, F = c/b: Fig. 5"),
             ("normal_long_step", "normal mass removed, Δt = 2 > Δt₀")]
    header = ["case", "Δt", "c/b", "F", "grid points where solver = closed form",
              "points with 1 / 2 / 3 solutions", "points on σ5", "starts not converged"]
    rows = []
    for key, label in cases:
        c = data[key]
        rows.append([label, f"{c.get('dt', 1):g}", f"{c['c_over_b']:.2f}", f"{c['friction']:.3g}",
                     f"{c['agree']} of {c['points']}",
                     f"{c['one_solution']} / {c['two_solutions']} / {c['three_solutions']}",
                     c["continuum_points"], f"{c['failed_starts']:,}"])
    return table(header, rows)


@generator
def stribeck_bifurcation(data):
    """Substeps with several contact solutions, and where their branches go
    (examples/stribeck_bifurcation.py)."""
    end = f"E({data[0]['steps'] * data[0]['dt'] * 1e3:g} ms)"
    header = ["variant", "nx", "Δt [s]", "substeps", "with several solutions", "most",
              f"{end} [J/m]", f"{end} of the branches"]
    rows = [[r["variant"], r["nx"], short(r["dt"]), r["steps"], r["substeps_with_several"],
             r["most_solutions"], f"{r['energy_end']:.5f}",
             ", ".join(f"{b['energy_end']:.5f}" for b in r["branches"]) or "-"]
            for r in data]
    return table(header, rows)


@generator
def impact(data):
    """The force-driven impact per variant at two steps (examples/scenes.py)."""
    variants = list(dict.fromkeys(r["mass_matrix"] for r in data["impact"]))
    header = ["mass_matrix", "Δt [s]", "E(end) / E(0)", "contact intervals"]
    rows = []
    for v in variants:
        runs = [r for r in data["impact"] if r["mass_matrix"] == v]
        rows.append([v, " / ".join(short(r["dt"]) for r in runs),
                     " / ".join(f"{r['energy_ratio']:.4f}" for r in runs),
                     " / ".join(str(r["contact_intervals"]) for r in runs)])
    return table(header, rows)


@generator
def platforms(data):
    """The platform table (platforms.json): where each binary is and how it is tested."""
    header = ["platform", "FMI 2.0 folder", "FMI 3.0 folder", "built with", "tested"]
    rows = [[p["name"], f"`binaries/{p['fmi2_folder']}`", f"`binaries/{p['fmi3_tuple']}`",
             f"`{p['toolchain']}`", p["tested"]] for p in data["platforms"]]
    return table(header, rows)


def generate(name, file, root):
    return GENERATORS[name](json.loads((root / file).read_text()))


def write(document, root):
    """Rewrites every marked table of one document; True if it changed."""
    text = document.read_text()
    new = MARKER.sub(lambda m: m.group(0).split("\n", 1)[0] + "\n"
                     + generate(m["name"], m["file"], root), text)
    if new != text:
        document.write_text(new)
    return new != text


def main(argv):
    if argv != ["--write"]:
        print(__doc__)
        return 2
    for document in documents():
        if write(document, ROOT):
            print(f"rewrote {document.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
