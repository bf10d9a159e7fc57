"""report.pdf in two parts (assess/report/pdf.py): the body and Appendix A (item by item) laid out apart,
the appendix in a second process where there is a second core, and joined into one file whose page labels,
links and bytes do not depend on how many processes drew it; a second process that dies or a Ctrl-C leaves
no half-written file and no process behind."""
from __future__ import annotations

import io
import multiprocessing
import os
import re
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from assess.report import pdf as pdf_module
from assess.report.pdf import ELSEWHERE, render_part, render_pdf, split_appendix
from tests.commands import LAB, child_env
from tests.report.test_report import html, result  # noqa: F401, F811 (test_report's fixtures: its sample result and report)

pypdf = pytest.importorskip("pypdf")


@pytest.fixture(scope="module")
def pdf(html) -> bytes:
    return render_pdf(html, processes=2)


def test_the_bytes_do_not_depend_on_the_processes_that_drew_them(html, pdf):
    assert render_pdf(html, processes=1) == pdf
    assert render_pdf(html) == pdf
    assert multiprocessing.active_children() == []  # the second process ended with the PDF


def test_the_report_files_are_the_html_and_its_pdf(result, html, pdf):
    """report_files, what the command writes: report.html and the PDF of that HTML, byte for byte."""
    from assess.report import report_files

    files = report_files(result)
    assert files["report.html"] == html.encode()
    assert files["report.pdf"] == pdf
    assert report_files(result, pdf=False) == {"report.html": html.encode()}
    assert set(report_files(result, html=False)) == {"report.pdf"}
    assert multiprocessing.active_children() == []


def test_the_pdf_is_the_body_then_the_appendix_each_laid_out_alone(html, pdf):
    """Independently of how the parts are laid out: the merged file has the body's pages, then the appendix's."""
    body, appendix = split_appendix(html)
    pages = [len(pypdf.PdfReader(io.BytesIO(render_part(part))).pages) for part in (body, appendix)]
    assert len(pypdf.PdfReader(io.BytesIO(pdf)).pages) == sum(pages) and min(pages) >= 1


def test_a_second_process_that_dies_leaves_the_appendix_to_this_one(html, pdf, monkeypatch):
    """The second process is killed as this one starts on the body: the appendix is laid out here, the same bytes."""
    killed = []
    lay_out = pdf_module.render_part

    def kill_then_lay_out(document, url_fetcher=None):
        for child in multiprocessing.active_children():
            child.kill()
            child.join()
            killed.append(child.exitcode)
        return lay_out(document, url_fetcher)

    monkeypatch.setattr(pdf_module, "render_part", kill_then_lay_out)
    assert render_pdf(html, processes=2) == pdf
    # one process was killed; its exit code reads None where the pool's own thread, seeing it die, reaped it first
    assert len(killed) == 1 and killed[0] in (-signal.SIGKILL, None)
    assert multiprocessing.active_children() == []


def test_the_appendix_holds_every_item_block_and_the_body_none(html, result):
    body, appendix = split_appendix(html)
    freestanding = result.summary[result.summary["risk"] != "anchored"]
    assert appendix.count('<div class="item-detail"') == len(freestanding) > 0
    assert '<div class="item-detail"' not in body and 'id="details"' not in body
    assert body.count("<style>") == appendix.count("<style>") == 1  # the same stylesheet heads both
    assert split_appendix("<html><body><p>no appendix</p></body></html>")[1] is None


def _text(page) -> str:
    return " ".join(page.extract_text().split())


def test_pages_are_labelled_as_their_footers_number_them(pdf):
    reader = pypdf.PdfReader(io.BytesIO(pdf))
    labels = reader.page_labels
    body = [label for label in labels if not label.startswith("A-")]
    appendix = [label for label in labels if label.startswith("A-")]
    assert body == [str(k) for k in range(1, len(body) + 1)] and labels[:len(body)] == body
    assert appendix == [f"A-{k}" for k in range(1, len(appendix) + 1)] and len(appendix) >= 1
    for page, label in zip(reader.pages, labels):
        total = len(appendix) if label.startswith("A-") else len(body)
        prefix = "A-" if label.startswith("A-") else ""
        assert f"Page {label} of {prefix}{total}" in _text(page), label
    assert "Appendix A. Item by item" in _text(reader.pages[len(body)])
    # the appendix's pages are headed as the body's (not its first: the report's title page)
    assert "earthquake risk report" in _text(reader.pages[len(body)])


def test_every_link_of_the_body_lands_on_its_item_in_the_appendix(pdf, result):
    reader = pypdf.PdfReader(io.BytesIO(pdf))
    labels = reader.page_labels
    page_of = {page.indirect_reference.idnum: k for k, page in enumerate(reader.pages)}
    destinations = reader.named_destinations
    targets = set()
    for page in reader.pages:
        for reference in page.get("/Annots", []):
            annotation = reference.get_object()
            action = annotation.get("/A")
            assert action is None or not str(action.get_object().get("/URI", "")).startswith(ELSEWHERE)
            if "/Dest" in annotation:
                assert str(annotation["/Dest"]) in destinations, annotation["/Dest"]
                targets.add(str(annotation["/Dest"]))
    for item_id in result.summary.loc[result.summary["risk"] == "high", "id"].astype(str):
        anchor = "item-" + re.sub(r"[^A-Za-z0-9_-]", "_", item_id)
        assert anchor in targets, anchor
        page = page_of[destinations[anchor].page.idnum]
        assert labels[page].startswith("A-") and item_id in _text(reader.pages[page]), (anchor, labels[page])


def _descendants(pid: int) -> set[int]:
    found, todo = set(), [pid]
    while todo:
        parent = todo.pop()
        try:
            tasks = list(Path(f"/proc/{parent}/task").iterdir())
            children = {int(c) for task in tasks for c in (task / "children").read_text().split()}
        except OSError:  # the process has just ended
            continue
        todo.extend(children - found)
        found |= children
    return found


def _spawned_child(pid: int) -> bool:
    for child in _descendants(pid):
        try:
            if b"spawn_main" in Path(f"/proc/{child}/cmdline").read_bytes():
                return True
        except OSError:
            pass
    return False


@pytest.mark.skipif(not Path("/proc/self/task").exists() or len(os.sched_getaffinity(0)) < 2,
                    reason="needs Linux's /proc and a second core (the second process)")
def test_ctrl_c_as_the_second_process_starts_is_acted_on_once_it_has_started_and_never_reaches_it(html):
    """Ctrl-C that comes while the second process is being started is held back until it has started (never
    half-told what to run), then acted on here: KeyboardInterrupt (or, where a library dropped it, the
    interrupt the command's handler recorded, which stops the run as it returns), and the second process
    ended. Ctrl-C that reaches the second process itself (the terminal sends it to the whole group) leaves it
    running, silent."""
    script = """
import multiprocessing, os, signal, sys, time
from assess.report import pdf
from assess.command.interrupts import Interrupt, sigint_recorded
start = multiprocessing.context.SpawnProcess.start
def interrupted_start(self):
    os.kill(os.getpid(), signal.SIGINT)  # Ctrl-C here, as it starts
    time.sleep(0.1)
    start(self)
    time.sleep(0.5)  # into its imports
    os.kill(self.pid, signal.SIGINT)  # Ctrl-C there
    time.sleep(0.5)
    print('started', self.is_alive(), flush=True)
multiprocessing.context.SpawnProcess.start = interrupted_start
with sigint_recorded():  # the command's handler, as every run has it
    try:
        pdf.render_pdf(sys.stdin.read(), processes=2)
        said = 'interrupted' if Interrupt.received else 'not interrupted'
        print(said, multiprocessing.active_children(), flush=True)
    except KeyboardInterrupt:
        print('interrupted', multiprocessing.active_children(), flush=True)
"""
    done = subprocess.run([sys.executable, "-c", script], input=html, capture_output=True, text=True, timeout=300,
                          env=child_env())
    assert done.stdout.split("\n")[:2] == ["started True", "interrupted []"], (done.stdout, done.stderr)
    assert "Traceback" not in done.stderr and "Error" not in done.stderr, done.stderr


def test_ctrl_c_while_two_processes_draw_the_pdf_exits_130_and_leaves_no_process(tmp_path):
    """Ctrl-C at the terminal reaches the whole process group, the second process too: the run exits 130 in
    one line, no traceback from either process, the folder as it was, and no process of the run is left."""
    out = tmp_path / "out"
    out.mkdir()
    (out / "summary.csv").write_text("previous\n")
    process = subprocess.Popen([sys.executable, "-m", "assess", str(LAB), "--hazard", "2in50", "--out", str(out)],
                               cwd=tmp_path, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                               env=child_env(), start_new_session=True)
    try:
        deadline = time.monotonic() + 300
        while not _spawned_child(process.pid):
            assert process.poll() is None and time.monotonic() < deadline, "the second process never started"
            time.sleep(0.05)
        time.sleep(1.5)  # into the drawing
        os.killpg(process.pid, signal.SIGINT)
        stderr = process.communicate(timeout=300)[1]
    finally:
        if process.poll() is None:
            os.killpg(process.pid, signal.SIGKILL)
    lines = stderr.splitlines()
    assert process.returncode == 130, stderr
    assert lines[-1] == "assess: interrupted; nothing was written." and "Traceback" not in stderr, stderr
    assert sorted(p.name for p in out.iterdir()) == ["summary.csv"] and (out / "summary.csv").read_text() == "previous\n"
    deadline = time.monotonic() + 10
    while True:  # the second process (and multiprocessing's resource tracker) end with the run
        try:
            os.killpg(process.pid, 0)
        except ProcessLookupError:
            break
        assert time.monotonic() < deadline, "a process of the run outlived it"
        time.sleep(0.1)


def _words_past_their_cell(html: str) -> list[str]:
    """The words of the appendix's item tables (table.kv) that WeasyPrint lays out past the right edge of their
    cell's content (into the next column or off the page)."""
    weasyprint = pytest.importorskip("weasyprint")
    from weasyprint.formatting_structure import boxes

    from assess.report.pdf import data_only_url_fetcher

    _, appendix = split_appendix(html)
    document = weasyprint.HTML(string=appendix, url_fetcher=data_only_url_fetcher()).render()
    past = []

    def walk(box, cell):
        if isinstance(box, boxes.TableCellBox):
            cell = box
        if cell is not None and isinstance(box, boxes.TextBox):
            if box.position_x + box.width > cell.content_box_x() + cell.width + 0.5:
                past.append(box.text)
        for child in getattr(box, "children", None) or ():
            walk(child, cell)

    for page in document.pages:
        walk(page._page_box, None)  # the laid-out boxes of the page (WeasyPrint keeps them there)
    return past


def test_no_word_of_an_item_table_runs_past_its_cell(html):
    """On paper the item tables have fixed column widths (templates/report.css): their headings ("Chance of rocking
    that harms it", one line) and values fit their columns, as they did when WeasyPrint measured them."""
    assert _words_past_their_cell(html) == []
    narrow = html.replace("table.kv col.kv-th { width: 30%; }", "table.kv col.kv-th { width: 20%; }")
    assert narrow != html and "Chance of rocking that harms it" in _words_past_their_cell(narrow)
