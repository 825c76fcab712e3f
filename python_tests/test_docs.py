"""Documentation that stands alone: the variable table matches the build, every
document the READMEs link exists in the repository, and no variable description points to
files a user does not have."""
import json
import re

import fmpy

from conftest import FMU, ROOT
from contactbody.docs import variable_table
from contactbody.tools.quotes import documents, quotes

DOCUMENTS = [ROOT / "README.md", ROOT / "examples" / "README.md", *sorted((ROOT / "docs").glob("*.md"))]


def test_variable_table_is_generated_from_this_build():
    assert (ROOT / "docs" / "variables.md").read_text() == variable_table(FMU), \
        "regenerate: .venv/bin/python -m contactbody.docs > docs/variables.md"


def test_every_linked_document_exists():
    checked = 0
    for document in DOCUMENTS:
        text = document.read_text()
        for target in re.findall(r"\]\(([^)\s]+)\)", text):
            if re.match(r"[a-z]+://", target) or target.startswith("#"):
                continue
            path = (document.parent / target.split("#")[0]).resolve()
            assert path.exists(), f"{document.relative_to(ROOT)} links {target}, which is missing"
            assert ROOT in path.parents, f"{document.relative_to(ROOT)} links outside the repository: {target}"
            checked += 1
        for target in re.findall(r"`([\w./-]+\.(?:md|py|toml|cpp|hpp))`", text):
            candidates = [document.parent / target, ROOT / target]
            if "/" in target:
                assert any(c.exists() for c in candidates), \
                    f"{document.relative_to(ROOT)} names {target}, which is missing"
                checked += 1
    assert checked > 20


def test_descriptions_point_to_no_missing_files():
    md = fmpy.read_model_description(str(FMU))
    for v in md.modelVariables:
        assert not re.search(r"SPEC|\.\./|\.md\b", v.description or ""), v.name


def test_readme_is_the_front_door():
    """What it is, the two commands, a quick start, which settings, where to
    read on; the depth is in docs/ (whose links the test above checks)."""
    text = (ROOT / "README.md").read_text()
    assert len(text.splitlines()) <= 150
    for needed in ("scripts/run_paper_scene.sh", "scripts/test.sh", "```python",
                   "**Which settings to use.**", "## Where to read on"):
        assert needed in text, needed
    for document in ("docs/contract.md", "docs/user_guide.md", "docs/studies.md",
                     "docs/system_models.md", "docs/decisions.md"):
        assert f"]({document})" in text, document


def test_numbers_quoted_from_results_files_hold():
    """A number that prose quotes from a results file carries a marker naming
    the file and the value (contactbody/tools/quotes.py); each is the value rounded as shown."""
    found = {document: quotes(document) for document in documents()}
    wrong = [f"{d.relative_to(ROOT)}:{line}: {shown} against {value}"
             for d, entries in found.items() for line, shown, value, holds in entries if not holds]
    assert not wrong, "\n".join(wrong)
    assert sum(map(len, found.values())) >= 250  # markers are not dropped unnoticed


def test_quote_checker_catches_a_wrong_number(tmp_path, monkeypatch):
    results = tmp_path / "r.json"
    results.write_text('{"runs": [{"n": 1, "ratio": 7.129}, {"n": 2, "ratio": 0.7649}, '
                       '{"n": 3, "scene": "a, b/c", "ratio": 2.5}]}')
    monkeypatch.setattr("contactbody.tools.quotes.ROOT", tmp_path)
    page = tmp_path / "p.md"
    page.write_text("a 7.1 ×<!-- r.json: runs/n=1/ratio --> b 0.77<!-- r.json: runs/n=2/ratio -->"
                    " c 7.12<!-- r.json: runs/0/ratio --> d <!-- r.json: runs/1/ratio -->"
                    " e 3<!-- r.json: runs/n=4/ratio -->"
                    ' f 2.5 ms<!-- r.json: runs/scene="a, b/c"/ratio -->')
    assert [holds for _, _, _, holds in quotes(page)] == [True, False, False, False, True, False]


def test_table_checker_catches_a_changed_row(tmp_path, monkeypatch):
    """A table marked as copied from a results table holds only while every row below its
    header is a line of that file."""
    (tmp_path / "r.md").write_text("| a | b |\n|---|---|\n| 1 | 2.5 |\n| 2 | 3.5 |\n")
    monkeypatch.setattr("contactbody.tools.quotes.ROOT", tmp_path)
    page = tmp_path / "p.md"
    table = "| a | b |\n|---|---|\n| 1 | 2.5 |\n| 2 | {} |\n"
    page.write_text("<!-- rows of r.md -->\n" + table.format("3.5") + "\ntext\n\n"
                    "<!-- rows of r.md -->\n" + table.format("3.6") +
                    "\n<!-- rows of missing.md -->\n" + table.format("3.5"))
    assert [holds for _, _, _, holds in quotes(page)] == [True, False, False]


def test_generated_table_ratio_and_text_lines_are_checked(tmp_path, monkeypatch):
    """A table generated from a results file holds only while it is what its generator makes of
    the file (contactbody/tools/doc_tables.py); a ratio quote is the ratio of the two values; lines
    copied from a text results file into a fenced block must be lines of it."""
    from contactbody.tools import doc_tables
    data = {"impact": [{"mass_matrix": "standard", "dt": 4e-6, "energy_ratio": 7.4228,
                        "contact_intervals": 2},
                       {"mass_matrix": "standard", "dt": 1e-6, "energy_ratio": 12.1523,
                        "contact_intervals": 4}]}
    (tmp_path / "s.json").write_text(json.dumps(data))
    (tmp_path / "r.txt").write_text("h  mean\n2  11.41\n1  23.98\n")
    monkeypatch.setattr("contactbody.tools.quotes.ROOT", tmp_path)
    good = doc_tables.GENERATORS["impact"](data)
    assert "| standard | 4e-6 / 1e-6 | 7.4228 / 12.1523 | 2 / 4 |" in good
    page = tmp_path / "p.md"
    page.write_text("<!-- table impact from s.json -->\n" + good + "\n"
                    "<!-- table impact from s.json -->\n" + good.replace("12.1523", "11.07") + "\n"
                    "a 1.64×<!-- s.json: impact/1/energy_ratio ÷ impact/0/energy_ratio --> "
                    "b 1.7×<!-- s.json: impact/1/energy_ratio ÷ impact/0/energy_ratio -->\n\n"
                    "<!-- rows of r.txt -->\n```\nh  mean\n2  11.41\n```\n\n"
                    "<!-- rows of r.txt -->\n```\n2  11.40\n```\n")
    assert [holds for _, _, _, holds in sorted(quotes(page), key=lambda q: (q[0], q[1]))] == [
        True, False, True, False, True, False]
    doc_tables.write(page, tmp_path)  # --write regenerates the stale table
    assert [holds for _, _, _, holds in quotes(page)].count(False) == 2


def test_the_contact_solve_cost_model_is_the_measured_crossover():
    """Stepper's kappa(F) = kappa_0 + kappa_F F lies, at every friction coefficient measured,
    above every (2 n_c)^2 / n_f where the condensed solve was clearly faster and below every
    one where the sparse solve was (benchmarks/contact_crossover.py)."""
    header = (ROOT / "solver" / "body" / "stepper.hpp").read_text()
    k0, kf = map(float, re.search(r"sparse_contact_kappa_0 = ([0-9.]+), sparse_contact_kappa_F = "
                                  r"([0-9.]+);", header).groups())
    measured = json.loads((ROOT / "benchmarks" / "results" / "contact_crossover.json").read_text())
    assert len(measured["kappa_bounds"]) >= 3
    for friction, b in measured["kappa_bounds"].items():
        kappa = k0 + kf * float(friction)
        assert b["above"] < kappa, friction
        assert b["below"] is None or kappa < b["below"], friction


def _decision_headings():
    text = (ROOT / "docs" / "decisions.md").read_text()
    return text, [h.strip() for h in re.findall(r"^#{2,3} (.+)$", text, re.M) if h.strip() != "Contents"]


def test_decisions_have_a_heading_each_and_a_table_of_contents():
    """docs/decisions.md: one heading per decision, every one listed in its contents."""
    text, headings = _decision_headings()
    assert len(headings) > 50
    contents = text.split("## Contents", 1)[1].split("\n## ", 1)[0]
    listed = re.findall(r"^\s*- \[(.+)\]\(#([^)]+)\)$", contents, re.M)
    assert [title for title, _ in listed] == headings


def test_comments_name_decisions_that_exist():
    """A comment or document that names a decision ("docs/decisions.md, "Far travel ..."") names
    the start of one of its headings."""
    _, headings = _decision_headings()
    named = 0
    for folder in ("solver", "fmu_src", "docs", "examples", "benchmarks", "contactbody", "cmake"):
        for path in (ROOT / folder).rglob("*"):
            if path.suffix not in {".cpp", ".hpp", ".md", ".py", ".cmake"}:
                continue
            for name in re.findall(r'decisions\.md`?,? "([^"]+)"', path.read_text(errors="replace")):
                name = " ".join(re.sub(r"//|#", " ", name).split())  # a name wrapped in a comment
                assert any(h.startswith(name) for h in headings), f"{path.relative_to(ROOT)} names \"{name}\""
                named += 1
    assert named >= 10


def test_no_issue_numbers_in_code_docs_or_examples():
    """Issues are the tracker's: code, docs and examples say what and why without them (an
    upstream project's issue is named by its repository, owner/name#N)."""
    found = []
    for folder in ("solver", "fmu_src", "docs", "examples"):
        for path in (ROOT / folder).rglob("*"):
            if not path.is_file() or path.suffix not in {".cpp", ".hpp", ".h", ".md", ".py", ".txt"}:
                continue
            for line_number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
                if re.search(r"\bissues? #?\d+", line, re.I):
                    found.append(f"{path.relative_to(ROOT)}:{line_number}")
    assert not found, found


def test_every_benchmark_is_in_the_benchmarks_readme():
    """benchmarks/README.md names every benchmark script and every results file's stem."""
    text = (ROOT / "benchmarks" / "README.md").read_text()
    missing = [p.name for p in (ROOT / "benchmarks").glob("*.py") if f"`{p.name}`" not in text]
    assert not missing, missing
    stems = {p.name.split(".")[0] for p in (ROOT / "benchmarks" / "results").iterdir()}
    unnamed = [s for s in sorted(stems) if f"`{s}`" not in text and f"`{s}.json`" not in text]
    assert not unnamed, unnamed
