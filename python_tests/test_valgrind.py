"""Issue 5 item 3: one simulation through a minimal C++ host under valgrind: no memory error,
no definite or indirect leak."""
import pathlib
import shutil
import subprocess

from conftest import ROOT, SANITIZED

import pytest


@pytest.mark.skipif(SANITIZED, reason="valgrind does not run sanitizer builds")
def test_one_simulation_under_valgrind_has_no_error_and_no_leak(unzipped, model_description):
    valgrind = shutil.which("valgrind")
    assert valgrind, "valgrind is not installed (scripts/setup.sh installs it)"
    host = ROOT / "build" / "fmu_host"
    library = pathlib.Path(unzipped) / "binaries" / "linux64" / "ContactBody.so"
    out = subprocess.run([valgrind, "--error-exitcode=99", "--leak-check=full",
                          f"--suppressions={ROOT / 'tests_cpp' / 'valgrind.supp'}",
                          "--errors-for-leak-kinds=definite,indirect",
                          "--show-leak-kinds=definite,indirect", str(host), str(library),
                          model_description.guid], capture_output=True, text=True, timeout=600)
    assert out.returncode == 0, out.stderr[-4000:]
    assert "ERROR SUMMARY: 0 errors" in out.stderr
