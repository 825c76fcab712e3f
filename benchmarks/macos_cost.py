"""What the macOS binaries cost the FMU users get, against issue 41's limits (ContactBody.fmu
<= 5 MB with every platform; a default simulate_fmu's start-up share <= 20 %), in one run:
build/ContactBody.fmu as it is against the same FMU without its macOS folders (the FMU before
macOS went in: its other binaries are the same files), interleaved in each round. Also the
static facts of each macOS binary (contactbody.tools.macho; the tests assert them, this reports them).
No macOS runs here: nothing is run on macOS.

Writes benchmarks/results/macos.json and macos.md.

    .venv/bin/python benchmarks/macos_cost.py [--rounds N]
"""
import argparse
import json
import pathlib
import tempfile
import zipfile

from portable_benchmark import median_and_range, simulate_seconds

from contactbody.tools import macho, platforms

ROOT = pathlib.Path(__file__).resolve().parents[1]
OUT = ROOT / "benchmarks" / "results"
FMU = ROOT / "build" / "ContactBody.fmu"


def without(fmu, folders, out):
    """`fmu` without binaries/FOLDER/ for each of `folders`, every other entry as it was packed."""
    with zipfile.ZipFile(fmu) as z, zipfile.ZipFile(out, "w") as o:
        for info in z.infolist():
            if info.filename.split("/")[:2] not in [["binaries", f] for f in folders]:
                o.writestr(info, z.read(info), compress_type=info.compress_type)
    return out


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--rounds", type=int, default=9)
    args = parser.parse_args()
    rows = [p for p in platforms.platforms() if p["static_checks"]]
    folders = sorted({p["fmi2_folder"] for p in rows})
    result = {"rounds": args.rounds, "binaries": {}, "fmus": {}}
    with tempfile.TemporaryDirectory() as tmp, zipfile.ZipFile(FMU) as z:
        tmp = pathlib.Path(tmp)
        for folder in folders:
            name = f"binaries/{folder}/ContactBody.dylib"
            info = z.getinfo(name)
            universal = tmp / "ContactBody.dylib"
            universal.write_bytes(z.read(name))
            result["binaries"][folder] = {"MB": info.file_size / 1e6, "deflated_MB": info.compress_size / 1e6}
            for p in rows:
                arch = p["static_checks"]["lipo_arch"]
                thin = macho.thin(universal, arch, tmp)
                f = macho.facts(thin)
                result["binaries"][p["name"]] = {
                    "MB": thin.stat().st_size / 1e6, "cpu": f["cpu"], "libraries": f["libraries"],
                    "minos": f["minos"], "signed": f["signed"],
                    "fmi_exports": len({e for e in f["exports"] if e.startswith(("_fmi2", "_fmi3"))}),
                    "other_exports": sorted(e for e in f["exports"] if not e.startswith(("_fmi2", "_fmi3")))}
        fmus = {"with_macos": FMU, "without_macos": without(FMU, folders, tmp / "without.fmu")}
        for fmu in fmus.values():  # warm the page cache and fmpy's imports
            simulate_seconds(fmu, 1e-4)
        one_step = {k: [] for k in fmus}
        shares = {k: [] for k in fmus}
        for _ in range(args.rounds):
            for k, fmu in fmus.items():
                s1 = simulate_seconds(fmu, 1e-4)
                s2 = simulate_seconds(fmu, 0.02)
                one_step[k].append(1e3 * s1)
                shares[k].append(100 * s1 / s2)
        for k, fmu in fmus.items():
            result["fmus"][k] = {"zipped_MB": fmu.stat().st_size / 1e6,
                                 "share_percent": median_and_range(shares[k]),
                                 "one_step_run_ms": median_and_range(one_step[k])}
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / "macos.json").write_text(json.dumps(result, indent=1) + "\n")
    (OUT / "macos.md").write_text(report(result))
    print(report(result))


def report(r):
    lines = ["# What the macOS binaries cost the FMU", "",
             f"`.venv/bin/python benchmarks/macos_cost.py --rounds {r['rounds']}`: build/'s FMU "
             "with its macOS binaries against the same FMU without them, interleaved in each round, "
             "medians with their range. The binaries' facts from llvm-14's tools: never run (no "
             "macOS here).", "",
             "| binary | size [MB] | CPU | libraries | minos | signed | fmi exports | other exports |",
             "|---|---|---|---|---|---|---|---|"]
    for name, b in r["binaries"].items():
        if "cpu" in b:
            lines.append(f"| {name} | {b['MB']:.2f} | {b['cpu']} | {', '.join(b['libraries'])} | "
                         f"{b['minos']} | {b['signed']} | {b['fmi_exports']} | {len(b['other_exports'])} |")
        else:
            lines.append(f"| {name} (universal) | {b['MB']:.2f} ({b['deflated_MB']:.2f} deflated) | | | | | | |")
    lines += ["", "| FMU | zipped [MB] (limit 5) | start-up share [%] (limit 20) | one-step run [ms] |",
              "|---|---|---|---|"]
    labels = {"with_macos": "with macOS (build/)", "without_macos": "without macOS"}
    for k, f in r["fmus"].items():
        s, o = f["share_percent"], f["one_step_run_ms"]
        lines.append(f"| {labels[k]} | {f['zipped_MB']:.2f} | {s['median']:.1f} ({s['min']:.1f}-{s['max']:.1f}) | "
                     f"{o['median']:.0f} ({o['min']:.0f}-{o['max']:.0f}) |")
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    main()
