"""Time and peak memory of reading hostile workbooks (issue 9): each in a fresh process.

Run: python benchmarks/bench_workbook_read.py
Builds, in a scratch folder, the test suite's good inventory and variants of it: one
whitespace cell at row 1,048,576; a sheet padded to inflate to 4 GB; 600,000 empty
cells; 190 MB of one-letter shared strings; 6 million empty elements. Prints, per file,
its size, the outcome of ``read_workbook`` (read, or the first line of the refusal),
the seconds it took and the process's peak resident memory (Linux). Not a test.
"""
from __future__ import annotations

import subprocess
import sys
import tempfile
import zipfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))

from conftest import RECORD_TEXT  # noqa: E402
from workbooks import (RECORD_FILE, good_sheets, replace_member_streamed, rewrite_member,  # noqa: E402
                       sheet_xml, sheet_xml_name, write_workbook)

PROBE = """
import sys, time
from assess.errors import InputError
from assess.inventory import read_workbook
start = time.perf_counter()
try:
    read_workbook(sys.argv[1])
    outcome = "read"
except InputError as error:
    outcome = "refused: " + error.problems[0].message[:90]
seconds = time.perf_counter() - start
status = open("/proc/self/status").read()  # VmHWM: this process's peak, reset at exec
peak_mb = int(status.split("VmHWM:")[1].split()[0]) / 1024
print(f"{seconds:8.2f} s {peak_mb:8.0f} MB  {outcome}")
"""


def build(folder: Path) -> dict[str, Path]:
    def base(name):
        return write_workbook(folder / name, good_sheets(), None, {RECORD_FILE: RECORD_TEXT})

    files = {"good": base("good.xlsx")}
    files["row 1,048,576"] = write_workbook(folder / "far.xlsx", good_sheets(),
                                            {"equipment": {"A1048576": " "}},
                                            {RECORD_FILE: RECORD_TEXT})
    path = files["inflates to 4 GB"] = base("inflate.xlsx")
    replace_member_streamed(path, sheet_xml_name(path, "equipment"),
                            sheet_xml(b" " * 2**24 for _ in range(256)))
    path = files["600,000 empty cells"] = base("cells.xlsx")
    replace_member_streamed(path, sheet_xml_name(path, "equipment"), sheet_xml(
        f'<row r="{r}">'.encode() + b"<c/>" * 100 + b"</row>" for r in range(1, 6002)))
    path = files["190 MB of shared strings"] = base("strings.xlsx")
    replace_member_streamed(path, "xl/sharedStrings.xml", (
        b'<sst xmlns="http://schemas.openxmlformats.org/spreadsheetml/2006/main">',
        *(b"<si><t>a</t></si>" * (2**20 // 17) for _ in range(190)), b"</sst>"))
    rewrite_member(path, "[Content_Types].xml", lambda xml: xml.replace("</Types>", (
        '<Override PartName="/xl/sharedStrings.xml" ContentType="application/vnd.openxmlformats-'
        'officedocument.spreadsheetml.sharedStrings+xml"/></Types>')))
    path = files["6 million empty elements"] = base("elements.xlsx")
    replace_member_streamed(path, sheet_xml_name(path, "equipment"), sheet_xml(
        [b"</sheetData><cols>", *(b"<x/>" * 100_000 for _ in range(60)), b"</cols><sheetData>"]))
    return files


def main() -> None:
    with tempfile.TemporaryDirectory() as scratch:
        for label, path in build(Path(scratch)).items():
            inflated = sum(i.file_size for i in zipfile.ZipFile(path).infolist())
            done = subprocess.run([sys.executable, "-c", PROBE, str(path)], capture_output=True,
                                  text=True, cwd=ROOT)
            print(f"{label:26s} {path.stat().st_size / 1024:8.0f} kB file, "
                  f"{inflated / 2**20:7.0f} MB inflated: {done.stdout.strip() or done.stderr[-300:]}")


if __name__ == "__main__":
    main()
