"""A default range of the friction coefficient μ for an item whose row leaves ``mu`` empty.

μ is the least certain input of a freestanding item (Konstantinidis & Makris 2010 [1] measured
0.23–0.31 by slow pull on their three prototypes, laboratory equipment on its feet, and needed 0.13–0.20 to match
the shake table). A row without ``mu`` therefore gets a *range*, never a single guessed value: the
range the item's ``base`` on its ``floor_finish`` is known to take where the workbook says both (or
the base alone), else :data:`WIDE_RANGE`. The range goes through the μ-range machinery as a
workbook's ``mu_low`` / ``mu_high`` would (:mod:`assess.fragility.friction_range`: a triangular
distribution, here with its mode, the nominal ``mu``, at the middle), and the report says which
items took a default and why (``mu_source``). The values and their sources are in docs/workbook.md.

References
----------
.. [1] Konstantinidis, D., Makris, N. (2010). Experimental and analytical studies on the response of
   1/4-scale models of freestanding laboratory equipment subjected to strong earthquake shaking.
   Bull. Earthquake Eng. 8:1457-1477: Table 3 p.1467 (equipment on the floor: best fit 0.13-0.20,
   slow pull 0.23-0.31); p.1460 (wooden blocks on concrete: slow pull 0.68).
.. [2] Engineering ToolBox (2004). Friction and friction coefficients for various materials:
   rubber on concrete, kinetic, dry 0.6-0.85, wet 0.45-0.75 (the values of the common handbook
   tables). https://www.engineeringtoolbox.com/friction-coefficients-d_778.html
"""
from __future__ import annotations

from dataclasses import dataclass

#: The range for an item whose base or floor finish the workbook does not say, or whose base on its
#: finish has no published value: from about the slow-pull values of steel feet [1] (0.23-0.31) to
#: rubber on concrete and wood on concrete (0.6-0.68, [1], [2]), the span of the measured values.
WIDE_RANGE = (0.2, 0.6)

#: ``base`` as a workbook may write it -> the kind of base.
BASES = {
    "steel feet": "steel", "steel": "steel", "steel legs": "steel", "metal feet": "steel", "metal": "steel",
    "metal base": "steel", "levelling feet": "steel", "leveling feet": "steel", "steel base": "steel",
    "rubber feet": "rubber", "rubber": "rubber", "rubber pads": "rubber", "elastomer pads": "rubber",
    "rubber base": "rubber",
    "wood base": "wood", "wood": "wood", "wooden base": "wood", "plastic base": "wood", "plastic": "wood",
    "wood/plastic base": "wood", "plastic feet": "wood",
    "casters": "casters", "castors": "casters", "wheels": "casters",
}
#: ``floor_finish`` as a workbook may write it -> the kind of finish: hard (vinyl, concrete, epoxy, tile) or carpet.
FINISHES = {
    "vinyl": "hard", "vct": "hard", "vinyl/vct": "hard", "sheet vinyl": "hard", "linoleum": "hard",
    "sealed concrete": "hard", "concrete": "hard", "epoxy": "hard", "tile": "hard", "ceramic tile": "hard",
    "terrazzo": "hard", "rubber flooring": "hard",
    "carpet": "carpet", "carpet tile": "carpet",
}


@dataclass(frozen=True)
class DefaultRange:
    """A default μ range and why it applies (the sentence ``mu_source`` gives)."""

    mu_low: float
    mu_high: float
    why: str

    @property
    def mu(self) -> float:
        """The nominal μ: the middle of the range (the triangular distribution's mode)."""
        return round(0.5 * (self.mu_low + self.mu_high), 6)


#: (kind of base, kind of finish) -> (mu_low, mu_high, source). A finish not given reads as a hard floor.
_PUBLISHED = {
    ("steel", "hard"): (0.13, 0.31, "metal feet on a hard floor: Konstantinidis & Makris 2010 Table 3, laboratory "
                                    "equipment on its feet, best fit 0.13-0.20 to slow pull 0.23-0.31"),
    ("rubber", "hard"): (0.45, 0.85, "rubber on a hard floor: rubber on concrete 0.6-0.85 dry, 0.45-0.75 wet "
                                     "(handbook tables, e.g. Engineering ToolBox)"),
    ("wood", "hard"): (0.3, 0.7, "a wood or plastic base on a hard floor: up to wood on concrete 0.68 "
                                 "(Konstantinidis & Makris 2010 p.1460)"),
}


def base_kind(text: str) -> str | None:
    """The kind of base ``text`` names (``steel``, ``rubber``, ``wood``, ``casters``); None when unknown.

    >>> base_kind("Levelling feet"), base_kind(" rubber pads "), base_kind("granite")
    ('steel', 'rubber', None)
    """
    return BASES.get(" ".join(str(text).strip().lower().split()))


def finish_kind(text: str) -> str | None:
    """The kind of floor finish ``text`` names (``hard``, ``carpet``); None when unknown.

    >>> finish_kind("VCT"), finish_kind("Sealed concrete"), finish_kind("shag")
    ('hard', 'hard', None)
    """
    return FINISHES.get(" ".join(str(text).strip().lower().split()))


def default_range(base: str = "", finish: str = "", casters: bool = False) -> DefaultRange:
    """The default μ range of an item with no ``mu``, from its ``base`` and ``floor_finish`` (either may be "").

    >>> default_range("steel feet", "vinyl/VCT")  # doctest: +NORMALIZE_WHITESPACE
    DefaultRange(mu_low=0.13, mu_high=0.31, why='default for steel feet on vinyl/VCT (metal feet on a hard floor:
    Konstantinidis & Makris 2010 Table 3, laboratory equipment on its feet, best fit 0.13-0.20 to slow pull 0.23-0.31)')
    >>> default_range().mu_low, default_range().mu_high, default_range().mu
    (0.2, 0.6, 0.4)
    >>> default_range("casters", "epoxy").why
    'default for casters on epoxy (no published value for it: the wide range 0.2-0.6)'
    """
    kind = "casters" if casters and not base else base_kind(base) if base else None
    surface = finish_kind(finish) if finish else "hard"
    named = " on ".join(part for part in ((base or ("casters" if casters else "")).strip(), finish.strip()) if part)
    found = _PUBLISHED.get((kind, surface)) if kind is not None else None
    if found is not None:
        low, high, source = found
        return DefaultRange(low, high, f"default for {named} ({source})")
    low, high = WIDE_RANGE
    if not named:
        return DefaultRange(low, high, f"default, no base or floor finish given (the wide range {low:g}-{high:g})")
    return DefaultRange(low, high, f"default for {named} (no published value for it: the wide range {low:g}-{high:g})")
