"""With a slip-rate law the initialization warning places F and dF/dv at the sliding speed on
the measured rate map (examples/results/rate_stability.json: F x dF/dv x beta), and says
plainly when the setting lies outside it (docs/contract.md, "Warnings and guards").

The law is the rate map's own FMU check: F(5 m/s) = F(1 m/s) = 0.5 with dF/dv = +0.05 s/m at
5 m/s and -0.15 s/m at 1 m/s (nx = 10, beta = 4e-6 s). The FMU measured steady sliding decay
at 5 m/s (-125 /s) and grow at 1 m/s (+198 /s): the warning must be silent at the first and
speak at the second."""
import json

import pytest

from conftest import ROOT
from test_warnings import at_init, run

CHECK = json.loads((ROOT / "examples" / "results" / "rate_stability.json").read_text())["fmu_check"]
LAW = {**CHECK["law"], "damping_stiffness": CHECK["beta"]}
MESH = {"nx": CHECK["nx"], "ny": CHECK["nx"]}


def warned(model_description, unzipped, vr, reals):
    return at_init(run(model_description, unzipped, vr, reals, MESH))


def test_the_measured_decaying_speed_is_not_warned_about(model_description, unzipped, vr):
    assert CHECK["measured"][0] < 0 and CHECK["speeds"][0] == 5.0
    assert warned(model_description, unzipped, vr, {**LAW, "foundation_velocity": 5.0}) == []


def test_the_measured_growing_speed_is_warned_about(model_description, unzipped, vr):
    assert CHECK["measured"][1] > 0 and CHECK["speeds"][1] == 1.0
    warnings = warned(model_description, unzipped, vr, {**LAW, "foundation_velocity": -1.0})
    assert len(warnings) == 1, warnings
    text = warnings[0]
    assert "sliding speed |foundation_velocity| = 1 m/s" in text and "dF/dv = -0.15" in text
    assert "unstable on the rate map" in text and "stable with" in text


def test_without_the_law_the_same_scene_is_judged_by_the_constant_map(model_description,
                                                                      unzipped, vr):
    """F = 0.5 constant at beta = 4e-6 s, h = 1 cm is stable on the damped map: no warning,
    so the warning above comes from dF/dv < 0."""
    assert warned(model_description, unzipped, vr, {"friction_coefficient": 0.5,
                                                    "damping_stiffness": CHECK["beta"],
                                                    "foundation_velocity": 1.0}) == []


@pytest.mark.parametrize("speed", [0.05, 20.0])
def test_outside_the_map_it_says_so(model_description, unzipped, vr, speed):
    """At 0.05 m/s the Stribeck drop gives dF/dv = -0.43 s/m, below the map's -0.2: the warning
    says the setting is outside the map and that dF/dv < 0 destabilizes (the map: every point
    grows at dF/dv = -0.1 s/m). At 20 m/s F = 1.33 (the viscous term), above the map's 1.2,
    where the constant map finds no steady state."""
    warnings = warned(model_description, unzipped, vr, {**LAW, "foundation_velocity": speed})
    assert len(warnings) == 1, warnings
    assert warnings[0].startswith("fmi2ExitInitializationMode: settings outside the measured maps")
    if speed < 1:
        assert "dF/dv < 0 destabilizes: on the rate map dF/dv = -0.1 s/m made every" in warnings[0]
    else:
        assert "no steady sliding state exists" in warnings[0]
