"""One simulation through a minimal C++ host under valgrind: no memory error,
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


@pytest.mark.skipif(SANITIZED, reason="valgrind does not run sanitizer builds")
def test_the_fmi3_layer_under_valgrind_has_no_error_and_no_leak(tmp_path, model_description):
    """fmi3_host through the FMI 3.0 entry points: nx = 10 set in Configuration Mode, ten
    steps reading scalars and edge arrays, a state restored from its bytes and saved again."""
    valgrind = shutil.which("valgrind")
    host = ROOT / "build" / "fmi3_host"
    library = ROOT / "build" / "fmu" / "ContactBody_fmi3" / "binaries" / "x86_64-linux" / "ContactBody.so"
    common = [valgrind, "--error-exitcode=99", "--leak-check=full",
              f"--suppressions={ROOT / 'tests_cpp' / 'valgrind.supp'}",
              "--errors-for-leak-kinds=definite,indirect",
              "--show-leak-kinds=definite,indirect", str(host), str(library),
              model_description.guid, "10"]
    arrays = ["100:1", "131:11", "132:11", "134:11"]
    first = subprocess.run(common + ["-", "0", "5", "1e-4", str(tmp_path / "a.txt"),
                                     str(tmp_path / "a.bin")] + arrays,
                           capture_output=True, text=True, timeout=600)
    assert first.returncode == 0, first.stderr[-4000:]
    second = subprocess.run(common + [str(tmp_path / "a.bin"), "5e-4", "5", "1e-4",
                                      str(tmp_path / "b.txt"), str(tmp_path / "b.bin")] + arrays,
                            capture_output=True, text=True, timeout=600)
    assert second.returncode == 0, second.stderr[-4000:]
    for out in (first, second):
        assert "ERROR SUMMARY: 0 errors" in out.stderr
    rows = (tmp_path / "b.txt").read_text().splitlines()
    assert len(rows) == 5 and all(len(r.split()) == 34 for r in rows)
