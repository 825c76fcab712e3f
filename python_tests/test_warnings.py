"""The FMU knows its own map: at initialization one warning
(logStatusWarning) when the settings lie in a region the project measured unstable, naming the
setting to change; during the run a warning when the contact creates energy, and when the top
travels beyond the body's height; an error where nothing sensible can follow. Silent on the
recommended settings. Warnings reach the logger with logging off (docs/contract.md)."""
import json
import pathlib
import sys

import numpy as np
import pytest
from fmpy.fmi1 import FMICallException

from conftest import ROOT, Instance

sys.path.insert(0, str(ROOT / "examples"))
from damped_stability import critical_beta  # noqa: E402

WARNING = 1


def run(model_description, unzipped, vr, reals=None, integers=None, steps=0, h=1e-4,
        inputs=None):
    """Initializes (and steps) an instance; returns its warnings as (function, text) and the
    instance's messages."""
    inst = Instance(model_description, unzipped, "warnings")
    try:
        inst.setupExperiment(startTime=0)
        inst.enterInitializationMode()
        for name, value in (reals or {}).items():
            inst.setReal([vr[name]], [value])
        for name, value in (integers or {}).items():
            inst.setInteger([vr[name]], [value])
        inst.exitInitializationMode()
        for k in range(steps):
            for name, value in (inputs or {}).items():
                inst.setReal([vr[name]], [value(k * h)])
            inst.doStep(k * h, h)
        warnings = [m for m in inst.messages if m[0] == WARNING]
        assert all(category == "logStatusWarning" for _, category, _ in warnings)
        return [text for _, _, text in warnings]
    finally:
        inst.close()


def at_init(warnings):
    return [w for w in warnings if w.startswith("fmi2ExitInitializationMode")]


DAMPED = json.loads((ROOT / "examples" / "results" / "damped_stability.json").read_text())


def test_the_paper_scene_is_warned_about_and_the_recommended_settings_are_not(
        model_description, unzipped, vr):
    default = run(model_description, unzipped, vr)
    assert len(default) == 1 and "friction_coefficient = 1.2" in default[0]
    row = next(r for r in DAMPED["rows"] if r["nx"] == 20 and r["friction"] == 1.2)
    assert f"set damping_stiffness >= {critical_beta(row['growth']):g} s" in default[0], default
    for nx in (5, 10, 20, 40):  # README: beta = 4e-6 s stabilizes F <= 0.3 on every mesh
        assert run(model_description, unzipped, vr, {"friction_coefficient": 0.3,
                                                     "damping_stiffness": 4e-6},
                   {"nx": nx, "ny": nx}) == [], nx


@pytest.mark.parametrize("nx, friction", [(5, 0.2), (10, 0.4), (20, 0.5), (40, 0.5), (20, 0.7)])
def test_the_sliding_warning_follows_the_measured_damped_map(model_description, unzipped, vr,
                                                             nx, friction):
    """Just below the smallest stabilizing beta of examples/results/damped_stability.json a
    warning naming it; at it, none. On a body twice the paper's size (with the same material)
    the map's beta doubles: beta scales with H / c_p."""
    row = next(r for r in DAMPED["rows"] if r["nx"] == nx and r["friction"] == friction)
    beta = critical_beta(row["growth"])
    for size in (1, 2):
        reals = {"friction_coefficient": friction, "width": 0.1 * size, "height": 0.1 * size}
        below = run(model_description, unzipped, vr, {**reals, "damping_stiffness":
                                                      0.99 * beta * size}, {"nx": nx, "ny": nx})
        assert len(below) == 1 and f"damping_stiffness >= {beta * size:g} s" in below[0], below
        assert run(model_description, unzipped, vr, {**reals, "damping_stiffness": beta * size},
                   {"nx": nx, "ny": nx}) == []


def test_friction_without_a_steady_sliding_state_is_warned_at_every_damping(
        model_description, unzipped, vr):
    """F >= 1.3: the map finds no admissible steady sliding state on any
    mesh, so no damping helps; F = 1.2 has one, and the map's beta stabilizes it."""
    assert all(r["growth"] is None for r in DAMPED["rows"] if r["friction"] >= 1.3)
    for beta in (0.0, 4e-6, 1e-5):
        warnings = run(model_description, unzipped, vr, {"friction_coefficient": 1.5,
                                                         "damping_stiffness": beta})
        assert len(warnings) == 1 and "no steady sliding state exists" in warnings[0], warnings
    assert run(model_description, unzipped, vr, {"friction_coefficient": 1.2,
                                                 "damping_stiffness": 1e-5}) == []


def test_between_measured_frictions_the_larger_beta_is_asked_for(model_description, unzipped,
                                                                  vr):
    """The map is not monotone in F (about the admissible state the contact set changes with
    F), so between two measured rows the warning asks for the larger of their betas."""
    rows = {r["friction"]: critical_beta(r["growth"]) for r in DAMPED["rows"] if r["nx"] == 5}
    needed = max(rows[0.4], rows[0.5])
    assert rows[0.4] != rows[0.5]
    below = run(model_description, unzipped, vr, {"friction_coefficient": 0.45,
                                                  "damping_stiffness": 0.99 * needed},
                {"nx": 5, "ny": 5})
    assert len(below) == 1 and f"damping_stiffness >= {needed:g} s" in below[0], below
    assert run(model_description, unzipped, vr, {"friction_coefficient": 0.45,
                                                 "damping_stiffness": needed},
               {"nx": 5, "ny": 5}) == []


FRICTIONLESS = {"friction_coefficient": 0.0, "foundation_velocity": 0.0, "lambda": 1.5e9}


def test_frictionless_midpoint_contact_is_warned_where_the_map_measured_growth(
        model_description, unzipped, vr):
    """lambda/mu = 10 at Courant 1.07 (internal_step 4e-6 s): the map measured 12.8 x E(0)
    for variant 1 and 5.8 x for variant 2; variant 4 cannot gain, lambda/mu = 2 does not."""
    for variant in (0, 1, 2):
        warnings = run(model_description, unzipped, vr, FRICTIONLESS, {"mass_matrix": variant})
        assert len(warnings) == 1, (variant, warnings)
        assert f"mass_matrix = {variant} gains energy" in warnings[0]
        assert "mass_matrix = 4" in warnings[0]
    assert run(model_description, unzipped, vr, FRICTIONLESS, {"mass_matrix": 4}) == []
    assert run(model_description, unzipped, vr, {**FRICTIONLESS, "lambda": 300e6}) == []


def test_the_run_warns_once_when_the_contact_creates_energy(model_description, unzipped, vr):
    """Variant 1 at lambda/mu = 10: the normal contact work passes 1 % of E(0) within 20 ms
    (and grows 30-fold, test_frictionless_stability.py); variant 4 stays silent."""
    warnings = run(model_description, unzipped, vr, FRICTIONLESS, {"mass_matrix": 1}, steps=200)
    during = [w for w in warnings if w.startswith("fmi2DoStep")]
    assert len(during) == 1 and "normal_contact_work" in during[0], warnings
    assert run(model_description, unzipped, vr, FRICTIONLESS, {"mass_matrix": 4}, steps=200) == []


def test_recommended_settings_run_without_a_word(model_description, unzipped, vr):
    """F = 0.3, beta = 4e-6 s, the paper's sliding at 20 m/s over 20 ms: no warning at all."""
    assert run(model_description, unzipped, vr, {"friction_coefficient": 0.3,
                                                 "damping_stiffness": 4e-6}, steps=200) == []


def test_top_travel_beyond_the_height_warns_and_below_the_foundation_fails(
        model_description, unzipped, vr):
    lifted = run(model_description, unzipped, vr, {"friction_coefficient": 0.0}, steps=3,
                 inputs={"top_displacement": lambda t: 0.15})  # 1.5 x the height, up
    assert len(lifted) == 1 and "more than the body's height" in lifted[0]
    inst = Instance(model_description, unzipped, "pressed")
    try:
        inst.setupExperiment(startTime=0)
        inst.enterInitializationMode()
        inst.exitInitializationMode()
        inst.doStep(0.0, 1e-4)
        inst.setReal([vr["top_displacement"]], [-0.5])  # 5 x the height, into the foundation
        with pytest.raises(FMICallException) as failure:
            inst.doStep(1e-4, 1e-4)
        assert failure.value.status == 3
        assert "at or below the foundation" in inst.text()
        assert "compressed to nothing" in inst.text()
    finally:
        inst.close()


@pytest.mark.parametrize("variant, ratio, courant", [(1, 100, 0.61), (2, 16.7, 47)])
def test_the_sweeps_frictionless_findings_are_warned_about(model_description, unzipped, vr,
                                                          variant, ratio, courant):
    """The stress sweep: variant 1 gained below Courant 1 (lambda/mu = 100, Courant 0.61), and
    redistributed_both gained without friction (lambda/mu = 16.7, Courant 47)."""
    mu, rho, h = 150e6, 1000.0, 0.005
    dt = courant * h / np.sqrt((ratio + 2) * mu / rho)
    warnings = run(model_description, unzipped, vr,
                   {**FRICTIONLESS, "lambda": ratio * mu, "internal_step": dt},
                   {"mass_matrix": variant})
    assert len(warnings) == 1 and f"mass_matrix = {variant} gains energy" in warnings[0]
