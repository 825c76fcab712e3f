"""The example parameter study: apparent friction ratio <T>/<N>, frictional power and the
largest energy over F x V, on dask (contactbody.study), from examples/friction_study.toml.

Writes the table to OUT/friction_study/ (results.csv, results.parquet) and the heat maps and
a copy of the table to FIGURES (default OUT; --refresh: examples/results, the committed
copies). Prints the measured facts.

    .venv/bin/python examples/friction_study.py [--out DIR] [--figures DIR | --refresh] [--workers N]
"""
import argparse
import pathlib
import shutil

import numpy as np

from contactbody import plots
from contactbody.study import Study, run_study

HERE = pathlib.Path(__file__).resolve().parent


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=HERE / "output", type=pathlib.Path)
    parser.add_argument("--figures", type=pathlib.Path,
                        help="where the heat maps and the table's copy go (default: --out)")
    parser.add_argument("--refresh", action="store_true",
                        help="write them to examples/results, the committed copies")
    parser.add_argument("--workers", type=int)
    args = parser.parse_args()
    if args.figures is None:  # a run leaves the checkout clean unless asked to refresh
        args.figures = HERE / "results" if args.refresh else args.out
    study = Study.from_toml(HERE / "friction_study.toml")
    table = args.out / "friction_study"
    df = run_study(study, table, workers=args.workers)
    args.figures.mkdir(parents=True, exist_ok=True)
    x, y = "foundation_velocity", "friction_coefficient"
    units = plots.units_of(table)
    plots.heatmap(df, x, y, "apparent_friction_ratio", args.figures / "friction_study_ratio.png",
                  title="apparent friction ratio <T>/<N> (last 10 ms)", units=units)
    plots.heatmap(df, x, y, "friction_power", args.figures / "friction_study_power.png",
                  title="frictional power (last 10 ms)", fmt="{:.3g}", units=units)
    plots.heatmap(df, x, y, "energy_max", args.figures / "friction_study_energy.png",
                  title="largest energy E over 20 ms", fmt="{:.3g}", units=units)
    shutil.copy(table / "results.csv", args.figures / "friction_study.csv")

    ok = df[df["status"] == "ok"]
    print(f"{len(df)} points, {len(ok)} ok; wall time per point "
          f"{ok['wall_time'].mean():.2f} s (doSteps {ok['dostep_time'].mean():.2f} s)")
    deviation = (ok["apparent_friction_ratio"] - ok[y]).abs() / ok[y]
    for f, group in ok.assign(deviation=deviation).groupby(y):
        print(f"F = {f:g}: |<T>/<N> - F| / F max {group['deviation'].max():.2e}, "
              f"slip fraction min {group['slip_fraction'].min():.3f}, "
              f"E max {group['energy_max'].max():.3g} J/m, "
              f"balance error max {group['balance_error_max'].max():.1e} J/m")


if __name__ == "__main__":
    main()
