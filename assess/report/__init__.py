"""The risk report for facility managers: ``report.html`` and ``report.pdf`` (docs/outputs.md).

``render_html(result)`` turns an :class:`~assess.assessment.result.AssessmentResult` into
one self-contained HTML document (stylesheet inlined, figures as SVG ``data:``
URIs, workbook text escaped, no timestamp); ``render_pdf(html)`` prints it to
PDF with WeasyPrint, refusing every URL that is not a ``data:`` URI
(:mod:`assess.report.pdf`).

The names are imported when first used (PEP 562), so that importing
``assess.report.pdf`` alone, as the process that lays out the PDF's appendix
does, does not import pandas and matplotlib.
"""
import importlib

#: Each public name and the module that defines it.
_HOMES = {
    "render_html": "assess.report.render",
    "report_files": "assess.report.render",
    "render_pdf": "assess.report.pdf",
    "fragility_curve": "assess.report.figures",
    "data_only_url_fetcher": "assess.report.pdf",
    "RefusedURLError": "assess.report.pdf",
}

__all__ = ["render_html", "report_files", "render_pdf", "fragility_curve", "data_only_url_fetcher", "RefusedURLError"]


def __getattr__(name: str):
    if name not in _HOMES:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(importlib.import_module(_HOMES[name]), name)
    globals()[name] = value
    return value


def __dir__():
    return sorted(set(globals()) | set(__all__))
