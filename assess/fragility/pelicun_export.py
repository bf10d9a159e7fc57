"""Item fragilities in pelicun's damage-and-loss model library format (``fragility.csv`` + ``.json``).

pelicun (NHERI SimCenter) reads component fragilities from a table, one row
per component, and a metadata file that documents each component and its
damage states, as in its model library ([1]; e.g. ``seismic/building/
component/FEMA P-58 2nd Edition/fragility.csv`` and ``fragility.json``).
This module writes each item as one component:

* ``ID``: the item, made safe for pelicun (:func:`pelicun_component_id`:
  pelicun splits its random-variable tags on ``-``);
* ``Demand-Type`` ``Peak Floor Acceleration`` in ``g``, ``Demand-Offset`` 0,
  as for the FEMA P-58 unanchored contents ``E.20.22.*``; where the fragility
  was fitted on stripes of ground acceleration passed through the building,
  ``Peak Ground Acceleration`` (the library's ``PGA``, as its Hazus
  ground-intensity fragilities), with ``Demand-Offset`` −(its story) so that
  pelicun reads the PGA at location 0 (the ground) whatever story the item
  stands on: the building is inside the fragility;
* ``Demand-Directional`` 1 by default: the fragility was fitted on the floor
  acceleration along the direction simulated, so pelicun must feed it the PFA
  of the direction the user gives the component. With 0 (as the FEMA P-58
  contents) pelicun feeds 1.2 × the larger of the two directions (its
  ``NonDirectionalMultipliers`` default), which the fit never saw;
* ``LS1`` = slides past its clearance (``beyond_clearance``), ``LS2`` =
  overturns (``overturn``), each ``lognormal`` with ``Theta_0`` = θ [g] and
  ``Theta_1`` = β; one damage state per limit state (DS1, DS2), so no
  ``DamageStateWeights``.

Stories: how pelicun counts them
--------------------------------
pelicun counts a component's ``Location`` in stories from 1 (the ground
story, standing on the ground slab) to the number of stories (``roof`` is one
more), and its floor accelerations ``PFA-<loc>-<dir>`` in levels from 0 (the
ground) up. A PFA component at story ``s`` reads ``PFA-(s + Demand-Offset +
DemandOffset["PFA"])``; pelicun's default ``DemandOffset`` is ``{"PFA": -1}``,
so with ``Demand-Offset`` 0 it reads ``PFA-(s − 1)``, the slab it stands on
(``pelicun/model/demand_model.py``, ``_get_required_demand_type``;
``pelicun/settings/default_config.json``). assess numbers floors from 0 (the
ground). An item on assess floor ``f`` is therefore at pelicun ``Location``
``f + 1`` (:func:`pelicun_location`): written as ``f``, a ground-floor item
would ask for ``PFA--1`` (pelicun refuses it) and an upper-floor item would
silently read the floor below. ``cmp_marginals.csv`` (:func:`component_table`)
gives every item its ``Location`` so counted. pelicun has no level below the
ground: a basement item (floor −1, −2, …) is put at story 1, reading the
ground's PFA (``PFA-0``), and its row's ``Comment`` says so.

How pelicun reads two limit states
----------------------------------
pelicun's damage state is the *highest* limit state whose capacity the demand
exceeds, and it samples the capacities of one component's limit states fully
correlated (one standard normal for all; ``pelicun/model/damage_model.py``,
"perfectly correlated limit state random variables"). Hence
P(DS2 | a) = P(overturn | a) exactly, and P(DS ≥ 1 | a) = max(P₁, P₂): where
the overturning fragility lies above the sliding one (an item that tips
before it slides that far), DS1 is "slid past the clearance or overturned".
The metadata says so, per item.

A limit state without a finite fit (no failure simulated, outcomes separated;
:mod:`assess.fragility.msa`) is never given invented numbers: without LS2 the
component has LS1 only (overturning was not simulated, say up to which
intensity, in ``Comments``); without LS1 the row is flagged ``Incomplete`` =
1, as the library flags components whose parameters it lacks, and pelicun
leaves it out of a damage assessment (with a warning naming it).

The column set, value domains and metadata schema follow the library's own
format tests (``tests/test_data_format.py`` of [1]).

Using the files in a FEMA P-58 assessment (pelicun 3.10)
--------------------------------------------------------
``cmp_marginals.csv`` is the asset model's rows for the items (component
marginals, the ``CMP_QNT.csv`` of pelicun's examples): ``ID``, ``Units``
``ea``, ``Location`` (the story, counted as above), ``Direction`` 1 (the
building direction whose PFA runs along the item's width: change it to 2
where it runs along the building's second direction), ``Theta_0`` (the
item's quantity), ``Blocks`` (one block per item), ``Comment``. Load it, and
the exported fragilities before the library's::

    asmnt.asset.load_cmp_model({"marginals": "fragility/cmp_marginals.csv"})
    asmnt.damage.load_model_parameters(
        ["fragility/fragility.csv", "PelicunDefault/FEMA P-58/fragility.csv"], cmp_set)

Consequences (repair cost and time) are the user's: the library has none for
these components, as it has none for the P-58 unanchored contents.

References
----------
.. [1] NHERI SimCenter, Damage and Loss Model Library (DLML),
   https://github.com/NHERI-SimCenter/DamageAndLossModelLibrary (BSD-3-Clause),
   ``src/dlml/data/seismic/building/component/FEMA P-58 2nd Edition/``.
.. [2] Zsarnóczay, A., Deierlein, G. G. (2020). PELICUN - A computational
   framework for estimating damage, loss and community resilience.
   Proc. 17th World Conf. Earthquake Eng., Sendai.
"""
from __future__ import annotations

import json
import math
import re
from dataclasses import dataclass
from pathlib import Path

import pandas as pd

from assess import __version__
from assess.data import as_declared
from assess.fragility.msa import FragilityFit

DEMAND_TYPE = "Peak Floor Acceleration"
#: The library's demand types by the acceleration the fragility is in: the floor's, or the ground's where
#: the stripes were ground motions passed through the building (:mod:`assess.fragility.ground_stripes`).
DEMAND_TYPES = {"PFA": DEMAND_TYPE, "PGA": "Peak Ground Acceleration"}
DEMAND_UNIT = "g"
FAMILY = "lognormal"
#: The library's columns up to LS2, in its order (the FEMA P-58 table goes on to LS4).
COLUMNS = (
    "ID", "Incomplete", "Demand-Type", "Demand-Unit", "Demand-Offset", "Demand-Directional",
    "LS1-Family", "LS1-Theta_0", "LS1-Theta_1", "LS1-DamageStateWeights",
    "LS2-Family", "LS2-Theta_0", "LS2-Theta_1", "LS2-DamageStateWeights",
)
#: Significant digits written for θ and β (a fit's standard error is a few per cent).
SIGNIFICANT_DIGITS = 4
CSV_NAME = "fragility.csv"
JSON_NAME = "fragility.json"
#: The asset model's rows for the items (pelicun's component marginals).
COMPONENTS_NAME = "cmp_marginals.csv"
#: Columns of :data:`COMPONENTS_NAME`, as pelicun's ``load_cmp_model`` reads them (the first is the index).
COMPONENT_COLUMNS = ("ID", "Units", "Location", "Direction", "Theta_0", "Blocks", "Comment")
#: pelicun's default ``DemandOffset`` of a PFA demand (its ``settings/default_config.json``).
PELICUN_PFA_OFFSET = -1

_LIMIT_STATES = (
    ("LS1", "DS1", "beyond_clearance",
     "Slides past its clearance: the item's peak sliding exceeds the free distance around it.",
     "Move the item back into place; inspect it, its cables and hoses, and what it struck."),
    ("LS2", "DS2", "overturn",
     "Overturns.",
     "Right or replace the item and its contents; repair what it struck."),
)


@dataclass(frozen=True)
class LimitStateFragility:
    """One limit state's lognormal fragility in PFA, or the reason there is none.

    Attributes
    ----------
    median_g : float
        θ [g]; NaN when there is no finite fragility.
    beta : float
        β [-]; NaN when there is none.
    note : str
        How it was obtained (the fit's sentence), or why it is missing.
    """

    median_g: float
    beta: float
    note: str = ""

    @property
    def defined(self) -> bool:
        return math.isfinite(self.median_g) and math.isfinite(self.beta)

    @classmethod
    def from_fit(cls, fit: FragilityFit) -> "LimitStateFragility":
        """The fitted θ, β of a :class:`~assess.fragility.msa.FragilityFit` (NaN without a fit)."""
        return cls(median_g=fit.median_g, beta=fit.beta, note=fit.message)


@dataclass(frozen=True)
class ItemFragilities:
    """An item's two fragilities, as one pelicun component."""

    component_id: str
    description: str
    beyond_clearance: LimitStateFragility
    overturn: LimitStateFragility
    #: The floor it stands on, as assess numbers floors (0 = ground; :func:`pelicun_location`).
    floor: int = 0
    #: How many identical items the component stands for.
    quantity: int = 1
    #: A sentence for the metadata's ``Comments`` (e.g. how the level's answer compares), or "".
    comment: str = ""


def pelicun_location(floor: int) -> int:
    """pelicun's ``Location`` (story, 1 = the ground story) of an item on assess ``floor`` (0 = ground).

    With ``Demand-Offset`` 0 and pelicun's default ``DemandOffset`` ``{"PFA": -1}``, the component then
    reads ``PFA-floor``, the floor it stands on (module docstring). Below ground, story 1 (``PFA-0``).

    >>> [pelicun_location(f) for f in (0, 1, 6, -1)]
    [1, 2, 7, 1]
    """
    return int(floor) + 1 if int(floor) >= 0 else 1


def pelicun_pfa_level(location: int) -> int:
    """The level of the PFA that pelicun feeds a component at ``location`` with ``Demand-Offset`` 0.

    >>> pelicun_pfa_level(pelicun_location(3))
    3
    """
    return int(location) + PELICUN_PFA_OFFSET


def pelicun_component_id(name) -> str:
    """A component ID pelicun accepts: letters, digits, ``.`` and ``_`` only.

    pelicun builds tags such as ``FRG-<ID>-<loc>-<dir>-...`` and splits them on
    ``-``, so other characters become ``_``.

    >>> pelicun_component_id("Freezer F-12 (room 2.14)")
    'Freezer_F_12_room_2.14'
    """
    text = re.sub(r"[^A-Za-z0-9._]+", "_", str(name).strip()).strip("_")
    if not text:
        raise ValueError(f"item name {name!r} gives an empty pelicun component ID")
    return text


def fragility_table(items, directional=True, demand="PFA") -> pd.DataFrame:
    """The rows of ``fragility.csv``: one component per item, columns :data:`COLUMNS`.

    >>> item = ItemFragilities("cabinet_1", "Cabinet", LimitStateFragility(0.35, 0.4),
    ...                        LimitStateFragility(0.8, 0.5))
    >>> print(fragility_table([item]).to_csv(index=False, lineterminator="\\n"), end="")
    ID,Incomplete,Demand-Type,Demand-Unit,Demand-Offset,Demand-Directional,LS1-Family,LS1-Theta_0,LS1-Theta_1,LS1-DamageStateWeights,LS2-Family,LS2-Theta_0,LS2-Theta_1,LS2-DamageStateWeights
    cabinet_1,0,Peak Floor Acceleration,g,0,1,lognormal,0.35,0.4,,lognormal,0.8,0.5,
    """
    items = list(items)
    _check_ids(items)
    rows = []
    for item in items:
        # PGA: offset back to location 0, the ground, from the item's story
        offset = -pelicun_location(item.floor) if demand == "PGA" else 0
        row = {"ID": item.component_id, "Incomplete": 0, "Demand-Type": DEMAND_TYPES[demand],
               "Demand-Unit": DEMAND_UNIT, "Demand-Offset": offset,
               "Demand-Directional": 1 if directional else 0}
        for (ls, _ds, _mode, _text, _repair), state in zip(
                _LIMIT_STATES, (item.beyond_clearance, item.overturn)):
            present = state.defined or ls == "LS1"  # LS1 stays, flagged incomplete, if missing
            row[f"{ls}-Family"] = FAMILY if present else None
            row[f"{ls}-Theta_0"] = _rounded(state.median_g) if state.defined else None
            row[f"{ls}-Theta_1"] = _rounded(state.beta) if state.defined else None
            row[f"{ls}-DamageStateWeights"] = None
        if not item.beyond_clearance.defined:
            row["Incomplete"] = 1
        rows.append(row)
    return pd.DataFrame(rows, columns=list(COLUMNS))


def component_table(items) -> pd.DataFrame:
    """The rows of ``cmp_marginals.csv``: each item at the story pelicun counts (:func:`pelicun_location`).

    >>> item = ItemFragilities("cabinet_1", "Cabinet", LimitStateFragility(0.35, 0.4),
    ...                        LimitStateFragility(0.8, 0.5), floor=2, quantity=3)
    >>> print(component_table([item]).to_csv(index=False, lineterminator="\\n"), end="")
    ID,Units,Location,Direction,Theta_0,Blocks,Comment
    cabinet_1,ea,3,1,3,3,assess floor 2: pelicun story 3 (reads PFA-2)
    """
    items = list(items)
    _check_ids(items)
    rows = []
    for item in items:
        location = pelicun_location(item.floor)
        comment = f"assess floor {item.floor}: pelicun story {location} (reads PFA-{pelicun_pfa_level(location)})"
        if item.floor < 0:
            comment = (f"assess floor {item.floor}, below ground: pelicun counts no story below the ground; story "
                       f"{location} reads PFA-{pelicun_pfa_level(location)}, the ground's")
        rows.append({"ID": item.component_id, "Units": "ea", "Location": location, "Direction": 1,
                     "Theta_0": int(item.quantity), "Blocks": int(item.quantity), "Comment": comment})
    return pd.DataFrame(rows, columns=list(COMPONENT_COLUMNS))


def fragility_metadata(items, directional=True, demand="PFA") -> dict:
    """The content of ``fragility.json``: ``_GeneralInformation`` and one entry per component."""
    items = list(items)
    _check_ids(items)
    meta = {"_GeneralInformation": {
        "ShortName": "assess freestanding items",
        "Description": (
            "Fragilities of freestanding (unanchored) items, fitted by assess "
            f"{__version__} by maximum likelihood on rigid-body simulations over stripes of "
            + ("peak floor acceleration" if demand == "PFA" else
               "peak ground acceleration, each ground motion passed through the building to the item's floor")
            + " (multiple-stripe analysis, Baker 2015, Earthquake "
            "Spectra 31(1):579-599). LS1: the item slides past its clearance; LS2: it "
            "overturns. pelicun takes the highest limit state exceeded, with the two "
            "capacities fully correlated: DS2 is overturning; DS1 is sliding past the "
            "clearance without overturning (or overturning, where that is the likelier)."),
        "Version": __version__,
        "ComponentGroups": {"Freestanding items": [
            f"{item.component_id} - {item.description}" for item in items]},
    }}
    for item in items:
        states = {}
        for (ls, ds, _mode, text, repair), state in zip(
                _LIMIT_STATES, (item.beyond_clearance, item.overturn)):
            if state.defined or ls == "LS1":
                states[ls] = {ds: {"Description": text, "RepairAction": repair}}
        meta[item.component_id] = {
            "Description": item.description,
            "Comments": _comments(item, directional, demand),
            "SuggestedComponentBlockSize": "1 EA",
            "RoundUpToIntegerQuantity": "True",
            "LimitStates": states,
        }
    return meta


def pelicun_fragility_files(items, directional=True, demand="PFA") -> dict[str, bytes]:
    """``fragility.csv``, ``fragility.json`` and ``cmp_marginals.csv`` as bytes, by name (nothing written);
    ``demand``: ``PFA`` or ``PGA``, the acceleration the fragilities are in (:data:`DEMAND_TYPES`)."""
    items = list(items)
    csv_text = as_declared(f"fragility/{CSV_NAME}", fragility_table(items, directional, demand)).to_csv(
        index=False, lineterminator="\n")
    json_text = json.dumps(fragility_metadata(items, directional, demand), indent=2, ensure_ascii=False) + "\n"
    components = as_declared(f"fragility/{COMPONENTS_NAME}", component_table(items)).to_csv(
        index=False, lineterminator="\n")
    return {CSV_NAME: csv_text.encode("utf-8"), JSON_NAME: json_text.encode("utf-8"),
            COMPONENTS_NAME: components.encode("utf-8")}


def write_pelicun_fragility(folder, items, directional=True, demand="PFA") -> tuple[Path, Path]:
    """Write ``fragility.csv``, ``fragility.json`` and ``cmp_marginals.csv`` into ``folder``; return the paths
    of the first two (the third is ``folder / COMPONENTS_NAME``).

    All are built in memory first, so a failure leaves no half-written set.
    """
    files = pelicun_fragility_files(items, directional, demand)
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    for name, content in files.items():
        (folder / name).write_bytes(content)
    return folder / CSV_NAME, folder / JSON_NAME


# --------------------------------------------------------------------------- helpers


def _rounded(value) -> float:
    return float(f"{value:.{SIGNIFICANT_DIGITS}g}")


def _check_ids(items) -> None:
    seen = set()
    for item in items:
        if item.component_id != pelicun_component_id(item.component_id):
            raise ValueError(f"component ID {item.component_id!r}: use letters, digits, '.' "
                             "and '_' only (pelicun_component_id makes one)")
        if item.component_id in seen:
            raise ValueError(f"component ID {item.component_id!r} is given twice")
        seen.add(item.component_id)


def _comments(item: ItemFragilities, directional: bool, demand: str = "PFA") -> str:
    lines = []
    for (ls, _ds, mode, _text, _repair), state in zip(
            _LIMIT_STATES, (item.beyond_clearance, item.overturn)):
        if state.defined:
            lines.append(f"{ls} ({mode}): median {_rounded(state.median_g):g} g, beta "
                         f"{_rounded(state.beta):g}. {state.note}".strip())
        elif ls == "LS1":
            lines.append(f"{ls} ({mode}): no fragility, hence Incomplete. {state.note[:1].upper()}{state.note[1:]}"
                         .strip())
        else:
            lines.append(f"{ls} ({mode}) not defined: {state.note}".strip())
    a, b = item.beyond_clearance, item.overturn
    if a.defined and b.defined and not (b.beta == a.beta and b.median_g >= a.median_g):
        lines.append("The two fragilities cross or overturning comes first: in pelicun "
                     "P(DS>=1) = max(P(LS1), P(LS2)).")
    direction = ("along the component's direction (Demand-Directional 1)." if directional
                 else "non-directional (pelicun: 1.2 x the larger direction).")
    location = pelicun_location(item.floor)
    if demand == "PGA":
        lines.append("Fragility in PGA (ground), through the building: the ground motions were scaled to "
                     "each stripe of peak ground acceleration and passed through the building to the floor "
                     f"the item stands on (assess floor {item.floor}, pelicun story {location}). Demand: peak "
                     f"ground acceleration (PGA, location 0: Demand-Offset -{location} from story {location}), "
                     + direction)
    else:
        lines.append(f"Demand: peak floor acceleration of the floor the item stands on (assess floor {item.floor}, "
                     f"pelicun story {location}: PFA-{pelicun_pfa_level(location)} with Demand-Offset 0 and "
                     "pelicun's default DemandOffset PFA -1), " + direction)
    if item.comment:
        lines.append(item.comment)
    return "\n".join(lines)
