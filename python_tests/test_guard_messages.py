"""The blow-up guard's message says what is true (docs/contract.md, "Warnings and guards"):
E(0) is the initial energy itself, kept with the state, not rebuilt from the energy balance
(where E is 1e15-1e17 the balance's round-off is larger than E(0): outside checks saw -65 for
a true 22.99); and where the map finds no steady sliding (F >= 1.3) it does not advise the
damping that the sentence before says cannot help."""
import math
import re

import pytest
from fmpy.fmi1 import FMICallException

from conftest import Instance

H = 1e-4


def fail_by_the_guard(model_description, unzipped, vr, reals, integers=None, steps=400):
    """Steps until the guard's fmi2Error; returns (E at t0, the error text)."""
    inst = Instance(model_description, unzipped, "guard")
    try:
        inst.setupExperiment(startTime=0)
        inst.enterInitializationMode()
        for name, value in reals.items():
            inst.setReal([vr[name]], [value])
        for name, value in (integers or {}).items():
            inst.setInteger([vr[name]], [value])
        inst.exitInitializationMode()
        e0 = inst.getReal([vr["energy"]])[0]
        with pytest.raises(FMICallException):
            for k in range(steps):
                inst.doStep(k * H, H)
        errors = [text for status, _, text in inst.messages if status == 3]
        assert errors and "exceeds" in errors[-1], errors
        return e0, errors[-1]
    finally:
        inst.close()


def test_the_guard_reports_the_true_initial_energy_at_huge_energies(model_description,
                                                                     unzipped, vr):
    """Frictionless variant 1 at lambda/mu = 50 and Courant 3 gains energy at the contact
    (examples/results/frictionless_stability.md: x 1.4e44 in 20 ms); with the guard at 1e16 x
    (E(0) + the work put in) it fails near E = 1e16, where the balance's round-off is ~1."""
    mu, rho, h = 150e6, 1000.0, 0.005
    dt = 3.0 * h / math.sqrt(52 * mu / rho)
    e0, error = fail_by_the_guard(model_description, unzipped, vr, {
        "friction_coefficient": 0.0, "lambda": 50 * mu, "internal_step": dt,
        "max_energy_ratio": 1e16}, {"mass_matrix": 1})
    energy = float(re.search(r"energy E = (\S+) J/m", error).group(1))
    reported = float(re.search(r"\(E\(0\) = (\S+?),", error).group(1))
    assert energy > 1e15 * e0
    assert reported == pytest.approx(e0, rel=1e-5), (reported, e0, error)  # printed to 6 digits


def test_where_no_steady_sliding_exists_the_guard_does_not_advise_damping(model_description,
                                                                          unzipped, vr):
    """F = 1.5 wedges the clamped body (no steady sliding state on the map): the guard's
    likely cause says so, and its advice is to lower F, not to set damping_stiffness."""
    _, error = fail_by_the_guard(model_description, unzipped, vr, {
        "friction_coefficient": 1.5, "damping_stiffness": 4e-6, "max_energy": 0.5})
    assert "no steady sliding" in error and "wedges" in error, error
    advice = error.split("What to change:")[1]
    assert "set damping_stiffness" not in advice and "lower friction_coefficient below 1.3" in advice, error


def test_below_the_wedge_the_guard_still_advises_damping(model_description, unzipped, vr):
    """F = 1.2 undamped (the paper's scene) is damped by the map's beta: the advice stays."""
    _, error = fail_by_the_guard(model_description, unzipped, vr, {"max_energy": 0.3})
    assert "set damping_stiffness" in error.split("What to change:")[1], error
