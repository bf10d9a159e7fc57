"""What the report's method says about the anchorage forces of a run (``templates/_anchorage_method.html.j2``).

Built here from the run's :class:`~assess.anchorage.AnchorageSite` and its summary, so the template only
lays it out: the edition applied, where S_DS, z/h, T_a and R_μ came from, and each component type used
with its coefficients, whether they were confirmed and where they come from
(``assess/data/components.csv``).
"""
from __future__ import annotations

import math

import pandas as pd

from assess.anchorage.coefficients import component_coefficients
from assess.anchorage.item import ANCHORAGE_KINDS, AnchorageSite

#: What ``confirmed`` means, for the reader.
CONFIRMATION_TEXT = {
    "yes": "read in a public copy of the standard",
    "partly": "from public transcriptions of the table (not the standard's text): check before signing",
    "no": "not confirmed: check against the standard before signing",
}


def _coefficients_text(row) -> str:
    if row.edition == "ASCE 7-16":
        return f"a_p {row.amplification:g}, R_p {row.response_modification:g}, Omega_0p {row.overstrength:g}"
    return (f"C_AR {row.resonance_at_or_below_grade:g} at or below grade, {row.resonance_above_grade:g} above; "
            f"R_po {row.strength:g}, Omega_0p {row.overstrength:g}")


def anchorage_method(site: AnchorageSite | None, summary: pd.DataFrame) -> dict:
    """``edition``, ``basis`` (where each input came from), ``types`` (one dict per component type with a
    force in this run: ``name``, ``row``, ``coefficients``, ``confirmed``, ``source``) and ``item_count`` (how
    many items have a force); an empty dict without a site (a result from before this field existed).

    >>> from assess.anchorage.item import anchorage_site
    >>> table = pd.DataFrame({"action_kind": ["anchor", "none"], "component_type": ["freezer", "lab"],
    ...                       "anchor_force_kn": [1.0, float("nan")]})
    >>> from assess.inventory.settings import Settings
    >>> m = anchorage_method(anchorage_site(None, None, Settings(sds_g=1.0)), table)
    >>> m["edition"], [t["name"] for t in m["types"]], m["item_count"]
    ('ASCE 7-22', ['refrigeration'], 1)
    """
    if site is None:
        return {}
    kinds = summary["action_kind"].astype(str) if "action_kind" in summary else pd.Series([], dtype=str)
    forces = summary["anchor_force_kn"] if "anchor_force_kn" in summary else pd.Series([], dtype=float)
    with_force = summary[kinds.isin(ANCHORAGE_KINDS) & forces.apply(lambda x: x is not None and math.isfinite(x))]
    types = []
    for name in dict.fromkeys(with_force["component_type"].astype(str)) if len(with_force) else []:
        row = component_coefficients(site.edition, name)
        if any(t["name"] == row.component_type for t in types):
            continue
        types.append({"name": row.component_type, "row": row.row, "coefficients": _coefficients_text(row),
                      "confirmed": CONFIRMATION_TEXT[row.confirmed], "source": row.source})
    return {"edition": site.edition, "basis": site.basis, "types": types, "item_count": int(len(with_force)),
            "sds_known": bool(site.sds_g > 0.0)}
