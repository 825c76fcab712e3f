"""The platform table (platforms.json at the top of the checkout): the platforms whose binaries
the FMUs carry, how each is built and how it is tested.

    .venv/bin/python -m contactbody.tools.platforms test-jobs [PYTEST ARGS]   # each platform's job

(scripts/setup.sh reads the apt packages from the same file with Debian's python3, before the
virtual environment exists.)
"""
import json
import os
import pathlib
import subprocess
import sys

TABLE = pathlib.Path(__file__).resolve().parents[2] / "platforms.json"


def platforms():
    return json.loads(TABLE.read_text())["platforms"]


def names():
    return [p["name"] for p in platforms()]


def platform(name):
    for p in platforms():
        if p["name"] == name:
            return p
    raise KeyError(f"no platform {name!r} in {TABLE} (it has {', '.join(names())})")


def run_test_jobs(extra_args, python=sys.executable):
    """Runs the pytest job of every platform that has one (CONTACTBODY_PLATFORM=name); the
    native one runs the whole suite elsewhere (scripts/test.sh). Returns the first failure's
    exit code, or 0."""
    for p in platforms():
        if not p["test_job"]:
            continue
        print(f"== {p['name']} job: {p['tested']} ==", flush=True)
        env = dict(os.environ, CONTACTBODY_PLATFORM=p["name"])
        code = subprocess.call([python, "-m", "pytest", *p["test_job"], *extra_args], env=env)
        if code:
            return code
    return 0


def main(argv):
    if argv[:1] == ["test-jobs"]:
        return run_test_jobs(argv[1:])
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
