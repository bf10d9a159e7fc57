"""The report's figure labels, placed by arithmetic for speed, are where matplotlib draws them.

- Labels of the fragility figure are placed by arithmetic (:func:`assess.report.figures._place_labels`):
  the labels it places, drawn by matplotlib, lie inside the axes and overlap neither each other.
"""
from __future__ import annotations

import numpy as np

from tests.report.test_figure_labels import draw


def test_placed_labels_lie_inside_and_apart():
    rng = np.random.default_rng(3)
    points = list(zip(rng.uniform(0, 7, 40), rng.uniform(0, 1, 40)))
    labels = [f"ITEM-{i:02d}" for i in range(40)]
    axes, renderer = draw(points, labels)  # the fragility figure's axes, labelled by the placer
    frame = axes.get_window_extent(renderer)
    texts = [child for child in axes.texts]
    assert 10 <= len(texts) <= 40  # most labels find a place, none is drawn twice
    assert len({t.get_text() for t in texts}) == len(texts)
    boxes = [t.get_window_extent(renderer) for t in texts]  # the text alone, as matplotlib draws it
    for i, box in enumerate(boxes):
        assert frame.x0 - 0.5 <= box.x0 and box.x1 <= frame.x1 + 0.5
        assert frame.y0 - 0.5 <= box.y0 and box.y1 <= frame.y1 + 0.5
        for other in boxes[i + 1:]:
            assert not box.overlaps(other)
