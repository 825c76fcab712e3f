"""The results table as a journal: results.csv, one flushed line per finished point, and
results.parquet rewritten from it."""
from __future__ import annotations

import csv
import io
import os
import pathlib


class Table:
    """results.csv (the journal: one flushed line per finished point) and results.parquet."""

    def __init__(self, directory, columns: list[str]):
        self.directory = pathlib.Path(directory)
        self.directory.mkdir(parents=True, exist_ok=True)
        self.csv = self.directory / "results.csv"
        self.parquet = self.directory / "results.parquet"
        self.columns = columns
        if self.csv.exists() and self.csv.stat().st_size > 0:
            with open(self.csv, newline="") as f:
                header = next(csv.reader(f), None)
            if header != columns:
                raise ValueError(f"{self.csv} holds another study's table (columns {header}); "
                                 "give another output directory")
        else:
            self._write_line(columns)

    def _write_line(self, values):
        buffer = io.StringIO()
        csv.writer(buffer).writerow(values)
        fd = os.open(self.csv, os.O_WRONLY | os.O_APPEND | os.O_CREAT, 0o644)
        try:  # one write: a killed study leaves whole lines (a torn last one is ignored)
            os.write(fd, buffer.getvalue().encode())
            os.fsync(fd)
        finally:
            os.close(fd)

    def append(self, record: dict):
        self._write_line([_format(record.get(c)) for c in self.columns])

    def frame(self):
        import pandas as pd
        with open(self.csv, newline="") as f:
            text = f.read()
        if not text.endswith("\n"):  # the last line of a killed run may be torn
            text = text[:text.rfind("\n") + 1]
        # a parameter a point does not set: NaN
        df = pd.read_csv(io.StringIO(text), dtype={"message": str, "status": str})
        df["message"] = df["message"].fillna("")
        return df.drop_duplicates("point_id", keep="last").reset_index(drop=True)

    def write_parquet(self):
        df = self.frame()
        tmp = self.parquet.with_suffix(".parquet.tmp")
        df.to_parquet(tmp, index=False)
        os.replace(tmp, self.parquet)
        return df


def _format(value):
    if isinstance(value, float):
        return repr(value)  # round-trips exactly
    return "" if value is None else value
