"""When substep halvings pile up in a step (at least 4, and 5 % of its substeps) the FMU says so
once for that step, naming the time, the halvings and the internal_step that avoids them; a
step with fewer says nothing. The scene is the outside checks' slip-rate scene
(benchmarks/rate_law_cost.py), whose steps halve from none to hundreds of times."""
import re
import sys

import numpy as np

from contactbody.fmu import Model, Profile
from conftest import ROOT

sys.path.insert(0, str(ROOT / "benchmarks"))
import rate_law_cost  # noqa: E402


def test_piled_up_halvings_are_said_once_per_step(fmu_path):
    scene = rate_law_cost.SCENE
    times = np.linspace(0, rate_law_cost.PERIOD, 41)
    inputs = {"foundation_velocity": Profile.of(
                  [[t, 19.88 * np.sin(2 * np.pi * t / rate_law_cost.PERIOD)] for t in times]),
              "top_displacement": Profile.of([[0, -2.67e-5], [rate_law_cost.PERIOD, 2e-5]])}
    h = rate_law_cost.STEP
    with Model(fmu_path, name="halvings") as model:
        # Eleven steps: halvings 2, 0, 0, 0, 5 (at least 4, but under 5 % of 903), 0, ..., then
        # 47 (piled up).
        rows, _ = model.run(scene, 11 * h, h, ["substep_refinements", "substeps"], inputs=inputs)
        warnings = [m[2] for m in model.instance.messages if m[0] == 1 and "halvings" in m[2]]
    nominal = int(np.ceil(h / scene["internal_step"] * (1 - 1e-9)))
    halvings = rows["substep_refinements"][1:]
    piled = [k for k, n in enumerate(halvings) if n >= 4 and n >= 0.05 * nominal]
    assert piled and len(piled) < len(halvings), halvings  # some steps pile up, some do not
    assert len(warnings) == len(piled), (halvings, warnings)
    for k, text in zip(piled, warnings):
        assert f"step to t = {float(rows['time'][k + 1]):.6g}:" in text, text
        assert f"{int(halvings[k])} substep halvings" in text
        smallest = float(re.search(r"set internal_step <= (\S+) s", text).group(1))
        assert 0 < smallest < scene["internal_step"]
        assert "static_friction_ratio = 2.3534 over stribeck_velocity = 0.11687" in text
