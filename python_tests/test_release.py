"""The release folder (contactbody.tools.release, scripts/release.sh) and its wheel: installed into a
fresh virtual environment that has only pip, with no checkout on sys.path and nothing compiled
(only binary wheels), it runs README's quick start and a two-point study with
contactbody-study, and gets the numbers the checkout gets."""
import hashlib
import json
import os
import pathlib
import subprocess
import venv
import zipfile

import pandas as pd
import pytest

from conftest import FMU, ROOT, SANITIZED
from contactbody.tools.release import FMUS, release
from test_quick_start import quick_start

pytestmark = pytest.mark.skipif(SANITIZED, reason="the release is made of the portable FMUs")

STUDY = ["run", "--stop-time", "0.002", "--output-interval", "1e-4", "--set",
         "damping_stiffness=4e-6", "--grid", "friction_coefficient=0.1,0.3", "--workers", "1"]
PRINTS = 'print(repr(float(r["energy"].max())), repr(float(r["normal_force"][-1])))'


@pytest.fixture(scope="module")
def dist(tmp_path_factory):
    return release(tmp_path_factory.mktemp("dist") / "dist", systems=False)


@pytest.fixture(scope="module")
def fresh(dist, tmp_path_factory):
    """A new virtual environment with only pip, the wheel installed into it (its dependencies
    at the versions requirements.txt pins, binary wheels only), and an environment that points
    nowhere near the checkout."""
    home = tmp_path_factory.mktemp("fresh")
    venv.EnvBuilder(with_pip=True).create(home / "venv")
    python = home / "venv" / "bin" / "python"
    wheel = next(dist.glob("contactbody-*.whl"))
    subprocess.run([str(python), "-m", "pip", "install", "--quiet", "--only-binary=:all:",
                    "--constraint", str(ROOT / "requirements.txt"), str(wheel)], check=True,
                   cwd=home)
    env = {k: v for k, v in os.environ.items()
           if k not in ("PYTHONPATH", "CONTACTBODY_FMU", "VIRTUAL_ENV")}
    return python, env, home


def test_the_release_holds_the_fmus_the_wheel_and_checksums(dist):
    names = {p.name for p in dist.iterdir()}
    assert {f"{n}.fmu" for n in FMUS} | {"SHA256SUMS", "licenses"} <= names
    for line in (dist / "SHA256SUMS").read_text().splitlines():
        digest, name = line.split("  ", 1)
        assert hashlib.sha256((dist / name).read_bytes()).hexdigest() == digest, name
    assert {"LICENSE", "CHOLMOD-LGPL-2.1.txt", "libcxx-LICENSE.txt"} <= {
        p.name for p in (dist / "licenses").iterdir()}
    wheel = next(dist.glob("contactbody-*.whl"))
    assert wheel.name.endswith("-py3-none-any.whl")  # pure Python: the binaries are FMU data
    with zipfile.ZipFile(wheel) as z:
        packed = {n: z.read(n) for n in z.namelist() if n.startswith("contactbody/fmus/")}
        # the user's API only: the repository tooling (contactbody/tools) stays in the checkout
        assert not [n for n in z.namelist() if n.startswith("contactbody/tools/")]
        assert "contactbody/fmu.py" in z.namelist()
        assert "Root-Is-Purelib: true" in z.read(
            next(n for n in z.namelist() if n.endswith(".dist-info/WHEEL"))).decode()
    assert sorted(packed) == sorted(f"contactbody/fmus/{n}.fmu" for n in FMUS)
    assert packed["contactbody/fmus/ContactBody.fmu"] == FMU.read_bytes()


def test_auditwheel_finds_no_platform_binary_in_the_wheel(dist):
    """auditwheel judges the ELF files a wheel holds: this one holds none outside the FMUs."""
    wheel = next(dist.glob("contactbody-*.whl"))
    out = subprocess.run([str(ROOT / ".venv" / "bin" / "auditwheel"), "show", str(wheel)],
                         capture_output=True, text=True)
    assert "platform wheel" in (out.stdout + out.stderr) and "manylinux" not in out.stdout, \
        out.stdout + out.stderr


def test_the_installed_wheel_runs_the_quick_start_as_the_checkout(fresh):
    python, env, home = fresh
    code = quick_start() + PRINTS + "\nimport contactbody; print(contactbody.find_fmu())\n"
    done = subprocess.run([str(python), "-c", code], capture_output=True, text=True, env=env,
                          cwd=home, check=True)
    lines = done.stdout.strip().splitlines()
    (energy, force), where = lines[-2].split(), lines[-1]
    assert pathlib.Path(where).is_relative_to(home / "venv")  # the wheel's FMU, no checkout
    scope = {}
    exec(compile(quick_start(), "README quick start", "exec"), scope)
    r = scope["r"]
    assert (float(energy), float(force)) == (float(r["energy"].max()), float(r["normal_force"][-1]))


def test_the_installed_wheel_runs_a_study_as_the_checkout(fresh, tmp_path):
    python, env, home = fresh
    tables = {}
    for name, cli in (("wheel", home / "venv" / "bin" / "contactbody-study"),
                      ("checkout", ROOT / ".venv" / "bin" / "contactbody-study")):
        out = tmp_path / name
        subprocess.run([str(cli), *STUDY, "--out", str(out)], check=True, env=env, cwd=home,
                       capture_output=True, text=True)
        tables[name] = pd.read_csv(out / "results.csv").sort_values("friction_coefficient")
        assert json.loads((out / "study.json").read_text())
    wheel, checkout = tables["wheel"], tables["checkout"]
    assert len(wheel) == 2 and list(wheel.columns) == list(checkout.columns)
    numbers = [c for c in wheel.columns if pd.api.types.is_float_dtype(wheel[c])
               and c not in ("wall_time", "dostep_time")]  # the clock's, not the model's
    assert len(numbers) >= 5
    pd.testing.assert_frame_equal(wheel[numbers].reset_index(drop=True),
                                  checkout[numbers].reset_index(drop=True), check_exact=True)
