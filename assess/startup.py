"""What the ``assess`` command starts before it imports the core (seconds of imports), so that the second
core works meanwhile: on a first run after install, the general solver's compilation
(:mod:`assess.mechanics.warmup`); on later runs, the PDF's second process, which has imported WeasyPrint and
the figures' modules by the time the result is made (:func:`assess.report.render.report_figures`).
"""
from __future__ import annotations

import contextlib


def warm_up(scheduler: str | None, jobs: int | None) -> None:
    """A first run after install on this machine: the general solver compiles while the core imports
    (:meth:`assess.mechanics.runner.LocalRunner.warm_up`); nothing where a cluster (``scheduler``) runs
    the engine."""
    if scheduler is None:
        from assess.mechanics.runner import LocalRunner

        LocalRunner().warm_up(jobs)


def pdf_process(formats: tuple[str, ...]):
    """The PDF's second process (a context manager), started now with the figures' modules
    (:data:`assess.report.FIGURE_MODULES`), so that it draws some figures while this process draws the
    others; None (a null context) without a PDF to draw, or on a first run after install, whose second
    core compiles the general solver meanwhile (:func:`warm_up`): the report starts it itself then."""
    from assess.mechanics.runner import LocalRunner

    if "pdf" not in formats or LocalRunner.warming_up():
        return contextlib.nullcontext(None)
    from assess import report  # assess.report.pdf alone: no pandas, no matplotlib

    return report.pdf_process(modules=report.FIGURE_MODULES)
