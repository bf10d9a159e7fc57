"""The calibrated model in the assessment: ``assess WORKBOOK --hazard LEVEL --calibration calibration.json``.

``assess calibrate`` selects an effect and its parameters
(``calibration.json``, docs/outputs.md). Here that effect is switched on for the
items assessed, by the same function the calibration fitted it with
(:func:`assess.calibration.effects.calibrated_block`), so that on the
shake-table workbook of a calibration the assessment simulates each specimen
under each tested motion exactly as ``assess calibrate`` predicted it.

**Which items.** ``calibration.json`` names them in ``applies_to``: the ids
of the specimens it was fitted on (what ``assess calibrate`` writes), or
``"all"``. The tests measured those items; an effect such as feet inset by a
fraction of the width or a restitution is a property of an item, not of a
building, so it is not carried to other items unless the user says so by
writing ``"applies_to": "all"``. A calibration naming no item of the
workbook is refused (exit 2) with that fix. ``input_scale`` is the exception:
it says the floor shook s times what the workbook says, a property of the
motions, so it multiplies the level's motions (PTA, vp, records) and with
them every item's demand.

**With and without.** The assessment runs twice, as declared and with the
effect (:func:`with_declared`); each affected item carries a ``calibrated``
flag that states its risk, mode, simulated sliding and overturning share
both ways, and the report's notes say what was applied to which items.

**What the effect changes.** The block of each affected item × motion ×
direction (its μ and μ_s for ``friction_scale`` and ``static_friction``,
which the sliding regression's IM = PTA/(μg) − 1 then uses too, as the
paper's loop did with its best-fit μ; the restitution; the feet; the sliding
interface). θmax/α is read against α of the declared box throughout, as in
the calibration.
"""
from __future__ import annotations

import json
import math
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Optional

import numpy as np
import pandas as pd

from assess.calibration.effects import EFFECTS, calibrated_block, theta_over_declared_alpha
from assess.decision.flags import Flag, result_state
from assess.errors import InputError, Problem
from assess.inventory.schema import clip
from assess.mechanics.block import Block
from assess.quantity_text import system_of

#: Largest calibration.json read [bytes] (a real one is a few kB).
MAX_FILE_BYTES = 5_000_000
#: Flag code of an item the calibration changed.
FLAG_CODE = "calibrated"


@dataclass(frozen=True)
class AppliedCalibration:
    """The effect of a ``calibration.json`` as the assessment applies it.

    Attributes
    ----------
    effect : str
        An effect name of :data:`assess.calibration.effects.EFFECTS`.
    parameters : dict
        Its parameters; a parameter the tests did not determine (null in the
        file) takes its neutral value, the declared model's (``neutral_used``).
    applies_to : tuple of str or None
        Ids of the items it changes; None for every item.
    file : str
        The file's name, for messages and the report.
    neutral_used : tuple of str
        Parameters that were null in the file.
    """

    effect: str
    parameters: dict
    applies_to: Optional[tuple]
    file: str
    neutral_used: tuple = ()

    def applies(self, item_id) -> bool:
        """Whether the item's blocks change (``input_scale`` changes the motions instead)."""
        return self.applies_to is None or str(item_id) in self.applies_to

    @property
    def motion_scale(self) -> float:
        """Factor on the level's motions (1 unless the effect is ``input_scale``)."""
        return float(self.parameters["s"]) if self.effect == "input_scale" else 1.0

    def describe(self) -> str:
        """'friction_scale (factor k on μ and μ_s = 0.8)' from the effect's own labels."""
        parts = []
        for p in EFFECTS[self.effect].parameters:
            value = self.parameters[p.name]
            unit = "" if p.unit == "-" else f" {p.unit}"
            text = "Housner's value" if value is None else f"{value:.3g}{unit}"
            note = " (not determined by the tests: the declared model's)" if p.name in self.neutral_used else ""
            parts.append(f"{p.label or p.name} = {text}{note}")
        return f"{self.effect} ({'; '.join(parts)})" if parts else self.effect


def case_block(block: Block, item_id, calibration: Optional[AppliedCalibration]) -> Block:
    """The block of one case of item ``item_id`` with the calibration's effect where it applies.

    >>> calibration = AppliedCalibration("friction_scale", {"k": 0.5}, ("A",), "calibration.json")
    >>> block = Block(half_width_m=0.3, cg_height_m=1.0, height_m=2.0, mu=0.2)
    >>> case_block(block, "A", calibration).mu, case_block(block, "B", calibration).mu
    (0.1, 0.2)
    """
    if calibration is None or not calibration.applies(item_id):
        return block
    return calibrated_block(block, calibration.effect, calibration.parameters)


def theta_over_declared(theta_max_over_alpha, blocks) -> np.ndarray:
    """Each run's θmax/α over α of its declared box (the feet's α is the solver's) [-]."""
    return np.array([theta_over_declared_alpha(t, b) if b.foot_inset_m else float(t)
                     for t, b in zip(np.asarray(theta_max_over_alpha, dtype=float), blocks)])


def scaled_motions(level_motions: pd.DataFrame, calibration: Optional[AppliedCalibration],
                   through_building: bool = False):
    """The level's motions × s for ``input_scale`` (PTA, vp and records' scale), and a note; else unchanged.
    ``through_building``: a building sheet gives floors their motions, which the building takes from the ground
    motions at the level's own amplitude and are then multiplied by s
    (:class:`assess.assessment.motions.LevelMotions`), as the note says."""
    if calibration is None or calibration.motion_scale == 1.0:
        return level_motions, None
    s = calibration.motion_scale
    scaled = level_motions.assign(pta_g=level_motions["pta_g"] * s, vp_m_s=level_motions["vp_m_s"] * s,
                                  scale=level_motions["scale"].astype(float) * s)
    building = (f" (the building takes the ground motions as the workbook gives them and its floors' motions are "
                f"multiplied by {s:.3g}: a yielding building's floors do not scale with its ground)"
                if through_building else "")
    note = (f"Calibration {calibration.file}: the floor shook {s:.3g} times what the workbook says "
            f"(input_scale), so every motion of the level is multiplied by {s:.3g}, for every item on it{building}.")
    return scaled, note


def check_applies(calibration: AppliedCalibration, equipment: pd.DataFrame) -> None:
    """Refuse a calibration that names no item of the workbook (it would change nothing)."""
    if calibration.applies_to is None or calibration.effect in ("none", "input_scale"):
        return
    ids = set(str(i) for i in equipment["id"])
    if not ids & set(calibration.applies_to):
        named = ", ".join(sorted(calibration.applies_to)[:10])
        raise InputError([Problem(calibration.file, f"the calibration applies to the items {named}, none of "
                                  f"which is in this workbook, so it would change nothing.",
                                  'write "applies_to": "all" in the file to apply it to every item, or list '
                                  "the ids of the items it should change.")])


def with_declared(calibrated, declared, calibration: AppliedCalibration):
    """The calibrated assessment, with each affected item's result as declared beside it.

    Each item whose risk, mode, simulated sliding or overturning share the
    calibration changed gets a :data:`FLAG_CODE` flag stating both; the notes
    say what was applied to which items and that the assessment ran twice.
    """
    if calibration.effect == "none":
        note = (f"Calibration {calibration.file}: the tests selected no effect (none), so the model is "
                f"assessed as declared.")
        return replace(declared, hazard_notes=list(declared.hazard_notes) + [note])
    before = declared.summary.set_index("id")
    after = calibrated.summary.set_index("id")
    system = system_of(calibrated.settings)
    flags = list(calibrated.flags)
    codes = list(calibrated.summary["flags"])
    changed = []
    for k, item_id in enumerate(calibrated.summary["id"]):
        if item_id not in before.index or after.loc[item_id, "risk"] == "anchored":
            continue
        affected = calibration.applies(item_id) or calibration.motion_scale != 1.0
        if not affected:
            continue
        changed.append(str(item_id))
        flags.append(Flag(str(item_id), FLAG_CODE, (
            f"with the calibration ({calibration.describe()}, from {calibration.file}): "
            f"{result_state(after.loc[item_id], system)}; as declared: {result_state(before.loc[item_id], system)}.")))
        codes[k] = tuple(codes[k]) + (FLAG_CODE,)
    summary = calibrated.summary.assign(flags=codes)
    scope = ("every item" if calibration.applies_to is None or calibration.motion_scale != 1.0
             else f"{len(changed)} item(s) it was fitted on: {', '.join(changed)}" if changed
             else "no freestanding item of this workbook")
    note = (f"Calibration {calibration.file} applied: {calibration.describe()}, to {scope}. The assessment "
            f"was run twice, as declared and with it; each affected item's result both ways is under Flags "
            f"({FLAG_CODE}).")
    return replace(calibrated, summary=summary, flags=flags, hazard_notes=list(calibrated.hazard_notes) + [note])


def read_calibration(path) -> AppliedCalibration:
    """The selected effect of a ``calibration.json`` written by ``assess calibrate``.

    Raises
    ------
    InputError
        When the file is missing, too large, not JSON, or its ``selected``
        effect, parameters or ``applies_to`` are not what ``assess
        calibrate`` writes; the message names the key and how to fix it.
    """
    path = Path(path)
    name = path.name

    def refuse(message, fix="give the calibration.json that assess calibrate wrote."):
        return InputError([Problem(name, message, fix)])

    try:
        size = path.stat().st_size
        if not path.is_file():
            raise refuse(f"{name} is not a file.")
        if size > MAX_FILE_BYTES:
            raise refuse(f"{name} is {size} bytes, far more than a calibration (a few kB).")
        text = path.read_text(encoding="utf-8-sig")  # a byte order mark (Windows editors) is not content
    except FileNotFoundError:
        raise refuse(f"the calibration file {name} does not exist.") from None
    except (OSError, UnicodeDecodeError) as error:
        raise refuse(f"{name} cannot be read ({type(error).__name__}).") from None
    try:
        content = json.loads(text)
    except (ValueError, RecursionError):
        raise refuse(f"{name} is not JSON.") from None
    selected = content.get("selected") if isinstance(content, dict) else None
    if not isinstance(selected, dict) or not isinstance(selected.get("effect"), str):
        raise refuse(f'{name} has no "selected": {{"effect": ..., "parameters": ...}}.')
    effect_name = selected["effect"]
    if effect_name not in EFFECTS:
        raise refuse(f"{name}: the selected effect '{clip(effect_name, 60)}' is not one of {', '.join(EFFECTS)}.")
    effect = EFFECTS[effect_name]
    given = selected.get("parameters", {})
    if not isinstance(given, dict):
        raise refuse(f'{name}: "selected" "parameters" is not an object.')
    parameters, neutral_used = {}, []
    for p in effect.parameters:
        value = given.get(p.name, "missing")
        if value is None:  # the tests did not determine it: the declared model's value
            parameters[p.name] = p.neutral
            neutral_used.append(p.name)
            continue
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) \
                or not p.lower <= value <= p.upper:
            raise refuse(f"{name}: parameter {p.name} of {effect_name} is {clip(value, 40)}, not a number "
                         f"from {p.lower:g} to {p.upper:g}.",
                         "give the value assess calibrate wrote, or re-run assess calibrate.")
        parameters[p.name] = float(value)
    applies = content.get("applies_to", "all")
    if applies == "all":
        applies_to = None
    elif isinstance(applies, list) and applies and all(isinstance(i, (str, int)) and str(i).isprintable()
                                                       for i in applies):
        applies_to = tuple(str(i) for i in applies)
    else:
        raise refuse(f'{name}: "applies_to" must be "all" or a list of equipment ids.',
                     'write "applies_to": "all", or ["ID1", "ID2", ...].')
    return AppliedCalibration(effect_name, parameters, applies_to, name, tuple(neutral_used))
