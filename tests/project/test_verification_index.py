"""tests/verification/README.md, the index of the physical claims, cannot rot: every test a row names exists
(the file, and a test function of that name in it), every row gives a claim, a source and a tolerance, and every
test file of tests/verification/ is named by at least one row."""
import ast
import re
from pathlib import Path

VERIFICATION = Path(__file__).resolve().parents[1] / "verification"
INDEX = VERIFICATION / "README.md"
#: A row of the index's table: | claim | file::function | source | tolerance |
ROW = re.compile(r"^\|(?P<claim>[^|]+)\|\s*(?P<file>[\w/]+\.py)::(?P<function>\w+)\s*\|(?P<source>[^|]+)\|"
                 r"(?P<tolerance>[^|]+)\|\s*$")


def index_rows(text: str) -> list[dict]:
    """The table rows that name a test, as dicts of the four columns (stripped)."""
    return [{key: value.strip() for key, value in match.groupdict().items()}
            for match in map(ROW.match, text.splitlines()) if match]


def defined_tests(path: Path) -> set[str]:
    """The names of the test functions defined at the top of ``path``."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    return {node.name for node in tree.body if isinstance(node, ast.FunctionDef) and node.name.startswith("test_")}


def test_the_row_reader_reads_a_row_and_only_rows():
    text = ("| Claim | Test (file::function) | Source | Tolerance |\n|---|---|---|---|\n"
            "| Newmark | test_sliding.py::test_newmark_rectangular_pulse_table | Newmark 1965 | rel 1e-12 |\n"
            "prose naming test_sliding.py::test_x\n")
    assert index_rows(text) == [{"claim": "Newmark", "file": "test_sliding.py",
                                 "function": "test_newmark_rectangular_pulse_table", "source": "Newmark 1965",
                                 "tolerance": "rel 1e-12"}]


def test_every_test_the_index_names_exists():
    rows = index_rows(INDEX.read_text(encoding="utf-8"))
    assert len(rows) >= 50
    missing = []
    for row in rows:
        path = VERIFICATION / row["file"]
        if not path.is_file():
            missing.append(f"{row['file']} (no such file in tests/verification/)")
        elif row["function"] not in defined_tests(path):
            missing.append(f"{row['file']}::{row['function']} (no such test)")
    assert not missing, "tests/verification/README.md names tests that do not exist:\n" + "\n".join(missing)


def test_every_row_has_a_claim_a_source_and_a_tolerance():
    rows = index_rows(INDEX.read_text(encoding="utf-8"))
    empty = [f"{row['file']}::{row['function']}" for row in rows
             if not (row["claim"] and row["source"] and row["tolerance"])]
    assert not empty


def test_every_verification_file_is_in_the_index():
    named = {row["file"] for row in index_rows(INDEX.read_text(encoding="utf-8"))}
    files = {path.name for path in VERIFICATION.glob("test_*.py")}
    assert files - named == set(), "add a row to tests/verification/README.md for each of these files"
