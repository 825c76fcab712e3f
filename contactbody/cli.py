"""contactbody-study: run a parameter study of the ContactBody FMU, and plot its table.

  contactbody-study run STUDY.toml --out DIR [--workers N | --scheduler ADDRESS]
  contactbody-study run --stop-time 0.01 --output-interval 1e-4 \\
      --set damping_stiffness=4e-6 --grid friction_coefficient=0.1,0.3 --out DIR
  contactbody-study plot DIR --heatmap foundation_velocity friction_coefficient apparent_friction_ratio
  contactbody-study plot DIR --lines foundation_velocity friction_power --hue friction_coefficient
  contactbody-study plot DIR --heatmap ... --where damping_stiffness=4e-6   (or --facet NAME)
  contactbody-study series DIR energy,friction_force --where friction_coefficient=0.3
"""
from __future__ import annotations

import argparse
import pathlib
import sys


def _value(text: str):
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            pass
    return text


def _assignments(items, split):
    out = {}
    for item in items or []:
        name, sep, value = item.partition("=")
        if not sep:
            raise SystemExit(f"expected name=value, got {item!r}")
        out[name.strip()] = [_value(v) for v in value.split(",")] if split else _value(value)
    return out


def main(argv=None):
    """Runs the command; a user's mistake (a study file, a name, a value, a scheduler that
    cannot be reached) ends in one line on stderr and exit status 2, without a traceback
    unless --debug."""
    argv = sys.argv[1:] if argv is None else list(argv)
    debug = "--debug" in argv
    try:
        return _main([a for a in argv if a != "--debug"])
    except Exception as e:  # noqa: BLE001 (sorted below: a mistake, or a bug to show)
        from .study import StudyError
        if debug or not isinstance(e, (StudyError, OSError)):
            raise
        print(f"contactbody-study: error: {e}", file=sys.stderr)
        return 2


def _main(argv):
    parser = argparse.ArgumentParser(prog="contactbody-study", description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter,
                                     epilog="--debug (anywhere): show the traceback of an error")
    sub = parser.add_subparsers(dest="command", required=True)
    run = sub.add_parser("run", help="run the points not yet in DIR's table")
    run.add_argument("study", nargs="?", help="study file (TOML); or give --stop-time etc.")
    run.add_argument("--out", required=True, help="directory of the table (results.csv, "
                     "results.parquet, series/)")
    run.add_argument("--stop-time", type=float)
    run.add_argument("--output-interval", type=float)
    run.add_argument("--average-from", type=float)
    run.add_argument("--set", action="append", metavar="NAME=VALUE", help="a fixed value")
    run.add_argument("--grid", action="append", metavar="NAME=V1,V2,...", help="a grid axis")
    run.add_argument("--series", help="outputs to keep per point, comma separated")
    run.add_argument("--fmu", help="the FMU (default: $CONTACTBODY_FMU or build/ContactBody.fmu)")
    where = run.add_mutually_exclusive_group()
    where.add_argument("--workers", type=int, help="size of the LocalCluster (default: cores)")
    where.add_argument("--scheduler", help="address of an existing dask scheduler")
    run.add_argument("--retry-failed", action="store_true",
                     help="run again the points recorded as failed")
    run.add_argument("--no-progress", action="store_true")
    plot = sub.add_parser("plot", help="heat map or lines from DIR's table, as PNG")
    plot.add_argument("directory")
    plot.add_argument("--heatmap", nargs=3, metavar=("X", "Y", "VALUE"))
    plot.add_argument("--lines", nargs=2, metavar=("X", "VALUE"))
    plot.add_argument("--hue", help="one line per value of this column (--lines)")
    plot.add_argument("--facet", help="one heat map panel per value of this column")
    plot.add_argument("--where", action="append", metavar="NAME=VALUE",
                      help="keep the rows with this value (fixes a parameter the plot does not show)")
    plot.add_argument("--output", help="PNG path (default: DIR/<value>_<x>[_<y>].png)")
    series = sub.add_parser("series", help="plot outputs' time series of chosen points")
    series.add_argument("directory")
    series.add_argument("outputs", help="outputs kept by the study's `series`, comma separated")
    series.add_argument("--where", action="append", metavar="NAME=VALUE",
                        help="keep the points with this value (repeatable)")
    series.add_argument("--output", help="PNG path (default: DIR/series_<outputs>.png)")
    args = parser.parse_args(argv)

    if args.command == "run":
        from .study import Study, run_study
        if args.study:
            study = Study.from_toml(args.study)
        elif args.stop_time and args.output_interval:
            study = Study(stop_time=args.stop_time, output_interval=args.output_interval)
        else:
            parser.error("give a study file, or --stop-time and --output-interval")
        if args.stop_time:
            study.stop_time = args.stop_time
        if args.output_interval:
            study.output_interval = args.output_interval
        if args.average_from is not None:
            study.average_from = args.average_from
        study.fixed.update(_assignments(args.set, split=False))
        study.grid.update(_assignments(args.grid, split=True))
        if args.series:
            study.series = args.series.split(",")
        try:
            df = run_study(study, args.out, fmu=args.fmu, workers=args.workers,
                           scheduler=args.scheduler, retry_failed=args.retry_failed,
                           progress=not args.no_progress)
        except OSError as e:
            if args.scheduler:
                raise OSError(f"cannot reach the dask scheduler {args.scheduler} ({e})") from e
            raise
        counts = df["status"].value_counts().to_dict()
        print(f"{len(df)} points in {pathlib.Path(args.out) / 'results.parquet'} "
              f"({df.attrs['ran']} run now): {counts}")
        from .study import parameter_columns
        for _, row in df[df["status"] == "failed"].iterrows():
            values = ", ".join(f"{c} = {row[c]}" for c in parameter_columns(df))
            print(f"  failed: {row['point_id']} ({values}): {row['message']}")
        return 0 if counts.get("failed", 0) == 0 else 1

    import pandas as pd
    from . import plots
    directory = pathlib.Path(args.directory)
    df = pd.read_parquet(directory / "results.parquet")
    df = plots.select(df, _assignments(args.where, split=False))
    units = plots.units_of(directory)
    if args.command == "series":
        outputs = args.outputs.split(",")
        path = args.output or directory / f"series_{'_'.join(outputs)}.png"
        plots.series(directory, df, outputs, path, units=units)
    elif args.heatmap:
        x, y, value = args.heatmap
        path = args.output or directory / f"{value}_{x}_{y}.png"
        plots.heatmap(df, x, y, value, path, facet=args.facet, units=units)
    elif args.lines:
        x, value = args.lines
        path = args.output or directory / f"{value}_{x}.png"
        plots.lines(df, x, value, path, hue=args.hue, units=units)
    else:
        parser.error("give --heatmap X Y VALUE or --lines X VALUE")
    print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
