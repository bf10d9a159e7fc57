"""ASCE 7 design spectra (assess/site/asce7.py) against published worked examples and the code's equations."""
import csv
from pathlib import Path

import numpy as np
import pytest

from assess.errors import InputError
from assess.site import asce7

DATA = Path(__file__).resolve().parents[1] / "data" / "asce7"
with open(DATA / "worked_examples.csv", newline="") as handle:
    EXAMPLES = list(csv.DictReader(handle))


@pytest.mark.parametrize("row", EXAMPLES, ids=lambda r: r["source"][:40])
def test_published_worked_examples(row):
    ss = float(row["in_ss_g"])
    s1 = float(row["in_s1_g"]) if row["in_s1_g"] else 0.1
    spectrum = asce7.from_mapped_values(ss, s1, row["in_site_class"], code=row["in_code"])
    tol = float(row["tolerance_g"])
    checks = {"fa": spectrum.fa, "fv": spectrum.fv, "sms_g": spectrum.sms_g, "sm1_g": spectrum.sm1_g,
              "sds_g": spectrum.sds_g, "sd1_g": spectrum.sd1_g}
    for name, ours in checks.items():
        expected = row[f"expected_{name}"]
        if expected:
            # printed to 2 decimals (Fa, Fv: tolerance 0.005) or 3 (accelerations)
            allowed = 0.005 if name in ("fa", "fv") else tol
            assert abs(ours - float(expected)) <= allowed + 1e-12, (row["source"], name, ours, expected)


def test_usgs_quality_control_boise():
    """USGS design-maps web service QC (usgs/earthquake-design-ws qc/results/asce7-16.qc.md), Boise:
    SMS 0.276 (B), 0.399 (C), 0.477 (D), 0.688 (E); SM1 0.088 (B), 0.164 (C), 0.261 (D)."""
    ss = 0.276 / 0.9  # site class B, Fa = 0.9
    s1 = 0.088 / 0.8  # Fv = 0.8
    expected_sms = {"C": 0.399, "D": 0.477, "E": 0.688}
    for site_class, sms in expected_sms.items():
        ours = asce7.from_mapped_values(ss, s1, site_class, code="ASCE 7-16").sms_g
        # the QC values are rounded to 3 decimals, and so is the SS recovered from them (x Fa/0.9 <= 2.7)
        assert ours == pytest.approx(sms, abs=0.0005 + 0.0005 * 2.7)
    for site_class, sm1 in {"C": 0.164, "D": 0.261}.items():
        ours = asce7.from_mapped_values(ss, s1, site_class, code="ASCE 7-16").sm1_g
        assert ours == pytest.approx(sm1, abs=0.0005 + 0.0005 * 4.2 / 0.8)


def test_table_points_and_interpolation():
    # tabulated points (ASCE 7-16 Tables 11.4-1/2) and the ends held constant
    assert asce7.site_coefficient_fa(0.1, "E") == 2.4
    assert asce7.site_coefficient_fa(0.625, "D") == pytest.approx(1.3)
    assert asce7.site_coefficient_fa(2.0, "C") == 1.2
    assert asce7.site_coefficient_fa(1.2, "E") == 1.2  # §11.4.8 exception 1: class C's
    assert asce7.site_coefficient_fv(0.05, "E") == 4.2
    assert asce7.site_coefficient_fv(0.25, "E") == pytest.approx(3.05)
    assert asce7.site_coefficient_fv(0.8, "C") == 1.4
    assert asce7.site_coefficient_fa(1.5, "D", default_class=True) == 1.2
    assert asce7.site_coefficient_fa(0.5, "D", default_class=True) == 1.4


def test_design_spectrum_branches_and_continuity():
    """Hand-computed from ASCE 7-16 eqs. 11.4-5 to 11.4-8: SDS 0.8, SD1 0.4, TL 6 s -> T0 0.1, TS 0.5."""
    s = asce7.from_design_values(0.8, 0.4, 6.0, code="ASCE 7-16")
    assert (s.t0_s, s.ts_s) == pytest.approx((0.1, 0.5))
    sa = s.design_g([0.0, 0.05, 0.1, 0.5, 1.0, 6.0, 12.0])
    np.testing.assert_allclose(sa, [0.32, 0.56, 0.8, 0.8, 0.4, 0.4 / 6, 0.4 * 6 / 144])
    # continuous at T0, TS and TL
    for t in (s.t0_s, s.ts_s, 6.0):
        assert s.design_g(t * (1 - 1e-9)) == pytest.approx(s.design_g(t * (1 + 1e-9)), rel=1e-6)
    np.testing.assert_allclose(s.target_g("MCE_R", [1.0]), [0.6])
    np.testing.assert_allclose(s.target_g("de", [1.0]), [0.4])


def test_without_tl_no_long_period_branch():
    s = asce7.from_design_values(1.0, 0.6)
    assert float(s.design_g(10.0)) == pytest.approx(0.06)
    assert any("TL not given" in n for n in s.notes)


def test_asce7_22_mapped_values_state_the_coefficients_or_refuse():
    s = asce7.from_mapped_values(1.5, 0.6, "C", code="ASCE 7-22")
    assert (s.fa, s.fv) == (1.2, 1.4)
    assert any("ASCE 7-16 Tables 11.4-1 and 11.4-2" in n for n in s.notes)
    for site_class in ("BC", "CD", "DE", "default"):
        with pytest.raises(ValueError, match="USGS"):
            asce7.from_mapped_values(1.5, 0.6, site_class, code="ASCE 7-22")
    with pytest.raises(ValueError, match="site response"):
        asce7.from_mapped_values(1.5, 0.6, "F", code="ASCE 7-16")


def test_site_sheet_values_and_refusals():
    """The site sheet's values become the spectrum (assess.assessment.floors.design_spectrum_of); the
    sheet's own refusals are tested with its reader (tests/inventory/test_site_building_sheets.py)."""
    from assess.assessment.floors import design_spectrum_of
    from assess.inventory.site_building import SiteSheet

    s = design_spectrum_of(SiteSheet(sds_g=1.0, sd1_g=0.6, tl_s=8.0), "hospital.xlsx")
    assert (s.code, s.sds_g, s.sd1_g, s.tl_s) == ("ASCE 7-22", 1.0, 0.6, 8.0)
    assert design_spectrum_of(SiteSheet(risk_category="IV"), "x.xlsx") is None
    with pytest.raises(InputError) as error:
        design_spectrum_of(SiteSheet(ss_g=1.2, s1_g=0.5, site_class="CD", rows={"site_class": 4}), "h.xlsx")
    problem = error.value.problems[0]
    assert "USGS" in str(problem) and problem.sheet == "site" and problem.row == 4


def test_tabulated_target_refuses_extrapolation():
    f = asce7.tabulated_target([0.1, 1.0, 5.0], [1.2, 0.6, 0.1])
    assert float(f(1.0)) == pytest.approx(0.6)
    with pytest.raises(ValueError):
        f(6.0)
