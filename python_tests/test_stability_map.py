"""The FMU's map of its measured unstable regions is a committed header next to the code that
reads it (solver/simulation/stability_map_data.hpp), written by an explicit command from the examples'
results (scripts/write_stability_map.py); the C++ build needs no Python package for it, nor
the FMI headers from fmpy (third_party/fmi-headers-2.0-3.0)."""
import filecmp
import pathlib
import shutil
import subprocess
import sys

import fmpy
import pytest

from conftest import ROOT

sys.path.insert(0, str(ROOT / "scripts"))
import write_stability_map  # noqa: E402


def test_the_committed_map_is_what_the_examples_measured():
    committed = (ROOT / "solver" / "simulation" / "stability_map_data.hpp").read_text()
    assert committed == write_stability_map.text(), (
        "solver/simulation/stability_map_data.hpp differs from examples/results: run "
        ".venv/bin/python scripts/write_stability_map.py")


def test_the_vendored_fmi_headers_are_fmpys():
    vendored = ROOT / "third_party" / "fmi-headers-2.0-3.0"
    shipped = pathlib.Path(fmpy.__file__).parent / "c-code"
    headers = sorted(p.name for p in vendored.glob("*.h"))
    assert headers == sorted(p.name for p in shipped.glob("fmi[23]*.h"))
    for name in headers:
        assert filecmp.cmp(vendored / name, shipped / name, shallow=False), name
    assert "BSD-2-Clause" in (vendored / "LICENSE.txt").read_text()


@pytest.mark.skipif(not pathlib.Path("/usr/bin/python3").exists(), reason="needs Debian's python3")
def test_the_build_configures_with_a_python_that_has_no_plotting_stack(tmp_path):
    """Debian's python3 has neither matplotlib nor fmpy (asserted): the native build's
    configure step succeeds with it (the portable one also needs zig's package, ziglang)."""
    python = "/usr/bin/python3"
    for package in ("matplotlib", "fmpy"):
        assert subprocess.run([python, "-c", f"import {package}"], capture_output=True).returncode != 0
    out = subprocess.run([shutil.which("cmake", path="/usr/bin") or "cmake", "-S", str(ROOT),
                          "-B", str(tmp_path / "build"), "-G", "Ninja",
                          "-DCONTACTBODY_PORTABLE=OFF", f"-DPython3_EXECUTABLE={python}"],
                         capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stdout[-3000:] + out.stderr[-3000:]
