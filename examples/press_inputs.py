"""Inputs through fmpy (scenes issue, item 3): a press moving the top by 0 -> -20 um -> 0 at
500 Hz (top(t) = -20e-6 sin^2(pi 500 t)), F = 0, communication step 1e-4 s, 0.02 s, driven
three ways: held values (FMI 2.0 without derivatives: the clamp jumps at every communication
point), input_interpolation = ramp (from the previous communication point's value: one step of
delay, no jumps), and exact slopes through fmi2SetRealInputDerivatives (what fmpy's
simulate_fmu cannot pass to this FMU: its input_derivatives path allocates 9 slots). Against
a reference with slopes at a 1e-6 s communication step. Prints max E, E(end), the clamp's work
and the max |E - E_ref| over the output times.

    .venv/bin/python examples/press_inputs.py
"""
import math

import fmpy
import numpy as np
from fmpy.fmi2 import FMU2Slave

from scene import FMU

AMPLITUDE, FREQUENCY, STOP = 20e-6, 500.0, 0.02


def top(t):
    return -AMPLITUDE * math.sin(math.pi * FREQUENCY * t) ** 2


def top_rate(t):
    return -AMPLITUDE * math.pi * FREQUENCY * math.sin(2 * math.pi * FREQUENCY * t)


def run(mode, h, fmu=FMU):
    """E at every multiple of 1e-4 s (and the clamp's work at the end) for one input mode."""
    md = fmpy.read_model_description(str(fmu))
    vr = {v.name: v.valueReference for v in md.modelVariables}
    slave = FMU2Slave(guid=md.guid, unzipDirectory=fmpy.extract(str(fmu)),
                      modelIdentifier=md.coSimulation.modelIdentifier, instanceName=mode)
    slave.instantiate()
    slave.setupExperiment(startTime=0)
    slave.enterInitializationMode()
    slave.setReal([vr["friction_coefficient"], vr["foundation_velocity"], vr["top_displacement"]],
                  [0.0, 0.0, 0.0])
    slave.setInteger([vr["input_interpolation"]], [1 if mode == "ramp" else 0])
    slave.exitInitializationMode()
    energy, every = [slave.getReal([vr["energy"]])[0]], round(1e-4 / h)
    for k in range(round(STOP / h)):
        t = k * h
        if mode == "slopes":
            slave.setRealInputDerivatives([vr["top_displacement"]], [1], [top_rate(t)])
        else:  # held, or ramped by the FMU toward this value
            slave.setReal([vr["top_displacement"]], [top(t + h) if mode == "ramp" else top(t)])
        slave.doStep(t, h)
        if (k + 1) % every == 0:
            energy.append(slave.getReal([vr["energy"]])[0])
    clamp = slave.getReal([vr["clamp_work"]])[0]
    slave.terminate()
    slave.freeInstance()
    return np.array(energy), clamp


def main():
    reference, _ = run("slopes", 1e-6)
    print(f"{'inputs':<8} {'max E [J/m]':>12} {'E(end)':>10} {'clamp_work':>11} {'max |E - E_ref|':>16}")
    print(f"{'ref':<8} {reference.max():>12.4g} {reference[-1]:>10.4g}")
    for mode in ("held", "ramp", "slopes"):
        e, clamp = run(mode, 1e-4)
        print(f"{mode:<8} {e.max():>12.4g} {e[-1]:>10.4g} {clamp:>11.4g} "
              f"{np.abs(e - reference).max():>16.4g}")


if __name__ == "__main__":
    main()
