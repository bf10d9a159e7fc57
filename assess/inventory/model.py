"""The validated inventory, in SI units with canonical column names."""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import pandas as pd

from assess.inventory.settings import Settings
from assess.inventory.site_building import BuildingSheet, SiteSheet


@dataclass(frozen=True)
class Inventory:
    """A validated workbook.

    Attributes
    ----------
    path : Path
        The workbook file.
    equipment : pandas.DataFrame
        One row per item, columns (SI, see ``docs/nomenclature.md``):
        ``id`` (str), ``name`` (str), ``room`` (str, "" when not given),
        ``floor`` (int), ``height_m``, ``width_m``, ``depth_m``,
        ``mass_kg``, ``mu``, ``mu_static`` (= ``mu`` when not given),
        ``clearance_m``, ``cg_height_m`` (= ``height_m / 2`` when not given),
        ``anchored`` (bool), ``casters`` (bool, False when not given), ``quantity`` (int, 1 when not given),
        ``consequence`` (str, one of
        :data:`~assess.inventory.schema.CONSEQUENCES`, ``ordinary`` when not given), ``contents`` (str:
        ``movable``, ``fixed`` or ``none``; when not given ``movable`` for shelving and cabinets, ``none``
        otherwise: :func:`assess.inventory.kinds.default_contents`), ``component_type`` (the workbook's, else
        the type its name selects, else ""), ``equipment_kind``, ``type_source`` (``typed``, ``name``,
        ``default``), ``connections`` (``"gas, fluid"``, ``"none"``...) and ``connections_assumed``
        (:func:`assess.inventory.kinds.item_type`),
        ``mu_low``, ``mu_high`` (the range μ may take, NaN when not given; both or neither,
        ``mu_low <= mu <= mu_high``), ``value`` and ``mitigation_cost`` (per unit, in the settings'
        ``currency``, NaN when not given; :mod:`assess.decision.costs`), ``base`` and ``floor_finish`` (str, "" when
        not given), ``mu_source`` (str: ``workbook``, or why ``mu``, ``mu_low`` and ``mu_high`` are a default:
        :func:`assess.inventory.friction.default_range`; "" for an anchored item without ``mu``, whose ``mu``
        is NaN), ``row`` (int, the Excel row the item came from).
    hazard : pandas.DataFrame
        One row per motion and floor: ``level`` (canonical name, e.g.
        ``2in50``, or a label such as ``DE`` as first written: every spelling
        of one level has one name, see :mod:`assess.hazard.levels`),
        ``level_label`` (as written), ``motion`` (str),
        ``all_floors`` (bool), ``floor`` (pandas ``Int64``, <NA> when
        ``all_floors``), ``pta_g`` [g], ``tp_s`` [s], ``vp_m_s`` [m/s]
        (NaN where not given), ``pulse`` ("A", "B", "C" or ""),
        ``record_path`` (absolute path as str, "" when none), ``scale`` (float,
        1.0 when not given; applies to both components), ``record_2_path`` (the second horizontal
        component, along the items' depth, absolute path, "" when none), ``azimuth_deg`` (the angle
        from the items' width axis to ``record``'s axis, towards their depth axis; 0 when not given,
        see :mod:`assess.hazard.record_pairs`), ``row`` (int).
    settings : Settings
        The packaged defaults (``assess/data/defaults.toml``) updated with the user's ``settings`` sheet,
        each value checked and of its field's type (:class:`assess.inventory.settings.Settings`).
    site : SiteSheet or None
        The ``site`` sheet (:mod:`assess.inventory.site_building`), None when the workbook has none.
    building : BuildingSheet or None
        The ``building`` sheet, None when the workbook has none.
    warnings : tuple of Implausible
        Items whose size or density no equipment has (:mod:`assess.inventory.plausibility`), each with
        its cell; the items are assessed as written.
    """

    path: Path
    equipment: pd.DataFrame
    hazard: pd.DataFrame
    settings: Settings = field(default_factory=Settings)
    site: SiteSheet | None = None
    building: BuildingSheet | None = None
    warnings: tuple = ()

    @property
    def levels(self) -> list[str]:
        """The hazard levels the workbook defines, in order of appearance."""
        return list(dict.fromkeys(self.hazard["level"]))
