"""Figures of the risk report, drawn with matplotlib and returned as SVG text.

Every figure is a pure function of an :class:`~assess.assessment.result.AssessmentResult`
(and, for the regression figure, the paper's Table 3) returning an SVG
document as ``str``. The same result gives byte-identical SVG: the SVG hash
salt is fixed, the date and creator are left out of the metadata, text is
written as SVG text in DejaVu Sans (``svg.fonttype`` ``none``: a glyph drawn as
a path is a node the PDF renderer must parse at every use, and those nodes took
a quarter of the PDF's time), lines are simplified below a pixel
(``path.simplify``: the time histories shrink to a third) and nothing depends on
the clock or on global matplotlib state (each figure is drawn inside its own
``rc_context`` on a :class:`~matplotlib.figure.Figure`, never through pyplot).

The fragility curve itself is :func:`fragility_curve`, the paper's eq. 20.
"""
from __future__ import annotations

import io
import math
import re
import sys

import matplotlib
import matplotlib.ticker
import matplotlib.transforms

if "matplotlib.pyplot" not in sys.modules:  # headless; never switch an interactive session
    matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402
from matplotlib.backends.backend_agg import FigureCanvasAgg  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

from assess.data import km2010_table3  # noqa: E402
from assess.fragility import median_edp, probability_of_exceedance  # noqa: E402
from assess.quantity_text import length_unit, length_value  # noqa: E402
from assess.report.sentences import slides_in_both  # noqa: E402

#: Capacities c of the paper's Fig. 12.
PAPER_CAPACITIES = (0.2, 0.4, 0.6, 0.8)

#: Colours of the risk classes (the same as the report's CSS).
RISK_COLOURS = {
    "high": "#c0392b",
    "moderate": "#d68910",
    "low": "#1e8449",
    "anchored": "#7f8c8d",
}

#: Width of a figure [in]: the text width of a portrait A4 page with the report's margins.
FIGURE_WIDTH_IN = 6.6

#: Items per sliding-demand figure; a longer inventory is split over several figures.
ITEMS_PER_DEMAND_FIGURE = 36

_RC = {
    "svg.hashsalt": "assess-report",
    "svg.fonttype": "none",
    "font.family": "DejaVu Sans",
    "font.size": 8.0,
    "axes.titlesize": 8.5,
    "axes.labelsize": 8.0,
    "legend.fontsize": 7.0,
    "xtick.labelsize": 7.5,
    "ytick.labelsize": 7.5,
    "axes.spines.top": False,
    "axes.spines.right": False,
    "axes.grid": True,
    "grid.color": "#dddddd",
    "grid.linewidth": 0.5,
    "path.simplify": True,
}


# --------------------------------------------------------------------------- physics
#: Eq. 20 of the paper, from the one place it is computed (assess.fragility).
fragility_curve = probability_of_exceedance


def edp_median(im, zeta, eta):
    """Median EDP ζ·IM^η (eq. 11) [–] for plotting: NaN where IM ≤ 0 (no sliding, no log)."""
    im_array = np.asarray(im, dtype=float)
    out = np.where(im_array > 0, median_edp(im_array, zeta, eta), np.nan)
    return float(out) if np.ndim(im) == 0 else out


# --------------------------------------------------------------------------- helpers
def plain_text(text) -> str:
    r"""``text`` as matplotlib must draw it, character for character.

    Matplotlib reads text between two ``$`` as mathtext (TeX-like), so an item
    named ``Freezer $\foo$`` is parsed, and fails, when the figure is drawn.
    Every ``$`` of user text is escaped (``\$``): with no unescaped ``$`` left
    the text is not math, and matplotlib draws each ``\$`` as ``$``.

    >>> print(plain_text("Freezer $\\foo$ (5$)"))
    Freezer \$\foo\$ (5\$)
    """
    return str(text).replace("$", r"\$")


def _new_figure(height_in: float, width_in: float = FIGURE_WIDTH_IN) -> Figure:
    figure = Figure(figsize=(width_in, height_in), layout="constrained")
    FigureCanvasAgg(figure)  # a renderer for measuring labels
    return figure


def _to_svg(figure: Figure) -> str:
    buffer = io.StringIO()
    figure.savefig(buffer, format="svg", metadata={"Date": None, "Creator": None})
    return lean_svg(buffer.getvalue())


_SVG_GROUP = re.compile(r'<g id="[^"]*">|<g\b[^>]*>|</g>')
_NO_ROTATION = re.compile(r' transform="rotate\(-0 [-+0-9.e]+ [-+0-9.e]+\)"')


def lean_svg(svg: str) -> str:
    """Matplotlib's SVG without what draws nothing: the groups that only name an artist (``<g id="…">``, each a
    node the PDF's renderer visits, a third of a figure's nodes) give their children to their parent, and a
    text's rotation by −0° goes. A group with any other attribute (a clip path, a style) stays.

    >>> lean_svg('<g id="axes_1"><g clip-path="url(#p1)"><g id="line2d_1"><path d="M 0 0"/></g></g></g>')
    '<g clip-path="url(#p1)"><path d="M 0 0"/></g>'
    >>> lean_svg('<text x="1" y="2" transform="rotate(-0 1 2)">0</text>')
    '<text x="1" y="2">0</text>'
    """
    out, kept, last = [], [], 0
    for match in _SVG_GROUP.finditer(svg):
        tag = match.group(0)
        if tag == "</g>":
            keep = kept.pop()
        else:
            keep = not (tag.startswith('<g id="') and tag.count('"') == 2)
            kept.append(keep)
        out.append(svg[last:match.start()])
        if keep:
            out.append(tag)
        last = match.end()
    out.append(svg[last:])
    return _NO_ROTATION.sub("", "".join(out))


def regression_constants(result) -> tuple[float, float, float, float, float]:
    """``(zeta, eta, sigma, im_min, im_max)`` of ``result.regression``, the paper's by default."""
    regression = result.regression  # a RegressionRecord: the paper's constants unless the run's differ
    return regression.zeta, regression.eta, regression.sigma, regression.im_min, regression.im_max


def _freestanding(result) -> pd.DataFrame:
    summary = result.summary
    return summary[summary["risk"].astype(str) != "anchored"]


def _place_labels(axes, points, labels, colours, fontsize=6.5) -> None:
    """Label points by id where a label fits: offsets on rings of growing radius around the point (a thin
    leader line beyond the first ring), never over another label or outside the axes; a point whose
    label fits nowhere stays unlabelled (every item is in the report's tables).

    Each label is measured once and its box at every candidate offset is computed, not drawn: only the
    offset chosen becomes an annotation (drawing and removing a trial annotation with its leader for
    every offset took most of the report's figure time).
    """
    renderer = axes.figure.canvas.get_renderer()
    frame = axes.get_window_extent(renderer)
    pixels_per_point = axes.figure.dpi / 72.0
    near = [(5, 4), (5, -9), (-5, 4), (-5, -9)]
    rings = [(r * np.cos(a), r * np.sin(a)) for r in (16, 26, 38, 52)
             for a in np.deg2rad([30, -30, 150, -150, 90, -90, 0, 180, 60, -60, 120, -120])]
    placed = []
    for (x, y), label, colour in zip(points, labels, colours):
        label = plain_text(label)
        probe = axes.text(0.0, 0.0, label, fontsize=fontsize, transform=None)  # its box as matplotlib lays it out
        extent = probe.get_window_extent(renderer)
        width, height = extent.width, extent.height
        probe.remove()
        px, py = axes.transData.transform((x, y))
        for k, (dx, dy) in enumerate(near + rings):
            x0 = px + dx * pixels_per_point - (0.0 if dx >= 0 else width)
            y0 = py + dy * pixels_per_point - (0.0 if dy >= 0 else height)
            box = matplotlib.transforms.Bbox([[x0, y0], [x0 + width, y0 + height]])
            if k >= len(near):  # the leader runs from the point to the label
                box = matplotlib.transforms.Bbox.union([box, matplotlib.transforms.Bbox([[px, py], [px, py]])])
            box = box.expanded(1.05, 1.1)
            inside = frame.x0 <= box.x0 and box.x1 <= frame.x1 and frame.y0 <= box.y0 and box.y1 <= frame.y1
            if inside and not any(box.overlaps(other) for other in placed):
                leader = {"arrowstyle": "-", "color": colour, "lw": 0.4} if k >= len(near) else None
                axes.annotate(label, (x, y), xytext=(dx, dy), textcoords="offset points", fontsize=fontsize,
                              color=colour, ha="left" if dx >= 0 else "right", va="bottom" if dy >= 0 else "top",
                              arrowprops=leader)
                placed.append(box)
                break


def plain_log_ticks(*axes_axis) -> None:
    """Label a log axis with plain numbers (0.5, 2, 30), never "2×10⁰"; no labels on minor ticks."""
    for axis in axes_axis:
        axis.set_major_formatter(matplotlib.ticker.FuncFormatter(lambda v, _: f"{v:g}"))
        axis.set_minor_formatter(matplotlib.ticker.NullFormatter())


def _shade_fitted_range(axes, im_min: float, im_max: float, label: str | None) -> None:
    axes.axvspan(im_min, im_max, color="#eaf2f8", zorder=0, lw=0, label=label)


# --------------------------------------------------------------------------- figures
def fragility_points(result) -> pd.DataFrame:
    """The items Fig. 2 marks: each freestanding item's ``id``, governing ``im``, ``risk`` and ``chance``, its
    chance of sliding past its room as the tables give it (``p_beyond_clearance`` of the summary: the demand
    over all its motions, simulated or the regression's), and ``from_regression``, whether that chance is the
    regression's (its demand from the regression alone) rather than the simulation's.

    The regression's own Pf at the governing motion (``pf_sliding``) is not drawn: for an item whose demand
    the simulation gives it is a number no table shows (near 1 for a cart on casters far outside the fitted
    range, whose tables say 0 %)."""
    items = _freestanding(result)
    chance = pd.to_numeric(items["p_beyond_clearance"], errors="coerce") if "p_beyond_clearance" in items \
        else pd.Series(np.nan, index=items.index)
    im = pd.to_numeric(items["im"], errors="coerce")
    source = items["demand_source"] if "demand_source" in items else pd.Series("", index=items.index)
    from_regression = source.map(lambda s: tuple(s) == ("regression",) if isinstance(s, (tuple, list))
                          else str(s) == "regression")
    points = pd.DataFrame({"id": items["id"].astype(str), "im": im, "chance": chance,
                           "risk": items["risk"].astype(str), "from_regression": from_regression.astype(bool)})
    return points[np.isfinite(points["im"]) & np.isfinite(points["chance"])]


def fragility_figure(result) -> str:
    """Fragility curves as the paper's Fig. 12, with each freestanding item marked.

    Curves: :func:`fragility_curve` for c = 0.2, 0.4, 0.6, 0.8 against IM.
    Points: :func:`fragility_points`, each freestanding item at its governing IM and its chance of sliding past
    its room as the tables give it, coloured by risk and labelled by id; filled where that chance is the
    regression's (its own capacity c = clearance·ωp²/PTA, between the paper's curves), hollow where the
    simulation gives it.
    """
    zeta, eta, sigma, im_min, im_max = regression_constants(result)
    items = fragility_points(result)
    im_top = max(7.0, float(items["im"].max()) * 1.05 if len(items) else 0.0)
    im_bottom = min(0.0, float(items["im"].min()) - 0.2 if len(items) else 0.0)
    grid = np.linspace(im_bottom, im_top, 701)
    with matplotlib.rc_context(_RC):
        figure = _new_figure(3.5)
        axes = figure.add_subplot()
        _shade_fitted_range(axes, im_min, im_max,
                            f"IM range of the paper's 27 simulations ({im_min:g}–{im_max:g})")
        styles = ["-", "--", "-.", ":"]
        for capacity, style in zip(PAPER_CAPACITIES, styles):
            axes.plot(grid, fragility_curve(grid, capacity, zeta, eta, sigma), style,
                      color="#2c3e50", lw=1.1, label=f"c = {capacity:g}")
        for (risk, regression), group in items.groupby([items["risk"], items["from_regression"]], sort=False):
            colour = RISK_COLOURS.get(risk, "#000000")
            axes.scatter(group["im"], group["chance"], s=18, zorder=5, color=colour if regression else "white",
                         edgecolor="white" if regression else colour, linewidth=0.5 if regression else 0.9)
        _place_labels(axes, list(zip(items["im"], items["chance"])), list(items["id"]),
                      [RISK_COLOURS.get(str(r), "#000000") for r in items["risk"]])
        axes.set_xlim(im_bottom, im_top)
        axes.set_ylim(-0.02, 1.05)
        axes.set_xlabel("Intensity measure IM = PTA/(μg) − 1 [–]")
        axes.set_ylabel("Pf = P(sliding demand > capacity c) [–]\nitems: chance past their room")
        filled = bool(items["from_regression"].any())
        handles, labels = axes.get_legend_handles_labels()  # the range, then the 4 curves
        second_row = [(handles[0], labels[0])] + [
            (Line2D([], [], ls="", marker="o", ms=4.5, color=RISK_COLOURS[r],  # hollow as the dots are where
                    markerfacecolor=RISK_COLOURS[r] if filled else "white"), f"item, {r} risk")  # none is filled
            for r in ("high", "moderate", "low")]
        ordered = []  # the legend fills column by column: curves on the first row
        for curve, other in zip(zip(handles[1:], labels[1:]), second_row):
            ordered += [curve, other]
        figure.legend([h for h, _ in ordered], [label for _, label in ordered],
                      loc="outside lower center", ncol=4, frameon=False)
        return _to_svg(figure)


def regression_figure(result, table3: pd.DataFrame | None = None) -> str:
    """IM–EDP data and regression as the paper's Fig. 10.

    Left, log–log: the 27 (IM, Π) points of Table 3, the median ζ·IM^η and the
    16th–84th percentile band (median × e^{∓σ}), the fitted IM range shaded.
    Right: the same on linear axes (the funnel of Fig. 10, bottom). The items'
    governing IM is marked on the median line (items with a sliding estimate).
    """
    zeta, eta, sigma, im_min, im_max = regression_constants(result)
    table = km2010_table3() if table3 is None else table3
    items = _freestanding(result)
    items = items[np.isfinite(items["im"].astype(float)) & (items["im"].astype(float) > 0)
                  & np.isfinite(items["sliding_median_cm"].astype(float))]
    im_top = max(7.0, float(items["im"].max()) * 1.05 if len(items) else 0.0)
    markers = {"FORMA": "o", "KELVINATOR": "s", "ASP": "^"}
    with matplotlib.rc_context(_RC):
        figure = _new_figure(3.3)
        log_axes, linear_axes = figure.subplots(1, 2)
        for axes, logscale in ((log_axes, True), (linear_axes, False)):
            lower = 0.3 if logscale else 0.0
            grid = (np.geomspace(lower, im_top, 400) if logscale
                    else np.linspace(1e-3, im_top, 400))
            median = zeta * grid ** eta
            _shade_fitted_range(axes, im_min, im_max, "fitted IM range")
            axes.fill_between(grid, median * math.exp(-sigma), median * math.exp(sigma),
                              color="#aab7b8", alpha=0.45, lw=0,
                              label="16th–84th percentile (median × e$^{\\mp\\sigma}$)")
            axes.plot(grid, median, color="#2c3e50", lw=1.2,
                      label=f"median Π = {zeta:.3g}·IM$^{{{eta:.3g}}}$")
            for equipment, group in table.groupby("equipment", sort=False):
                axes.scatter(group["im"], group["edp"], s=14, marker=markers.get(equipment, "o"),
                             facecolor="white", edgecolor="#34495e", linewidth=0.8,
                             zorder=4, label=plain_text(f"Table 3, {equipment}"))
            if len(items):
                item_im = items["im"].astype(float).to_numpy()
                axes.scatter(item_im, zeta * item_im ** eta, s=26, marker="D",
                             color=[RISK_COLOURS.get(str(r), "#000") for r in items["risk"]],
                             edgecolor="white", linewidth=0.5, zorder=6)
            if logscale:
                axes.set_xscale("log")
                axes.set_yscale("log")
                axes.set_xlim(lower, im_top * 1.1)
                axes.set_ylim(0.05, 10)
                axes.set_title("log–log: ln Π is linear in ln IM", loc="left")
                axes.set_xticks([0.5, 1, 2, 3, 5, 7])
                axes.set_yticks([0.1, 0.2, 0.5, 1, 2, 5])
                plain_log_ticks(axes.xaxis, axes.yaxis)
            else:
                axes.set_xlim(0, im_top)
                axes.set_ylim(0, max(4.0, float(table["edp"].max()) * 1.2))
                axes.set_title("linear: the scatter grows with IM", loc="left")
            axes.set_xlabel("IM = PTA/(μg) − 1 [–]")
            axes.set_ylabel("EDP Π = Umax·ωp²/PTA [–]")
        if len(items):
            item_im = items["im"].astype(float).to_numpy()
            _place_labels(linear_axes, list(zip(item_im, zeta * item_im ** eta)),
                          list(items["id"].astype(str)),
                          [RISK_COLOURS.get(str(r), "#000") for r in items["risk"]])
        handles, labels = log_axes.get_legend_handles_labels()
        if len(items):
            handles.append(Line2D([], [], ls="", marker="D", ms=4.5, color="#7f8c8d"))
            labels.append("items (colour = risk)")
        figure.legend(handles, labels, loc="outside lower center", ncol=3, frameon=False)
        return _to_svg(figure)


def sliding_demand_figures(result, per_figure: int = ITEMS_PER_DEMAND_FIGURE, system: str = "si") -> list[str]:
    """Per item: the governing demand's median sliding (bar) and 84th percentile (whisker) against clearance.

    One horizontal row per freestanding item, in the order of ``result.summary``
    (the caller sorts it); an item with no sliding estimate (it rocks, or stays
    put) says so in its row. Inventories longer than ``per_figure`` items are
    split over several figures. Lengths in cm, or in inches for ``system`` ``'us'``. Returns a list of
    SVG documents (empty when no item is freestanding).
    """
    items = _freestanding(result)
    scale = length_value(1.0, system)
    x_top = _demand_axis_top(items) * scale  # one scale for all the figures, so bars compare across them
    return [_sliding_demand_figure(items.iloc[start:start + per_figure], x_top, system)
            for start in range(0, len(items), per_figure)]


def _demand_axis_top(items: pd.DataFrame) -> float:
    values = [items[c].astype(float).to_numpy() for c in ("demand_median_cm", "demand_p84_cm", "clearance_cm")]
    finite = np.concatenate([v[np.isfinite(v)] for v in values] + [[10.0]])
    return float(np.max(finite)) * 1.12


def _short(text: str, limit: int = 26) -> str:
    return text if len(text) <= limit else text[: limit - 1] + "…"


def _left_align_tick_labels(axes) -> None:
    """Left-align the y tick labels (ids in one column) by padding them by the widest one."""
    renderer = axes.figure.canvas.get_renderer()
    labels = axes.get_yticklabels()
    if not labels:
        return
    widest_px = max(label.get_window_extent(renderer).width for label in labels)
    for label in labels:
        label.set_horizontalalignment("left")
    axes.tick_params(axis="y", pad=widest_px * 72.0 / axes.figure.dpi + 3.0)


def _sliding_demand_figure(items: pd.DataFrame, x_top: float, system: str = "si") -> str:
    count = len(items)
    scale = length_value(1.0, system)
    median = items["demand_median_cm"].astype(float).to_numpy() * scale
    p84 = items["demand_p84_cm"].astype(float).to_numpy() * scale
    clearance = items["clearance_cm"].astype(float).to_numpy() * scale
    rows = np.arange(count)
    colours = [RISK_COLOURS.get(str(r), "#000000") for r in items["risk"]]
    with matplotlib.rc_context(_RC):
        figure = _new_figure(0.9 + 0.21 * count)
        axes = figure.add_subplot()
        axes.grid(axis="y", visible=False)
        for row, m, p, c, colour, mode in zip(rows, median, p84, clearance, colours,
                                              items["mode"].astype(str)):
            if np.isfinite(m):
                axes.barh(row, m, height=0.55, color=colour, alpha=0.85, zorder=3)
            if np.isfinite(m) and np.isfinite(p):
                axes.plot([m, p], [row, row], color="#2c3e50", lw=1.0, zorder=4)
                axes.plot([p, p], [row - 0.17, row + 0.17], color="#2c3e50", lw=1.0, zorder=4)
            if not np.isfinite(m):
                note = {"rock": "rocks: sliding not estimated, see action",
                        "rest": "does not move"}.get(mode, "no sliding estimate")
                x_note = (c if np.isfinite(c) else 0.0) + x_top * 0.015
                axes.text(x_note, row, note, va="center", fontsize=6.8,
                          color=colour, style="italic")
            if np.isfinite(c):
                axes.plot([c, c], [row - 0.36, row + 0.36], color="black", lw=2.0, zorder=5,
                          solid_capstyle="butt")
        labels = [plain_text(f"{_short(str(i), 12)}  {_short(str(n), 40)}") for i, n in
                  zip(items["id"], items["name"])]
        axes.set_yticks(rows, labels)
        _left_align_tick_labels(axes)
        axes.set_ylim(count - 0.5, -0.5)
        axes.set_xlim(0, x_top)
        axes.set_xlabel(f"sliding [{length_unit(system)}]")
        axes.set_ylabel("item (id, name)")
        axes.tick_params(axis="y", length=0)
        handles = [Patch(color="#7f8c8d", alpha=0.85, label="median sliding (bar colour = risk)"),
                   Line2D([], [], color="#2c3e50", lw=1.0, marker="|", ms=6,
                          label="84th percentile (1 in 6 chance of more)"),
                   Line2D([], [], color="black", lw=0, marker="|", ms=9, mew=2.0,
                          label="clearance (room to slide)")]
        figure.legend(handles=handles, loc="outside upper center", ncol=3, frameon=False)
        return _to_svg(figure)


# --------------------------------------------------------------------------- simulation
def history_figure(history: dict, system: str = "si") -> str:
    """Time histories of one simulated case, as Fig. 7 of the paper.

    Three panels on one time axis: sliding relative to the floor [cm] with the
    clearance marked, rotation θ/α (±1 dotted: the block's centre of mass is
    over its pivot) and the floor acceleration [g]. Sliding in inches for ``system`` ``'us'``.
    """
    scale = length_value(1.0, system)
    with matplotlib.rc_context(_RC):
        figure = _new_figure(3.6)
        axes = figure.subplots(3, 1, sharex=True)
        time_s = np.asarray(history["time_s"])
        axes[0].plot(time_s, np.asarray(history["sliding_cm"], dtype=float) * scale, color="#1f4e79", linewidth=0.9)
        for sign in (1, -1):
            axes[0].axhline(sign * history["clearance_cm"] * scale, color="black", linewidth=0.7, linestyle="--")
        axes[0].set_ylabel(f"sliding [{length_unit(system)}]")
        axes[1].plot(time_s, history["theta_over_alpha"], color="#922b21", linewidth=0.9)
        for sign in (1, -1):
            axes[1].axhline(sign, color="#922b21", linewidth=0.6, linestyle=":")
        axes[1].set_ylabel("θ/α [–]")
        axes[2].plot(time_s, history["floor_accel_g"], color="#555555", linewidth=0.7)
        axes[2].set_ylabel("floor acc. [g]")
        axes[2].set_xlabel("time [s]")
        title = (f"{history['id']}: {history['mode']}"
                 f"{', overturns' if history['overturned'] else ''}")
        axes[0].set_title(plain_text(title), loc="left")
        return _to_svg(figure)


def simulation_vs_regression_figure(result, system: str = "si") -> str:
    """Simulated peak sliding against the regression's median for every sliding case.

    Log–log axes; the diagonal is agreement, the dotted lines the regression's
    16th and 84th percentiles (median × e^∓σ). Cases where either is zero are
    left out (said in the caption).
    """
    zeta, eta, sigma, *_ = regression_constants(result)
    motions = result.motions
    scale = length_value(1.0, system)
    sim = pd.to_numeric(motions["sim_sliding_max_cm"], errors="coerce") * scale
    reg = pd.to_numeric(motions["sliding_median_cm"], errors="coerce") * scale
    shown = slides_in_both(motions)
    with matplotlib.rc_context(_RC):
        figure = _new_figure(3.4)
        axes = figure.subplots()
        axes.set_box_aspect(1.0)
        if shown.any():
            axes.scatter(reg[shown], sim[shown], s=10, color="#1f4e79", alpha=0.75, linewidths=0)
            low = float(min(reg[shown].min(), sim[shown].min())) / 1.5
            high = float(max(reg[shown].max(), sim[shown].max())) * 1.5
            line = np.array([low, high])
            axes.plot(line, line, color="black", linewidth=0.8, label="simulation = regression median")
            for factor, label in ((np.exp(sigma), "regression 16th / 84th percentile"), (np.exp(-sigma), None)):
                axes.plot(line, line * factor, color="black", linewidth=0.6, linestyle=":", label=label)
            axes.set_xscale("log")
            axes.set_yscale("log")
            axes.set_xlim(low, high)
            axes.set_ylim(low, high)
            plain_log_ticks(axes.xaxis, axes.yaxis)
            axes.legend(loc="upper left", frameon=False)
        else:
            axes.text(0.5, 0.5, "no case slides in both", ha="center", va="center", transform=axes.transAxes)
        axes.set_xlabel(f"regression median sliding [{length_unit(system)}]")
        axes.set_ylabel(f"simulated peak sliding [{length_unit(system)}]")
        return _to_svg(figure)
