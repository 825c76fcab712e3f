"""Documentation that stands alone (issue 15): the variable table matches the build, every
document the READMEs link exists in the repository, and no variable description points to
files a user does not have."""
import re

import fmpy

from conftest import FMU, ROOT
from contactbody.docs import variable_table

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
    """Issue 24, item 8: what it is, the two commands, a quick start, which settings, where to
    read on; the depth is in docs/ (whose links the test above checks)."""
    text = (ROOT / "README.md").read_text()
    assert len(text.splitlines()) <= 150
    for needed in ("scripts/run_paper_scene.sh", "scripts/test.sh", "```python",
                   "**Which settings to use.**", "## Where to read on"):
        assert needed in text, needed
    for document in ("docs/contract.md", "docs/user_guide.md", "docs/studies.md",
                     "docs/system_models.md", "docs/decisions.md"):
        assert f"]({document})" in text, document
