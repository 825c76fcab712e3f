"""GetFEM (benchmarks/getfem_scene.py: its own assembly, its basic contact brick and Newton)
solving the `standard` variant's discrete scheme gives the FMU's fields to round-off: an
independent check of the assembly, the midpoint step, the contact law's signs and the damping."""
import pathlib
import subprocess
import sys

import fmpy
import numpy as np
import pytest

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "examples"))
import convergence  # noqa: E402

INTERVAL = 1.6e-4


@pytest.mark.parametrize("friction,beta,stop,outputs_compared", [
    (0.0, 0.0, 1.6e-3, 11),
    # Sliding is chaotic for the standard mass: round-off grows by ~1e9 within 1 ms, so only
    # the first 0.64 ms are compared.
    (0.3, 4e-6, 6.4e-4, 5),
])
def test_getfem_matches_the_standard_variant(fmu_path, tmp_path, friction, beta, stop,
                                             outputs_compared):
    nx, dt = 10, 8e-6
    out = tmp_path / "getfem.npz"
    subprocess.run(["/usr/bin/python3", str(ROOT / "benchmarks" / "getfem_scene.py"), str(nx),
                    repr(dt), repr(stop), repr(INTERVAL), repr(friction), repr(beta), str(out)],
                   check=True, capture_output=True, text=True)
    getfem = np.load(out)["displacement"]
    fmpy.simulate_fmu(fmu_path, stop_time=stop, output_interval=INTERVAL,
                      start_values={"nx": nx, "ny": nx, "internal_step": dt, "mass_matrix": 0,
                                    "friction_coefficient": friction, "damping_stiffness": beta,
                                    "result_directory": str(tmp_path / "fields"),
                                    "field_output_interval": INTERVAL})
    ours = [u for _, _, u in convergence.snapshots(tmp_path / "fields")]
    assert len(ours) == len(getfem) == outputs_compared
    scale = max(np.abs(u).max() for u in ours)
    for k, (a, b) in enumerate(zip(ours, getfem)):
        assert np.abs(a - b).max() <= 1e-11 * scale, k
    assert np.abs(ours[-1] - ours[0]).max() > 1e-3 * scale  # the body did move
