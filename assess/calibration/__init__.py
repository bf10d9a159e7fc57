"""Calibration against measured tests (``assess calibrate``, docs/calibration.md).

:func:`run_calibration` only sequences the pure functions of
:mod:`assess.calibration.measured` (the tests and the motion each played),
:mod:`assess.calibration.effects` (the candidate changes of the model) and
:mod:`assess.calibration.fit` (errors, fitting, cross-validated selection),
and returns a :class:`CalibrationResult` whose :meth:`~CalibrationResult.as_json`
is the content of ``calibration.json``.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable, Optional

import numpy as np
import pandas as pd

from assess.hazard.processing import peak_velocity_m_s
from assess.inventory.units import CM_PER_M
from assess.mechanics.geometry import STANDARD_GRAVITY_M_S2

from assess.calibration.effects import EFFECTS, available_effects, half_width_of
from assess.calibration.fit import (MARGIN, Case, EffectFit, Measured, Predicted, fit_effect,
                                    select_effect, sliding_log_ratio, test_losses, theta_difference)
from assess.calibration.measured import read_measured, test_motion

__all__ = ["CalibrationResult", "run_calibration", "read_measured", "build_cases", "EFFECTS"]

#: Columns of the residual tables (``residuals_before``, ``residuals_after``).
RESIDUAL_COLUMNS = ["specimen", "motion", "direction", "sliding_measured_cm", "sliding_predicted_cm",
                    "sliding_log_ratio", "theta_measured", "theta_predicted", "theta_difference",
                    "overturned_measured", "overturned_predicted", "mode_predicted", "loss"]
#: Columns of the diagnosis table.
DIAGNOSIS_COLUMNS = ["specimen", "motion", "direction", "pta_g", "tp_s", "pgv_m_s", "mu", "b_over_h",
                     "pressure_kpa", "im", "omega_p_over_p", "mode"]
#: Explanatory quantities whose rank correlation with the residuals is reported.
EXPLANATORY_QUANTITIES = ("im", "omega_p_over_p", "pgv_m_s", "mu", "b_over_h", "pressure_kpa")


@dataclass
class CalibrationResult:
    """What ``assess calibrate`` reports.

    Attributes
    ----------
    error_before, error_after : dict
        Error measures (:func:`assess.calibration.fit.error_measures`) of the
        declared model and of the selected effect at its fitted parameters.
    selected : str
        Name of the selected effect (``none`` when no effect earns its parameters).
    parameters : dict
        Its fitted parameters (units in :data:`assess.calibration.effects.EFFECTS`).
    indistinguishable_from : list of str
        Effects the data cannot tell from the selected one.
    fits : list of EffectFit
        Every candidate, ``none`` first.
    residuals_before, residuals_after : pandas.DataFrame
        One row per test, columns :data:`RESIDUAL_COLUMNS` (cm for sliding).
    diagnosis : pandas.DataFrame
        One row per test, columns :data:`DIAGNOSIS_COLUMNS`: IM = PTA/(μg) − 1,
        ωp/p (NaN for a record without Tp), the declared μ and b/h, and the
        declared model's mode.
    notes : list of str
        E.g. effects left out because their solver is not installed.
    margin : float
        The selection margin used.
    """

    error_before: dict
    error_after: dict
    selected: str
    parameters: dict
    indistinguishable_from: list
    fits: list
    residuals_before: pd.DataFrame
    residuals_after: pd.DataFrame
    diagnosis: pd.DataFrame
    notes: list = field(default_factory=list)
    margin: float = MARGIN

    def as_json(self) -> dict:
        """The content of ``calibration.json`` (docs/outputs.md).

        A parameter the tests cannot fix (:func:`~assess.calibration.fit.undetermined_parameters`)
        is ``null`` in ``parameters`` and ``standard_error``, and ``not_determined`` says why.
        ``applies_to`` lists the specimens, the items ``assess --calibration``
        applies the effect to (:mod:`assess.calibration.apply`; "all" for every item).
        """
        correlations = residual_correlations(self.residuals_before, self.diagnosis)
        selected = self._fit(self.selected)
        return {"error_before": dict(self.error_before), "error_after": dict(self.error_after),
                "residual_correlation_before": {k: (None if np.isnan(v) else v) for k, v in correlations.items()},
                "selected": {"effect": self.selected, **_parameters_json(selected)},
                "indistinguishable_from": list(self.indistinguishable_from),
                "applies_to": sorted(set(str(s) for s in self.residuals_before["specimen"])),
                "candidates": [{"effect": f.effect.name, **_parameters_json(f), "error": dict(f.error),
                                "score": float(f.score)} for f in self.fits]}

    def _fit(self, name: str):
        return next(f for f in self.fits if f.effect.name == name)


def _parameters_json(fit) -> dict:
    """``parameters``, ``standard_error`` (null where not determined) and ``not_determined`` of a fit."""
    missing = fit.not_determined
    return {"parameters": {k: (None if k in missing else float(v)) for k, v in fit.parameters.items()},
            "standard_error": {k: (None if k in missing or v is None else float(v))
                               for k, v in fit.standard_error.items()},
            "not_determined": dict(missing)}


def build_cases(inventory, measured: pd.DataFrame) -> list[Case]:
    """One :class:`Case` per test: the declared item, the half-width shaken, the motion played."""
    equipment = inventory.equipment.set_index("id", drop=False)
    records = {}
    cases = []
    for test in measured.itertuples(index=False):
        if test.motion not in records:
            records[test.motion] = test_motion(inventory, test.motion)
        item = equipment.loc[test.specimen].to_dict()
        observed = test.overturned is not None and not (isinstance(test.overturned, float)
                                                        and np.isnan(test.overturned))
        rocking = bool(np.isfinite(float(test.theta_max_over_alpha)) or observed)
        cases.append(Case(str(test.specimen), str(test.motion), int(test.direction), item,
                          half_width_of(item, test.direction), records[test.motion], rocking))
    return cases


def run_calibration(inventory, measured: pd.DataFrame, *, effects=None, margin: float = MARGIN,
                    progress: Optional[Callable[[int, int], None]] = None,
                    cache: Optional[dict] = None, runner=None) -> CalibrationResult:
    """Fit every available effect to the measured tests and select one (docs/calibration.md).

    Parameters
    ----------
    inventory : assess.inventory.Inventory
    measured : pandas.DataFrame
        The tests, as :func:`read_measured` returns them.
    effects : list of str, optional
        Effect names to try (default: all of :data:`EFFECTS`); ``none`` is
        always tried. Effects whose solver is not installed are left out with
        a note.
    margin : float
        Selection margin (:func:`assess.calibration.fit.select_effect`).
    progress : callable(done, total), optional
        Called after each effect is fitted.
    cache : dict, optional
        Predictions already computed, reused between calls on the same tests
        (the key holds the item's numbers and the motion's samples).
    runner : optional
        Runs the test simulations (:mod:`assess.mechanics.gateway`; default this machine).
    """
    cache = {} if cache is None else cache
    names = list(EFFECTS) if effects is None else list(effects)
    chosen = available_effects(names)
    notes = [f"effect '{n}' not tried: its solver ({EFFECTS[n].requires}) is not installed."
             for n in names if n in EFFECTS and EFFECTS[n] not in chosen]
    cases = build_cases(inventory, measured)
    observed = Measured.from_table(measured)
    fits: list[EffectFit] = []
    for k, effect in enumerate(chosen):
        fits.append(fit_effect(effect, cases, observed, cache, runner=runner))
        if progress is not None:
            progress(k + 1, len(chosen))
    selected, similar = select_effect(fits, margin)
    by_name = {f.effect.name: f for f in fits}
    before, after = by_name["none"], by_name[selected]
    return CalibrationResult(
        error_before=before.error, error_after=after.error, selected=selected,
        parameters=dict(after.parameters), indistinguishable_from=similar, fits=fits,
        residuals_before=residual_table(measured, before.predicted, observed),
        residuals_after=residual_table(measured, after.predicted, observed),
        diagnosis=diagnosis_table(inventory, cases, before.predicted), notes=notes, margin=margin)


def residual_table(measured: pd.DataFrame, predicted: Predicted, observed: Measured) -> pd.DataFrame:
    """Per test: measured and predicted peaks, their residuals and the test's loss."""
    over = [None if not np.isfinite(v) else bool(v) for v in observed.overturned]
    table = pd.DataFrame({
        "specimen": measured["specimen"].to_numpy(), "motion": measured["motion"].to_numpy(),
        "direction": measured["direction"].to_numpy(),
        "sliding_measured_cm": observed.sliding_m * CM_PER_M, "sliding_predicted_cm": predicted.sliding_m * CM_PER_M,
        "sliding_log_ratio": np.where(np.isfinite(observed.sliding_m),
                                      sliding_log_ratio(predicted.sliding_m, observed.sliding_m), np.nan),
        "theta_measured": observed.theta_max_over_alpha, "theta_predicted": predicted.theta_max_over_alpha,
        "theta_difference": theta_difference(predicted.theta_max_over_alpha, observed.theta_max_over_alpha),
        "overturned_measured": over, "overturned_predicted": predicted.overturned,
        "mode_predicted": predicted.mode, "loss": test_losses(predicted, observed)})
    return table[RESIDUAL_COLUMNS]


def residual_correlations(residuals: pd.DataFrame, diagnosis: pd.DataFrame) -> dict:
    """Spearman rank correlation of ln(predicted/measured) sliding with each explanatory quantity.

    A residual that follows one quantity points to the effect the model lacks
    (pressure-dependent friction: pressure, μ, IM; elastic legs: ωp/p).
    NaN where fewer than 4 tests have both numbers or the quantity does not vary.
    """
    from scipy import stats

    out = {}
    for name in EXPLANATORY_QUANTITIES:
        x = pd.to_numeric(diagnosis[name], errors="coerce").to_numpy(dtype=float)
        y = pd.to_numeric(residuals["sliding_log_ratio"], errors="coerce").to_numpy(dtype=float)
        ok = np.isfinite(x) & np.isfinite(y)
        if ok.sum() < 4 or np.ptp(x[ok]) == 0 or np.ptp(y[ok]) == 0:
            out[name] = float("nan")
        else:
            out[name] = float(stats.spearmanr(x[ok], y[ok]).statistic)
    return out


def diagnosis_table(inventory, cases, declared: Predicted) -> pd.DataFrame:
    """Per test, what explains a residual: IM = PTA/(μg) − 1, ωp/p, PGV, μ, b/h, bearing
    pressure mg/(width·depth) and the declared model's mode."""
    from assess.calibration.effects import item_block

    first = inventory.hazard.drop_duplicates("motion").set_index("motion")
    pgv_m_s = {}  # per record: the cases of one motion share it (build_cases), its PGV made once
    rows = []
    for case, mode in zip(cases, declared.mode):
        if id(case.record) not in pgv_m_s:
            pgv_m_s[id(case.record)] = peak_velocity_m_s(case.record.accel_g, case.record.dt_s)
        block = item_block(case.item, case.half_width_m)
        tp = float(first.loc[case.motion, "tp_s"]) if case.motion in first.index else np.nan
        pta = case.record.pta_g
        area_m2 = float(case.item["width_m"]) * float(case.item["depth_m"])
        pressure_kpa = float(case.item["mass_kg"]) * STANDARD_GRAVITY_M_S2 / area_m2 / 1000.0 \
            if "mass_kg" in case.item and area_m2 > 0 else np.nan
        rows.append({"specimen": case.specimen, "motion": case.motion, "direction": case.direction,
                     "pta_g": pta, "tp_s": tp, "pgv_m_s": pgv_m_s[id(case.record)],
                     "mu": block.mu, "b_over_h": block.b_over_h, "pressure_kpa": pressure_kpa,
                     "im": pta / block.mu - 1.0 if block.mu > 0 else np.inf,
                     "omega_p_over_p": 2 * np.pi / tp / block.p_rad_s if np.isfinite(tp) and tp > 0 else np.nan,
                     "mode": mode})
    return pd.DataFrame(rows, columns=DIAGNOSIS_COLUMNS)
