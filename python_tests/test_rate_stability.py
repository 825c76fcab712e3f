"""Stability of steady sliding with dF/dv (build/sliding_stability --slope,
examples/rate_stability.py), about the admissible steady state (--lift-off), and two points of
the map checked against the FMU."""
import json
import pathlib
import subprocess
import sys

import fmpy
import numpy as np
import pytest

from conftest import FMU

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "examples"))
from rate_stability import envelope_rate, fmu_check, friction_law, growth_rates, law_through  # noqa: E402

PROGRAM = ROOT / "build" / "sliding_stability"


def analyse(*args):
    return json.loads(subprocess.run([str(PROGRAM), *map(str, args)], check=True,
                                     capture_output=True, text=True).stdout)


def test_the_full_contact_state_pulls_on_nodes_and_the_admissible_one_does_not():
    """The full-contact linearization kept every node touching; with friction its steady reactions
    pull (F = 0.3: the last node; F = 0.8: half the edge). --lift-off lifts them."""
    for F, lifted in ((0.0, 0), (0.3, 1), (0.8, 5)):
        full, admissible = analyse(10, F, 1), analyse("--lift-off", 10, F, 1)
        assert (full["min_pressure"] < 0) == (lifted > 0), (F, full["min_pressure"])
        assert admissible["min_pressure"] >= 0
        assert len(admissible["lifted_nodes"]) == lifted, admissible["lifted_nodes"]


def test_the_slope_path_meets_the_proportional_one_as_the_slope_vanishes():
    """With dF/dv the damping is no longer proportional and each beta solves the quadratic
    pencil's companion matrix; at dF/dv = 1e-12 s/m it must give the rates that the undamped
    eigenvalues give exactly at 0."""
    betas = (4e-6, 1e-5)
    exact = analyse("--lift-off", 10, 0.8, 1, *betas)["damped"]
    companion = analyse("--lift-off", "--slope=1e-12", 10, 0.8, 1, *betas)["damped"]
    for a, b in zip(exact, companion):
        assert b["max_growth_rate"] == pytest.approx(a["max_growth_rate"], rel=1e-6)


def test_the_slope_enters_with_the_normal_load():
    """D = F' p_i and p_i is linear in the clamp's displacement: halving the displacement and
    doubling the slope is the same pencil."""
    a = growth_rates(10, 0.5, 0.1, [4e-6], top=-2.5e-5)["growth"][0]
    b = growth_rates(10, 0.5, 0.2, [4e-6], top=-1.25e-5)["growth"][0]
    assert b == pytest.approx(a, rel=1e-9)


def test_velocity_strengthening_stabilizes_and_weakening_destabilizes():
    """F = 0.8 and 1.2 at beta = 4e-6 s, h = 1 cm: the growth rate falls as dF/dv rises,
    weakening (-0.1 s/m) grows, strengthening (0.1 s/m) decays."""
    for F in (0.8, 1.2):
        rates = [growth_rates(10, F, s, [4e-6])["growth"][0] for s in (-0.1, 0.0, 0.1)]
        assert rates[0] > 0 > rates[2] and rates[0] > rates[1] > rates[2], (F, rates)


def test_the_fmu_settles_in_the_admissible_steady_state_at_the_predicted_rate():
    """F = 0.8, beta = 4e-6 s, h = 1 cm, constant F: the full-contact map called this
    unstable; about the admissible state (5 nodes lifted) it decays at about -29 /s. The FMU
    ends with the same nodes touching, the same normal force to 1e-3 (averaged over its last
    10 ms, six periods of the mode still decaying), and its kinetic
    energy's envelope decays at the predicted rate within 20 %."""
    predicted = growth_rates(10, 0.8, 0.0, [4e-6])
    r = fmpy.simulate_fmu(str(FMU), stop_time=0.2, output_interval=2e-5, start_values={
        "friction_coefficient": 0.8, "nx": 10, "ny": 10, "damping_stiffness": 4e-6,
        "initial_state": 1}, output=["kinetic_energy", "normal_force", "active_contact_nodes"])
    assert r["active_contact_nodes"][-1] == 11 - len(predicted["lifted_nodes"])
    last = r["time"] > 0.19
    assert np.mean(r["normal_force"][last]) == pytest.approx(predicted["normal_force"], rel=1e-3)
    rate = envelope_rate(r["time"], r["kinetic_energy"], 0.1, 0.2,
                         4 / predicted["frequency_hz"][0])
    assert predicted["growth"][0] < 0
    assert rate == pytest.approx(predicted["growth"][0], rel=0.2)


def test_two_points_of_the_map_against_the_fmu():
    """F(5 m/s) = F(1 m/s) = 0.5 with dF/dv = 0.05 and -0.15 s/m there (beta = 4e-6 s,
    h = 1 cm): the map predicts decay at the first speed and growth at the second. The FMU
    settles at 5 m/s (bounded: its kinetic energy falls by orders of magnitude) at the
    predicted rate within 20 %, and after the switch to 1 m/s grows at the predicted rate
    within 20 %."""
    c = fmu_check(fmu=FMU)
    np.testing.assert_allclose(c["law_at_speeds"], 0.5, rtol=1e-12)
    decay, growth = c["predicted"]
    assert decay < 0 < growth
    assert c["measured"][0] == pytest.approx(decay, rel=0.2)
    assert c["measured"][1] == pytest.approx(growth, rel=0.2)
    ke = c["kinetic_energy_at"]
    assert ke["switch"] < 1e-2 * ke["settle/2"] and ke["end"] > 1e4 * ke["switch"]
    assert c["fmu_active_nodes_before_switch"] == c["touching_nodes"]
    assert c["fmu_normal_force_before_switch"] == pytest.approx(c["steady_normal_force"],
                                                                rel=1e-3)


def test_the_law_through_two_slopes():
    law = law_through(0.5, 5.0, 0.05, 1.0, -0.15)
    v = np.array([1.0, 5.0])
    np.testing.assert_allclose(friction_law(v, **law), 0.5, rtol=1e-12)
    slope = (friction_law(v + 1e-6, **law) - friction_law(v - 1e-6, **law)) / 2e-6
    np.testing.assert_allclose(slope, [-0.15, 0.05], rtol=1e-6)


def test_beyond_the_last_steady_state_the_foundation_wedges_the_body():
    """F = 1.5: the active sets find no admissible steady state (they cycle), and in the FMU
    (beta = 1e-5 s, h = 1 cm) the normal force keeps growing, past 1000 x the frictionless
    one, with two nodes touching."""
    run = subprocess.run([str(PROGRAM), "--lift-off", "10", "1.5", "1"], capture_output=True,
                         text=True)
    assert run.returncode == 1 and "no admissible steady contact set" in run.stderr
    r = fmpy.simulate_fmu(str(FMU), stop_time=0.1, output_interval=1e-3, start_values={
        "friction_coefficient": 1.5, "nx": 10, "ny": 10, "damping_stiffness": 1e-5,
        "initial_state": 1}, output=["normal_force", "active_contact_nodes"])
    n = r["normal_force"]
    assert n[-1] > 3 * n[30] > 1000 * 1.17e4
    assert np.all(np.diff(n[30:]) > 0)
    assert r["active_contact_nodes"][-1] == 2
