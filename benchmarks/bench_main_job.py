"""Time the main job on inventories/lab.xlsx, phase by phase and end to end.

Run: python benchmarks/bench_main_job.py [--repeat N]
Prints seconds per phase (best of N) and the end-to-end CLI time. Not a test. On a machine shared with
other work, run it when the machine is quiet, or compare runs taken one after the other.
"""
from __future__ import annotations

import argparse
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from timing import best_of

ROOT = Path(__file__).resolve().parents[1]
WORKBOOK = ROOT / "inventories" / "lab.xlsx"


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--repeat", type=int, default=3)
    repeat = parser.parse_args().repeat

    from assess.assessment.pipeline import run_assessment
    from assess.inventory import read_workbook
    from assess.report import render_html, render_pdf

    t_read, inventory = best_of(repeat, lambda: read_workbook(WORKBOOK))
    t_assess, result = best_of(repeat, lambda: run_assessment(inventory, "2in50"))
    t_html, html = best_of(repeat, lambda: render_html(result))
    t_pdf, pdf = best_of(repeat, lambda: render_pdf(html))
    t_pdf_one, _ = best_of(repeat, lambda: render_pdf(html, processes=1))
    cases = len(result.motions)
    runs = int(result.motions["sim_realizations"].sum())
    print(f"workbook: {len(inventory.equipment)} items, {len(inventory.hazard)} hazard rows")
    print(f"read workbook      {t_read:8.3f} s")
    print(f"assess             {t_assess:8.3f} s  ({cases} item x motion x direction cases, {runs} simulated "
          f"runs over the suites: {runs / t_assess:.0f} runs/s, synthesis included)")
    print(f"render html        {t_html:8.3f} s")
    print(f"render pdf         {t_pdf:8.3f} s  ({len(pdf) / 1024:.0f} KiB; the appendix in a second process where "
          "there is a second core)")
    print(f"render pdf, 1 proc {t_pdf_one:8.3f} s  (the body, then the appendix, in this process)")
    with tempfile.TemporaryDirectory() as out:
        start = time.perf_counter()
        subprocess.run([sys.executable, "-m", "assess", str(WORKBOOK), "--hazard", "2in50", "--out", out,
                        "--quiet"], check=True, stdout=subprocess.DEVNULL)
        print(f"end to end (CLI)   {time.perf_counter() - start:8.3f} s  (one run, interpreter start included)")
        start = time.perf_counter()
        subprocess.run([sys.executable, "-m", "assess", str(WORKBOOK), "--hazard", "2in50", "--out", out,
                        "--quiet", "--format", "html"], check=True, stdout=subprocess.DEVNULL)
        print(f"end to end, no PDF {time.perf_counter() - start:8.3f} s  (--format html)")


if __name__ == "__main__":
    main()
