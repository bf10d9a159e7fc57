"""Anchorage design forces, ASCE 7-16 and ASCE 7-22 §13.3.1 (assess.anchorage).

Verification tables in tests/data/anchorage/ (see its README.md): five items worked by hand under both
editions, and two published ASCE 7-16 calculations. Expected values are never our own output.
"""
import csv
import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from assess.anchorage import (
    DEFAULT_COMPONENT_TYPE, component_coefficients, component_importance_factor, component_types, design_force,
    in_us_units,
)
from assess.anchorage.equations import (
    ductility_reduction, force_asce7_16, force_asce7_22, force_bounds, height_factor,
)

DATA = Path(__file__).resolve().parents[1] / "data" / "anchorage"


def _rows(name):
    with open(DATA / name, newline="") as handle:
        return list(csv.DictReader(line for line in handle if not line.startswith("#")))


def _num(text):
    return None if text == "" else float(text)


HAND = _rows("hand_checked.csv")
PUBLISHED = _rows("published_7_16.csv")


@pytest.mark.parametrize("row", HAND, ids=[f"{r['item']}-{r['in_edition']}" for r in HAND])
def test_hand_checked_items(row):
    forces = design_force(
        row["in_edition"], row["in_component_type"], float(row["in_weight_n"]), float(row["in_sds_g"]),
        float(row["in_z_over_h"]), ip=_num(row["in_ip"]), period_s=_num(row["in_period_s"]),
        building_r=_num(row["in_building_r"]), building_omega0=_num(row["in_building_omega0"]),
        building_ie=float(row["in_building_ie"]), consequence=row["in_consequence"],
        risk_category=row["in_risk_category"], cg_height_m=float(row["in_cg_height_m"]),
        half_width_m=float(row["in_half_width_m"]))
    tol = float(row["tolerance_n"])
    where = f"{row['item']} under {row['in_edition']}: {row['hand']}"
    assert forces.importance == float(row["expected_importance"]), where
    if row["in_edition"] == "ASCE 7-22":
        assert forces.height_factor == pytest.approx(float(row["expected_height_factor"]), abs=5e-5), where
        assert forces.ductility_reduction == pytest.approx(float(row["expected_ductility_reduction"]), abs=5e-5), where
    else:
        assert math.isnan(forces.height_factor) and math.isnan(forces.ductility_reduction), where
    for field in ("force_equation_n", "force_n", "tension_n", "anchor_shear_n", "anchor_tension_n"):
        assert getattr(forces, field) == pytest.approx(float(row[f"expected_{field}"]), abs=tol), f"{field}: {where}"
    assert forces.governs == row["expected_governs"], where
    assert forces.shear_n == forces.force_n and forces.overstrength_applied


@pytest.mark.parametrize("row", PUBLISHED, ids=[r["source"][:30] for r in PUBLISHED])
def test_published_asce7_16_calculations(row):
    weight, sds, importance = float(row["in_weight"]), float(row["in_sds_g"]), float(row["in_importance"])
    equation = float(force_asce7_16(weight, sds, float(row["in_z_over_h"]), importance,
                                    float(row["in_amplification"]), float(row["in_response_modification"])))
    minimum, maximum = (float(x) for x in force_bounds(weight, sds, importance))
    tol = float(row["tolerance"])
    assert equation == pytest.approx(float(row["expected_force_equation"]), abs=tol), row["source"]
    assert maximum == pytest.approx(float(row["expected_force_maximum"]), abs=tol), row["source"]
    assert minimum == pytest.approx(float(row["expected_force_minimum"]), abs=tol), row["source"]


@pytest.mark.parametrize("consequence", ["ordinary", "valuable", "critical", "hazardous", "life-safety"])
@pytest.mark.parametrize("z_over_h", [0.0, 0.2, 0.5, 0.9, 1.0, 1.3])
@pytest.mark.parametrize("sds_g", [0.3, 1.0, 1.7])
def test_asce7_16_laboratory_equipment_written_out(consequence, z_over_h, sds_g):
    """7-16, no component type (laboratory equipment, a_p 1.0, R_p 2.5), I_p from consequence alone (no Risk
    Category): eq. 13.3-1 within 13.3-2/3 and the tension, written out here."""
    weight_n, cg_height_m, half_width_m = 2943.0, 0.9, 0.3
    ip = 1.5 if consequence in ("hazardous", "life-safety") else 1.0
    z = min(max(z_over_h, 0.0), 1.0)
    force = min(max(0.4 * 1.0 * sds_g * weight_n / (2.5 / ip) * (1 + 2 * z), 0.3 * sds_g * ip * weight_n),
                1.6 * sds_g * ip * weight_n)
    tension = max(0.0, (force * cg_height_m - (0.9 - 0.2 * sds_g) * weight_n * half_width_m) / (2 * half_width_m))
    forces = design_force("ASCE 7-16", None, weight_n, sds_g, z_over_h, consequence=consequence,
                          cg_height_m=cg_height_m, half_width_m=half_width_m)
    assert forces.force_n == pytest.approx(force, rel=1e-12)
    assert forces.tension_n == pytest.approx(tension, rel=1e-12, abs=1e-9)
    assert forces.component_type == DEFAULT_COMPONENT_TYPE


def test_importance_factor_rules_and_override():
    assert component_importance_factor("life-safety", "II") == 1.5
    assert component_importance_factor("hazardous", None) == 1.5
    assert component_importance_factor("critical", "IV") == 1.5
    assert component_importance_factor(" Critical ", "iv") == 1.5
    assert component_importance_factor("critical", "III") == 1.0
    assert component_importance_factor("ordinary", "IV") == 1.0
    assert component_importance_factor("hazardous", "IV", ip=1.0) == 1.0
    assert component_importance_factor("ordinary", "I", ip=float("nan")) == 1.0
    assert component_importance_factor("hazardous", "I", ip=" ") == 1.5
    assert component_importance_factor("ordinary", "I", ip="1.5") == 1.5
    with pytest.raises(ValueError, match="1.0 or 1.5"):
        component_importance_factor("ordinary", "II", ip=1.25)


def test_component_names_aliases_and_refusal():
    for edition in ("ASCE 7-16", "ASCE 7-22"):
        for name in component_types():
            assert component_coefficients(edition, name.upper()).component_type == name
        assert component_coefficients(edition, None).component_type == DEFAULT_COMPONENT_TYPE
        assert component_coefficients(edition, "  ").component_type == DEFAULT_COMPONENT_TYPE
        assert component_coefficients(edition, float("nan")).component_type == DEFAULT_COMPONENT_TYPE
        assert component_coefficients(edition, "Server_Rack").component_type == "computer rack"
        assert component_coefficients(edition, "ultra-low freezer").component_type == "refrigeration"
    with pytest.raises(ValueError, match="unknown component_type"):
        component_coefficients("ASCE 7-22", "toaster")
    with pytest.raises(ValueError, match="unknown code edition"):
        component_coefficients("ASCE 7-10", None)


def test_table_rows_are_complete_and_say_whether_confirmed():
    for edition in ("ASCE 7-16", "ASCE 7-22"):
        for name in component_types():
            row = component_coefficients(edition, name)
            assert row.confirmed in ("yes", "partly", "no") and row.source and row.overstrength >= 1.0
            if edition == "ASCE 7-16":
                assert row.amplification in (1.0, 2.5) and 1.0 <= row.response_modification <= 12.0
            else:
                assert 1.0 <= row.resonance_at_or_below_grade <= row.resonance_above_grade <= 2.8
                assert 1.0 <= row.strength <= 6.0
    # ASCE 7-10 Table 13.6-1 (public copy; unchanged in 7-16), read for this table:
    assert (component_coefficients("7-16", "switchgear").amplification,
            component_coefficients("7-16", "switchgear").response_modification) == (2.5, 6.0)
    assert component_coefficients("7-16", "computer rack").response_modification == 2.5
    assert component_coefficients("7-16", "mechanical equipment").response_modification == 1.5


def test_height_factor_branches():
    assert float(height_factor(0.0, 0.5)) == 1.0
    # short period: a1 capped at 2.5, a2 floored at 0 (T_a = 0.2 s: 1/0.2 = 5 > 2.5; 1 - 4 < 0)
    assert float(height_factor(1.0, 0.2)) == pytest.approx(3.5)
    # long period: a1 = 1/2 = 0.5, a2 = 1 - 0.04 = 0.96: 1 + 0.5 + 0.96
    assert float(height_factor(1.0, 2.0)) == pytest.approx(2.46)
    assert float(height_factor(1.0)) == 3.5 and float(height_factor(1.4)) == 3.5
    np.testing.assert_allclose(height_factor(np.array([0.0, 0.5, 1.0])), [1.0, 2.25, 3.5])


def test_ductility_reduction_floor():
    assert ductility_reduction(None) == 1.3
    assert ductility_reduction(3.0, 1.0, 3.0) == 1.3  # sqrt(1.1) = 1.049 < 1.3
    assert ductility_reduction(8.0, 1.0, 3.0) == pytest.approx(math.sqrt(1.1 * 8 / 3))


def test_asce7_22_bounds_govern_both_ways():
    # maximum: a heavy resonance / low strength at the roof, 0.4*3.5/1.3*2.8/1.0 = 3.02 > 1.6
    assert float(force_asce7_22(1000.0, 1.0, 1.0, 3.5, 1.3, 2.8, 1.0)) > 1600.0
    forces = design_force("ASCE 7-22", "computer rack", 1000.0, 1.0, 1.0, ip=1.0, period_s=0.5)
    assert forces.governs in ("equation", "maximum") and forces.force_n <= forces.force_maximum_n


def test_ductile_anchorage_drops_overstrength():
    kwargs = dict(cg_height_m=1.0, half_width_m=0.4)
    with_omega = design_force("ASCE 7-22", "freezer", 3000.0, 1.0, 0.25, ip=1.5, period_s=0.5, **kwargs)
    ductile = design_force("ASCE 7-22", "freezer", 3000.0, 1.0, 0.25, ip=1.5, period_s=0.5, ductile_anchorage=True,
                           **kwargs)
    assert not ductile.overstrength_applied and ductile.anchor_shear_n == ductile.force_n
    assert ductile.anchor_tension_n == ductile.tension_n
    assert with_omega.anchor_shear_n == pytest.approx(2.0 * with_omega.force_n)
    assert "Omega_0 2" in with_omega.basis() and "without Omega_0" in ductile.basis()
    assert "checked against the standard" in with_omega.basis()


def test_us_units():
    forces = design_force("ASCE 7-16", "computer rack", 5000.0, 1.0, 1.0, ip=1.5, cg_height_m=1.0, half_width_m=0.5)
    us = in_us_units(forces)
    newton_per_lbf = 0.45359237 * 9.80665  # the avoirdupois pound times standard gravity (exact definitions)
    assert us["force_lbf"] == pytest.approx(3600.0 / newton_per_lbf, rel=1e-12)
    assert us["force_kip"] == pytest.approx(3600.0 / newton_per_lbf / 1000.0, rel=1e-12)
    assert us["anchor_tension_kip"] == pytest.approx(5450.0 / newton_per_lbf / 1000.0, rel=1e-12)
    assert us["overturning_moment_lbf_ft"] == pytest.approx(3600.0 / newton_per_lbf / 0.3048, rel=1e-12)
    assert us["weight_lbf"] == pytest.approx(1124.04, abs=0.01)  # 5000 N = 1124.04 lbf


def test_without_base_geometry_no_tension():
    forces = design_force("ASCE 7-22", None, 2000.0, 1.0, 0.5)
    assert math.isnan(forces.tension_n) and math.isnan(forces.anchor_tension_n)
    assert forces.force_n > 0.0 and forces.anchor_shear_n == pytest.approx(2.0 * forces.force_n)


def test_asce7_22_rows_as_public_calculators_transcribe_them():
    """components.csv's ASCE 7-22 rows against tests/data/anchorage/public_tables_7_22.csv (two public
    calculators' transcriptions of Tables 13.5-1 / 13.6-1; not the standard's text)."""
    table = pd.read_csv(DATA / "public_tables_7_22.csv", comment="#")
    for row in table.itertuples(index=False):
        ours = component_coefficients("ASCE 7-22", row.component_type)
        where = f"{row.component_type} vs {row.source} {row.source_row}"
        assert (ours.resonance_at_or_below_grade, ours.resonance_above_grade, ours.strength, ours.overstrength) == \
            (row.car_at_or_below_grade, row.car_above_grade, row.r_po, row.omega_0p), where
        assert row.source in ours.source and ours.confirmed == "partly", where


PUBLISHED_7_22 = pd.read_csv(DATA / "published_7_22.csv", comment="#")


@pytest.mark.parametrize("case", list(PUBLISHED_7_22.itertuples(index=False)), ids=list(PUBLISHED_7_22["case"]))
def test_published_asce7_22_calculations(case):
    """Two hand-worked ASCE 7-22 cases of a public calculator (tests/data/anchorage/published_7_22.csv), through
    the equations and through design_force (the transformer is our 'battery rack' row, the chiller 'mechanical
    equipment': C_AR 1.0, R_po 1.5 in both)."""
    z = float(case.in_z_over_h)
    height = float(height_factor(z, None if math.isnan(case.in_period_s) else case.in_period_s))
    known = not math.isnan(case.in_building_r)
    ductility = 1.0 if z == 0.0 else ductility_reduction(case.in_building_r if known else None,
                                                         case.in_building_ie, case.in_building_omega0 if known else None)
    assert height == pytest.approx(case.expected_height_factor, abs=5e-4)
    assert ductility == pytest.approx(case.expected_ductility_reduction, abs=5e-4)
    equation = float(force_asce7_22(case.in_weight_lb, case.in_sds_g, case.in_importance, height, ductility,
                                    case.in_resonance, case.in_strength))
    minimum, maximum = (float(x) for x in force_bounds(case.in_weight_lb, case.in_sds_g, case.in_importance))
    assert equation == pytest.approx(case.expected_force_equation_lb, abs=case.tolerance_lb), case.case
    assert (minimum, maximum) == pytest.approx((case.expected_force_minimum_lb, case.expected_force_maximum_lb))
    component = "transformer" if z > 0 else "mechanical equipment"
    forces = design_force("ASCE 7-22", component, case.in_weight_lb, case.in_sds_g, z, ip=case.in_importance,
                          building_r=case.in_building_r if known else None,
                          building_omega0=case.in_building_omega0 if known else None,
                          building_ie=case.in_building_ie)
    assert forces.force_n == pytest.approx(case.expected_force_lb, abs=case.tolerance_lb), case.case
