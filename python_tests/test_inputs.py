"""input_interpolation (scenes issue, item 3): held inputs jump at every communication point
and pump energy into a pressed body; `ramp` goes linearly from the previous communication
point's value, which fmpy's simulate_fmu can use (it cannot pass input derivatives to an FMU
with other than 9 inputs)."""
import pathlib
import sys

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "examples"))
import press_inputs  # noqa: E402

from conftest import Instance  # noqa: E402


def test_ramp_removes_the_energy_that_held_inputs_inject(fmu_path):
    """The press at h = 1e-4 against slopes at 1e-5 (measured max |E - E_ref|: held 5.1,
    ramp 0.0072, slopes 0.0129 J/m, for max E_ref = 0.094 J/m)."""
    reference, _ = press_inputs.run("slopes", 1e-5, fmu_path)
    error = {}
    for mode in ("held", "ramp", "slopes"):
        e, clamp = press_inputs.run(mode, 1e-4, fmu_path)
        error[mode] = np.abs(e - reference).max()
    assert error["held"] > 10 * reference.max()
    assert error["ramp"] < 0.15 * reference.max() and error["slopes"] < 0.15 * reference.max()
    assert error["ramp"] < 2 * error["slopes"]


def test_ramp_start_is_part_of_the_state(model_description, unzipped, vr):
    """A restored state ramps from the value it had when saved, not from the instance's."""
    inst = Instance(model_description, unzipped, "ramp")
    inst.setupExperiment(startTime=0)
    inst.enterInitializationMode()
    inst.setInteger([vr["input_interpolation"]], [1])
    inst.exitInitializationMode()
    h, top = 1e-4, vr["top_displacement"]
    inst.setReal([top], [-3e-5])
    inst.doStep(0.0, h)
    saved = inst.getFMUstate()
    rows = []
    for k, value in enumerate((-4e-5, -2e-5, -3.5e-5)):
        inst.setReal([top], [value])
        inst.doStep((k + 1) * h, h)
        rows.append(inst.getReal([vr["energy"], vr["top_reaction_y"]]))
    inst.setReal([top], [1e-5])
    inst.doStep(4 * h, h)  # moves the ramp's start elsewhere
    inst.setFMUstate(saved)
    for k, value in enumerate((-4e-5, -2e-5, -3.5e-5)):
        inst.setReal([top], [value])
        inst.doStep((k + 1) * h, h)
        assert inst.getReal([vr["energy"], vr["top_reaction_y"]]) == rows[k]
    inst.freeFMUstate(saved)
    inst.close()
