"""What the section 7 examples share: the FMU, the variant names, the paper's ladders, and one
call that simulates the paper scene through fmpy's own master."""
import pathlib
import time

from fmpy import simulate_fmu

ROOT = pathlib.Path(__file__).resolve().parents[1]
FMU = ROOT / "build" / "ContactBody.fmu"
OUT = ROOT / "examples" / "output"
VARIANTS = ["standard", "redistributed_normal", "redistributed_both", "standard_implicit_contact"]
DT_LADDER = [1.6e-5, 8e-6, 4e-6, 2e-6, 1e-6]                      # Figs. 7-8 (h = 0.5 cm)
TABLE2 = [(2e-2, 1.6e-5), (1e-2, 8e-6), (5e-3, 4e-6), (2.5e-3, 2e-6)]  # (h [m], dt [s])
REFERENCE = (6.25e-4, 5e-7)
WIDTH = 0.1


def cells(h):
    return int(round(WIDTH / h))


def simulate(stop_time, output_interval, fmu=FMU, outputs=None, **start_values):
    """fmpy.simulate_fmu of the paper scene; returns (result, wall seconds).

    The output interval must be a multiple of internal_step so that every substep has
    exactly the size asked for (each step runs ceil(h / internal_step) substeps)."""
    start = time.perf_counter()
    result = simulate_fmu(str(fmu), stop_time=stop_time, output_interval=output_interval,
                          start_values=start_values, output=outputs)
    return result, time.perf_counter() - start


def output_argument(parser):
    """--out DIR: where the script writes its files (default examples/output; created)."""
    parser.add_argument("--out", type=pathlib.Path, default=OUT,
                        help="output directory (default: examples/output)")
