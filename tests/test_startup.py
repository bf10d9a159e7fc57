"""What the assess command starts before it imports the core (assess/startup.py)."""
from __future__ import annotations

import os
import subprocess
import sys
import threading

import pytest

from assess import report, startup
from assess.mechanics import warmup
from assess.report import pdf


def test_the_pdf_processes_start_early_the_bodys_with_the_figures_modules(monkeypatch):
    monkeypatch.setattr(pdf, "second_core", lambda: True)
    with startup.pdf_process(("html", "pdf")) as processes:
        assert processes is not None and processes.modules == processes.body.modules == report.FIGURE_MODULES
        assert processes.appendix.modules == ("assess.report.pdf:warm_up",)  # fonts only: no figures there
        assert processes.body.process.is_alive() and processes.appendix.process.is_alive()
    assert not processes.body.process.is_alive() and not processes.appendix.process.is_alive()  # ended on leaving


def test_one_core_starts_no_pdf_process(monkeypatch):
    monkeypatch.setattr(pdf, "second_core", lambda: False)
    with startup.pdf_process(("html", "pdf")) as processes:
        assert processes is None


def test_no_early_pdf_process_without_a_pdf_or_on_a_first_run(monkeypatch):
    with startup.pdf_process(("html", "xlsx")) as process:
        assert process is None
    monkeypatch.setattr(warmup, "_process", object())  # the general solver compiling: a first run after install
    assert warmup.running()
    with startup.pdf_process(("html", "pdf")) as process:
        assert process is None


def test_the_command_collects_garbage_less_often_and_leaves_the_imports_alone():
    """as_command (the assess command only, not a process that calls cli.main among other work)."""
    script = ("import gc; from assess import startup; startup.core_imported(); print(gc.get_freeze_count() > 0); "
              "startup.as_command(); startup.core_imported(); print(gc.get_threshold(), gc.get_freeze_count() > 0)")
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=60)
    assert done.stdout.split("\n")[:2] == ["False", f"{startup.COMMAND_GC_THRESHOLDS} True"], done.stderr


def test_what_the_figures_process_runs_as_it_starts_is_there_and_runs():
    """Each ``module:function`` of FIGURE_MODULES (the second process imports and runs them as it starts)."""
    import importlib

    from assess.report import render

    assert "pypdf" in report.FIGURE_MODULES
    for name in report.FIGURE_MODULES:
        module, _, function = name.partition(":")
        imported = importlib.import_module(module)
        if function:
            getattr(imported, function)()
    assert render.report_template() is render.report_template()  # the first process's template: compiled once


def test_the_command_gives_numpys_blas_one_thread_unless_the_user_set_it():
    script = "import os; from assess import startup; startup.as_command(); print(os.environ['OPENBLAS_NUM_THREADS'])"
    for given, expected in ((None, "1"), ("2", "2")):
        env = {k: v for k, v in os.environ.items() if k != "OPENBLAS_NUM_THREADS"}
        if given is not None:
            env["OPENBLAS_NUM_THREADS"] = given
        done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=60, env=env)
        assert done.stdout.strip() == expected, done.stderr


@pytest.mark.skipif(sys.platform != "linux", reason="a thread's own priority: Linux only")
def test_the_second_process_lowers_its_imports_priority_only_on_an_idle_machine(monkeypatch):
    lowered = []
    monkeypatch.setattr(os, "setpriority", lambda which, who, value: lowered.append((which, who, value)))
    cores = len(os.sched_getaffinity(0))
    monkeypatch.setattr(os, "getloadavg", lambda: (cores + 1.0, 0.0, 0.0))  # a busy machine
    pdf._import_priority()
    assert lowered == []
    monkeypatch.setattr(os, "getloadavg", lambda: (cores - 0.5, 0.0, 0.0))  # an idle one
    pdf._import_priority()
    assert lowered == [(os.PRIO_PROCESS, threading.get_native_id(), pdf.IMPORT_NICENESS)]
