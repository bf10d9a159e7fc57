"""Writing the run's files so that a failed run leaves nothing half-written.

Everything is first produced in memory, written into a temporary folder next
to the output folder, and only then moved into place file by file with
``os.replace`` (atomic on one file system). A failure before the move leaves
the output folder as it was.
"""
from __future__ import annotations

import os
import shutil
import tempfile
from pathlib import Path

import pandas as pd

from assess.result import AssessmentResult


def csv_text(table: pd.DataFrame) -> str:
    """A table as CSV text: fixed float format so that reruns compare byte for byte."""
    return table.to_csv(index=False, float_format="%.6g", lineterminator="\n")


def render_outputs(result: AssessmentResult, formats: tuple[str, ...]) -> dict[str, bytes]:
    """All files of a run, by name, as bytes (nothing is written here)."""
    files = {
        "summary.csv": csv_text(result.summary).encode(),
        "motions.csv": csv_text(result.motions).encode(),
    }
    if result.comparison is not None:
        files["comparison.csv"] = csv_text(result.comparison).encode()
    if "html" in formats or "pdf" in formats:
        from assess.report import render_html, render_pdf

        html = render_html(result)
        if "html" in formats:
            files["report.html"] = html.encode()
        if "pdf" in formats:
            files["report.pdf"] = render_pdf(html)
    return files


def write_atomically(files: dict[str, bytes], out_dir: Path) -> list[Path]:
    """Write ``files`` into ``out_dir``: all of them, or (on failure) none of them."""
    out_dir = Path(out_dir)
    out_dir.parent.mkdir(parents=True, exist_ok=True)
    staging = Path(tempfile.mkdtemp(prefix=f".{out_dir.name}-", dir=out_dir.parent))
    try:
        for name, content in files.items():
            (staging / name).write_bytes(content)
        out_dir.mkdir(exist_ok=True)
        written = []
        for name in files:
            os.replace(staging / name, out_dir / name)
            written.append(out_dir / name)
        return written
    finally:
        shutil.rmtree(staging, ignore_errors=True)
