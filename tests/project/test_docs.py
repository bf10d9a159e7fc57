"""The reference pages in docs/ say what the code does: every column and option it has, and none it lacks.

Each check compares a table of a page (the names in its first column) with what the code declares: the
columns of summary.csv and motions.csv (``assess.assessment.result``, ``assess.fragility.stripes``), the options of
every command (the argparse parsers of ``assess.cli``), the workbook's columns (``assess.inventory.schema``)
and settings (``assess/data/defaults.toml``). A name the code has and the page lacks, or the page has and the
code no longer does, fails the test with the names.
"""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from assess import cli
from assess.assessment.result import MOTION_COLUMNS, SUMMARY_COLUMNS
from assess.data import default_settings
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


def test_every_summary_column_is_documented():
    compare(table_names(section("outputs.md", "`summary.csv`")), SUMMARY_COLUMNS + CURVE_COLUMNS,
            "docs/outputs.md, summary.csv")


def test_every_work_orders_column_is_documented():
    from assess.decision.actions import WORK_ORDER_COLUMNS
    compare(table_names(section("outputs.md", "`work_orders.csv`")), WORK_ORDER_COLUMNS,
            "docs/outputs.md, work_orders.csv")


def test_every_motions_column_is_documented():
    compare(table_names(section("outputs.md", "`motions.csv`")), MOTION_COLUMNS, "docs/outputs.md, motions.csv")


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
