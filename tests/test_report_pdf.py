"""report.pdf in two parts (assess/report/pdf.py): the body and Appendix A (item by item) laid out apart,
on two cores where there are two, and joined into one file whose page labels, links and bytes do not depend
on how many processes drew it."""
from __future__ import annotations

import io
import os
import re
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from assess.report.pdf import ELSEWHERE, pdf_process, render_pdf, split_appendix
from tests.commands import LAB, child_env
from tests.report.test_report import html, result  # noqa: F401, F811 (test_report's fixtures: its sample result and report)

pypdf = pytest.importorskip("pypdf")


@pytest.fixture(scope="module")
def pdf(html) -> bytes:
    return render_pdf(html, processes=2)


def test_the_bytes_do_not_depend_on_the_processes_that_drew_them(html, pdf):
    assert render_pdf(html, processes=1) == pdf
    assert render_pdf(html, processes=2) == pdf


def test_the_appendix_is_handed_on_when_a_core_is_free_for_it(result, html, monkeypatch):
    """render_html asks the second process for its figures, and hands on the appendix's document, the very one
    split_appendix cuts out of the whole report, once this process has drawn its own figures (the other's
    nearly done: the appendix never takes a core from them); to a process that draws no figures, before this
    one draws them. Where the second process gives no figures, this one draws them too: the same report."""
    from assess.report import FIGURE_MODULES, figures, render

    events = []

    class Answered:
        def result(self):
            return None  # as a second process that died: this one draws them

    class Process:
        def __init__(self, modules):
            self.modules = modules

        def call(self, function, jobs):
            events.append(("call", function.__name__, tuple(jobs)))
            return Answered()

        def draw(self, document):
            events.append(document)

    drawn = figures.sliding_demand_figures
    monkeypatch.setattr(figures, "sliding_demand_figures", lambda *a, **k: events.append("drawing") or drawn(*a, **k))
    appendix = split_appendix(html)[1]
    assert render.render_html(result, Process(FIGURE_MODULES)) == html
    elsewhere = tuple(name for name in render.ELSEWHERE_FIGURES if name != "simulation" or result.simulated)
    assert events == [("call", "draw_figures", elsewhere), "drawing", appendix]
    events.clear()
    assert render.render_html(result, Process(())) == html
    assert events == [appendix, "drawing"]


def test_the_second_process_draws_its_figures_and_the_report_is_the_same(result, html):
    """Started with the figures' modules, the second process answers the call for its figures (not this
    process drawing them after all), with the bytes this process would draw, and joins the PDF's parts."""
    from assess.report import FIGURE_MODULES, render
    from assess.report.pdf import Call

    answers = []
    result_of = Call.result

    def recorded(call):
        value = result_of(call)
        answers.append(call.reply[0])
        return value

    with pdf_process(2, modules=FIGURE_MODULES) as process:
        Call.result = recorded
        try:
            assert render.render_html(result, process) == html
            assert render_pdf(html, process=process) == render_pdf(html, processes=1)
        finally:
            Call.result = result_of
    assert answers == [True, True]  # the figures, then the merge: both done there


def test_the_body_and_the_appendix_each_in_a_process_of_its_own_give_the_same_pdf(result, html, pdf):
    """The assess command's processes: one draws figures then lays out the body, the other the appendix;
    this process lays out nothing, and the report and its PDF are the same bytes."""
    from assess.report import FIGURE_MODULES, render
    from assess.report.pdf import body_and_appendix_processes

    with body_and_appendix_processes(FIGURE_MODULES) as processes:
        if processes is None:
            pytest.skip("one core: no second process")
        assert render.render_html(result, processes) == html
        assert render_pdf(html, process=processes) == pdf
        assert processes.body.sent == processes.appendix.sent == []  # every answer read


def test_what_this_process_does_meanwhile_runs_once_while_the_body_is_laid_out_elsewhere(html, pdf):
    from assess.report import FIGURE_MODULES
    from assess.report.pdf import body_and_appendix_processes

    calls = []
    assert render_pdf(html, processes=1, meanwhile=lambda: calls.append("alone")) == pdf
    with body_and_appendix_processes(FIGURE_MODULES) as processes:
        if processes is None:
            pytest.skip("one core: no second process")
        # when it runs, the body has been sent to its process and is not laid out yet (its PDF not read)
        meanwhile = lambda: calls.append(("elsewhere", len(processes.body.sent)))  # noqa: E731
        assert render_pdf(html, process=processes, meanwhile=meanwhile) == pdf
    assert calls == ["alone", ("elsewhere", 1)]


def test_figures_a_dead_second_process_owes_are_drawn_here(result):
    from assess.report import FIGURE_MODULES, render

    with pdf_process(2, modules=FIGURE_MODULES) as process:
        process.process.kill()
        process.process.join()
        assert render.FigureDrawing(result, process).drawn() == render.report_figures(result)


def test_a_process_sent_another_appendix_first_still_draws_this_one(html, pdf):
    """What the second process was sent early is dropped where it is not the report's appendix."""
    _, appendix = split_appendix(html)
    with pdf_process(2) as process:
        process.draw(appendix.replace("Appendix A. Item by item", "Not this appendix"))
        assert not process.drawing(appendix)
        assert render_pdf(html, process=process) == pdf
        process.draw(appendix)
        assert process.drawing(appendix)
        assert render_pdf(html, process=process) == pdf and process.sent == []


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


def test_a_second_process_that_dies_is_an_error_not_a_wait_without_end(html):
    with pdf_process(processes=2) as process:
        process.process.kill()
        with pytest.raises(RuntimeError, match="ended without it") as raised:
            render_pdf(html, process=process)
    assert raised.value.__context__ is None  # not a BrokenPipeError, which the commands read as stdout's reader gone


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
def test_ctrl_c_as_the_second_process_starts_is_acted_on_once_it_has_started():
    """An interrupt that comes while the second process is being started (told what to run) is held back
    until it is, then acted on: the process is ended and the interrupt raised, and the second process
    never prints a half-read start ("EOFError: Ran out of input")."""
    script = """
import multiprocessing, os, signal, sys, time
from assess.report import pdf
start = multiprocessing.context.SpawnProcess.start
def interrupted_start(self):
    os.kill(os.getpid(), signal.SIGINT)  # Ctrl-C as it starts
    time.sleep(0.1)
    start(self)
    print('started', flush=True)
multiprocessing.context.SpawnProcess.start = interrupted_start
try:
    pdf.AppendixProcess()
except KeyboardInterrupt:
    print('interrupted', [p.name for p in multiprocessing.active_children()], flush=True)
"""
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120, env=child_env())
    assert done.stdout.split("\n")[:2] == ["started", "interrupted []"], (done.stdout, done.stderr)
    assert "Error" not in done.stderr, done.stderr


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
