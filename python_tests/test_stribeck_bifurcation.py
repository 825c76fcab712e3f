"""With velocity-weakening friction one substep of the full body has several
solutions without tangential mass (redistributed_both), and the trajectories that start from
them part; with it (redistributed_normal) the substep is unique once dt is small enough
(examples/stribeck_bifurcation.py, reduced ladder)."""
import json
import subprocess
import sys

from conftest import ROOT


def test_redistributed_both_bifurcates_where_redistributed_normal_is_unique(tmp_path):
    out = subprocess.run([sys.executable, str(ROOT / "examples" / "stribeck_bifurcation.py"),
                          "--quick", "--out", str(tmp_path)], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    runs = {(r["variant"], r["dt"]): r for r in
            json.loads((tmp_path / "stribeck_bifurcation.json").read_text())}
    for dt in (4e-6, 1e-6):
        both = runs["redistributed_both", dt]
        assert both["substeps_with_several"] > 0.3 * both["steps"] and both["most_solutions"] >= 2
        branches = both["branches"]
        assert len(branches) >= 2 and all(b["took_it"] for b in branches)
        energies = [b["energy_end"] for b in branches]
        assert max(energies) - min(energies) > 1e-3 * max(energies)  # the trajectories part
    normal = runs["redistributed_normal", 1e-6]
    assert normal["substeps_with_several"] == 0 and normal["most_solutions"] == 1
    assert runs["redistributed_normal", 4e-6]["most_solutions"] >= 2  # too long a step
