"""Steps that refine instead of failing, failures that say what to change, and the FMI 2.0.5
state-table fixes (scenes issue, items 2, 7 and 8)."""
import fmpy
import numpy as np
import pytest
from fmpy.fmi1 import FMICallException

from conftest import Instance

ERROR = 3


def test_large_friction_completes_where_it_used_to_fail(fmu_path):
    """F = 5 at internal_step 1.6e-5 stopped on its first step; Gauss-Seidel and substep
    halving now carry it through 0.02 s."""
    r = fmpy.simulate_fmu(fmu_path, stop_time=0.02, output_interval=1e-4,
                          start_values={"friction_coefficient": 5.0, "internal_step": 1.6e-5},
                          output=["energy", "normal_force"])
    assert abs(r["time"][-1] - 0.02) < 1e-12
    assert np.isfinite(r["energy"]).all() and r["normal_force"].max() > 0


def test_random_sweep_scene_that_stalled_newton_completes(fmu_path):
    """One of the sweep's scenes whose first step stopped with 'did not converge in 100
    iterations' (F = 2.63 > c/b)."""
    start = {"width": 0.0453, "height": 0.0246, "nx": 18, "ny": 30, "density": 250.0,
             "mu": 2.56e9, "lambda": 2.56e11, "friction_coefficient": 2.63,
             "internal_step": 1.81e-5, "foundation_velocity": 8.98,
             "top_displacement": -5.47e-7}
    r = fmpy.simulate_fmu(fmu_path, stop_time=2e-3, output_interval=1e-4, start_values=start,
                          output=["energy"])
    assert abs(r["time"][-1] - 2e-3) < 1e-12 and np.isfinite(r["energy"]).all()


def test_unsolvable_steps_raise_in_fmpy_with_the_cause(fmu_path):
    """A step without a unique solution (F = 5 > c/b with redistributed_both, paper section 6)
    fails even at min_internal_step: fmi2Error from fmi2DoStep, and simulate_fmu raises
    instead of returning a short result."""
    messages = []
    with pytest.raises(FMICallException) as failure:
        fmpy.simulate_fmu(fmu_path, stop_time=1e-3, output_interval=1e-4,
                          start_values={"friction_coefficient": 5.0, "mass_matrix": 2,
                                        "min_internal_step": 1e-7},
                          logger=lambda *args: messages.append(str(args[-1])))
    assert failure.value.status == ERROR
    assert any("fmi2DoStep" in m and "contact solve failed" in m for m in messages)


def test_failed_step_restores_its_start_and_set_state_recovers(instance, vr):
    instance.setupExperiment(startTime=0)
    instance.enterInitializationMode()
    # F above c/b with the tangential mass removed too: a step may have no unique solution
    # (paper, section 6), and here the contact solve fails at every size.
    instance.setReal([vr["friction_coefficient"], vr["min_internal_step"]], [5.0, 1e-7])
    instance.setInteger([vr["mass_matrix"]], [2])
    instance.exitInitializationMode()
    start = instance.getFMUstate()
    refs = [vr[n] for n in ("energy", "normal_force", "clamp_work")]
    before = instance.getReal(refs)
    with pytest.raises(FMICallException) as failure:
        instance.doStep(0.0, 1e-4)
    assert failure.value.status == ERROR
    text = instance.text()
    for words in ("fmi2DoStep", "failed, state restored", "contact solve failed at t = ",
                  "F = 5", "for substeps of 4e-06, 2e-06, 1e-06", "min_internal_step = 1e-07",
                  "section 6"):
        assert words in text, words
    assert instance.getReal(refs) == before  # outputs of the step's start
    with pytest.raises(FMICallException):
        instance.doStep(0.0, 1e-4)  # Error state: only set-state, reset, free
    assert "not allowed in state Error" in instance.text()
    instance.setFMUstate(start)  # FMI 2.0.5 allows it after an error
    assert instance.getReal(refs) == before
    instance.freeFMUstate(start)


def test_non_finite_outputs_are_an_error_not_ok(fmu_path):
    """Found while probing: NaN energies under fmi2OK for 73 steps (lambda/mu = 100, F = 0).
    Now the first step with a non-finite output fails and says what to change; the stable
    variant runs the same scene with bounded energy."""
    start = {"mu": 1.185e10, "lambda": 1.185e12, "density": 3088.0, "internal_step": 1e-6,
             "friction_coefficient": 0.0, "foundation_velocity": 0.0,
             "max_energy_ratio": 0.0}  # the blow-up guard off: on, it stops this earlier
    messages = []
    with pytest.raises(FMICallException):
        fmpy.simulate_fmu(fmu_path, stop_time=0.02, output_interval=1e-4, start_values=start,
                          logger=lambda *args: messages.append(str(args[-1])))
    text = "\n".join(messages)
    assert "energy = " in text and "grows without bound" in text, text
    assert "lambda/mu = 100" in text and "mass_matrix = 4" in text, text
    assert "damping_stiffness" not in text  # no friction here: no advice about it
    r = fmpy.simulate_fmu(fmu_path, stop_time=0.02, output_interval=1e-4,
                          start_values={**start, "mass_matrix": 4}, output=["energy"])
    assert np.isfinite(r["energy"]).all() and r["energy"].max() <= r["energy"][0] * (1 + 1e-9)


def test_state_get_and_set_in_instantiated(instance, vr):
    """FMI 2.0.5 allows both before initialization (fmusim --initial-fmu-state-file)."""
    state = instance.getFMUstate()
    instance.setFMUstate(state)
    blob = instance.serializeFMUstate(state)
    restored = instance.deSerializeFMUstate(blob)
    instance.setFMUstate(restored)
    instance.setupExperiment(startTime=0)
    instance.enterInitializationMode()
    instance.exitInitializationMode()
    instance.doStep(0.0, 1e-4)
    instance.freeFMUstate(state)
    instance.freeFMUstate(restored)
