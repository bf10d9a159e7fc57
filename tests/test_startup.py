"""What the assess command starts before it imports the core (assess/startup.py)."""
from __future__ import annotations

from assess import report, startup
from assess.report import pdf
from assess.mechanics import warmup


def test_the_pdf_process_starts_early_with_the_figures_modules(monkeypatch):
    monkeypatch.setattr(pdf, "second_core", lambda: True)
    with startup.pdf_process(("html", "pdf")) as process:
        assert process is not None and process.modules == report.FIGURE_MODULES
        assert process.process.is_alive()
    assert not process.process.is_alive()  # ended on leaving


def test_no_early_pdf_process_without_a_pdf_or_on_a_first_run(monkeypatch):
    with startup.pdf_process(("html", "xlsx")) as process:
        assert process is None
    monkeypatch.setattr(warmup, "_process", object())  # the general solver compiling: a first run after install
    assert warmup.running()
    with startup.pdf_process(("html", "pdf")) as process:
        assert process is None
