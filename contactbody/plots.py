"""Figures over a study's table: heat maps over two parameters (faceted by a third), lines
over one, and time series of chosen points. None averages silently: a parameter that varies
in the table and is neither an axis nor a facet must be fixed first (select)."""
from __future__ import annotations

import json
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from .study import StudyError, parameter_columns  # noqa: E402


def units_of(directory) -> dict:
    """Units of the table's columns, kept in DIR/study.json by the study (empty if none)."""
    path = pathlib.Path(directory) / "study.json"
    return json.loads(path.read_text()).get("units", {}) if path.exists() else {}


def label(name: str, units: dict | None) -> str:
    unit = (units or {}).get(name)
    return f"{name} [{unit}]" if unit else name


def select(df, where: dict):
    """The rows with each name = value of where (values compared as numbers where they can)."""
    for name, value in where.items():
        if name not in df.columns:
            raise StudyError(f"--where {name}: not a column of the table "
                             f"(parameters: {', '.join(parameter_columns(df))})")
        column = df[name]
        keep = np.isclose(column.astype(float), float(value), rtol=1e-12, atol=0) \
            if isinstance(value, (int, float)) and column.dtype.kind in "fi" else column == value
        if not keep.any():
            raise StudyError(f"--where {name}={value}: no row has it (values: "
                             f"{', '.join(map(str, sorted(column.unique())))})")
        df = df[keep]
    return df


def require_fixed(df, used: list[str], what: str):
    """Refuses a plot that would average (or zigzag) over a parameter that varies in df."""
    free = [c for c in parameter_columns(df) if c not in used and df[c].nunique(dropna=False) > 1]
    if free:
        values = "; ".join(f"{c} in {sorted(df[c].dropna().unique().tolist())}" for c in free)
        raise StudyError(f"{what}: the table also varies {values}: fix it with --where "
                         f"{free[0]}=VALUE" + (" or show it with --facet" if what.startswith(
                             "heatmap") else " or with --hue"))


def _heat(ax, table, fmt):
    image = ax.imshow(table.to_numpy(dtype=float), origin="lower", aspect="auto", cmap="viridis")
    ax.set_xticks(range(len(table.columns)), [f"{c:g}" for c in table.columns])
    ax.set_yticks(range(len(table.index)), [f"{r:g}" for r in table.index])
    for (i, j), v in np.ndenumerate(table.to_numpy(dtype=float)):
        ax.text(j, i, "failed" if np.isnan(v) else fmt.format(v), ha="center", va="center",
                fontsize=7, color="w" if not np.isnan(v) else "r")
    return image


def heatmap(df, x: str, y: str, value: str, path, title: str | None = None, fmt="{:.3g}",
            facet: str | None = None, units: dict | None = None):
    """value over the (x, y) grid, one cell per pair (blank where a point failed), one panel
    per value of facet. Every other parameter must be fixed in df (StudyError otherwise).
    Written as PNG to path."""
    require_fixed(df, [x, y] + ([facet] if facet else []), f"heatmap of {value} over {x}, {y}")
    ok = df[df["status"] == "ok"]
    panels = sorted(df[facet].unique()) if facet else [None]
    fig, axes = plt.subplots(1, len(panels), squeeze=False,
                             figsize=(len(panels) * (1.1 * df[x].nunique() + 2.5),
                                      0.6 * df[y].nunique() + 2))
    for ax, key in zip(axes[0], panels):
        rows = ok if key is None else ok[ok[facet] == key]
        table = rows.pivot_table(index=y, columns=x, values=value, aggfunc="first")
        table = table.reindex(index=sorted(df[y].unique()), columns=sorted(df[x].unique()))
        image = _heat(ax, table, fmt)
        ax.set(xlabel=label(x, units), ylabel=label(y, units),
               title=(title or value) if key is None else f"{facet} = {key:g}")
        fig.colorbar(image, ax=ax, label=label(value, units))
    if facet:
        fig.suptitle(title or value)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def lines(df, x: str, value: str, path, hue: str | None = None, title: str | None = None,
          units: dict | None = None):
    """value against x, one line per value of hue (if given); every other parameter must be
    fixed in df (StudyError otherwise). Written as PNG to path."""
    require_fixed(df, [x] + ([hue] if hue else []), f"lines of {value} over {x}")
    ok = df[df["status"] == "ok"]
    fig, ax = plt.subplots(figsize=(6.5, 4.2))
    groups = ok.groupby(hue) if hue else [(None, ok)]
    for key, group in groups:
        group = group.sort_values(x)
        ax.plot(group[x], group[value], "o-", ms=3,
                label=f"{hue} = {key:g}" if hue else None)
    ax.set(xlabel=label(x, units), ylabel=label(value, units), title=title or value)
    if hue:
        ax.legend(fontsize=7)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def series(directory, df, outputs: list[str], path, units: dict | None = None):
    """The time series of outputs (one panel each) of the points in df, from DIR/series/
    (kept for the study's series outputs), each line labelled by the parameters that vary."""
    directory = pathlib.Path(directory)
    ok = df[df["status"] == "ok"]
    if ok.empty:
        raise StudyError("series: no successful point is selected")
    varying = [c for c in parameter_columns(df) if df[c].nunique(dropna=False) > 1]
    fig, axes = plt.subplots(len(outputs), 1, squeeze=False, sharex=True,
                             figsize=(7, 2.6 * len(outputs) + 0.6))
    for _, row in ok.iterrows():
        path_npz = directory / "series" / f"{row['point_id']}.npz"
        if not path_npz.exists():
            raise StudyError(f"series: {path_npz} is missing: the study keeps series only for "
                             "its `series` outputs")
        data = np.load(path_npz)
        name = ", ".join(f"{c} = {row[c]:g}" if isinstance(row[c], float) else f"{c} = {row[c]}"
                         for c in varying) or row["point_id"]
        for ax, output in zip(axes[:, 0], outputs):
            if output not in data:
                raise StudyError(f"series: {output} is not kept (kept: "
                                 f"{', '.join(k for k in data.files if k not in ('time', 'point'))})")
            ax.plot(data["time"], data[output], lw=1, label=name)
    for ax, output in zip(axes[:, 0], outputs):
        ax.set_ylabel(label(output, units))
        ax.grid(alpha=0.3)
    axes[-1, 0].set_xlabel("time [s]")
    axes[0, 0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
