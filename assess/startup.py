"""What the ``assess`` command starts before it imports the core (seconds of imports), so that the second
core works meanwhile: on a first run after install, the general solver's compilation
(:mod:`assess.mechanics.warmup`); on later runs, the PDF's second process, which has imported WeasyPrint and
the figures' modules by the time the result is made (:class:`assess.report.render.FigureDrawing`).
"""
from __future__ import annotations

import contextlib
import gc
import os

#: The cyclic garbage collector's thresholds in the command (Python's default: 700, 10, 10). A run makes
#: hundreds of thousands of objects that live until it ends (the libraries it imports, the result, the
#: report's layout); with the default thresholds the collector scans them again and again: 1.05 s of a
#: 9.6 s run of the lab job, 0.14 s with these, for 3 % more memory. Cycles are still collected, a
#: thirtieth as often. The PDF's second processes use them too (:func:`assess.report.pdf._serve`).
COMMAND_GC_THRESHOLDS = (20_000, 50, 50)

#: The threads of numpy's BLAS (OpenBLAS) in the command, where the user sets none: the command's matrices are
#: small, and OpenBLAS's extra thread spins after each call, waiting for the next, on the core the PDF's second
#: process works on (a later run of the lab job: about 1 CPU s less with one thread).
BLAS_THREADS = {"OPENBLAS_NUM_THREADS": "1"}

#: Whether this process is the ``assess`` command (:func:`as_command`), which ends when its run does.
_command = False


def as_command() -> None:
    """This process is the ``assess`` command (:func:`assess.__main__.run`): its garbage collector runs less
    often (:data:`COMMAND_GC_THRESHOLDS`), and leaves alone what the core's imports made (:func:`core_imported`);
    numpy's BLAS uses one thread (:data:`BLAS_THREADS`). Not for a process that calls :func:`assess.cli.main`
    among other work (the tests). Called before numpy is imported."""
    global _command
    _command = True
    gc.set_threshold(*COMMAND_GC_THRESHOLDS)
    for name, value in BLAS_THREADS.items():
        os.environ.setdefault(name, value)  # a user's own setting stands; the PDF's second process inherits it


def core_imported() -> None:
    """The core is imported: in the command (:func:`as_command`), what the imports made lives until the
    process ends, so the garbage collector need not scan it again (:func:`gc.freeze`; the lab report's body
    is laid out in 0.15 s less)."""
    if _command:
        gc.freeze()


def warm_up(scheduler: str | None, jobs: int | None) -> None:
    """A first run after install on this machine: the general solver compiles while the core imports
    (:meth:`assess.mechanics.runner.LocalRunner.warm_up`); nothing where a cluster (``scheduler``) runs
    the engine."""
    if scheduler is None:
        from assess.mechanics.runner import LocalRunner

        LocalRunner().warm_up(jobs)


def pdf_process(formats: tuple[str, ...]):
    """The PDF's processes (a context manager, :func:`assess.report.body_and_appendix_processes`), started now:
    one imports the figures' modules (:data:`assess.report.FIGURE_MODULES`), draws some figures while this
    process draws the others, then lays out the report's body; the other lays out its appendix. None (a null
    context) without a PDF to draw, or on a first run after install, whose second core compiles the general
    solver meanwhile (:func:`warm_up`): the report starts its one second process itself then."""
    from assess.mechanics.runner import LocalRunner

    if "pdf" not in formats or LocalRunner.warming_up():
        return contextlib.nullcontext(None)
    from assess import report  # assess.report.pdf alone: no pandas, no matplotlib

    return report.body_and_appendix_processes(report.FIGURE_MODULES)
