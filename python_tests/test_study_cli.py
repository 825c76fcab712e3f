"""Study mistakes are caught before anything runs: each ends in one line
on stderr naming the file and the key, exit status 2, and no traceback (--debug shows one)."""
import os
import subprocess
import sys

import pytest

from conftest import FMU, ROOT, SANITIZED

# Runs that start a dask cluster: as test_study.py, not in the sanitizer job (its workers do
# not load the sanitized FMU); the mistakes are caught before any cluster starts.
with_cluster = pytest.mark.skipif(SANITIZED, reason="dask workers do not load the sanitized FMU")

GOOD = """stop_time = 0.002
output_interval = 1e-4
average_from = 0.001
[fixed]
nx = 10
ny = 10
[grid]
friction_coefficient = [0.1, 0.2]
"""


def study_cli(tmp_path, text, *extra, debug=False):
    path = tmp_path / "study.toml"
    path.write_text(text)
    env = dict(os.environ, CONTACTBODY_FMU=str(FMU),
               DASK_DISTRIBUTED__COMM__TIMEOUTS__CONNECT="2s")
    args = [sys.executable, "-m", "contactbody.cli", "run", str(path), "--out",
            str(tmp_path / "out"), "--no-progress", *extra] + (["--debug"] if debug else [])
    return subprocess.run(args, capture_output=True, text=True, cwd=ROOT, env=env, timeout=120)


MISTAKES = {
    "negative stop_time": (GOOD.replace("stop_time = 0.002", "stop_time = -0.002"),
                           ["stop_time", "must be > 0"]),
    "interval that does not divide": (GOOD.replace("1e-4", "3e-4"),
                                      ["output_interval", "must divide stop_time"]),
    "average_from = stop_time": (GOOD.replace("average_from = 0.001", "average_from = 0.002"),
                                 ["average_from", "at least one output interval"]),
    "misspelled parameter": (GOOD.replace("ny = 10", "damping_stiffnes = 4e-6"),
                             ["fixed.damping_stiffnes", "did you mean damping_stiffness"]),
    "not TOML": ("stop_time: 0.002\n", ["study.toml", "not a TOML file"]),
    "wrong enumeration name": (GOOD + "mass_matrix = ['redistributed_nromal']\n",
                               ["grid.mass_matrix", "did you mean 'redistributed_normal'"]),
    "value out of range": (GOOD.replace("nx = 10", "nx = 0"), ["fixed.nx", "out of range"]),
    "half a material pair": (GOOD.replace("ny = 10", "ny = 10\nyoungs_modulus = 4e8"),
                             ["point 1 of 2", "youngs_modulus and poisson_ratio go together"]),
    "material out of range": (GOOD.replace("ny = 10", "ny = 10\nyoungs_modulus = 4e8\n"
                                           "poisson_ratio = 0.5"), ["poisson_ratio must be in"]),
}


@pytest.mark.parametrize("mistake", MISTAKES)
def test_a_mistake_is_one_line_and_exit_2(tmp_path, mistake):
    text, words = MISTAKES[mistake]
    out = study_cli(tmp_path, text)
    assert out.returncode == 2, out.stderr
    assert "Traceback" not in out.stderr
    lines = out.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("contactbody-study: error: "), out.stderr
    for word in words:
        assert word in lines[0], (word, lines[0])
    assert not (tmp_path / "out" / "results.csv").exists()  # nothing ran


def test_an_unreachable_scheduler_is_one_line(tmp_path):
    out = study_cli(tmp_path, GOOD, "--scheduler", "tcp://127.0.0.1:9")
    assert out.returncode == 2 and "Traceback" not in out.stderr, out.stderr
    assert "cannot reach the dask scheduler tcp://127.0.0.1:9" in out.stderr


def test_debug_shows_the_traceback(tmp_path):
    out = study_cli(tmp_path, MISTAKES["negative stop_time"][0], debug=True)
    assert out.returncode != 0 and "Traceback" in out.stderr and "StudyError" in out.stderr


@pytest.fixture(scope="module")
def three_axes(tmp_path_factory):
    """A study table over F x V x beta (2 x 2 x 2 points, series kept)."""
    from contactbody.study import Study, run_study
    out = tmp_path_factory.mktemp("three_axes")
    study = Study(stop_time=0.002, output_interval=1e-4, average_from=0.001,
                  fixed={"nx": 10, "ny": 10},
                  grid={"friction_coefficient": [0.1, 0.3], "foundation_velocity": [1.0, 5.0],
                        "damping_stiffness": [2e-6, 4e-6]},
                  series=["energy", "friction_force"])
    run_study(study, out, fmu=FMU, workers=2, progress=False, dashboard=False)
    return out


def plot_cli(*args):
    return subprocess.run([sys.executable, "-m", "contactbody.cli", *map(str, args)],
                          capture_output=True, text=True, cwd=ROOT, timeout=120)


@with_cluster
def test_a_heatmap_refuses_to_average_over_a_third_axis(three_axes):
    """Fixed with --where, or shown with --facet; labelled with units."""
    args = ["plot", three_axes, "--heatmap", "foundation_velocity", "friction_coefficient",
            "friction_power"]
    out = plot_cli(*args)
    assert out.returncode == 2 and "Traceback" not in out.stderr
    assert "also varies damping_stiffness in [2e-06, 4e-06]" in out.stderr
    assert "--where damping_stiffness=VALUE" in out.stderr
    fixed = plot_cli(*args, "--where", "damping_stiffness=4e-6", "--output", three_axes / "a.png")
    assert fixed.returncode == 0 and (three_axes / "a.png").exists(), fixed.stderr
    faceted = plot_cli(*args, "--facet", "damping_stiffness", "--output", three_axes / "b.png")
    assert faceted.returncode == 0 and (three_axes / "b.png").exists(), faceted.stderr
    lines = plot_cli("plot", three_axes, "--lines", "foundation_velocity", "friction_power",
                     "--hue", "friction_coefficient")
    assert lines.returncode == 2 and "damping_stiffness" in lines.stderr


@with_cluster
def test_plots_label_their_axes_with_units(three_axes):
    from contactbody import plots
    units = plots.units_of(three_axes)
    assert plots.label("foundation_velocity", units) == "foundation_velocity [m/s]"
    assert plots.label("friction_power", units) == "friction_power [W/m]"
    assert plots.label("damping_stiffness", units) == "damping_stiffness [s]"
    assert plots.label("apparent_friction_ratio", units) == "apparent_friction_ratio"


@with_cluster
def test_the_series_command_plots_chosen_points_and_files_carry_their_values(three_axes):
    import json

    import numpy as np
    import pandas as pd
    out = plot_cli("series", three_axes, "energy,friction_force", "--where",
                   "damping_stiffness=4e-6", "--where", "foundation_velocity=5",
                   "--output", three_axes / "s.png")
    assert out.returncode == 0 and (three_axes / "s.png").exists(), out.stderr
    missing = plot_cli("series", three_axes, "normal_force")
    assert missing.returncode == 2 and "normal_force is not kept" in missing.stderr
    df = pd.read_parquet(three_axes / "results.parquet")
    row = df.iloc[0]
    point = json.loads(str(np.load(three_axes / "series" / f"{row['point_id']}.npz")["point"]))
    for name in ("friction_coefficient", "foundation_velocity", "damping_stiffness", "nx"):
        assert point[name] == row[name]


@with_cluster
def test_the_summary_lists_the_failed_points_with_their_messages(tmp_path):
    text = GOOD.replace("[grid]", "[[points]]\nfriction_coefficient = 0.3\n[[points]]\n"
                        "friction_coefficient = 20.0\nmass_matrix = 'redistributed_both'\n"
                        "min_internal_step = 4e-6\n[grid]").replace(
        "friction_coefficient = [0.1, 0.2]\n", "")
    text = text.replace("\n[grid]", "")
    out = study_cli(tmp_path, text, "--workers", "1")
    assert out.returncode == 1, out.stdout + out.stderr
    failed = [line for line in out.stdout.splitlines() if line.startswith("  failed: ")]
    assert len(failed) == 1, out.stdout
    assert "friction_coefficient = 20.0" in failed[0] and "contact solve failed" in failed[0]
