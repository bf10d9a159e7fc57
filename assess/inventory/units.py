"""Unit suffixes of workbook headers and their conversion to SI.

A numeric workbook column names its unit in a suffix: ``height_cm``,
``mass_lb``, ``pta_cm_s2``. Each physical dimension accepts a fixed set of
suffixes; values are converted once, at load time, with `pint
<https://pint.readthedocs.io>`_ to the canonical unit of that dimension
(``docs/nomenclature.md``): metres, kilograms, seconds, metres per second and,
for accelerations, multiples of standard gravity g = 9.80665 m/s² (pint's
``standard_gravity``, the same constant as
``assess.mechanics.geometry.STANDARD_GRAVITY_M_S2``).
"""
from __future__ import annotations

from dataclasses import dataclass

from assess.units import conversion_factor

#: Centimetres per metre and per inch, from pint (exact: 100 and 2.54); the summary's lengths are in cm.
CM_PER_M = conversion_factor("meter", "centimeter")
CM_PER_IN = conversion_factor("inch", "centimeter")
#: Newtons per pound-force and kilograms per pound, as defined (1 lb = 0.45359237 kg, 1 lbf = 1 lb x g):
#: pint's factors to the last bit but one (tests/inventory/test_unit_constants.py).
N_PER_LBF = 4.4482216152605
KG_PER_LB = 0.45359237
#: Metres per foot, as defined (1 ft = 0.3048 m).
M_PER_FT = 0.3048


@dataclass(frozen=True)
class Dimension:
    """A physical dimension: accepted suffixes and the canonical (output) unit."""

    name: str
    units: dict[str, str]  # suffix -> pint unit expression
    labels: dict[str, str]  # suffix -> unit as printed in messages
    canonical: str  # suffix of the canonical unit, used in output column names


LENGTH = Dimension(
    "length",
    {"m": "meter", "cm": "centimeter", "mm": "millimeter", "in": "inch", "ft": "foot"},
    {"m": "m", "cm": "cm", "mm": "mm", "in": "in", "ft": "ft"},
    "m",
)
MASS = Dimension(
    "mass",
    {"kg": "kilogram", "lb": "pound"},
    {"kg": "kg", "lb": "lb"},
    "kg",
)
ACCELERATION = Dimension(
    "acceleration",
    {"g": "standard_gravity", "m_s2": "meter / second ** 2", "cm_s2": "centimeter / second ** 2"},
    {"g": "g", "m_s2": "m/s²", "cm_s2": "cm/s²"},
    "g",
)
PERIOD = Dimension(
    "time",
    {"s": "second", "ms": "millisecond"},
    {"s": "s", "ms": "ms"},
    "s",
)
VELOCITY = Dimension(
    "velocity",
    {"cm_s": "centimeter / second", "m_s": "meter / second", "in_s": "inch / second"},
    {"cm_s": "cm/s", "m_s": "m/s", "in_s": "in/s"},
    "m_s",
)


def to_canonical(value: float, dimension: Dimension, suffix: str) -> float:
    """Convert ``value`` given in ``suffix`` units to the dimension's canonical unit.

    Examples
    --------
    >>> to_canonical(90.0, LENGTH, "in")
    2.286
    >>> to_canonical(-75.0, VELOCITY, "cm_s")
    -0.75
    """
    if suffix == dimension.canonical:
        return float(value)
    return float(value) * conversion_factor(dimension.units[suffix], dimension.units[dimension.canonical])


def label(dimension: Dimension, suffix: str) -> str:
    """The unit as a person writes it, e.g. ``cm/s²`` for ``cm_s2``."""
    return dimension.labels[suffix]


def alternative_suffixes(value: float, dimension: Dimension, suffix: str,
                         low: float, high: float, signed: bool = False) -> list[str]:
    """Suffixes other than ``suffix`` under which ``value`` lands in ``[low, high]``.

    Used to suggest the likely unit mistake behind an implausible value
    (a height of 2286 "cm" is plausible in mm).
    """
    found = []
    for other in dimension.units:
        if other == suffix:
            continue
        converted = to_canonical(value, dimension, other)
        if signed:
            converted = abs(converted)
        if low <= converted <= high:
            found.append(other)
    return found


#: Length suffixes of the US customary system; a workbook whose lengths are all in them is reported in US units.
US_LENGTH_SUFFIXES = ("in", "ft")


def unit_system_of_suffixes(length_suffixes) -> str:
    """``'us'`` when every length header of a sheet is in inches or feet (and there is one), else ``'si'``.

    >>> unit_system_of_suffixes(["in", "in", "ft"]), unit_system_of_suffixes(["in", "cm"]), unit_system_of_suffixes([])
    ('us', 'si', 'si')
    """
    suffixes = list(length_suffixes)
    return "us" if suffixes and all(suffix in US_LENGTH_SUFFIXES for suffix in suffixes) else "si"
