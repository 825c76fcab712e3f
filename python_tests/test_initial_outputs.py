"""Honest t0: before the first step the outputs describe the initial state,
for every initial state x top control x gap (docs/contract.md, "Initial state")."""
import itertools

import fmpy
import numpy as np
import pytest

OUTPUTS = ["normal_force", "friction_force", "active_contact_nodes", "slipping_contact_nodes",
           "corner_pressure", "corner_friction", "max_penetration", "top_reaction_y",
           "kinetic_energy"]
TOP_FORCE = 5e4  # N/m: under force control, the static state's load


def first_row(fmu_path, initial_state, control, gap):
    start = dict(initial_state=initial_state, top_control=control, initial_gap=gap,
                 friction_coefficient=0.3, nx=10, ny=10)
    if control == "force":
        start.update(top_control=1, top_force=TOP_FORCE)
    else:
        start.update(top_control=0)
    start["initial_state"] = {"paper": 0, "static": 1}[initial_state]
    r = fmpy.simulate_fmu(fmu_path, stop_time=1e-4, output_interval=1e-4, start_values=start,
                          output=OUTPUTS)
    return {name: float(r[name][0]) for name in OUTPUTS}


@pytest.mark.parametrize("initial_state, control, gap",
                         list(itertools.product(["paper", "static"], ["displacement", "force"],
                                                [0.0, 1e-5])))
def test_t0_outputs_describe_the_initial_state(fmu_path, initial_state, control, gap):
    t0 = first_row(fmu_path, initial_state, control, gap)
    assert t0["slipping_contact_nodes"] == 0, "at rest no node slips"
    assert t0["max_penetration"] <= 1e-15
    # The paper's state leaves the bottom at y = 0: a gap stays open. The static states close
    # it (the top displacement -2.5e-5 m, or the force, pushes the body down by more).
    touching = gap == 0 or initial_state == "static"
    if not touching:
        assert t0["normal_force"] == t0["corner_pressure"] == 0
        assert t0["active_contact_nodes"] == 0
        assert t0["friction_force"] == t0["corner_friction"] == 0
        return
    assert t0["normal_force"] > 0 and t0["corner_pressure"] > 0
    assert t0["active_contact_nodes"] == 11  # every bottom node of the 10 x 10 mesh pressed
    if initial_state == "static":  # in balance: the top carries what the foundation does
        assert t0["kinetic_energy"] == 0
        assert abs(t0["top_reaction_y"] + t0["normal_force"]) <= 1e-9 * t0["normal_force"]
        if control == "force":
            assert t0["normal_force"] == pytest.approx(TOP_FORCE, rel=1e-9)
    else:  # no slip history: friction starts with the first step
        assert t0["friction_force"] == t0["corner_friction"] == 0
