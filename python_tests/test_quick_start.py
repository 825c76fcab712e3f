"""README's quick start runs as printed and stays in the stable region; the
material helpers give the paper's material back."""
import contextlib
import io
import re

import numpy as np
import pytest

from conftest import ROOT
from contactbody.material import lame, stiffness_damping, to_fmu


def quick_start():
    text = (ROOT / "README.md").read_text()
    block = text[text.index("Use it from any FMI 2.0 importer"):]
    return re.search(r"```python\n(.*?)```", block, re.S).group(1)


def test_the_readme_quick_start_runs_and_its_energy_stays_bounded():
    code = quick_start()
    assert "damping_stiffness" in code  # the stable setting, not F alone
    scope = {}
    with contextlib.redirect_stdout(io.StringIO()):
        exec(compile(code, "README quick start", "exec"), scope)
    energy = scope["r"]["energy"]
    assert np.isfinite(energy).all()
    text = (ROOT / "README.md").read_text()
    bound, start, undamped = map(float, re.search(
        r"E stays below ([\d.]+) J/m \(it starts at ([\d.]+)\)\. Without\s+β the same scene is "
        r"unstable \(E grows to ([\d.]+) J/m", text).groups())
    assert energy.max() < bound and energy[-1] < 1.5 * energy[0]
    assert round(float(energy[0]), 2) == start
    # the sentence after it: the same scene without β, as README says
    code_undamped = re.sub(r',\s*"damping_stiffness": 4e-6', "", code)
    assert code_undamped != code
    with contextlib.redirect_stdout(io.StringIO()):
        exec(compile(code_undamped, "README quick start without damping", "exec"), scope)
    assert round(float(scope["r"]["energy"].max()), 1) == undamped


def test_material_helpers():
    lam, mu = lame(400e6, 1 / 3)  # the paper's material: E = 400 MPa, nu = 1/3
    assert lam == pytest.approx(300e6, rel=1e-12) and mu == pytest.approx(150e6, rel=1e-12)
    beta = stiffness_damping(0.1, 4000.0)
    assert beta * 2 * np.pi * 4000.0 == pytest.approx(0.1)
    point = to_fmu({"youngs_modulus": 400e6, "poisson_ratio": 1 / 3, "loss_factor": 0.1,
                    "loss_frequency": 4000.0, "nx": 10})
    assert point["lambda"] == pytest.approx(300e6) and point["nx"] == 10
    assert point["damping_stiffness"] == pytest.approx(beta)
    with pytest.raises(ValueError, match="go together"):
        to_fmu({"youngs_modulus": 1e9})
    with pytest.raises(ValueError, match="poisson_ratio must be in"):
        lame(1e9, 0.5)


def test_the_readme_3d_quick_start_runs_and_its_friction_follows_the_foundation():
    """README's 3D block, as printed: the block slides under a foundation moving along (2, 1.5)
    m/s, and isotropic friction drags it along that heading (a law that treated x and z apart,
    or a z twin lost on the way, would turn it), bounded by F N."""
    text = (ROOT / "README.md").read_text()
    block = text[text.index("A 3D body:"):]
    code = re.search(r"```python\n(.*?)```", block, re.S).group(1)
    scope = {}
    exec(compile(quick_start().split("r = simulate_fmu")[0], "README imports", "exec"), scope)
    with contextlib.redirect_stdout(io.StringIO()):
        exec(compile(code, "README 3D quick start", "exec"), scope)
    r = scope["r"]
    fx, fz, n = r["friction_force"][-1], r["friction_force_z"][-1], r["normal_force"][-1]
    assert n > 0 and np.hypot(fx, fz) > 0.5 * 0.3 * n
    assert np.hypot(fx, fz) <= 0.3 * n * (1 + 1e-9)
    assert abs(np.degrees(np.arctan2(fz, fx) - np.arctan2(1.5, 2.0))) < 1.0
