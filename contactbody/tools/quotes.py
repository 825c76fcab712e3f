"""Numbers that prose quotes from a results file, checked against that file.

A quoted number carries, right after it, an HTML comment (invisible once rendered) naming the
file and the value in it:

    costs 7.1 ×<!-- benchmarks/results/rate_law_cost.json: full law/ratio_to_constant --> the

The path's segments are keys of a JSON object, indices of a list, or `key=value,...` picking the
one record of a list whose fields have those values (a value with a comma or a slash in double
quotes); `PATH ÷ PATH` and `PATH − PATH` quote the ratio and the difference of two values of
the file, `min PATH` and `max PATH` the extremes over its `*` segments (every item of a list
or value of an object), `=NAME` a value that contactbody/tools/doc_tables.py computes from it. A
unit or sign may stand between the number and the comment (`7.1 ×<!-- ... -->`, `2.44 MB<!-- ... -->`). The quote holds when the value,
rounded to the digits the prose shows, is the number shown; `scale=K` after the path multiplies
the value first (a size in bytes quoted in MB: `scale=1e-6`).

A table copied from a results table carries the marker on the line before it,

    <!-- rows of examples/results/stick_slip.md -->

and holds when every one of its rows below the header is a line of that file. Lines of a text
results file are copied the same way into a fenced block after the marker. A table that
reshapes a results file is generated from it (contactbody/tools/doc_tables.py) and marked

    <!-- table convergence from examples/results/convergence.json -->

It holds when it is what that generator makes of the file today.

    .venv/bin/python -m contactbody.tools.quotes        # lists every quote and whether it holds
"""
import json
import math
import re
import sys

from contactbody.tools import doc_tables
from contactbody.tools.doc_tables import ROOT, documents  # noqa: F401 (quotes.documents, too)


NUMBER = r"(?P<number>[-−]?\d[\d,]*(?:\.\d+)?(?:e[-+−]?\d+)?)"
UNIT = r"(?P<unit>[ \u00a0]?(?:×|x|%|MB|kB|ms|µs|m²|s|J/m|J|kN/m|N/m|m/s|rad/s|/s|kHz|Hz|MPa|Pa|cm|mm|µm|m)?)"
QUOTE = re.compile(NUMBER + UNIT + r"<!-- (?P<file>[\w./-]+\.json): (?P<path>[^>]*?)"
                   r"(?: scale=(?P<scale>[-+.\de]+))? -->")
MARKER = re.compile(r"<!-- [\w./-]+\.json: ")
TABLE = re.compile(r"<!-- rows of (?P<file>[\w./-]+\.(?:md|txt)) -->\n"
                   r"(?:(?P<table>(?:\|.*\n?)+)|```\n(?P<block>(?:(?!```).*\n)*)```)")


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
    return node[segment.strip('"')]


def value_at(file, path):
    """The value at `path` in `file`; `A ÷ B` and `A − B` combine two values of the file."""
    for operator, combine in ((" ÷ ", lambda a, b: a / b), (" − ", lambda a, b: a - b)):
        if operator in path:
            left, _, right = path.partition(operator)
            return combine(value_at(file, left), value_at(file, right))
    node = json.loads((ROOT / file).read_text())
    if path.startswith("="):  # a value computed from the file (contactbody/tools/doc_tables.py)
        return float(doc_tables.DERIVED[path[1:]](node))
    for name, aggregate in (("min ", min), ("max ", max)):
        if path.startswith(name):
            return float(aggregate(_values(node, _split(path[len(name):], "/"))))
    for segment in _split(path, "/"):
        node = _select(node, segment)
    return float(node)


def _values(node, segments):
    """Every value at a path whose `*` segments range over a list's items or an object's values."""
    if not segments:
        return [node]
    head, rest = segments[0], segments[1:]
    if head == "*":
        items = node if isinstance(node, list) else list(node.values())
        return [v for item in items for v in _values(item, rest)]
    return _values(_select(node, head), rest)


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
        rows = ([r.strip() for r in match["table"].splitlines()[2:]] if match["table"]
                else [r.strip() for r in match["block"].splitlines() if r.strip()])
        try:
            source = {r.strip() for r in (ROOT / match["file"]).read_text().splitlines()}
        except OSError as error:
            found.append((line, "table", f"{match['file']}: {error!r}", False))
            continue
        missing = [r for r in rows if r not in source]
        found.append((line, f"table of {len(rows)} rows",
                      f"{match['file']}" + (f": not there: {missing[0]}" if missing else ""),
                      bool(rows) and not missing))
    for match in doc_tables.MARKER.finditer(text):
        line = text.count("\n", 0, match.start()) + 1
        try:
            expected = doc_tables.generate(match["name"], match["file"], ROOT)
        except (OSError, KeyError, ValueError, TypeError) as error:
            found.append((line, f"table {match['name']}", f"{match['file']}: {error!r}", False))
            continue
        shown = match["table"]
        differs = [(a, b) for a, b in zip(shown.splitlines(), expected.splitlines()) if a != b]
        holds = shown.strip() == expected.strip()
        found.append((line, f"table {match['name']}", f"{match['file']}" + (
            "" if holds else f": shown {differs[0][0] if differs else shown.strip()[-60:]!r}, "
            f"generated {differs[0][1] if differs else expected.strip()[-60:]!r} "
            "(python -m contactbody.tools.doc_tables --write)"), holds))
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
