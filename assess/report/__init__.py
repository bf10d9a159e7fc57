"""The risk report for facility managers: ``report.html`` and ``report.pdf`` (docs/outputs.md).

``render_html(result)`` turns an :class:`~assess.result.AssessmentResult` into
one self-contained HTML document (stylesheet inlined, figures as SVG ``data:``
URIs, workbook text escaped, no timestamp); ``render_pdf(html)`` prints it to
PDF with WeasyPrint, refusing every URL that is not a ``data:`` URI.
"""
from assess.report.figures import fragility_curve
from assess.report.render import (
    RefusedURLError,
    data_only_url_fetcher,
    render_html,
    render_pdf,
)

__all__ = ["render_html", "render_pdf", "fragility_curve", "data_only_url_fetcher",
           "RefusedURLError"]
