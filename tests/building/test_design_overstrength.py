"""The design-data route's overstrength (assess/building/design.py; docs/workbook.md, sheet ``building``).

What the module's text claims of its default Ω, checked against what it does not compute itself: the yield
base shear against ASCE 7-22 §12.8's C_s worked by hand; each system's default, steel moment frames'
Elkady & Lignos' pushover peak Ω_s 3.0 taken to the corner of a spring hardening 3 % at ductility 7 (3.0/1.18,
rounded to 2.5), the others 2 (no value for them could be sourced); the hardening that separates this Ω (the
corner of a hardening spring) from FEMA P-695's (the peak of its pushover), from the spring's own law against
the bilinear closed form; the same pushover peak at the hardening the engineer gives; and the users' pages stating
the code's defaults.
"""
from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from assess.building.design import (DEFAULT_OVERSTRENGTH, OVERSTRENGTH_BY_SYSTEM, SYSTEM_FACTORS, assumed_overstrength,
                                    design_strength)
from assess.building.hysteresis import spring_forces
from assess.building.nonlinear import DEFAULT_HARDENING
from tests.project.test_docs import section, table_rows

REPO = Path(__file__).resolve().parents[2]


def test_the_default_is_two_times_the_design_base_shear_of_asce_7_22_worked_by_hand():
    """5 storeys of 4 m, T_1 0.3 s, a shear wall (R 5) in Risk Category IV (I_e 1.5), S_DS 1.1 g, S_D1 0.6 g.

    T_a = 0.02 (65.6 ft)^0.75 = 0.46 s, C_u T_a = 0.64 s > 0.3 s, so T = 0.3 s (§12.8.2);
    C_s = min(1.1/(5/1.5), 0.6/(0.3 · 5/1.5)) = min(0.33, 0.6) = 0.33 (Eqs. 12.8-2, 12.8-3), above
    0.044 · 1.1 · 1.5 = 0.0726 (Eq. 12.8-5); yield at 2 × 0.33 = 0.66 W.
    """
    strength = design_strength("shear wall", [1.0] * 5, [4.0, 8.0, 12.0, 16.0, 20.0], 0.3, sds_g=1.1,
                               sd1_g=0.6, risk_category="IV")
    assert strength.design_period_s == pytest.approx(0.3)
    assert strength.seismic_response_coefficient == pytest.approx(0.33, rel=1e-12)
    assert (strength.overstrength, strength.yield_base_shear_g) == (2.0, pytest.approx(0.66, rel=1e-12))
    assert strength.source.endswith("times an assumed overstrength 2")


def test_an_overstrength_the_engineer_gives_is_not_called_assumed():
    """The run's note (the strength's ``source``) says whose Ω it is: the default is assumed, the sheet's given."""
    strength = design_strength("braced frame", [1.0] * 5, [4.0, 8.0, 12.0, 16.0, 20.0], 0.48, sds_g=0.74,
                               sd1_g=0.4, risk_category="IV", overstrength=2.5)
    assert strength.source.endswith("times the given overstrength 2.5")
    assert "assumed" not in strength.source


@pytest.mark.parametrize("system", sorted(SYSTEM_FACTORS))
def test_each_system_takes_its_documented_default(system):
    """Steel moment frames: Ω_s 3.0 (Elkady & Lignos 2015, with gravity framing) over 1 + 0.03 (7 - 1) = 1.18, the
    hardening spring's force at ductility 7 over its yield: 2.54, taken as 2.5; every other system 2."""
    expected = round(3.0 / (1.0 + DEFAULT_HARDENING * (7.0 - 1.0)) * 2) / 2 if system == "steel moment frame" else 2.0
    strength = design_strength(system, [1.0, 1.0], [3.0, 6.0], 0.2, sds_g=1.0, sd1_g=0.6)
    assert strength.overstrength == OVERSTRENGTH_BY_SYSTEM[system] == expected
    assert strength.overstrength_assumed
    assert strength.yield_base_shear_g == pytest.approx(expected * strength.seismic_response_coefficient, rel=1e-12)


@pytest.mark.parametrize("law", ["bilinear", "pinching"])
def test_a_spring_pushed_to_ductility_seven_carries_1_18_times_its_yield(law):
    """F = F_y (1 + b (μ - 1)) on the bilinear backbone, b = 0.03: 1.18 F_y at μ = 7 (the module's text)."""
    stiffness, yield_force = 1000.0, 10.0
    yield_drift = yield_force / stiffness
    ductility = np.linspace(0.1, 7.0, 70)
    forces = spring_forces(ductility * yield_drift, law, stiffness, yield_force, hardening=DEFAULT_HARDENING)
    expected = np.where(ductility <= 1.0, ductility, 1.0 + 0.03 * (ductility - 1.0)) * yield_force
    np.testing.assert_allclose(forces, expected, rtol=1e-9)
    assert forces[-1] / yield_force == pytest.approx(1.18, rel=1e-9)


def test_the_users_pages_state_the_code_s_defaults():
    default, steel = f"{DEFAULT_OVERSTRENGTH:g}", f"{OVERSTRENGTH_BY_SYSTEM['steel moment frame']:g}"
    rows = {row["key"].strip("`"): row for row in table_rows(section("workbook.md", "Sheet `building` (optional)"))
            if "key" in row}
    assert rows["overstrength"]["default"] == f"{steel} for `steel moment frame`, {default} for the others"
    assert f"{steel} for steel moment frames" in rows["overstrength"]["meaning"]
    assert re.search(rf"\b{default} for the other systems is a judgement", rows["overstrength"]["meaning"])
    readme = " ".join((REPO / "README.md").read_text().split())
    assert f"an assumed overstrength of {steel} for a steel moment frame and {default} for the other systems," in readme
    guide = " ".join((REPO / "docs" / "guide.md").read_text().split())
    assert f"times an overstrength of {steel} for steel moment frames and {default} for the others." in guide


@pytest.mark.parametrize("hardening", [0.0, 0.01, 0.02, 0.05, 0.1])
def test_a_steel_frame_s_assumed_overstrength_keeps_its_pushover_peak_at_the_hardening_the_engineer_gives(hardening):
    """The steel frames' 2.5 is a pushover peak, 2.5 × 1.18 (Elkady & Lignos' 3.0 as rounded), carried at ductility 7
    by a spring hardening 3 %. With the sheet's ``storey_hardening_ratio`` b the stick's first storey carries that
    peak at ductility 7 from its own corner: the spring's law (not this module) pushed to μ 7 gives the same force
    whatever b, and the yield base shear is that force over 1 + 6b."""
    design = dict(sds_g=1.0, sd1_g=0.6)
    strength = design_strength("steel moment frame", [1.0] * 4, [4.0, 8.0, 12.0, 16.0], 0.6, hardening=hardening,
                               **design)
    cs = strength.seismic_response_coefficient
    assert cs == pytest.approx(0.125, rel=1e-12)
    stiffness = 1000.0
    yield_force = strength.yield_base_shear_g * stiffness   # a spring whose yield drift is the base shear at yield
    peak = spring_forces(np.array([7.0 * strength.yield_base_shear_g]), "bilinear", stiffness, yield_force,
                         hardening=hardening)[0] / stiffness
    assert peak == pytest.approx(2.5 * 1.18 * cs, rel=1e-9)
    assert strength.overstrength_assumed
    assert strength.source.endswith(f"overstrength {strength.overstrength:.3g} (the system's 2.5 holds for storeys "
                                    f"hardening at 3% of their stiffness after yield, taken to the given "
                                    f"{100 * hardening:.3g}% so that the pushover's peak stays the same)")


def test_the_assumed_overstrength_of_the_other_systems_and_a_given_one_do_not_move_with_the_hardening():
    """Only the steel frames' value is a peak taken to a corner; the others' 2 is a judgement, and an engineer's
    overstrength is theirs. The default hardening gives the documented 2.5 and no clause."""
    heights = [4.0, 8.0, 12.0, 16.0]
    for system in sorted(set(SYSTEM_FACTORS) - {"steel moment frame"}):
        strength = design_strength(system, [1.0] * 4, heights, 0.6, sds_g=1.0, sd1_g=0.6, hardening=0.05)
        assert strength.overstrength == DEFAULT_OVERSTRENGTH and "pushover peak" not in strength.source
    given = design_strength("steel moment frame", [1.0] * 4, heights, 0.6, sds_g=1.0, sd1_g=0.6, hardening=0.05,
                            overstrength=2.5)
    assert given.overstrength == 2.5 and not given.overstrength_assumed
    default = design_strength("steel moment frame", [1.0] * 4, heights, 0.6, sds_g=1.0, sd1_g=0.6)
    assert default.overstrength == 2.5 and default.source.endswith("times an assumed overstrength 2.5")


def test_the_users_page_gives_the_overstrength_at_the_hardening_the_code_takes():
    rows = {row["key"].strip("`"): row for row in table_rows(section("workbook.md", "Sheet `building` (optional)"))
            if "key" in row}
    text = rows["overstrength"]["meaning"]
    for hardening in (0.02, 0.05):
        value = assumed_overstrength("steel moment frame", hardening)
        assert f"{value:.3g} at {100 * hardening:g} %" in text
