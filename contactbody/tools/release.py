"""The release folder: what a user downloads instead of building.

    .venv/bin/python -m contactbody.tools.release [DIST]     # default dist/; scripts/release.sh

DIST gets, from the FMUs that scripts/setup.sh built in build/:
- ContactBody.fmu, ContactBody_fmi3.fmu, ContactBody3D.fmu, ContactBody3D_fmi3.fmu,
  BeltDrive.fmu, Press.fmu: every platform of
  platforms.json in each;
- belt_and_body.ssp, press_and_body.ssp: the example system models (contactbody.system);
- contactbody-VERSION-py3-none-any.whl: the Python package with the six FMUs as package data,
  so that find_fmu() and the system models work after `pip install` with no checkout. It is a
  pure-Python wheel: the package loads no binary itself, fmpy extracts the one the FMU holds for
  the machine (Linux x86_64 and aarch64 with glibc >= 2.17, Windows x86_64), so no
  manylinux tag applies (auditwheel finds nothing to judge; python_tests/test_release.py);
- licenses/: the project's licence and those of everything linked into the binaries;
- SHA256SUMS: `sha256sum -c SHA256SUMS` checks the rest.
"""
import hashlib
import pathlib
import shutil
import subprocess
import sys
import tempfile
import zipfile

ROOT = pathlib.Path(__file__).resolve().parents[2]
FMUS = ["ContactBody", "ContactBody_fmi3", "ContactBody3D", "ContactBody3D_fmi3", "BeltDrive", "Press"]


def fmus(build):
    paths = [build / f"{name}.fmu" for name in FMUS]
    missing = [p for p in paths if not p.is_file()]
    if missing:
        raise FileNotFoundError(f"{', '.join(map(str, missing))} missing: build first "
                                "(scripts/setup.sh)")
    return paths


def build_wheel(fmu_paths, dist):
    """The wheel of this checkout's package with the FMUs inside, built in a staging copy (the
    checkout stays as it is). Returns its path."""
    with tempfile.TemporaryDirectory(prefix="contactbody_wheel_") as staging:
        staging = pathlib.Path(staging)
        for name in ("pyproject.toml", "LICENSE", "README.md"):
            shutil.copy2(ROOT / name, staging / name)
        shutil.copytree(ROOT / "contactbody", staging / "contactbody",
                        ignore=shutil.ignore_patterns("__pycache__", "*.pyc", "fmus"))
        (staging / "contactbody" / "fmus").mkdir()
        for path in fmu_paths:
            shutil.copy2(path, staging / "contactbody" / "fmus" / path.name)
        before = set(dist.glob("*.whl"))
        subprocess.run([sys.executable, "-m", "pip", "wheel", "--no-deps", "--no-build-isolation",
                        "--quiet", "--wheel-dir", str(dist), str(staging)], check=True)
    made = set(dist.glob("*.whl")) - before
    if len(made) != 1:
        raise RuntimeError(f"pip wheel made {sorted(made)}, not one wheel")
    return made.pop()


def licenses(fmu, folder):
    """The FMU's documentation/licenses (every component linked in) and the project's."""
    folder.mkdir()
    with zipfile.ZipFile(fmu) as z:
        for name in z.namelist():
            if name.startswith("documentation/licenses/") and not name.endswith("/"):
                (folder / pathlib.PurePosixPath(name).name).write_bytes(z.read(name))


def checksums(dist):
    lines = [f"{hashlib.sha256(p.read_bytes()).hexdigest()}  {p.relative_to(dist).as_posix()}"
             for p in sorted(dist.rglob("*")) if p.is_file() and p.name != "SHA256SUMS"]
    (dist / "SHA256SUMS").write_text("\n".join(lines) + "\n")


def release(dist, build=ROOT / "build", systems=True):
    """Writes the release folder `dist` (emptied first) and returns it."""
    dist = pathlib.Path(dist)
    paths = fmus(pathlib.Path(build))
    if dist.exists():
        shutil.rmtree(dist)
    dist.mkdir(parents=True)
    for path in paths:
        shutil.copy2(path, dist / path.name)
    if systems:
        from contactbody import system
        system.write_ssp(system.belt_system(), dist / "belt_and_body.ssp", "BeltAndBody", 0.01)
        system.write_ssp(system.press_system(), dist / "press_and_body.ssp", "PressAndBody", 0.03)
    build_wheel(paths, dist)
    licenses(paths[0], dist / "licenses")
    checksums(dist)
    return dist


def main(argv):
    dist = release(argv[0] if argv else ROOT / "dist")
    for path in sorted(dist.iterdir()):
        size = sum(p.stat().st_size for p in path.rglob("*")) if path.is_dir() else path.stat().st_size
        print(f"{size / 1e6:8.2f} MB  {path.relative_to(dist.parent)}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
