"""The body in system models (examples/system): a belt drive under it, a press on top, as
data (contactbody.master.System), written as an SSP for fmpy's simulate_ssp and as an fmpy
container FMU.

Interface, per connection (every sign and unit; see also the FMUs' modelDescriptions):
- belt.belt_velocity (m/s, the belt's velocity at the end of the communication step, +x)
  -> body.foundation_velocity (m/s, +x).
- body.friction_force (N per metre of thickness, the average over the body's last step of
  the foundation's tangential force on the body, +x drags the body along)
  -> belt.friction_force (N/m; the belt multiplies by its contact_width, 0.01 m, and is
  pulled back by that force).
- press.position (m, up positive, end of step) -> body.top_displacement (m, up positive).
- body.top_reaction_y (N/m, step average, the top edge's force on the body, < 0 pressing)
  -> press.top_reaction_y (N/m; the body pushes the press up with -top_reaction_y x width).
Power bond of the belt: belt.load_work (J, int friction_force x width x belt_velocity dt, with
the belt's own velocity) against body.foundation_work (J/m, the same with the body's input
velocity) x width; they differ by the coupling error only.
"""
from __future__ import annotations

import io
import pathlib
import shutil
import tempfile
import zipfile
from xml.sax.saxutils import quoteattr

from fmpy import read_model_description

from .fmu import configured_copy, contact_nodes, find_fmu  # noqa: F401 (system's own API too)
from .master import System

WIDTH = 0.01  # m: the body's thickness, the companions' contact_width

# The body under the belt: damped (the damping issue's stable setting), F = 0.3, starting at
# rest under its static preload; internal_step 3.125e-6 s divides every communication step the
# examples use (1e-4 ... 3.125e-6 s), so the body's own time step is the same in all of them.
BODY = {"nx": 10, "ny": 10, "friction_coefficient": 0.3, "damping_stiffness": 4e-6,
        "initial_state": 1, "internal_step": 3.125e-6}


def fmu(name):
    """The FMU `name` beside the body's (find_fmu: $CONTACTBODY_FMU, else this checkout's
    build/), so that the system models run on the FMUs the user points at."""
    return find_fmu().with_name(f"{name}.fmu")


def belt_system(**body) -> System:
    return System(
        components={"belt": fmu("BeltDrive"), "body": fmu("ContactBody")},
        connections=[("belt.belt_velocity", "body.foundation_velocity"),
                     ("body.friction_force", "belt.friction_force")],
        parameters={**{f"body.{k}": v for k, v in {**BODY, **body}.items()},
                    "belt.contact_width": WIDTH},
        record=["belt.belt_velocity", "body.friction_force", "body.normal_force",
                "body.slipping_contact_nodes", "body.active_contact_nodes", "belt.load_work",
                "body.foundation_work", "belt.drive_work", "body.energy"],
        bonds=[("belt.load_work", "body.foundation_work", WIDTH)],
        scales={"belt.belt_velocity": 1.0, "body.friction_force": 1e3, "belt.load_work": 0.1,
                "body.foundation_work": 10.0},
        averaged=["body.friction_force"])


def press_system(**body) -> System:
    """The press drives the top edge of the body, which starts at the paper's state with no
    load (top_displacement 0): the press's force ramp loads it."""
    params = {**BODY, "initial_state": 0, "top_displacement": 0.0, "friction_coefficient": 0.3,
              **body}
    return System(
        components={"press": fmu("Press"), "body": fmu("ContactBody")},
        connections=[("press.position", "body.top_displacement"),
                     ("body.top_reaction_y", "press.top_reaction_y")],
        parameters={**{f"body.{k}": v for k, v in params.items()},
                    "body.foundation_velocity": 0.5, "press.contact_width": WIDTH},
        record=["press.position", "press.velocity", "press.reaction_force",
                "press.actuator_force", "body.top_reaction_y", "body.normal_force",
                "body.energy"],
        scales={"press.position": 1e-5, "body.top_reaction_y": 1e4},
        averaged=["body.top_reaction_y"])


# --- SSP -------------------------------------------------------------------------------------

_NS = ('xmlns:ssc="http://ssp-standard.org/SSP1/SystemStructureCommon" '
       'xmlns:ssd="http://ssp-standard.org/SSP1/SystemStructureDescription" '
       'xmlns:ssv="http://ssp-standard.org/SSP1/SystemStructureParameterValues"')


def _connectors(system, component):
    kinds = {}
    for s, t in system.connections:
        for path, kind in ((s, "output"), (t, "input")):
            c, v = path.split(".", 1)
            if c == component:
                kinds[v] = kind
    for path in system.record:
        c, v = path.split(".", 1)
        if c == component:
            kinds.setdefault(v, "output")
    return kinds


def write_ssp(system: System, path, name="System", stop_time=0.01):
    """The system as an SSP 1.0 archive: SystemStructure.ssd, the FMUs in resources/, and
    the parameters in resources/parameters.ssv (bound to the system, names
    "component.variable"). fmpy 0.3.32's simulate_ssp reads the binding but does not apply
    it (only its parameter_set argument), and ignores the DefaultExperiment (it runs 1 s in
    100 steps unless told): simulate_ssp below passes both."""
    path = pathlib.Path(path)
    ssd = [f'<?xml version="1.0" encoding="UTF-8"?>',
           f'<ssd:SystemStructureDescription {_NS} version="1.0" name="{name}">',
           f'  <ssd:System name="{name}">',
           '    <ssd:ParameterBindings>',
           '      <ssd:ParameterBinding source="resources/parameters.ssv"/>',
           '    </ssd:ParameterBindings>',
           '    <ssd:Elements>']
    for component, fmu_path in system.components.items():
        ssd.append(f'      <ssd:Component name="{component}" '
                   f'source="resources/{pathlib.Path(fmu_path).name}" '
                   'type="application/x-fmu-sharedlibrary">')
        ssd.append('        <ssd:Connectors>')
        types = {v.name: v.type for v in read_model_description(str(fmu_path)).modelVariables}
        for variable, kind in _connectors(system, component).items():
            # the connector's type is the variable's (SSP 1.0: Real, Integer, Boolean, String;
            # an enumeration is passed as its integer)
            ssc = {"Enumeration": "Integer"}.get(types[variable], types[variable])
            ssd.append(f'          <ssd:Connector name="{variable}" kind="{kind}">'
                       f'<ssc:{ssc}/></ssd:Connector>')
        ssd += ['        </ssd:Connectors>', '      </ssd:Component>']
    ssd += ['    </ssd:Elements>', '    <ssd:Connections>']
    for s, t in system.connections:
        (sc, sv), (tc, tv) = s.split(".", 1), t.split(".", 1)
        ssd.append(f'      <ssd:Connection startElement="{sc}" startConnector="{sv}" '
                   f'endElement="{tc}" endConnector="{tv}"/>')
    ssd += ['    </ssd:Connections>', '  </ssd:System>',
            f'  <ssd:DefaultExperiment startTime="0" stopTime="{stop_time!r}"/>',
            '</ssd:SystemStructureDescription>', '']
    ssv = [f'<?xml version="1.0" encoding="UTF-8"?>',
           f'<ssv:ParameterSet {_NS} version="1.0" name="parameters">', '  <ssv:Parameters>']
    for key, value in system.parameters.items():
        kind = "Integer" if isinstance(value, int) else "Real"
        ssv.append(f'    <ssv:Parameter name={quoteattr(key)}><ssv:{kind} value="{value!r}"/>'
                   '</ssv:Parameter>')
    ssv += ['  </ssv:Parameters>', '</ssv:ParameterSet>', '']
    with zipfile.ZipFile(path, "w") as z:
        z.writestr("SystemStructure.ssd", "\n".join(ssd))
        z.writestr("resources/parameters.ssv", "\n".join(ssv))
        for component, fmu_path in system.components.items():
            values = {k.split(".", 1)[1]: v for k, v in system.parameters.items()
                      if k.split(".", 1)[0] == component}
            z.writestr(f"resources/{pathlib.Path(fmu_path).name}", configured_copy(fmu_path, values))
    return path


def simulate_ssp(path, stop_time, step_size):
    """fmpy's simulate_ssp with the archive's parameters. Note fmpy's conventions: every
    input starts at 0 (not at its source's initial output), and each row holds the outputs
    at the end of a step labelled with the step's start time; it adds up time
    (time += step_size), so it may take one step past stop_time."""
    from fmpy.ssp.ssd import read_ssv
    from fmpy.ssp.simulation import simulate_ssp as fmpy_simulate_ssp
    with tempfile.TemporaryDirectory() as tmp:
        with zipfile.ZipFile(path) as z:
            z.extract("resources/parameters.ssv", tmp)
        parameters = read_ssv(pathlib.Path(tmp) / "resources" / "parameters.ssv")
    return fmpy_simulate_ssp(str(path), stop_time=stop_time, step_size=step_size,
                             parameter_set=parameters)


# --- container FMU ---------------------------------------------------------------------------

def write_container(system: System, path, step_size, name="Container", stop_time=0.01):
    """The system as one FMI 2.0 co-simulation FMU (fmpy.container_fmu), fixed internal step
    step_size. Its parameters are the system's (start values of container parameters mapped
    to the components'); its outputs are the recorded Real variables, named
    component_variable. Its DefaultExperiment runs stop_time at step_size, so that plain
    fmpy.simulate_fmu(container) runs the documented scene."""
    from fmpy.container_fmu.cli import create_container_fmu
    from fmpy.container_fmu.config import Component, Configuration, Connection
    from fmpy.model_description import CoSimulation, DefaultExperiment, ModelDescription, \
        ModelVariable, Unknown

    components, variables = {}, {}
    for component, fmu_path in system.components.items():
        md = read_model_description(str(fmu_path))
        components[component] = Component(name=component, filename=pathlib.Path(fmu_path),
                                          modelDescription=md)
        variables[component] = {v.name: v for v in md.modelVariables}

    def var(p):
        c, v = p.split(".", 1)
        return components[c], variables[c][v]

    mappings = {}
    # The container answers value reference 0 with its time and maps the others from 1 on.
    model_variables = [ModelVariable(type="Real", variability="continuous", causality="local",
                                     name="time", initial="calculated")]
    for key, value in system.parameters.items():
        component, v = var(key)
        cv = ModelVariable(type="Integer" if v.type in ("Integer", "Enumeration") else "Real",
                           variability="fixed", causality="parameter", initial="exact",
                           name=key.replace(".", "_"), start=repr(value))
        model_variables.append(cv)
        mappings[cv] = [(component, v)]
    for key in system.record:
        component, v = var(key)
        if v.type != "Real":  # fmpy 0.3.32's container reads FMI 2 components' Integer
            continue          # variables with fmi2GetReal, which they refuse: left out
        cv = ModelVariable(type="Real", variability="continuous", causality="output",
                           initial="calculated", name=key.replace(".", "_"))
        model_variables.append(cv)
        mappings[cv] = [(component, v)]
    def float64(v):  # fmpy 0.3.32 writes a connection's type as given; the container wants
        copy = ModelVariable(type="Float64", name=v.name, causality=v.causality)  # FMI 3 names
        copy.valueReference = v.valueReference
        return copy

    connections = []
    for s, t in system.connections:
        (sc, sv), (tc, tv) = var(s), var(t)
        connections.append(Connection(sc, [float64(sv)], tc, [float64(tv)]))
    md = ModelDescription(fmiVersion="2.0", modelName=name,
                          instantiationToken="{5d0c6a52-1e7f-4b3a-9c2d-8f4e6b1a7c90}",
                          defaultExperiment=DefaultExperiment(startTime="0",
                                                              stopTime=repr(stop_time),
                                                              stepSize=repr(step_size)),
                          coSimulation=CoSimulation(fixedInternalStepSize=step_size),
                          modelVariables=model_variables)
    outputs = [v for v in model_variables if v.causality == "output"]
    md.outputs = [Unknown(variable=v) for v in outputs]
    md.initialUnknowns = [Unknown(variable=v) for v in outputs]
    config = Configuration(parallelDoStep=False, modelDescription=md,
                           components=list(components.values()), connections=connections,
                           variableMappings=mappings)
    work = pathlib.Path(tempfile.mkdtemp(prefix="container_"))
    try:
        create_container_fmu(config, work, pathlib.Path(path).resolve())
    finally:
        shutil.rmtree(work, ignore_errors=True)
    return pathlib.Path(path)
