"""The component coefficients of ASCE 7-16 and ASCE 7-22 Tables 13.5-1 / 13.6-1, by component type.

The numbers live in one packaged, cited table, ``assess/data/components.csv``: one row per edition and
component type, with a_p and R_p (7-16), C_AR at or below grade, C_AR above grade and R_po (7-22), the
overstrength factor Ω0p of the same row (anchors in concrete or masonry, §13.4.2), whether the numbers
were confirmed in a public copy of the standard (``confirmed``: ``yes``, ``partly`` or ``no``) and where
each came from (``source``). The file's header lists the sources read.

What could be confirmed (Nov 2026): a_p and R_p of the mechanical and electrical rows, read in a public
copy of ASCE 7-10 Table 13.6-1 (rows unchanged in 7-16). Every ASCE 7-22 C_AR, R_po and Ω0p, and the
7-16 Ω0p of the Table 13.5-1 rows, agree with the public FpCalc calculator's transcription of the tables
(its row numbers are quoted in ``source``), and four 7-22 rows also with a second, independent public
calculator; that transcription corrected two of our earlier readings (computer racks: C_AR 1.0/1.0,
R_po 1.5, not 1.4/2.2, 2.0; other mechanical or electrical components: R_po 1.5, not 1.3). No public copy
of the standard's own 7-22 tables was found, so no row is ``yes``; the 7-16 Ω0p of the mechanical and
electrical rows have no source. :class:`ComponentCoefficients` carries ``confirmed`` so that a report
can say which numbers an engineer must check before signing.

Names are matched case-insensitively, with the aliases of the table (``UPS``, ``freezer``,
``switchgear``, ...); no type given means :data:`DEFAULT_COMPONENT_TYPE`.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from importlib import resources

import pandas as pd

#: The editions whose Chapter 13 this package implements, as the ``site`` sheet's ``code`` names them.
EDITIONS = ("ASCE 7-16", "ASCE 7-22")
#: Component type when none is given: the row this tool applied to every item before component types
#: existed (ASCE 7-16 Table 13.5-1, laboratory equipment: a_p 1.0, R_p 2.5).
DEFAULT_COMPONENT_TYPE = "laboratory equipment"


@dataclass(frozen=True)
class ComponentCoefficients:
    """One row of ``components.csv``: the coefficients of one component type under one edition.

    ``amplification`` (a_p) and ``response_modification`` (R_p) are set for ASCE 7-16 and NaN for
    7-22; ``resonance_at_or_below_grade`` and ``resonance_above_grade`` (C_AR) and ``strength`` (R_po)
    the other way round. ``overstrength`` is Ω0p, ``row`` the table row in words, ``confirmed`` one of
    ``yes``, ``partly``, ``no`` and ``source`` where the numbers came from.
    """

    edition: str
    component_type: str
    row: str
    amplification: float
    response_modification: float
    resonance_at_or_below_grade: float
    resonance_above_grade: float
    strength: float
    overstrength: float
    confirmed: str
    source: str


def canonical_edition(edition) -> str:
    """``'ASCE 7-16'`` or ``'ASCE 7-22'`` from how a user may write it (``7-22``, ``asce 7-16``, ``ASCE7-22``).

    >>> canonical_edition("asce7-16"), canonical_edition(" 7-22 ")
    ('ASCE 7-16', 'ASCE 7-22')
    """
    text = str(edition).strip().upper().replace("ASCE", "").replace("/SEI", "").replace(" ", "")
    for name in EDITIONS:
        if text == name.replace("ASCE ", ""):
            return name
    raise ValueError(f"unknown code edition {edition!r}: use one of {', '.join(EDITIONS)}")


def _key(name) -> str:
    return " ".join(str(name).strip().lower().replace("_", " ").replace("-", " ").split())


@lru_cache(maxsize=1)
def component_table() -> pd.DataFrame:
    """The packaged ``components.csv`` as read (comment lines dropped)."""
    with resources.files("assess.data").joinpath("components.csv").open("r") as handle:
        return pd.read_csv(handle, comment="#", dtype={"aliases": str})


@lru_cache(maxsize=1)
def _index() -> dict:
    index = {}
    for row in component_table().itertuples(index=False):
        record = ComponentCoefficients(
            edition=row.edition, component_type=row.component_type, row=row.row,
            amplification=float(row.a_p), response_modification=float(row.r_p),
            resonance_at_or_below_grade=float(row.car_at_or_below_grade),
            resonance_above_grade=float(row.car_above_grade), strength=float(row.r_po),
            overstrength=float(row.omega_0p), confirmed=str(row.confirmed), source=str(row.source))
        names = [row.component_type] + (str(row.aliases).split(";") if isinstance(row.aliases, str) else [])
        for name in names:
            key = (row.edition, _key(name))
            if key in index and index[key] != record:
                raise ValueError(f"components.csv: {name!r} names two rows under {row.edition}")
            index[key] = record
    return index


def component_types() -> list[str]:
    """The component types of the table (without aliases), in its order."""
    return list(dict.fromkeys(component_table()["component_type"]))


def component_coefficients(edition, component_type=None) -> ComponentCoefficients:
    """The coefficients of ``component_type`` (a name or an alias, any case) under ``edition``.

    ``None``, NaN (an empty workbook cell) or an empty name gives :data:`DEFAULT_COMPONENT_TYPE`. An unknown name raises
    ``ValueError`` listing the known types.

    >>> c = component_coefficients("ASCE 7-16", "Lab Equipment")
    >>> c.component_type, c.amplification, c.response_modification
    ('laboratory equipment', 1.0, 2.5)
    >>> component_coefficients("7-22", "UPS").component_type
    'battery rack'
    """
    edition = canonical_edition(edition)
    missing = component_type is None or (isinstance(component_type, float) and component_type != component_type)
    name = DEFAULT_COMPONENT_TYPE if missing or not str(component_type).strip() else component_type
    try:
        return _index()[(edition, _key(name))]
    except KeyError:
        raise ValueError(f"unknown component_type {str(component_type)[:80]!r}: use one of "
                         f"{', '.join(component_types())}") from None
