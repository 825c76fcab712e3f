"""Linear stability of steady sliding (build/sliding_stability, examples/sliding_stability.py):
no growing mode without friction, growing modes for F > 0 whose rate rises with refinement."""
import json
import pathlib
import subprocess

import pytest

PROGRAM = pathlib.Path(__file__).resolve().parents[1] / "build" / "sliding_stability"


def growth(nx, friction, variant=1):
    out = subprocess.run([str(PROGRAM), str(nx), repr(friction), str(variant)], check=True,
                         capture_output=True, text=True).stdout
    return json.loads(out)


@pytest.mark.parametrize("variant", [0, 1, 2])
def test_frictionless_sliding_has_no_growing_mode(variant):
    r = growth(10, 0.0, variant)
    assert r["growing_modes"] == 0 and r["max_growth_rate"] == 0
    assert r["min_real_omega2"] > 0  # symmetric definite pencil: real positive omega^2


def test_friction_growth_rate_rises_under_refinement():
    rates = [growth(nx, 1.2)["max_growth_rate"] for nx in (5, 10, 20)]
    assert rates[0] > 0 and rates[0] < rates[1] < rates[2], rates
    # The independent implementation's figure: about 2.5e4 /s at F = 1.2, h = 0.5 cm.
    assert 2e4 < rates[2] < 3e4, rates


def test_growth_rate_rises_with_friction():
    rates = [growth(20, F)["max_growth_rate"] for F in (0.2, 0.6, 1.2)]
    assert 0 < rates[0] < rates[1] < rates[2], rates


def damped(nx, friction, betas):
    out = subprocess.run([str(PROGRAM), str(nx), repr(friction), "1", *map(repr, betas)],
                         check=True, capture_output=True, text=True).stdout
    return [d["max_growth_rate"] for d in json.loads(out)["damped"]]


def test_stiffness_damping_stabilizes_moderate_friction_on_both_meshes():
    """The damping issue's figures for C = beta A (from an independent solve of the damped
    pencil): F = 0.3, h = 0.5 cm: 1.25e3, 5.2e2, -51 /s at beta = 0, 1e-6, 4e-6 s; and -52 /s
    at h = 1 cm, where the least-damped mode is the same."""
    fine = damped(20, 0.3, [0.0, 1e-6, 4e-6])
    assert fine[0] == pytest.approx(1.25e3, rel=1e-2)
    assert fine[1] == pytest.approx(5.2e2, rel=1e-2)
    assert fine[2] == pytest.approx(-51, rel=2e-2)
    assert damped(10, 0.3, [4e-6])[0] == pytest.approx(-52, rel=2e-2)


def test_large_friction_stays_unstable_with_damping_but_no_longer_worsens_with_refinement():
    """F = 1.2, beta = 4e-6 s: 3.2e3 /s at h = 1 cm, 2.8e3 /s at h = 0.5 cm (2.48e4 undamped)."""
    coarse, fine = damped(10, 1.2, [4e-6])[0], damped(20, 1.2, [0.0, 4e-6])
    assert coarse == pytest.approx(3.2e3, rel=1e-2)
    assert fine[1] == pytest.approx(2.8e3, rel=1e-2)
    assert fine[1] < coarse < fine[0] / 5
