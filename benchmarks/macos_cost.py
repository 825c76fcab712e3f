"""What macOS binaries would cost the FMU, against issue 33's limits (the FMU <= 4 MB with
every platform, a default simulate_fmu's start-up share <= 15 %), and the static checks the
issue asks of them. No macOS runs here: nothing is run on macOS.

Builds the macOS x86_64 and arm64 dylibs with cmake/zig-*-macos.11.0.cmake in build/macos-*/
(as package.cmake builds a platform: CONTACTBODY_FMU_BINARIES_ONLY, build/linux64's zig and
Eigen), checks them with Debian's llvm-14 tools (architecture, libSystem only, minos 11.0,
signed, exports), joins them into FMI 2.0's universal darwin64 binary (llvm-lipo-14), adds it to
build/ContactBody.fmu twice (linux64 stored as cmake/pack_fmu.py packs it, and everything
deflated) and measures size and start-up share of the three FMUs, interleaved in each round.

Writes benchmarks/results/macos.json and macos.md.

    .venv/bin/python benchmarks/macos_cost.py [--rounds N]
"""
import argparse
import json
import pathlib
import re
import statistics
import subprocess
import tempfile
import time
import zipfile

from portable_benchmark import median_and_range, simulate_seconds

ROOT = pathlib.Path(__file__).resolve().parents[1]
OUT = ROOT / "benchmarks" / "results"
ARCHES = {"x86_64": "X86_64", "arm64": "ARM64"}  # lipo's name: otool's CPU type
TOOLCHAIN = {"x86_64": "cmake/zig-x86_64-macos.11.0.cmake",
             "arm64": "cmake/zig-aarch64-macos.11.0.cmake"}
# Every dylib's two symbols and libc++'s replaceable operator new/delete (docs/building.md).
OTHER_EXPORTS = {"__mh_dylib_header", "___dso_handle"} | {
    "__Zda" + s for s in ("Pv", "PvSt11align_val_t", "Pvm", "PvmSt11align_val_t")} | {
    "__Zdl" + s for s in ("Pv", "PvSt11align_val_t", "Pvm", "PvmSt11align_val_t")} | {
    "__Zn" + s for s in ("am", "amSt11align_val_t", "wm", "wmSt11align_val_t")}


def platform_build_settings():
    """ZIG and EIGEN3_INCLUDE_DIR as the top-level build passed them to linux64's build."""
    cache = (ROOT / "build" / "linux64" / "CMakeCache.txt").read_text()
    return {k: re.search(rf"^{k}:[A-Z]+=(.*)$", cache, re.M)[1] for k in ("ZIG", "EIGEN3_INCLUDE_DIR")}


def build(arch, settings):
    """The dylib, and the seconds configure and build took (configure includes zig's libc++
    for the target unless zig's cache has it)."""
    folder = ROOT / "build" / f"macos-{arch}"
    t0 = time.perf_counter()
    subprocess.run(["/usr/bin/cmake", "-S", str(ROOT), "-B", str(folder), "-G", "Ninja",
                    f"-DCMAKE_TOOLCHAIN_FILE={ROOT / TOOLCHAIN[arch]}", "-DCMAKE_BUILD_TYPE=Release",
                    "-DCONTACTBODY_FMU_BINARIES_ONLY=ON", "-DCONTACTBODY_HOSTS=",
                    *(f"-D{k}={v}" for k, v in settings.items())],
                   check=True, stdout=subprocess.DEVNULL)
    t1 = time.perf_counter()
    subprocess.run(["/usr/bin/cmake", "--build", str(folder), "--target", "ContactBody"],
                   check=True, stdout=subprocess.DEVNULL)
    return folder / "ContactBody.dylib", {"configure_s": t1 - t0, "build_s": time.perf_counter() - t1}


def tool(*args):
    return subprocess.run(args, check=True, capture_output=True, text=True).stdout


def checks(dylib, arch):
    """What the issue asks to check of a binary that cannot run here."""
    header = tool("llvm-otool-14", "-hv", str(dylib)).split("\n")[-2].split()
    libraries = [line.split(" (")[0].strip() for line in tool("llvm-otool-14", "-L", str(dylib)).splitlines()[1:]]
    commands = tool("llvm-otool-14", "-l", str(dylib))
    exports = {line.split()[-1] for line in tool("llvm-nm-14", "-gU", str(dylib)).splitlines()}
    fmi = {e for e in exports if e.startswith(("_fmi2", "_fmi3"))}
    return {"cpu": header[1], "cpu_expected": ARCHES[arch], "filetype": header[4],
            "libraries": libraries[1:],  # the first is the dylib's own name
            "minos": re.search(r"minos (\S+)", commands)[1],
            "signed": "LC_CODE_SIGNATURE" in commands,
            "fmi_exports": len(fmi), "other_exports": sorted(exports - fmi),
            "others_known": exports - fmi <= OTHER_EXPORTS,
            "imports_exp": "_exp" in tool("llvm-nm-14", "-u", str(dylib)).split()}


def with_darwin64(fmu, universal, out, deflate_all):
    """`fmu` with binaries/darwin64 added; linux64's binary stored as in `fmu`, or deflated."""
    with zipfile.ZipFile(fmu) as z, zipfile.ZipFile(out, "w") as o:
        for info in z.infolist():
            stored = info.compress_type == zipfile.ZIP_STORED and not deflate_all
            o.writestr(info.filename, z.read(info),
                       compress_type=zipfile.ZIP_STORED if stored else zipfile.ZIP_DEFLATED,
                       compresslevel=None if stored else 9)
        o.write(universal, "binaries/darwin64/ContactBody.dylib", compress_type=zipfile.ZIP_DEFLATED,
                compresslevel=9)
    return out


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--rounds", type=int, default=9)
    args = parser.parse_args()
    settings = platform_build_settings()
    result = {"rounds": args.rounds, "builds": {}, "checks": {}, "sizes_MB": {}}
    dylibs = {}
    for arch in ARCHES:
        dylibs[arch], result["builds"][arch] = build(arch, settings)
        result["checks"][arch] = checks(dylibs[arch], arch)
        result["sizes_MB"][arch] = dylibs[arch].stat().st_size / 1e6
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        universal = tmp / "ContactBody.dylib"
        tool("llvm-lipo-14", "-create", "-output", str(universal), *map(str, dylibs.values()))
        result["sizes_MB"]["darwin64"] = universal.stat().st_size / 1e6
        fmus = {"today": ROOT / "build" / "ContactBody.fmu",
                "with darwin64, linux64 stored": with_darwin64(ROOT / "build" / "ContactBody.fmu", universal, tmp / "stored.fmu", False),
                "with darwin64, all deflated": with_darwin64(ROOT / "build" / "ContactBody.fmu", universal, tmp / "deflated.fmu", True)}
        with zipfile.ZipFile(fmus["with darwin64, all deflated"]) as z:
            result["sizes_MB"]["darwin64_deflated"] = z.getinfo("binaries/darwin64/ContactBody.dylib").compress_size / 1e6
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
        result["fmus"] = {k: {"zipped_MB": fmu.stat().st_size / 1e6,
                              "share_percent": median_and_range(shares[k]),
                              "one_step_run_ms": median_and_range(one_step[k])}
                          for k, fmu in fmus.items()}
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / "macos.json").write_text(json.dumps(result, indent=1) + "\n")
    (OUT / "macos.md").write_text(report(result))
    print(report(result))


def report(r):
    lines = ["# What macOS binaries would cost the FMU", "",
             f"`.venv/bin/python benchmarks/macos_cost.py --rounds {r['rounds']}`: the macOS dylibs "
             "built here with zig, checked with llvm-14's tools, never run (no macOS here); the "
             "three FMUs interleaved in each round, medians with their range.", "",
             "| arch | configure [s] | build [s] | size [MB] | CPU | libraries | minos | signed | fmi exports | other exports known | imports exp |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for arch, c in r["checks"].items():
        b = r["builds"][arch]
        lines.append(f"| {arch} | {b['configure_s']:.0f} | {b['build_s']:.0f} | {r['sizes_MB'][arch]:.2f} | "
                     f"{c['cpu']} | {', '.join(c['libraries'])} | {c['minos']} | {c['signed']} | "
                     f"{c['fmi_exports']} | {c['others_known']} | {c['imports_exp']} |")
    lines += ["", f"Universal darwin64: {r['sizes_MB']['darwin64']:.2f} MB, "
              f"{r['sizes_MB']['darwin64_deflated']:.2f} MB deflated.", "",
              "| FMU | zipped [MB] (limit 4) | start-up share [%] (limit 15) | one-step run [ms] |",
              "|---|---|---|---|"]
    for k, f in r["fmus"].items():
        s, o = f["share_percent"], f["one_step_run_ms"]
        lines.append(f"| {k} | {f['zipped_MB']:.2f} | {s['median']:.1f} ({s['min']:.1f}-{s['max']:.1f}) | "
                     f"{o['median']:.0f} ({o['min']:.0f}-{o['max']:.0f}) |")
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    main()
