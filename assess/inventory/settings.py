"""The workbook's ``settings`` sheet as one typed, frozen record.

Every setting is a field with its type; a field's default is the packaged default
(``assess/data/defaults.toml``, read once by :func:`assess.data.default_settings`), where each is
explained and cited. Names are the workbook's keys (``docs/workbook.md``), so that a message about a
setting names the key the user typed; a setting that carries a unit says it in its name (``room_max_cm``,
``sds_g``, ``remaining_life_yr``). The values are checked where the sheet is read
(:mod:`assess.inventory.workbook`, each problem at its cell); a :class:`Settings` holds checked values
only, and a stage reads them as attributes (``settings.risk_pf_moderate``), never by a string key.
"""
from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, fields

from assess.data import default_settings

#: The packaged defaults, read once (the fields' defaults below).
_DEFAULTS = default_settings()
#: The kinds of action a per-unit mitigation cost may be set for (``mitigation_cost_<kind>``).
MITIGATION_KINDS = ("anchor", "tether", "strap", "chain", "lock_casters", "restrain", "room", "lower_contents",
                    "relocate")


@dataclass(frozen=True)
class Settings:
    """The settings of one assessment: the packaged defaults updated with the workbook's ``settings`` sheet.

    The meaning, source and bounds of each field are in ``assess/data/defaults.toml`` and
    ``docs/workbook.md``; the groups are: the report's title (``facility`` ... ``revision``), the
    regression of Konstantinidis & Makris (2010), eqs. 11 and 21, Table 3 (``zeta``, ``eta``, ``sigma``,
    ``im_min``, ``im_max``), the risk classes (``risk_*``, ``rocking_harm_theta_over_alpha``), the
    actions (``room_max_cm`` [cm], ``lower_contents_cg_fraction``), the motions simulated, the
    anchorage (``sds_g`` [g], ``roof_floor``), the costs (``currency``, ``discount_rate`` [1/yr],
    ``remaining_life_yr`` [yr], ``mitigation_cost_<kind>`` per unit) and the report's units and floor
    labels.

    >>> Settings().zeta, Settings().room_max_cm, Settings().synthetic_realizations
    (0.37, 30.0, 10)
    >>> Settings.from_mapping({"risk_pf_moderate": "0.2"}).risk_pf_moderate
    0.2
    """

    facility: str = _DEFAULTS["facility"]
    site: str = _DEFAULTS["site"]
    prepared_by: str = _DEFAULTS["prepared_by"]
    checked_by: str = _DEFAULTS["checked_by"]
    report_date: str = _DEFAULTS["report_date"]
    revision: str = _DEFAULTS["revision"]
    zeta: float = _DEFAULTS["zeta"]
    eta: float = _DEFAULTS["eta"]
    sigma: float = _DEFAULTS["sigma"]
    im_min: float = _DEFAULTS["im_min"]
    im_max: float = _DEFAULTS["im_max"]
    risk_pf_high: float = _DEFAULTS["risk_pf_high"]
    risk_pf_moderate: float = _DEFAULTS["risk_pf_moderate"]
    risk_overturn_high: float = _DEFAULTS["risk_overturn_high"]
    risk_overturn_moderate: float = _DEFAULTS["risk_overturn_moderate"]
    risk_rocking_moderate: float = _DEFAULTS["risk_rocking_moderate"]
    rocking_harm_theta_over_alpha: float = _DEFAULTS["rocking_harm_theta_over_alpha"]
    room_max_cm: float = _DEFAULTS["room_max_cm"]
    lower_contents_cg_fraction: float = _DEFAULTS["lower_contents_cg_fraction"]
    simulate_motions: str = _DEFAULTS["simulate_motions"]
    synthetic_realizations: int = _DEFAULTS["synthetic_realizations"]
    sds_g: float = _DEFAULTS["sds_g"]
    roof_floor: float = _DEFAULTS["roof_floor"]
    currency: str = _DEFAULTS["currency"]
    discount_rate: float = _DEFAULTS["discount_rate"]
    remaining_life_yr: float = _DEFAULTS["remaining_life_yr"]
    mitigation_cost_anchor: float = _DEFAULTS["mitigation_cost_anchor"]
    mitigation_cost_tether: float = _DEFAULTS["mitigation_cost_tether"]
    mitigation_cost_strap: float = _DEFAULTS["mitigation_cost_strap"]
    mitigation_cost_chain: float = _DEFAULTS["mitigation_cost_chain"]
    mitigation_cost_lock_casters: float = _DEFAULTS["mitigation_cost_lock_casters"]
    mitigation_cost_restrain: float = _DEFAULTS["mitigation_cost_restrain"]
    mitigation_cost_room: float = _DEFAULTS["mitigation_cost_room"]
    mitigation_cost_lower_contents: float = _DEFAULTS["mitigation_cost_lower_contents"]
    mitigation_cost_relocate: float = _DEFAULTS["mitigation_cost_relocate"]
    units: str = _DEFAULTS["units"]
    floor_numbering: str = _DEFAULTS["floor_numbering"]

    def __post_init__(self):
        """Each value as its field's type (a workbook number is a float; ``synthetic_realizations`` a whole
        number, checked where the sheet is read)."""
        for item in fields(self):
            cast = _CASTS[item.type]
            value = getattr(self, item.name)
            if type(value) is not cast:
                object.__setattr__(self, item.name, cast(value))

    @classmethod
    def from_mapping(cls, values: Mapping) -> "Settings":
        """The settings ``values`` gives (key: value, the workbook's keys), the defaults for the others; a key
        that is no setting is a bug (the workbook reader reports a user's unknown key at its cell)."""
        return cls(**dict(values))

    @classmethod
    def names(cls) -> tuple[str, ...]:
        """Every setting's key, in the order of ``defaults.toml``."""
        return tuple(item.name for item in fields(cls))

    def mitigation_cost(self, kind: str) -> float:
        """What one unit of action ``kind`` costs by default (``mitigation_cost_<kind>``); 0 (not given) for a
        kind that has no such setting.

        >>> Settings(mitigation_cost_anchor=800.0).mitigation_cost("anchor"), Settings().mitigation_cost("none")
        (800.0, 0.0)
        """
        return getattr(self, f"mitigation_cost_{kind}") if kind in MITIGATION_KINDS else 0.0


#: How a field's declared type (a string under ``from __future__ import annotations``) converts a value.
_CASTS = {"str": str, "float": float, "int": int}
