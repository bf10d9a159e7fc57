"""What a reader of a job's report sees that a layout change can spoil, measured from the job's folder.

Run: python benchmarks/report_layout.py OUT_DIR [OUT_DIR ...]   (an ``assess WORKBOOK --out OUT_DIR`` folder)

For each folder it prints:

* Fig. 2 against the tables: each freestanding item's point (:func:`assess.report.figures.fragility_points`
  on ``summary.csv``) as a percentage, against the "Past room" cell of the item's row of the all-items table
  of ``report.html``; the number that disagree (0: the figure reads the tables' number), and how many the
  regression's Pf at the governing motion (``pf_sliding``, what the figure drew until it read the tables'
  number) would;
* the flags' lead sentence (how many causes and items the report lists);
* the lines of text on each page of the report's body (``pdftotext``, poppler-utils): a page with a handful
  of lines is a page a forced break wasted.
"""
from __future__ import annotations

import re
import shutil
import subprocess
import sys
from pathlib import Path
from types import SimpleNamespace

import pandas as pd

from assess.quantity_text import percent_text
from assess.report.figures import fragility_points


def _sources(text) -> tuple:
    return tuple(part.strip() for part in str(text).split("+") if part.strip()) if isinstance(text, str) else ()


def figure_against_table(folder: Path) -> tuple[int, int, int]:
    """(items drawn in Fig. 2, items whose point reads otherwise than their "Past room" cell, items whose
    regression Pf does)."""
    summary = pd.read_csv(folder / "summary.csv")
    summary["demand_source"] = summary["demand_source"].map(_sources)
    points = fragility_points(SimpleNamespace(summary=summary))
    html = (folder / "report.html").read_text(encoding="utf-8")
    table = html[html.index('id="all-items-table"'):]
    cells = dict(re.findall(r'<a class="id" href="#item-[^"]+">([^<]+)</a></td>.*?<td class="num c-pfa">([^<]+)<',
                            table, re.S))
    shown = {key: value.replace("&lt;", "<").replace("&gt;", ">") for key, value in cells.items()}
    wrong = [(item, percent_text(chance), shown.get(item)) for item, chance in zip(points["id"], points["chance"])
             if percent_text(chance) != shown.get(item)]
    for item, drawn, cell in wrong:
        print(f"  {item}: drawn at {drawn}, its table says {cell}")
    pf = summary.set_index("id").loc[points["id"], "pf_sliding"]
    regression_wrong = sum(percent_text(value) != shown.get(item) for item, value in pf.items())
    return len(points), len(wrong), regression_wrong


def body_lines_per_page(pdf: Path) -> list[int]:
    """Lines of text on each page of the report before its appendix."""
    if shutil.which("pdftotext") is None:
        return []
    text = subprocess.run(["pdftotext", "-layout", str(pdf), "-"], capture_output=True, text=True).stdout
    found = re.findall(r"Page \d+ of (\d+)", text)
    pages = int(found[0]) if found else 0
    return [sum(1 for line in subprocess.run(["pdftotext", "-f", str(k), "-l", str(k), "-layout", str(pdf), "-"],
                                             capture_output=True, text=True).stdout.splitlines() if line.strip())
            for k in range(1, pages + 1)]


def main(folders: list[str]) -> None:
    for name in folders:
        folder = Path(name)
        drawn, wrong, regression_wrong = figure_against_table(folder)
        html = (folder / "report.html").read_text(encoding="utf-8")
        lead = re.search(r'<h2 id="flags">Flags</h2>\s*<p class="lead">([^<]*)</p>', html)
        print(f"{folder}: Fig. 2 draws {drawn} items, {wrong} disagree with the table "
              f"(at the regression's Pf {regression_wrong} would); "
              f"flags: {lead.group(1) if lead else 'none'}")
        print(f"  body lines per page: {body_lines_per_page(folder / 'report.pdf')}")


if __name__ == "__main__":
    main(sys.argv[1:])
