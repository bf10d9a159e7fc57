"""The calibration report (``assess calibrate``): residuals before and after, the chosen effect, the evidence.

Renders a :class:`~assess.calibration.CalibrationResult` with
``templates/calibration.html.j2`` (same stylesheet, same rules as the risk
report: autoescaped, figures as data: URIs, no dates).
"""
from __future__ import annotations

import math

import matplotlib
import numpy as np

import assess
from assess.report import figures
from assess.report.render import STYLESHEET_NAME, _data_uri, format_significant, make_environment, template_text

from markupsafe import Markup

TEMPLATE_NAME = "calibration.html.j2"
#: Explanatory quantities plotted against the residuals (diagnosis table column, axis label, log axis).
EXPLANATORY = (("im", "IM = PTA/(μg) − 1 [–]", False), ("omega_p_over_p", "ωp/p [–]", True),
               ("pgv_m_s", "PGV [m/s]", False), ("mu", "μ declared [–]", False), ("b_over_h", "b/h [–]", False),
               ("pressure_kpa", "bearing pressure [kPa]", False))


def residual_figure(result) -> str:
    """ln(predicted/measured) peak sliding against each explanatory quantity, before and after."""
    before, after, diagnosis = result.residuals_before, result.residuals_after, result.diagnosis
    with matplotlib.rc_context(figures._RC):
        figure = figures._new_figure(6.4)
        axes = figure.subplots(3, 2).ravel()
        for ax, (column, label, log) in zip(axes, EXPLANATORY):
            x = diagnosis[column].to_numpy(dtype=float)
            if not np.isfinite(x).any():
                ax.set_axis_off()
                continue
            ax.axhline(0.0, color="black", linewidth=0.7)
            ax.scatter(x, before["sliding_log_ratio"], s=14, facecolors="none", edgecolors="#c0392b",
                       linewidths=0.8, label="declared model")
            ax.scatter(x, after["sliding_log_ratio"], s=10, color="#1f4e79",
                       label=figures.plain_text(f"with {result.selected}"))
            if log and np.all(x[np.isfinite(x)] > 0):
                ax.set_xscale("log")
                figures.plain_log_ticks(ax.xaxis)
            ax.set_xlabel(label)
            ax.set_ylabel("ln(predicted / measured) [–]")
        axes[0].legend(loc="best", frameon=False)
        return figures._to_svg(figure)


def _number(value) -> str:
    if value is None:
        return "–"
    if isinstance(value, (int, np.integer)) and not isinstance(value, bool):
        return str(int(value))
    try:
        number = float(value)
    except (TypeError, ValueError):
        return str(value)
    if not math.isfinite(number):
        return "–"
    return str(int(number)) if number.is_integer() and abs(number) >= 1 else format_significant(number, 3)


#: What each error measure is, in words (the rows of the error table).
ERROR_SENTENCES = {
    "sliding_rms_log": "RMS of ln(predicted/measured) peak sliding",
    "overturn_misclassified": "Tests whose overturning (yes or no) the model gets wrong",
    "theta_rms": "RMS of predicted minus measured peak rotation θmax/α (both capped at 1)",
    "theta_rms_band": "RMS of how far the measured θmax/α lies outside what the model predicts within ±1 % of "
                      "the motion's amplitude",
    "objective": "Objective: mean squared standardised residual per measure",
    "tests_sliding": "Tests with a measured peak sliding",
    "tests_theta": "Tests with a measured peak rotation",
    "tests_overturned": "Tests with an observed overturning (yes or no)",
}
NOT_DETERMINED = "not determined by these tests"


def _with_errors(fit) -> str:
    """'factor k on μ and μ_s = 0.651 ± 0.004, …' (± the jackknife standard error), a sentence
    for a parameter the tests cannot fix, or '' without parameters."""
    parts = []
    for p in fit.effect.parameters:
        label = p.label or p.name
        unit = "" if p.unit == "-" else f" {p.unit}"
        if p.name in fit.not_determined:
            parts.append(f"{label}: {NOT_DETERMINED} ({fit.not_determined[p.name].rstrip('.')})")
            continue
        error = fit.standard_error.get(p.name)
        parts.append(f"{label} = {_number(fit.parameters[p.name])}{unit}"
                     + (f" ± {_number(error)}{unit}" if error is not None else ""))
    return "; ".join(parts)


def calibration_context(result, workbook: str, measured_file: str) -> dict:
    errors = [{"name": ERROR_SENTENCES.get(name, name), "before": _number(result.error_before.get(name)),
               "after": _number(result.error_after.get(name))} for name in result.error_before]
    candidates = [{"effect": f.effect.name, "description": f.effect.description,
                   "parameters": _with_errors(f) or "–",
                   "score": _number(f.score), "sliding": _number(f.error.get("sliding_rms_log")),
                   "overturn": _number(f.error.get("overturn_misclassified")),
                   "selected": f.effect.name == result.selected}
                  for f in sorted(result.fits, key=lambda f: f.score)]
    from assess.calibration import residual_correlations
    labels = {"im": "IM", "omega_p_over_p": "ωp/p", "pgv_m_s": "PGV", "mu": "μ declared", "b_over_h": "b/h",
              "pressure_kpa": "bearing pressure"}
    before = residual_correlations(result.residuals_before, result.diagnosis)
    after = residual_correlations(result.residuals_after, result.diagnosis)
    correlations = [{"name": labels.get(k, k), "before": _number(before[k]), "after": _number(after[k])}
                    for k in before]
    return {"version": assess.__version__, "workbook": workbook, "measured": measured_file,
            "correlations": correlations,
            "tests": len(result.residuals_before), "selected": result.selected,
            "parameters": _with_errors(result._fit(result.selected)) or "none",
            "description": result._fit(result.selected).effect.description,
            "indistinguishable": list(result.indistinguishable_from), "margin": result.margin,
            "errors": errors, "candidates": candidates, "notes": list(result.notes),
            "figure": _data_uri(residual_figure(result)),
            "stylesheet": Markup(template_text(STYLESHEET_NAME))}


def render_calibration_html(result, workbook: str, measured_file: str) -> str:
    """The calibration report of ``result`` as one self-contained HTML document."""
    template = make_environment().get_template(TEMPLATE_NAME)
    return template.render(calibration_context(result, workbook, measured_file))
