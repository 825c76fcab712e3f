"""A benchmark's function run in a fresh Python process (its own CPU clock, peak memory and
loaded FMU), its JSON result returned: child.in_child("rate_law_cost", "run", "constant", None)."""
import json
import pathlib
import subprocess
import sys

BENCHMARKS = pathlib.Path(__file__).resolve().parent


def in_child(module, function, *args):
    code = (f"import json, sys; sys.path.insert(0, {str(BENCHMARKS)!r}); import {module}; "
            f"print(json.dumps({module}.{function}(*{args!r})))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    return json.loads(out.stdout.strip().splitlines()[-1])
