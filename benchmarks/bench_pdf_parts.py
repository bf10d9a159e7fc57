"""The CPU seconds WeasyPrint takes to draw each part of the lab report's PDF, and the merge.

Run: python benchmarks/bench_pdf_parts.py [--repeat 4] [--html report.html ...]

Without ``--html`` it writes the lab report's HTML (inventories/lab.xlsx, hazard 2in50) and draws that.
Each HTML is split as :func:`assess.report.pdf.render_pdf` splits it (the body, which the main job lays out
in a second process, and Appendix A, which it lays out in its own), and :func:`~assess.report.pdf.render_part`
of each part is timed with ``time.process_time`` (best of ``--repeat``, the HTML files taken in turn, so that a
busy machine weighs on each alike), then :func:`~assess.report.pdf.merge` of the two PDFs (the main job joins
them in the second process, after the body). The main job waits for the larger of the two parts, then the merge.

Not a test.
"""
from __future__ import annotations

import argparse
import time
from pathlib import Path


def lab_html() -> str:
    from assess.assessment.pipeline import run_assessment
    from assess.inventory import read_workbook
    from assess.report import render_html

    root = Path(__file__).resolve().parents[1]
    return render_html(run_assessment(read_workbook(root / "inventories" / "lab.xlsx"), "2in50"))


def main() -> None:
    from assess.report.pdf import merge, render_part, split_appendix

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=4)
    parser.add_argument("--html", nargs="*", type=Path, default=[])
    arguments = parser.parse_args()
    documents = {str(path): path.read_text() for path in arguments.html} or {"lab": lab_html()}
    parts = {name: split_appendix(html) for name, html in documents.items()}
    render_part("<html><body><p>warm</p></body></html>")  # fonts and imports, once
    best = {(name, part): float("inf") for name in parts for part in ("body", "appendix", "merge")}
    pdfs = {}
    for _ in range(arguments.repeat):
        for name, (body, appendix) in parts.items():
            for part, html in (("body", body), ("appendix", appendix)):
                start = time.process_time()
                pdfs[name, part] = render_part(html)
                best[name, part] = min(best[name, part], time.process_time() - start)
            start = time.process_time()
            pdfs[name, "merge"] = merge(pdfs[name, "body"], pdfs[name, "appendix"])
            best[name, "merge"] = min(best[name, "merge"], time.process_time() - start)
    for name in parts:
        print(f"{name}: body {best[name, 'body']:.2f} s, appendix {best[name, 'appendix']:.2f} s, "
              f"merge {best[name, 'merge']:.2f} s CPU (best of {arguments.repeat}); "
              f"PDF {len(pdfs[name, 'merge']) / 1e3:.0f} kB")


if __name__ == "__main__":
    main()
