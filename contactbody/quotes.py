"""Numbers that prose quotes from a results file, checked against that file.

A quoted number carries, right after it, an HTML comment (invisible once rendered) naming the
file and the value in it:

    costs 7.1 ×<!-- benchmarks/results/rate_law_cost.json: full law/ratio_to_constant --> the

The path's segments are keys of a JSON object, indices of a list, or `key=value,...` picking the
one record of a list whose fields have those values (a value with a comma or a slash in double
quotes). A unit or sign may stand between the number
and the comment (`7.1 ×<!-- ... -->`, `2.44 MB<!-- ... -->`). The quote holds when the value,
rounded to the digits the prose shows, is the number shown; `scale=K` after the path multiplies
the value first (a size in bytes quoted in MB: `scale=1e-6`).

A table copied from a results table carries the marker on the line before it,

    <!-- rows of examples/results/stick_slip.md -->

and holds when every one of its rows below the header is a line of that file.

    .venv/bin/python -m contactbody.quotes        # lists every quote and whether it holds
"""
import json
import math
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]

NUMBER = r"(?P<number>[-−]?\d[\d,]*(?:\.\d+)?(?:e[-+−]?\d+)?)"
UNIT = r"(?P<unit>[ \u00a0]?(?:×|x|%|MB|ms|µs|m²|s|J/m|N/m)?)"
QUOTE = re.compile(NUMBER + UNIT + r"<!-- (?P<file>[\w./-]+\.json): (?P<path>[^>]*?)"
                   r"(?: scale=(?P<scale>[-+.\de]+))? -->")
MARKER = re.compile(r"<!-- [\w./-]+\.json: ")
TABLE = re.compile(r"<!-- rows of (?P<file>[\w./-]+\.(?:md|txt)) -->\n(?P<table>(?:\|.*\n?)+)")


def documents():
    """Every Markdown file of the repository outside build trees and environments."""
    skip = {".venv", "build", "third_party", ".git", "dist"}
    return sorted(p for p in ROOT.rglob("*.md")
                  if not skip & set(p.relative_to(ROOT).parts))


def parse_number(text):
    """The value shown and half a unit of its last digit."""
    text = text.replace("−", "-").replace(",", "")
    mantissa, _, exponent = text.partition("e")
    decimals = len(mantissa.partition(".")[2])
    half_unit = 0.5 * 10.0 ** (-decimals + (int(exponent) if exponent else 0))
    return float(text), half_unit


def _split(text, separator):
    """text split at `separator` outside double quotes."""
    parts, current, quoted = [], "", False
    for char in text:
        if char == '"':
            quoted = not quoted
        if char == separator and not quoted:
            parts.append(current)
            current = ""
        else:
            current += char
    return parts + [current]


def _select(node, segment):
    if isinstance(node, list) and "=" in segment:
        wanted = {key: value.strip('"') for key, value in
                  (pair.split("=", 1) for pair in _split(segment, ","))}

        def matches(record):
            for key, value in wanted.items():
                have = record.get(key)
                try:
                    if not math.isclose(float(have), float(value), rel_tol=1e-9):
                        return False
                except (TypeError, ValueError):
                    if str(have) != value:
                        return False
            return True
        found = [r for r in node if matches(r)]
        if len(found) != 1:
            raise KeyError(f"{len(found)} records match {segment}")
        return found[0]
    if isinstance(node, list):
        return node[int(segment)]
    return node[segment]


def value_at(file, path):
    node = json.loads((ROOT / file).read_text())
    for segment in _split(path, "/"):
        node = _select(node, segment)
    return float(node)


def quotes(document):
    """(line, shown, value or error, holds) for each quote in one document; a marker that no
    number precedes is reported as a quote that does not hold."""
    text = document.read_text()
    found = []
    covered = set()
    for match in QUOTE.finditer(text):
        line = text.count("\n", 0, match.start()) + 1
        shown, half_unit = parse_number(match["number"])
        covered.add(match.start("file") - len("<!-- "))
        try:
            value = value_at(match["file"], match["path"]) * float(match["scale"] or 1)
        except (OSError, KeyError, IndexError, ValueError, TypeError) as error:
            found.append((line, match["number"], f"{match['file']}: {match['path']}: {error!r}",
                          False))
            continue
        holds = abs(value - shown) <= half_unit * (1 + 1e-9)
        found.append((line, match["number"], value, holds))
    for match in TABLE.finditer(text):
        line = text.count("\n", 0, match.start()) + 1
        rows = [r.strip() for r in match["table"].splitlines()[2:]]
        try:
            source = {r.strip() for r in (ROOT / match["file"]).read_text().splitlines()}
        except OSError as error:
            found.append((line, "table", f"{match['file']}: {error!r}", False))
            continue
        missing = [r for r in rows if r not in source]
        found.append((line, f"table of {len(rows)} rows",
                      f"{match['file']}" + (f": not there: {missing[0]}" if missing else ""),
                      bool(rows) and not missing))
    for marker in MARKER.finditer(text):
        in_code = marker.start() > 0 and text[marker.start() - 1] == "`"  # shown, not used
        if marker.start() not in covered and not in_code:
            line = text.count("\n", 0, marker.start()) + 1
            found.append((line, "", "no number right before the marker", False))
    return found


def main():
    wrong = 0
    for document in documents():
        for line, shown, value, holds in quotes(document):
            wrong += not holds
            print(f"{'ok ' if holds else 'BAD'} {document.relative_to(ROOT)}:{line}: "
                  f"{shown} <- {value}")
    return 1 if wrong else 0


if __name__ == "__main__":
    sys.exit(main())
