"""Two builds' reduced-body substep against each other (issue 44): each build's
bench_contact_profile (contact_profile.py's scene: nx = 160, 80 modes, 2e-6 s, the massless
or the tangential-mass edge), run in alternating rounds so that both see the same state of this noisy machine, and the
median of each, and of the rounds' ratios. For changes whose effect is below the noise between separate runs of
contact_profile.py (about 10 %).

    .venv/bin/python benchmarks/contact_ab.py --name NAME --a LABEL=DIR --b LABEL=DIR [--rounds 5]
        [--edge massless|tangential_mass]

DIR holds a bench_contact_profile. Writes benchmarks/results/contact_ab.{json,md}, one entry per
NAME.
"""
import argparse
import json
import pathlib
import statistics
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import contact_profile  # noqa: E402

NX, DT = 160, contact_profile.DT
EDGES = {"massless": contact_profile.MASSLESS, "tangential_mass": contact_profile.TANGENTIAL_MASS}


def build_arg(text):
    label, _, directory = text.partition("=")
    if not directory:
        raise argparse.ArgumentTypeError("expected LABEL=DIR")
    return label, pathlib.Path(directory)


def compare(builds, rounds, edge):
    """Per build: pressed and lifted µs of every round (each a bench's own median of 5)."""
    times = {label: {"pressed_us": [], "lifted_us": []} for label, _ in builds}
    for _ in range(rounds):
        for label, directory in builds:
            r = contact_profile.profile(directory, NX, DT, EDGES[edge])
            times[label]["pressed_us"].append(r["substep_us_pressed"])
            times[label]["lifted_us"].append(r["substep_us_lifted"])
    return times


def summarize(times):
    """Each build's medians, and the second build's times over the first's: the median of the
    rounds' ratios, where a slow spell of the machine, which both builds of a round share,
    cancels."""
    first = next(iter(times.values()))
    for t in times.values():
        for kind in ("pressed", "lifted"):
            t[f"{kind}_median"] = statistics.median(t[f"{kind}_us"])
            t[f"{kind}_over_first"] = statistics.median(
                b / a for a, b in zip(first[f"{kind}_us"], t[f"{kind}_us"]))
    return times


def table(results):
    lines = ["# Two builds' substeps in alternating rounds", "",
             "`benchmarks/contact_ab.py`: nx = 160, 80 modes, 2e-6 s, the edge named; µs per "
             "substep pressed and lifted off, the median over alternating rounds of the two builds' "
             "bench_contact_profile (each round itself a median of 5).", "",
             "| comparison | edge | build | rounds | pressed µs | lifted µs | pressed / lifted | "
             "pressed / first build's, per round | lifted / first build's, per round |",
             "|---|---|---|---|---|---|---|---|---|"]
    for name, r in results.items():
        for label, t in r["builds"].items():
            lines.append(f"| {name} | {r.get('edge', 'massless')} | {label} | {r['rounds']} | {t['pressed_median']:.1f} | "
                         f"{t['lifted_median']:.1f} | "
                         f"{t['pressed_median'] / t['lifted_median']:.2f} | "
                         f"{t['pressed_over_first']:.3f} | {t['lifted_over_first']:.3f} |")
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--name", required=True, help="what the comparison is")
    parser.add_argument("--a", type=build_arg, required=True, help="LABEL=DIR")
    parser.add_argument("--b", type=build_arg, required=True, help="LABEL=DIR")
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--edge", choices=sorted(EDGES), default="massless")
    parser.add_argument("--out", type=pathlib.Path, default=contact_profile.ROOT / "benchmarks" / "results")
    args = parser.parse_args()
    path = args.out / "contact_ab.json"
    results = json.loads(path.read_text()) if path.exists() else {}
    results[args.name] = {"nx": NX, "modes": contact_profile.MODES, "dt": DT, "edge": args.edge,
                          "rounds": args.rounds,
                          "builds": summarize(compare([args.a, args.b], args.rounds, args.edge))}
    path.write_text(json.dumps(results, indent=1) + "\n")
    (args.out / "contact_ab.md").write_text(table(results))
    print(table(results))


if __name__ == "__main__":
    main()
