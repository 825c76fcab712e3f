"""The FMUs users get are portable. Each platform folder holds one binary; the
linux64 one needs nothing beyond glibc 2.17 (checked here and by PyPA's auditwheel), the win64
one only Windows' own DLLs, the macOS ones only libSystem (macOS 11; FMI 2.0's darwin64 one
universal binary of both architectures); all export the FMI functions and nothing else
(ContactBody's library: fmi2 and fmi3, the same file in ContactBody.fmu and
ContactBody_fmi3.fmu)."""
import base64
import hashlib
import json
import pathlib
import re
import subprocess
import zipfile

import fmpy
import pytest
from elftools.elf.dynamic import DynamicSection
from elftools.elf.elffile import ELFFile
from elftools.elf.gnuversions import GNUVerNeedSection

from conftest import FMU, ROOT, SANITIZED
from contactbody.tools import macho, platforms

# The sanitizer job packs its native instrumented binary instead: nothing here applies.
pytestmark = pytest.mark.skipif(SANITIZED, reason="the sanitizer build is not the portable one")

FMU3 = FMU.with_name("ContactBody_fmi3.fmu")
FMU3D = FMU.with_name("ContactBody3D.fmu")
FMUS = [FMU, FMU3, FMU3D, FMU.with_name("ContactBody3D_fmi3.fmu"), FMU.with_name("BeltDrive.fmu"),
        FMU.with_name("Press.fmu")]
# FMI 3.0 names the platform folders by tuple.
PLATFORM_TUPLES = {p["name"]: p["fmi3_tuple"] for p in platforms.platforms()}
GLIBC_LIBRARIES = {"libc.so.6", "libm.so.6", "libpthread.so.0", "libdl.so.2", "librt.so.1",
                   "ld-linux-x86-64.so.2", "ld-linux-aarch64.so.1"}
# The Linux rows of the table and the machine their ELF files must name.
LINUX_MACHINES = {"linux64": "EM_X86_64", "aarch64-linux": "EM_AARCH64"}
WINDOWS_SYSTEM_DLLS = {"kernel32.dll", "msvcrt.dll", "user32.dll", "advapi32.dll", "ws2_32.dll",
                       "shell32.dll", "ole32.dll", "bcrypt.dll", "ntdll.dll"}


def folder(fmu, platform):
    three = fmpy.read_model_description(str(fmu)).fmiVersion.startswith("3")
    return PLATFORM_TUPLES[platform] if three else platforms.platform(platform)["fmi2_folder"]


@pytest.mark.parametrize("fmu", FMUS, ids=lambda f: f.stem)
def test_fmu_holds_the_platform_tables_folders(fmu):
    """platforms.json is the one list of platforms: every FMU carries exactly its folders, one
    binary each, with the row's suffix."""
    with zipfile.ZipFile(fmu) as z:
        found = {n.split("/")[1]: n for n in z.namelist()
                 if n.startswith("binaries/") and not n.endswith("/")}
    expected = {folder(fmu, p["name"]): p["library_suffix"] for p in platforms.platforms()}
    assert set(found) == set(expected)
    for name, path in found.items():
        assert path.endswith(expected[name]), path


def exports_only_fmi(fmu, exported):
    prefixes = ("fmi2", "fmi3") if fmu.stem.startswith("ContactBody") else ("fmi2",)
    return exported and all(n.startswith(prefixes) for n in exported)


def binaries(fmu, platform):
    platform = folder(fmu, platform)
    with zipfile.ZipFile(fmu) as z:
        return {n: z.read(n) for n in z.namelist()
                if n.startswith(f"binaries/{platform}/") and not n.endswith("/")}


def only_binary(fmu, platform, tmp_path):
    files = binaries(fmu, platform)
    identifier = fmpy.read_model_description(str(fmu)).coSimulation.modelIdentifier
    suffix = platforms.platform(platform)["library_suffix"]
    assert list(files) == [f"binaries/{folder(fmu, platform)}/{identifier}{suffix}"], files.keys()
    path = tmp_path / f"{identifier}{suffix}"
    path.write_bytes(next(iter(files.values())))
    return path


def glibc_version(name):
    return tuple(int(x) for x in name[len("GLIBC_"):].split("."))


def test_every_linux_row_is_checked_here():
    assert {p["name"] for p in platforms.platforms() if p["library_suffix"] == ".so"} \
        == set(LINUX_MACHINES)


@pytest.mark.parametrize("platform", LINUX_MACHINES)
@pytest.mark.parametrize("fmu", FMUS, ids=lambda p: p.stem)
def test_linux_binary_needs_only_glibc_2_17(fmu, platform, tmp_path):
    path = only_binary(fmu, platform, tmp_path)
    with open(path, "rb") as f:
        elf = ELFFile(f)
        assert elf["e_machine"] == LINUX_MACHINES[platform]
        dynamic = elf.get_section_by_name(".dynamic")
        assert isinstance(dynamic, DynamicSection)
        needed = {t.needed for t in dynamic.iter_tags() if t.entry.d_tag == "DT_NEEDED"}
        assert needed <= GLIBC_LIBRARIES, needed - GLIBC_LIBRARIES
        assert "libc.so.6" in needed  # the section was really read
        versions = set()
        for section in elf.iter_sections():
            if isinstance(section, GNUVerNeedSection):
                for _, auxiliaries in section.iter_versions():
                    versions |= {a.name for a in auxiliaries}
        glibc = sorted((glibc_version(v) for v in versions if v.startswith("GLIBC_2")))
        assert glibc and glibc[-1] <= (2, 17), f"needs GLIBC_{'.'.join(map(str, glibc[-1]))}"
        assert not any(v.startswith(("GLIBCXX", "CXXABI", "GCC_")) for v in versions), versions
        exported = {s.name for s in elf.get_section_by_name(".dynsym").iter_symbols()
                    if s["st_shndx"] != "SHN_UNDEF" and s.name}
        assert exports_only_fmi(fmu, exported), sorted(exported)[:10]
        if fmu.stem.startswith("ContactBody"):
            assert {"fmi2DoStep", "fmi3DoStep", "fmi3InstantiateCoSimulation"} <= exported
        # The math the physics calls is inside (zig's compiler_rt, cmake/fmu_binaries.cmake),
        # not the host's libm, whose results differ between glibc versions and processors.
        imported = {s.name for s in elf.get_section_by_name(".dynsym").iter_symbols()
                    if s["st_shndx"] == "SHN_UNDEF" and s.name}
        assert not imported & {"exp", "log", "pow", "floor", "ceil", "sqrt", "hypot"}, sorted(imported)


@pytest.mark.parametrize("platform, arch", [("linux64", "x86_64"), ("aarch64-linux", "aarch64")])
def test_auditwheel_calls_the_linux_binary_manylinux_2_17(platform, arch, tmp_path):
    """An outside judge: PyPA's auditwheel on a throwaway wheel that holds the binary."""
    data = only_binary(FMU, platform, tmp_path).read_bytes()
    files = {"probe/ContactBody.so": data,
             "probe-0.0.0.dist-info/METADATA": b"Metadata-Version: 2.1\nName: probe\nVersion: 0.0.0\n",
             "probe-0.0.0.dist-info/WHEEL": b"Wheel-Version: 1.0\nGenerator: test\n"
                                            b"Root-Is-Purelib: false\nTag: py3-none-linux_"
                                            + arch.encode() + b"\n"}
    wheel = tmp_path / f"probe-0.0.0-py3-none-linux_{arch}.whl"
    record = []
    with zipfile.ZipFile(wheel, "w") as z:
        for name, content in files.items():
            z.writestr(name, content)
            digest = base64.urlsafe_b64encode(hashlib.sha256(content).digest()).rstrip(b"=")
            record.append(f"{name},sha256={digest.decode()},{len(content)}")
        record.append("probe-0.0.0.dist-info/RECORD,,")
        z.writestr("probe-0.0.0.dist-info/RECORD", "\n".join(record) + "\n")
    out = subprocess.run([str(ROOT / ".venv" / "bin" / "auditwheel"), "show", str(wheel)],
                         capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    text = " ".join(out.stdout.split())
    assert f'consistent with the following platform tag: "manylinux_2_17_{arch}"' in text, text


@pytest.mark.parametrize("fmu", FMUS, ids=lambda p: p.stem)
def test_windows_binary_imports_only_system_dlls(fmu, tmp_path):
    path = only_binary(fmu, "win64", tmp_path)
    out = subprocess.run(["x86_64-w64-mingw32-objdump", "-p", str(path)], capture_output=True,
                         text=True, check=True).stdout
    imports = {m.lower() for m in re.findall(r"DLL Name: (\S+)", out)}
    assert "kernel32.dll" in imports and imports <= WINDOWS_SYSTEM_DLLS, imports
    table = out.split("[Ordinal/Name Pointer] Table", 1)[1].split("\n\n", 1)[0]
    exported = re.findall(r"\]\s+(\S+)", table)
    assert exports_only_fmi(fmu, exported), exported
    if fmu.stem.startswith("ContactBody"):
        assert {"fmi2DoStep", "fmi3DoStep", "fmi3InstantiateCoSimulation"} <= set(exported)


@pytest.mark.parametrize("fmu", FMUS, ids=lambda p: p.stem)
def test_binaries_carry_no_folder_of_the_build_machine(fmu):
    """Source paths (__FILE__ in CHOLMOD's error reports) are relative to the project
    (-ffile-prefix-map): a binary shows nothing of where it was built, and a clone elsewhere
    builds the same bytes."""
    with zipfile.ZipFile(fmu) as z:
        for name in z.namelist():
            if name.startswith("binaries/") and not name.endswith("/"):
                assert str(ROOT).encode() not in z.read(name), name


@pytest.mark.parametrize("fmu, budget, quote", [
    (FMU, 5e6, "The FMU is ([\\d.]+) MB zipped"),  # with every platform (issue 41)
    # The 3D model carries the solid-body code the 2D one leaves out (the tetrahedral kernels,
    # the isotropic friction, the supernodal LU with the C++ library's locale machinery).
    (FMU3D, 6.5e6, "ContactBody3D.fmu is ([\\d.]+) MB zipped")])
def test_fmu_is_small_and_carries_the_licences(fmu, budget, quote):
    assert fmu.stat().st_size <= budget, fmu.stat().st_size
    quoted = re.search(quote, (ROOT / "README.md").read_text())
    assert quoted and float(quoted[1]) == round(fmu.stat().st_size / 1e6, 1), \
        f"README quotes {quoted and quoted[1]} MB, the FMU has {fmu.stat().st_size / 1e6:.2f}"
    with zipfile.ZipFile(fmu) as z:
        licences = {pathlib.PurePosixPath(n).name for n in z.namelist()
                    if n.startswith("documentation/licenses/")}
    for name in ("LICENSE", "CHOLMOD-License.txt", "CHOLMOD-LGPL-2.1.txt", "METIS-LICENSE.txt",
                 "Eigen-MPL-2.0.txt", "libcxx-LICENSE.txt",
                 "mingw-w64-copyright.txt", "AMD-License.txt", "CAMD-License.txt",
                 "COLAMD-License.txt", "CCOLAMD-License.txt", "Spectra-MPL-2.0.txt",
                 "Spectra-COPYRIGHT.txt"):
        assert name in licences, name


@pytest.mark.parametrize("name", ["ContactBody", "ContactBody_fmi3", "ContactBody3D",
                                  "ContactBody3D_fmi3", "BeltDrive", "Press"])
def test_no_fmu_carries_sources(name):
    """No sources/ (docs/building.md): a complete source FMU would need Eigen (C++) and
    SuiteSparse, which an importer's C compile cannot build, and FMI 3.0 ties sources/ to
    a buildDescription.xml; an incomplete sources/ promised what it could not do."""
    with zipfile.ZipFile(FMU.with_name(f"{name}.fmu")) as z:
        assert not [n for n in z.namelist() if n.startswith("sources/")]
        assert "<SourceFiles" not in z.read("modelDescription.xml").decode()


# Scenes recorded by running this file (`.venv/bin/python python_tests/test_portable.py FMU OUT`):
# NATIVE with this project built by the machine's gcc (-DCONTACTBODY_PORTABLE=OFF), BEFORE with
# the FMU before the portable build (commit 406a316: gcc 12 with Debian's SuiteSparse 5.12,
# METIS and reference LAPACK 3.11 as shared libraries), which also solved for u^{k+1/2} itself,
# not the increment. "metis": a mesh whose factor takes the METIS ordering (it has
# less fill than CAMD's from 120 x 120 on; 80 x 80 takes CAMD's) and whose contact systems
# exceed LAPACK's block size 64 (blocked dgetrf; 81 unknowns at 80 x 80).
SCENES = {"default": dict(stop_time=0.02, output_interval=1e-4, start_values={}),
          "metis": dict(stop_time=3e-4, output_interval=1e-4,
                        start_values={"nx": 120, "ny": 120, "friction_coefficient": 0.3})}
NATIVE = ROOT / "python_tests" / "data" / "outputs_native_build.json"
REFERENCE = ROOT / "python_tests" / "data" / "outputs_before_portable_build.json"


def scene_outputs(fmu, scene):
    """Every output of the scene, each value a hex float."""
    r = fmpy.simulate_fmu(str(fmu), **SCENES[scene], output=OUTPUTS)
    return {name: [float(x).hex() for x in r[name]] for name in OUTPUTS}


def outputs_of(fmu):
    return [v.name for v in fmpy.read_model_description(str(fmu)).modelVariables
            if v.causality == "output"]


OUTPUTS = outputs_of(ROOT / "modelDescription" / "modelDescription.xml")


def test_paper_scene_equals_the_native_build_bit_for_bit(fmu_path):
    """The portable toolchain (zig's clang, vendored SuiteSparse) computes the same
    bits as the machine's gcc."""
    for scene in SCENES:
        expected = json.loads(NATIVE.read_text())[scene]
        got = scene_outputs(fmu_path, scene)
        for name in expected:
            assert got[name] == expected[name], (scene, name)


def scaled_differences(expected, got, units):
    """Per output: the largest difference over the run / the largest value of its unit."""
    values = {n: [float.fromhex(x) for x in expected[n]] for n in expected}
    scale = {}
    for name, v in values.items():
        scale[units[name]] = max(scale.get(units[name], 0.0), max(abs(x) for x in v))
    return {name: max(abs(a - float.fromhex(b)) for a, b in zip(v, got[name])) /
            (scale[units[name]] or 1.0) for name, v in values.items()}


def test_paper_scene_agrees_with_the_absolute_form_before_it(fmu_path):
    """The increment form changed the paper scene's bits (F = 1.2, growing: round-off is
    amplified). Every output stays within 2e-6 of the largest value of its unit (measured:
    1.1e-6 for max_penetration, <= 1.2e-7 for the others), the counts are equal and t0 differs
    by at most 1e-15 (benchmarks/results/increment_form.md)."""
    expected = json.loads(REFERENCE.read_text())["default"]
    got = scene_outputs(fmu_path, "default")
    units = {v.name: v.unit for v in fmpy.read_model_description(fmu_path).modelVariables}
    for name, d in scaled_differences(expected, got, units).items():
        assert d <= 2e-6, (name, d)
        if units[name] is None:
            assert got[name] == expected[name], name
        assert abs(float.fromhex(got[name][0]) - float.fromhex(expected[name][0])) <= 1e-15


def test_metis_scene_differs_from_before_only_by_round_off(fmu_path):
    """Not bit for bit: METIS now draws GKlib's random numbers, not glibc's rand() (the same on
    every platform: test_windows.py), so its ordering, and the factor's round-off, changed.
    Each output stays within 1e-12 of the largest value of its unit (energies of energies,
    lengths of lengths); at least one differs, or this scene would not show the ordering."""
    expected = json.loads(REFERENCE.read_text())["metis"]
    got = scene_outputs(fmu_path, "metis")
    units = {v.name: v.unit for v in fmpy.read_model_description(fmu_path).modelVariables}
    differences = scaled_differences(expected, got, units)
    for name, d in differences.items():
        assert d <= 1e-12, (name, d)
    assert any(d > 0 for d in differences.values())


if __name__ == "__main__":
    import sys
    pathlib.Path(sys.argv[2]).write_text(
        json.dumps({s: scene_outputs(sys.argv[1], s) for s in SCENES}) + "\n")


# The rows no machine here can run (macOS): checked statically, each as platforms.json says.
STATIC_ROWS = [p["name"] for p in platforms.platforms() if p["static_checks"]]


@pytest.mark.parametrize("platform", STATIC_ROWS)
@pytest.mark.parametrize("fmu", FMUS, ids=lambda p: p.stem)
def test_macos_binary_passes_the_static_checks(fmu, platform, tmp_path):
    """The architecture's binary (FMI 3.0's own folder, or its slice of FMI 2.0's universal
    darwin64 binary) is a dylib of the row's CPU for the row's macOS, signed where the row asks
    (arm64 macOS runs no unsigned code), loading libSystem alone (libc++ is linked in), through
    an @rpath install name, and exports the FMI functions and libc++'s operators only."""
    expected = platforms.platform(platform)["static_checks"]
    dylib = macho.thin(only_binary(fmu, platform, tmp_path), expected["lipo_arch"], tmp_path)
    found = macho.facts(dylib)
    assert (found["cpu"], found["filetype"]) == (expected["cpu"], "DYLIB")
    assert found["libraries"] == [macho.LIBSYSTEM]
    assert found["install_name"].startswith("@rpath/"), found["install_name"]
    assert found["minos"] == expected["minos"]
    assert found["signed"] or not expected["signed"]
    prefixes = ("_fmi2", "_fmi3") if fmu.stem.startswith("ContactBody") else ("_fmi2",)
    fmi = {e for e in found["exports"] if e.startswith(prefixes)}
    assert found["exports"] - fmi <= macho.OTHER_EXPORTS, sorted(found["exports"] - fmi - macho.OTHER_EXPORTS)[:10]
    assert "_fmi2DoStep" in fmi and "_fmi2Instantiate" in fmi
    if fmu.stem.startswith("ContactBody"):
        assert {"_fmi3DoStep", "_fmi3InstantiateCoSimulation"} <= fmi
        # The model class's own code is in it, not only the FMI layer.
        assert found["imports"], "a dylib that imports nothing from libSystem links nothing"


@pytest.mark.parametrize("fmu", [f for f in FMUS if not f.stem.endswith("_fmi3")], ids=lambda p: p.stem)
def test_fmi2_universal_binaries_hold_each_row_sharing_their_folder(fmu, tmp_path):
    """FMI 2.0 has one folder for macOS (darwin64): it holds one slice per row that names it,
    and no other."""
    shared = {}
    for p in platforms.platforms():
        shared.setdefault(p["fmi2_folder"], []).append(p)
    universal = {f: rows for f, rows in shared.items() if len(rows) > 1}
    assert universal, "platforms.json has no FMI 2.0 folder shared by two rows (darwin64)"
    for rows in universal.values():
        path = only_binary(fmu, rows[0]["name"], tmp_path)
        assert macho.architectures(path) == {r["static_checks"]["lipo_arch"] for r in rows}
