"""One step of section 6's example with velocity-weakening friction
(examples/stribeck_one_step.py, reduced grid). The derived condition is sufficient: where it
holds there is exactly one solution, by the direct count and by the contact solver. Keeping
the tangential mass (redistributed_normal) makes small steps unique; removing it
(redistributed_both) gives several solutions at every step size tried, and the contact solver
started from different multipliers converges to different states there."""
import json
import subprocess
import sys

from conftest import ROOT


def test_one_step_solution_counts_and_the_derived_condition(tmp_path):
    out = subprocess.run([sys.executable, str(ROOT / "examples" / "stribeck_one_step.py"),
                          "--quick", "--points", "31", "--out", str(tmp_path)],
                         capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    results = json.loads((tmp_path / "stribeck_one_step.json").read_text())
    for rows in results.values():
        for r in rows:
            assert r["violations_exact"] == 0 and r["violations_solver"] == 0, r
            assert r["max_violation_of_23"] < 1e-10, r
    normal = {r["dt"]: r for r in results["redistributed_normal"]}
    both = {r["dt"]: r for r in results["redistributed_both"]}
    for dt in (0.1, 0.01):
        assert normal[dt]["max_solutions"] == 1 and normal[dt]["condition_holds_everywhere"]
        assert both[dt]["max_solutions"] >= 2 and both[dt]["loads_with_several"] > 0
        assert both[dt]["solver_found_several"] > 0  # different starts, different solutions
    assert normal[1.0]["max_solutions"] >= 2  # a long step is not unique with the mass either
    assert both[0.01]["loads_with_several"] >= both[1.0]["loads_with_several"]
