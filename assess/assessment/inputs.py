"""Stage 1 of the assessment: the rules an input must meet before any record is read or any case runs.

The workbook reader (:func:`assess.inventory.read_workbook`) checks each
cell; these are the rules about what a hazard sheet asks the run to do
(docs/workbook.md, sheet hazard). :func:`assess.assessment.pipeline.run_assessment` applies
them, so a library call is held to them as the command line and ``assess batch`` are.
"""
from __future__ import annotations

import math
from pathlib import Path

from assess.errors import Problem, raise_if_any
from assess.hazard.records import check_record_location


def check_inputs(inventory, allow_records_outside: bool = False) -> None:
    """Raise :class:`~assess.errors.InputError` with every :func:`hazard_problems` of ``inventory``."""
    raise_if_any(hazard_problems(inventory, allow_records_outside))


def hazard_problems(inventory, allow_records_outside: bool) -> list[Problem]:
    """What in the hazard sheet the run must refuse before reading any record or simulating.

    * a record outside the workbook's folder (:func:`assess.hazard.records.check_record_location`),
      unless ``--allow-records-outside``;
    * ``vp`` = 0: a velocity pulse has a non-zero amplitude (a pulse of
      acceleration ap and period Tp reaches vp = ap Tp / 2 pi for Type B), so a
      0 is a placeholder, not a measurement. Read as "no vp" it would silently
      change how the motion is simulated (its pulse instead of synthetic
      near-fault histories), so it is refused and the user says which is meant.
    """
    workbook = Path(inventory.path)
    problems = []
    for row in inventory.hazard.itertuples(index=False):
        for column in ("record", "record_2"):
            record_path = str(getattr(row, f"{column}_path", "") or "")
            why = check_record_location(record_path, workbook.parent) if record_path else None
            if why and not allow_records_outside:
                problems.append(Problem(file=workbook.name, sheet="hazard", row=int(row.row), column=column,
                                        message=f"motion '{row.motion}': {why}",
                                        fix="copy the record into the workbook's folder (or a subfolder) and "
                                            "give its path relative to the workbook, or run with "
                                            "--allow-records-outside if you trust this workbook."))
        vp = float(row.vp_m_s)
        if not math.isnan(vp) and vp == 0.0:
            problems.append(Problem(file=workbook.name, sheet="hazard", row=int(row.row), column="vp_cm_s",
                                    message=f"motion '{row.motion}': the pulse velocity vp is 0; a velocity "
                                            "pulse has a non-zero amplitude.",
                                    fix="give the pulse's peak velocity (e.g. -75 cm/s for Los Gatos), or "
                                        "leave the cell empty to simulate the motion's pulse from PTA and Tp."))
    return problems
