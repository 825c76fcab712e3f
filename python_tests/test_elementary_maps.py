"""Section 6 (paper Figs. 3-5) through examples/figures_3_5.py on a coarse grid: the contact
solver's solution sets equal the closed forms', and several solutions appear only where the
paper says (F > c/b: tangential mass removed, or dt beyond dt_0)."""
import json
import pathlib
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[1]


@pytest.fixture(scope="module")
def maps(tmp_path_factory):
    out = tmp_path_factory.mktemp("maps")
    subprocess.run([sys.executable, str(ROOT / "examples" / "figures_3_5.py"), "--points", "61",
                    "--out", str(out)], check=True, capture_output=True)
    assert (out / "figures_3_5.png").stat().st_size > 0
    return json.loads((out / "figures_3_5.json").read_text())


def test_normal_redistribution_has_one_solution_everywhere(maps):
    s = maps["normal"]
    assert s["c_over_b"] > s["friction"]
    assert s["agree"] == s["points"] == s["one_solution"]
    assert s["failed_starts"] == 0          # Newton converges from every start
    assert s["max_violation"] < 1e-12


@pytest.mark.parametrize("case", ["tangential", "both", "normal_long_step"])
def test_friction_above_c_over_b_gives_three_solutions_found_by_the_solver(maps, case):
    s = maps[case]
    assert s["friction"] > s["c_over_b"]
    assert s["three_solutions"] > 0
    assert s["max_violation"] < 1e-12        # every solution found solves (23)
    # Where the solver's set differs from the closed form's, the point lies on the line
    # c f_nu + b f_tau = 0 up to rounding (the grazing solution S1 with u_nu = 0).
    assert s["disagree_max_boundary_distance"] < 1e-12
    assert s["agree"] == s["points"] - len(s["disagree_points"])


def test_critical_friction_has_a_segment_of_solutions_on_sigma_5(maps):
    s = maps["critical"]
    assert s["friction"] == pytest.approx(s["c_over_b"], rel=1e-15)
    assert s["continuum_points"] > 0
    assert s["three_solutions"] == 0 and s["agree"] == s["points"]
