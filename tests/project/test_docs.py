"""The reference pages in docs/ say what the code does: every column and option it has, and none it lacks.

Each check compares a table of a page (the names in its first column) with what the code declares: the
columns of every CSV a run writes (``assess/data/columns.csv``, the table the writers read, with each column's
unit and meaning; and the code's own lists of columns against it), the options of
every command (the argparse parsers of ``assess.cli``), the workbook's columns (``assess.inventory.schema``)
and settings (``assess/data/defaults.toml``). A name the code has and the page lacks, or the page has and the
code no longer does, fails the test with the names.
"""
from __future__ import annotations

import re
from pathlib import Path

import pandas as pd
import pytest

from assess import cli
from assess.assessment.alpha_range import ALPHA_RANGE_COLUMNS
from assess.assessment.result import MOTION_COLUMNS, SUMMARY_COLUMNS
from assess.data import default_settings, output_columns
from assess.fragility.stripes import CURVE_COLUMNS
from assess.inventory.schema import EQUIPMENT, HAZARD

DOCS = Path(__file__).resolve().parents[2] / "docs"
_HEADING = re.compile(r"^(#+)\s+(.*?)\s*$")


def section(page: str, heading: str) -> str:
    """The text of ``page`` under the heading ``heading`` (as written after the #s), up to the next heading."""
    lines = (DOCS / page).read_text(encoding="utf-8").splitlines()
    for start, line in enumerate(lines):
        match = _HEADING.match(line)
        if match and match.group(2) == heading:
            body = []
            for other in lines[start + 1:]:
                if _HEADING.match(other):
                    break
                body.append(other)
            return "\n".join(body)
    raise AssertionError(f"docs/{page} has no heading {heading!r}")


def table_names(text: str) -> list[str]:
    """The names in backticks in the first cell of every table row of ``text`` (header and rule rows
    skipped); ``--hazard LEVEL`` counts as ``--hazard``."""
    names = []
    for line in text.splitlines():
        if not line.startswith("|") or re.match(r"^\|\s*-", line):
            continue
        first = re.split(r"(?<!\\)\|", line)[1]  # a cell's own "|" is written "\|"
        names += [name.split()[0] for name in re.findall(r"`([^`]+)`", first)]
    return names


def compare(documented: list[str], declared: list[str], where: str) -> None:
    missing = [name for name in declared if name not in documented]
    extra = [name for name in documented if name not in declared]
    assert not missing, f"{where}: not documented: {missing}"
    assert not extra, f"{where}: documented but not in the code: {extra}"


def test_table_names_reads_the_first_cell_only():
    text = "| column | unit |\n|---|---|\n| `a_cm`, `b` | `cm` |\n| `--out DIR` | x |\n| `--units si\\|us` | `c` |\nnot a `row`\n"
    assert table_names(text) == ["a_cm", "b", "--out", "--units"]


#: Each file of assess/data/columns.csv, the heading of docs/outputs.md that documents it, and which of the
#: heading's tables (several files under one heading: one table each, in the same order).
OUTPUT_TABLES = {
    "summary.csv": ("`summary.csv`", None),
    "motions.csv": ("`motions.csv`", None),
    "work_orders.csv": ("`work_orders.csv`", None),
    "comparison.csv": ("`comparison.csv`", None),
    "ground_motions.csv": ("With a `site` sheet: `ground_motions.csv` and `spectrum.csv`", 0),
    "spectrum.csv": ("With a `site` sheet: `ground_motions.csv` and `spectrum.csv`", 1),
    "floors.csv": ("With a `building` sheet: `floors.csv`", None),
    "fragility/stripes.csv": ("`fragility/stripes.csv`", None),
    "fragility/fragility.csv": ("`fragility/fragility.csv`", None),
    "fragility/cmp_marginals.csv": ("`fragility/cmp_marginals.csv`", None),
    "calibration_tests.csv": ("`calibration_tests.csv`", None),
    "portfolio.csv": ("`portfolio.csv`", None),
    "changes.csv": ("`changes.csv`", None),
    "summary.xlsx anchorage": ("The `anchorage` sheets", None),
}
#: The files whose column names hold spaces (a unit in brackets): a name is the whole text in backticks.
WHOLE_NAMES = ("summary.xlsx anchorage",)


def test_every_declared_file_has_its_table_on_the_page():
    assert set(OUTPUT_TABLES) == set(output_columns()["file"])


def table_rows(text: str) -> list[dict]:
    """The rows of the markdown tables of ``text``, in order: each a dict of header -> cell (a cell's own "|" is
    written "\\|"), with ``table``, the index of its table in ``text``."""
    rows, header, table = [], None, -1
    for line in text.splitlines() + [""]:
        if not line.startswith("|"):
            header = None
            continue
        cells = [cell.strip() for cell in re.split(r"(?<!\\)\|", line)[1:-1]]
        if header is None:
            header, table = cells, table + 1
        elif not re.match(r"^-+$", cells[0]):
            rows.append({**dict(zip(header, cells)), "table": table})
    return rows


def documented_columns(file: str) -> dict[str, tuple[str, str]]:
    """``column -> (unit, meaning)`` as docs/outputs.md gives them for ``file``; a row naming several columns
    gives each its unit (one for all, or one each: ``m, –``) and the row's meaning."""
    heading, which = OUTPUT_TABLES[file]
    documented = {}
    for row in table_rows(section("outputs.md", heading)):
        if which is not None and row["table"] != which:
            continue
        names = [name if file in WHOLE_NAMES else name.split()[0] for name in re.findall(r"`([^`]+)`", row["column"])]
        units = [unit.strip() for unit in row["unit"].split(",")]
        units = units if len(units) == len(names) else [row["unit"]] * len(names)
        documented.update({name: (unit, row["meaning"]) for name, unit in zip(names, units)})
    return documented


def test_table_rows_splits_tables_and_escaped_bars():
    text = "| column | unit |\n|---|---|\n| `a` | \\|x\\| |\n\nprose\n\n| column | unit |\n|---|---|\n| `b` | cm |\n"
    assert table_rows(text) == [{"column": "`a`", "unit": "\\|x\\|", "table": 0},
                                {"column": "`b`", "unit": "cm", "table": 1}]


@pytest.mark.parametrize("file", list(OUTPUT_TABLES))
def test_every_declared_column_is_documented_with_its_unit_and_meaning(file):
    """docs/outputs.md against assess/data/columns.csv, the table the writers read: the same columns (those
    converted at write time into the report's units are described once, in prose), the same unit and meaning."""
    declared = output_columns()
    declared = declared[(declared["file"] == file) & (declared["stage"] != "report units")]
    documented = documented_columns(file)
    compare(list(documented), list(declared["column"]), f"docs/outputs.md, {file}")
    for row in declared.itertuples(index=False):
        assert documented[row.column] == (row.unit, row.meaning), (
            f"docs/outputs.md, {file}, {row.column}: the page says {documented[row.column]}, "
            f"assess/data/columns.csv says {(row.unit, row.meaning)}")


def test_the_declared_columns_are_the_code_s_columns_in_its_order():
    """The columns the stages make, in the order the code selects them, are the table's, in its order."""
    from assess.assessment.comparison import COMPARISON_COLUMNS
    from assess.decision.actions import WORK_ORDER_COLUMNS

    declared = output_columns()
    declared = declared[declared["stage"] != "report units"]
    for file, columns in (("summary.csv", SUMMARY_COLUMNS + CURVE_COLUMNS + ALPHA_RANGE_COLUMNS),
                          ("motions.csv", MOTION_COLUMNS),
                          ("work_orders.csv", WORK_ORDER_COLUMNS), ("comparison.csv", COMPARISON_COLUMNS)):
        assert list(declared.loc[declared["file"] == file, "column"]) == list(columns), file
    curve = declared[(declared["file"] == "summary.csv") & (declared["when"] == "hazard curve")]
    assert list(curve["column"]) == list(CURVE_COLUMNS)
    alpha = declared[(declared["file"] == "summary.csv") & (declared["when"] == "--alpha-range")]
    assert list(alpha["column"]) == list(ALPHA_RANGE_COLUMNS)


def test_the_declared_columns_of_the_other_files_are_the_code_s_in_its_order():
    """The fragility folder's (pelicun's columns, as its library and ``load_cmp_model`` name them), the
    calibration's and ``assess batch``'s: the lists the code selects them by, and a portfolio row as the code
    makes it (every risk class and action kind, and the curve's columns)."""
    from assess.calibration import DIAGNOSIS_COLUMNS, RESIDUAL_COLUMNS
    from assess.fragility import pelicun_export
    from assess.portfolio.report import CHANGE_COLUMNS, CURVE_FIELDS, building_row

    declared = output_columns()

    def columns(file):
        return list(declared.loc[declared["file"] == file, "column"])

    assert columns("fragility/fragility.csv") == list(pelicun_export.COLUMNS)
    assert columns("fragility/cmp_marginals.csv") == list(pelicun_export.COMPONENT_COLUMNS)
    assert columns("fragility/stripes.csv") == ["id", "mode", "pfa_g", "pga_g", "trials", "failures"]
    residuals = [c for c in RESIDUAL_COLUMNS if c not in ("specimen", "motion", "direction")]
    assert columns("calibration_tests.csv") == (DIAGNOSIS_COLUMNS + [f"{c}_before" for c in residuals]
                                                + [f"{c}_after" for c in residuals])
    assert columns("changes.csv") == CHANGE_COLUMNS
    summary = pd.DataFrame({"quantity": [2], "risk": ["high"], "action_kind": ["anchor"],
                            **{field: ["0.01"] for field in CURVE_FIELDS}})
    row = building_row("b", "b.xlsx", "2in50", "curve.csv", summary, simulated=4, reused=0)
    assert columns("portfolio.csv") == list(row)


def test_the_us_columns_follow_their_si_column():
    """A column converted into US units at write time stands right after the SI column it converts, with the
    unit of its name (``_in``, ``_kip``, ``_kip_ft``) and "per report units"."""
    declared = output_columns()
    summary = declared[declared["file"] == "summary.csv"].reset_index(drop=True)
    us = summary[summary["stage"] == "report units"]
    assert len(us) >= 10
    for index, row in us.iterrows():
        before = summary.loc[index - 1, "column"]
        assert row.column == before[:-len("_cm")] + "_in" and row.unit == "in (per report units)", row.column
        assert f"`{before}` in inches" in row.meaning


PARSERS = {
    "`assess WORKBOOK`": cli.build_parser,
    "`assess simulate`": cli.build_simulate_parser,
    "`assess calibrate`": cli.build_calibrate_parser,
    "`assess batch`": cli.build_batch_parser,
}


def _declared_arguments(parser) -> list[str]:
    """Every option (its long name) and positional argument (its metavar) of ``parser``, help aside."""
    names = []
    for action in parser._actions:  # argparse keeps its arguments here; it has no public list
        if "--help" in action.option_strings:
            continue
        if action.option_strings:
            names.append(max(action.option_strings, key=len))
        else:
            names.append(action.metavar or action.dest)
    return names


@pytest.mark.parametrize("heading", list(PARSERS))
def test_every_option_of_every_command_is_documented(heading):
    declared = _declared_arguments(PARSERS[heading]())
    assert len(declared) >= 5  # the parser was read, not an empty list
    compare(table_names(section("commands.md", heading)), declared, f"docs/commands.md, {heading}")


def test_the_usage_block_names_every_option():
    usage = (DOCS / "commands.md").read_text(encoding="utf-8").split("```")[1]
    for heading, build in PARSERS.items():
        missing = [name for name in _declared_arguments(build()) if name not in usage]
        assert not missing, f"docs/commands.md, usage of {heading}: {missing}"


def _header_names(spec) -> list[str]:
    """The sheet's columns as the page writes them: a quantity with its documented suffix (``height_cm``)."""
    return [column.header() for column in spec.columns]


def test_every_equipment_column_is_documented():
    compare(table_names(section("workbook.md", "Sheet `equipment` (required)")), _header_names(EQUIPMENT),
            "docs/workbook.md, equipment")


def test_every_hazard_column_is_documented():
    compare(table_names(section("workbook.md", "Sheet `hazard` (required)")), _header_names(HAZARD),
            "docs/workbook.md, hazard")


def test_every_setting_is_documented_with_its_default():
    text = section("workbook.md", "Sheet `settings` (optional)")
    settings = default_settings()
    compare(table_names(text), list(settings), "docs/workbook.md, settings")
    rows = {re.findall(r"`([^`]+)`", line.split("|")[1])[0]: line.split("|")[2].strip()
            for line in text.splitlines() if line.startswith("| `")}
    for key, default in settings.items():
        shown = rows[key]
        if isinstance(default, str):
            assert shown == (f"`{default}`" if default else "empty"), (key, shown)
        elif default == 0.0:
            assert shown == "not given", (key, shown)  # 0 stands for "not given" (defaults.toml)
        else:
            assert float(shown) == pytest.approx(default), (key, shown)


def test_no_page_cites_a_contract_outside_the_project():
    """The pages are the contract: they never send the reader to a file the repository does not hold."""
    for page in sorted(DOCS.glob("*.md")):
        assert not re.search(r"\bSPEC\b", page.read_text(encoding="utf-8")), page.name


#: A path of the repository as the pages write it, e.g. ``tests/portfolio/test_batch.py::test_name``.
#: (A path inside another folder, ``~/venvs/assess/bin``, is not one; ``*`` is a wildcard.)
_PATH = re.compile(r"(?<![\w/~.-])((?:tests|assess|benchmarks|inventories|templates)/[\w./*-]*[\w*])(?:::(\w+))?")


def test_every_file_and_test_the_pages_name_is_there():
    """A page that sends the reader to ``tests/test_batch.py`` after the tests moved to their folders sends
    them nowhere (nine such paths were left by the move): every path the README and the pages name exists,
    and every ``file.py::test`` names a test of that file."""
    root = DOCS.parent
    missing, checked = [], 0
    for page in [root / "README.md", *sorted(DOCS.glob("*.md"))]:
        for path, test in _PATH.findall(page.read_text(encoding="utf-8")):
            checked += 1
            target = root / path
            if not (any(root.glob(path)) if "*" in path else target.exists()):
                missing.append(f"{page.name}: {path}")
            elif test and not re.search(rf"^def {test}\(", target.read_text(encoding="utf-8"), re.M):
                missing.append(f"{page.name}: {path}::{test}")
    assert checked > 50 and not missing, missing


def _anchor(heading: str) -> str:
    """GitHub's anchor of a heading: lower case, punctuation other than - and _ dropped, spaces made -."""
    return re.sub(r"[^\w\- ]", "", heading.lower()).replace(" ", "-")


def test_every_link_between_the_pages_lands_on_a_heading():
    anchors = {page.name: {_anchor(m.group(2)) for m in map(_HEADING.match, page.read_text().splitlines()) if m}
               for page in DOCS.glob("*.md")}
    broken, checked = [], 0
    for page in sorted(DOCS.glob("*.md")):
        for target, anchor in re.findall(r"\]\(([\w.-]+\.md)?(?:#([\w-]+))?\)", page.read_text()):
            target, checked = target or page.name, checked + 1
            if target not in anchors or (anchor and anchor not in anchors[target]):
                broken.append(f"{page.name} -> {target}#{anchor}")
    assert checked > 20 and not broken, broken


def test_every_key_of_simulate_json_is_documented():
    """``assess simulate --json`` prints :meth:`ItemSimulation.as_dict`; its keys (a pulse's run, which adds
    ``regression``) against the table of docs/commands.md."""
    import math

    from assess.assessment.simulation import ItemSimulation
    from assess.hazard.records import pulse_record
    from assess.mechanics.block import Block, BlockResponse

    response = BlockResponse(sliding_max_m=0.1, sliding_residual_m=0.05, theta_max_over_alpha=0.0, uplift=False,
                             overturned=False, overturn_time_s=math.nan, mode_sequence=((0.0, "slide"),),
                             solver="sliding kernel")
    run = ItemSimulation(block=Block(half_width_m=0.3, cg_height_m=1.0, height_m=2.0, mu=0.2),
                         motion=pulse_record("B", 0.5, 1.0), response=response, pulse_period_s=1.0, im=1.5,
                         regression_sliding_median_m=0.05)
    compare(table_names(section("commands.md", "What `assess simulate` prints")), list(run.as_dict()),
            "docs/commands.md, assess simulate --json")
