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
