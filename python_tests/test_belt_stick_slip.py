"""A stick-slip limit cycle in the belt-drive system (examples/system/
stick_slip.py): BeltDrive's speed-controlled motor drives the belt under the body through a
compliant shaft, the interface is a Stribeck law (F_s = 0.6 -> F_d = 0.3 over 0.3 m/s)."""
import pathlib
import sys

import numpy as np
import pytest

from conftest import SANITIZED

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "examples" / "system"))
from stick_slip import BELT, DRIVE_SPEED, LAW, cycles, run, summary  # noqa: E402

pytestmark = pytest.mark.skipif(SANITIZED, reason="runs the uninstrumented build's FMUs")


@pytest.fixture(scope="module")
def runs():
    return {step: run(step, 3.125e-6, 10, stop=0.3) for step in (5e-5, 2.5e-5)}


def test_the_belt_sticks_breaks_loose_at_the_static_friction_and_repeats(runs):
    """Every cycle has a stick phase (the belt below 5 % of the drive speed), the friction
    ratio reaches F_s = 0.6 before the edge breaks loose and never passes it, the belt then
    overshoots to twice the drive speed; the cycles repeat to 2 % in period."""
    r, _ = runs[2.5e-5]
    c = cycles(r)
    assert len(c) >= 3
    for x in c:
        assert x["stuck"] > 1e-3 and x["lowest"] < 0.05 * DRIVE_SPEED, x
        assert 0.58 < x["max_ratio"] <= 0.6 + 1e-9, x
        assert x["peak"] > 2 * DRIVE_SPEED, x
    period = np.array([x["period"] for x in c])
    assert period.std() < 0.02 * period.mean()
    assert LAW["static_friction_ratio"] * LAW["friction_coefficient"] == 0.6


def test_the_speed_controller_holds_the_drive_speed_less_its_droop(runs):
    """Over whole cycles the motor's mean torque is the shaft's, so the mean belt speed is
    r (setpoint - <shaft torque> / gain) (proportional droop), to 0.5 %."""
    r, _ = runs[2.5e-5]
    s = summary(r, 0.0)
    expected = 0.05 * (BELT["speed_setpoint"] - s["mean_shaft_torque"] / BELT["speed_gain"])
    assert s["mean_belt_speed"] == pytest.approx(expected, rel=5e-3)
    assert s["mean_belt_speed"] < DRIVE_SPEED


def test_the_period_settles_under_the_coupling_step(runs):
    """Halving the coupling step from 5e-5 to 2.5e-5 s moves the mean period by less than 1 %
    (examples/results/stick_slip.md: 46.27 and 46.38 ms over 1.5 s)."""
    coarse, fine = (summary(runs[h][0], 0.0)["period"] for h in (5e-5, 2.5e-5))
    assert abs(coarse - fine) < 0.01 * fine
