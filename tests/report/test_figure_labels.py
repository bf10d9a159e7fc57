"""Fig. 2's item labels (:func:`assess.report.figures._place_labels`): a label is left out only where it has no room.

Checked on the figure as matplotlib draws it: with the points apart, every item keeps its label, once; with
the points spread over the axes, nine in ten at least; with the points crowded, every point left unlabelled
has a drawn label within a label's width of it; and the labels drawn lie inside the axes and apart.
"""
from __future__ import annotations

import matplotlib
import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from assess.report import figures

def draw(points, labels):
    """The fragility figure's axes with ``points`` labelled by the placer: (axes, renderer)."""
    with matplotlib.rc_context(figures._RC):
        figure = Figure(figsize=(6.6, 3.5))
        FigureCanvasAgg(figure)
        axes = figure.add_subplot()
        axes.scatter(*zip(*points))
        axes.set_xlim(-0.5, 7.5)
        axes.set_ylim(-0.1, 1.1)
        figures._place_labels(axes, points, labels, ["#000000"] * len(points))
        return axes, figure.canvas.get_renderer()


def drawn_boxes(axes, renderer):
    return {text.get_text(): text.get_window_extent(renderer) for text in axes.texts}


def assert_inside_and_apart(axes, renderer, boxes):
    frame = axes.get_window_extent(renderer)
    listed = list(boxes.values())
    for i, box in enumerate(listed):
        assert frame.x0 - 0.5 <= box.x0 and box.x1 <= frame.x1 + 0.5
        assert frame.y0 - 0.5 <= box.y0 and box.y1 <= frame.y1 + 0.5
        assert not any(box.overlaps(other) for other in listed[i + 1:])


def test_points_apart_keep_every_label_once():
    points = [(x, y) for x in (0.5, 2.5, 4.5, 6.5) for y in (0.15, 0.5, 0.85)]
    labels = [f"ITEM-{i:02d}" for i in range(len(points))]
    axes, renderer = draw(points, labels)
    assert sorted(text.get_text() for text in axes.texts) == sorted(labels)
    assert_inside_and_apart(axes, renderer, drawn_boxes(axes, renderer))


def test_forty_points_over_the_axes_keep_nine_labels_in_ten():
    """The 40 items spread over the figure lose at most 4 labels (today they lose none, 39 with 3-digit ids)."""
    rng = np.random.default_rng(3)
    points = list(zip(rng.uniform(0, 7, 40), rng.uniform(0, 1, 40)))
    labels = [f"ITEM-{i:02d}" for i in range(40)]
    axes, renderer = draw(points, labels)
    boxes = drawn_boxes(axes, renderer)
    assert len(axes.texts) == len(boxes) >= 36  # none drawn twice, at most one in ten left out
    assert_inside_and_apart(axes, renderer, boxes)


def test_a_crowded_point_loses_its_label_only_among_other_labels():
    """60 items in a fifth of the axes: many labels cannot fit; each point left unlabelled has a drawn label
    within a label's width of it (measured: 12 px at most, labels 44 px wide)."""
    rng = np.random.default_rng(3)
    points = list(zip(rng.uniform(2, 4, 60), rng.uniform(0.3, 0.6, 60)))
    labels = [f"ITEM-{i:03d}" for i in range(60)]
    axes, renderer = draw(points, labels)
    boxes = drawn_boxes(axes, renderer)
    assert len(axes.texts) == len(boxes) and 0 < len(boxes) < len(labels)
    assert_inside_and_apart(axes, renderer, boxes)
    label_width_px = max(box.width for box in boxes.values())
    for (x, y), label in zip(points, labels):
        if label not in boxes:
            px, py = axes.transData.transform((x, y))
            nearest_px = min(max(box.x0 - px, px - box.x1, box.y0 - py, py - box.y1, 0.0) for box in boxes.values())
            assert nearest_px <= label_width_px, f"{label} has no label within {label_width_px:.0f} px"
