"""The caveats of an item's result: what the decisions, the calibration and the demand stage attach to an
item for the report and the CSVs to show (the ``flags`` column of summary.csv, docs/outputs.md)."""
from __future__ import annotations

import math
from dataclasses import dataclass

from assess.quantity_text import length_unit, length_value, percent_text


@dataclass(frozen=True)
class Flag:
    """A caveat attached to one item's result (shown in the report and the CSVs)."""

    item_id: str
    code: str  # e.g. "uplift", "im_outside_fit", "derived_floor_motion"
    message: str
    #: What is this item's own in a few words ("46 in", "IM 0.06–0.16"), shown beside its id where the report
    #: gathers the flags of one cause into one (:func:`assess.report.sentences.flag_groups`); "" for none.
    detail: str = ""
    #: A length of the item's own [cm] that ``message`` and ``detail`` name as ``{length}``, written in the
    #: report's units by the report (:func:`assess.report.sentences.flag_text`); None for none.
    length_cm: float | None = None


def result_state(row, system: str = "si") -> str:
    """An item's result in words, for a flag that sets two of them side by side: 'risk high (mode slide):
    sliding 12.3 cm median, 20.1 cm 84th percentile, 62 % chance past the clearance, 0 % chance of
    overturning' from one summary row (the governing demand); lengths in inches for ``system`` ``'us'``."""
    def number(column, fmt, scale=1.0):
        value = row.get(column)
        try:
            value = float(value)
        except (TypeError, ValueError):
            return "–"
        return fmt.format(value * scale) if math.isfinite(value) else "–"

    per_cm, unit = length_value(1.0, system), length_unit(system)
    return (f"risk {row['risk']} (mode {row['mode'] or '–'}): sliding "
            f"{number('demand_median_cm', '{:.1f}', per_cm)} {unit} median, "
            f"{number('demand_p84_cm', '{:.1f}', per_cm)} {unit} 84th percentile, "
            f"{percent_text(row.get('p_beyond_clearance'))} chance past the clearance, "
            f"{percent_text(row.get('p_overturn'))} chance of overturning")
