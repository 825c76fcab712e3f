"""The FMU as a file: valid, self-contained, and its modelDescription matches the table
."""
import pathlib
import subprocess

from fmpy.validation import validate_fmu

from conftest import ROOT


def test_fmpy_validate_reports_no_problem(fmu_path):
    assert validate_fmu(fmu_path) == []
    out = subprocess.run([str(ROOT / ".venv" / "bin" / "fmpy"), "validate", fmu_path],
                         capture_output=True, text=True)
    assert out.returncode == 0 and "No problems found" in out.stdout, out.stdout + out.stderr


def test_committed_model_description_is_the_generated_one(unzipped):
    generated = (pathlib.Path(unzipped) / "modelDescription.xml").read_text()
    committed = (ROOT / "modelDescription" / "modelDescription.xml").read_text()
    assert generated == committed, (
        "modelDescription/modelDescription.xml is stale: copy build/fmu/ContactBody/modelDescription.xml")


def test_variables_follow_spec(model_description):
    variables = {v.name: v for v in model_description.modelVariables}
    parameters = {"width": 0.1, "height": 0.1, "nx": 20, "ny": 20, "density": 1000,
                  "lambda": 300e6, "mu": 150e6, "friction_coefficient": 1.2, "mass_matrix": 1,
                  "internal_step": 4e-6, "contact_tolerance": 1e-10, "initial_gap": 0}
    for name, start in parameters.items():
        v = variables[name]
        assert v.causality == "parameter"
        assert float(v.start) == start, name
        assert v.variability == ("tunable" if name == "friction_coefficient" else "fixed")
    assert variables["mass_matrix"].type == "Enumeration"
    items = [i.name for i in variables["mass_matrix"].declaredType.items]
    assert items == ["standard", "redistributed_normal", "redistributed_both",
                     "standard_implicit_contact", "redistributed_implicit_contact"]
    assert variables["foundation_velocity"].causality == "input"
    assert float(variables["foundation_velocity"].start) == 20
    assert float(variables["top_displacement"].start) == -2.5e-5
    units = {"energy": "J/m", "kinetic_energy": "J/m", "strain_energy": "J/m",
             "friction_work": "J/m", "energy_minus_friction_work": "J/m", "normal_force": "N/m",
             "friction_force": "N/m", "corner_pressure": "Pa", "corner_friction": "Pa",
             "top_reaction_x": "N/m", "top_reaction_y": "N/m", "max_penetration": "m"}
    for name, unit in units.items():
        assert variables[name].causality == "output" and variables[name].unit == unit, name
    for name in ("active_contact_nodes", "slipping_contact_nodes"):
        assert variables[name].type == "Integer" and variables[name].variability == "discrete"
