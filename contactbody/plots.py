"""Figures over a study's table: heat maps over two parameters, lines over one."""
from __future__ import annotations

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def heatmap(df, x: str, y: str, value: str, path, title: str | None = None, fmt="{:.3g}"):
    """value over the (x, y) grid, one cell per pair (the mean where several rows share it;
    blank where a point failed). Written as PNG to path."""
    ok = df[df["status"] == "ok"]
    table = ok.pivot_table(index=y, columns=x, values=value, aggfunc="mean")
    table = table.reindex(index=sorted(df[y].unique()), columns=sorted(df[x].unique()))
    fig, ax = plt.subplots(figsize=(1.1 * len(table.columns) + 2.5, 0.6 * len(table) + 2))
    image = ax.imshow(table.to_numpy(dtype=float), origin="lower", aspect="auto", cmap="viridis")
    ax.set_xticks(range(len(table.columns)), [f"{c:g}" for c in table.columns])
    ax.set_yticks(range(len(table.index)), [f"{r:g}" for r in table.index])
    for (i, j), v in np.ndenumerate(table.to_numpy(dtype=float)):
        ax.text(j, i, "failed" if np.isnan(v) else fmt.format(v), ha="center", va="center",
                fontsize=7, color="w" if not np.isnan(v) else "r")
    ax.set(xlabel=x, ylabel=y, title=title or value)
    fig.colorbar(image, ax=ax, label=value)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def lines(df, x: str, value: str, path, hue: str | None = None, title: str | None = None):
    """value against x, one line per value of hue (if given). Written as PNG to path."""
    ok = df[df["status"] == "ok"]
    fig, ax = plt.subplots(figsize=(6.5, 4.2))
    groups = ok.groupby(hue) if hue else [(None, ok)]
    for key, group in groups:
        group = group.sort_values(x)
        ax.plot(group[x], group[value], "o-", ms=3,
                label=f"{hue} = {key:g}" if hue else None)
    ax.set(xlabel=x, ylabel=value, title=title or value)
    if hue:
        ax.legend(fontsize=7)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
