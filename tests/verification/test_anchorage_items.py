"""Five items of a workbook, by hand, through the item-level anchorage (assess.anchorage.item_anchorage).

The building of every item below: a Risk Category IV hospital, S_DS = 1.2 g from the site sheet, 4 storeys
(the roof is floor 4), 16.0 m high, a steel moment frame. Its approximate period (ASCE 7 eq. 12.8-7, C_t 0.0724
and x 0.8 in metres, Table 12.8-2):

    T_a = 0.0724 · 16.0^0.8 = 0.0724 · 9.18959 = 0.665326 s
    a_1 = min(1/T_a, 2.5) = 1.503022;   a_2 = max(1 − (0.4/T_a)², 0) = 1 − 0.361452 = 0.638548

R_μ = sqrt(1.1 R/(I_e Ω0)) = sqrt(1.1 · 8/(1.5 · 3)) = 1.398412 above grade (eq. 13.3-6: Table 12.2-1's C.1,
steel special moment frames, R 8 and Ω0 3; I_e 1.5 in Risk Category IV, Table 1.5-2) and 1.0 at grade. W_p = m·g,
g = 9.80665 m/s². Tension: 0.9D − 1.0E with E_v = 0.2 S_DS D, so the weight holds with
(0.9 − 0.24) W_p = 0.66 W_p; T = (F h_cg − 0.66 W_p b)/(2b), and with Omega_0 = 2 the same with 2F.
1 kip = 4448.2216 N. Coefficients: the rows named, from assess/data/components.csv (their sources there).

Each expected number is worked out in the test's comment and written to 0.01 N; the tolerance is 0.01 N.
"""
from __future__ import annotations

import math
from types import SimpleNamespace

import pytest

from assess.anchorage import anchorage_site
from assess.anchorage import item_anchorage as _item_anchorage
from assess.inventory.settings import Settings
from assess.inventory.site_building import BuildingSheet, SiteSheet
from assess.report.advice import anchorage_columns

G = 9.80665
N_PER_KIP = 4448.2216152605
BUILDING = BuildingSheet(storeys=4, height_m=16.0, system="steel moment frame")


def item_anchorage(item, consequence, action_kind, site):
    """The item's anchorage columns as summary.csv has them: SI (the decision's) and kip (the report's)."""
    anchorage = _item_anchorage(item, consequence, action_kind, site)
    return {**anchorage.columns(), **anchorage_columns(anchorage)}


def _site(code):
    return anchorage_site(SiteSheet(code=code, sds_g=1.2, risk_category="IV"), BUILDING, Settings())


def _item(floor, mass_kg, width_m, depth_m, cg_height_m, component_type=None, ip=math.nan):
    return SimpleNamespace(floor=floor, mass_kg=mass_kg, width_m=width_m, depth_m=depth_m, cg_height_m=cg_height_m,
                           component_type=component_type, ip=ip)


def _check(out, force_n, tension_n, tension_omega_n, ip):
    assert out["ip"] == ip
    assert out["anchor_force_kn"] * 1000 == pytest.approx(force_n, abs=0.01)
    assert out["anchor_force_kip"] * N_PER_KIP == pytest.approx(force_n, abs=0.01)
    assert out["anchor_tension_kn"] * 1000 == pytest.approx(tension_n, abs=0.01)
    assert out["anchor_tension_omega_kn"] * 1000 == pytest.approx(tension_omega_n, abs=0.01)
    assert out["anchor_shear_omega_kn"] == pytest.approx(2.0 * out["anchor_force_kn"], rel=1e-12)
    assert out["anchor_omega0"] == 2.0


def test_the_building_terms():
    site = _site("ASCE 7-22")
    assert site.period_s == pytest.approx(0.665326, abs=5e-7)
    assert (site.building_r, site.building_omega0, site.building_ie) == (8.0, 3.0, 1.5)
    assert "R_mu 1.398 (eq. 13.3-6: R 8 and Omega0 3 of Table 12.2-1's C.1" in site.basis
    assert site.edition == "ASCE 7-22" and site.risk_category == "IV" and site.sds_g == 1.2
    assert site.z_over_h(1) == 0.25 and site.z_over_h(4) == 1.0 and site.z_over_h(-1) == 0.0


def test_freezer_critical_first_floor():
    """1. Ultra-low freezer, 300 kg, floor 1 (z/h 0.25), consequence critical in Risk Category IV: I_p 1.5
    (§13.1.3); component type 'freezer' = refrigeration. Base 0.7 m (b 0.35), h_cg 0.9 m. W_p = 2941.995 N.

    7-22 (C_AR 1.4 above grade, R_po 2.0): H_f = 1 + 1.503022·0.25 + 0.638548·0.25^10 = 1.375756;
    0.4·1.2·1.5·2941.995·(1.375756/1.398412)·(1.4/2.0) = 2118.24·0.983799·0.7 = 1458.74 N
    < 0.3·1.2·1.5·2941.995 = 1588.68 N: the minimum governs, F_p = 1588.68 N.
    T = (1588.68·0.9 − 0.66·2941.995·0.35)/0.7 = (1429.81 − 679.60)/0.7 = 1071.73 N;
    Omega_0: (3177.35·0.9 − 679.60)/0.7 = (2859.62 − 679.60)/0.7 = 3114.31 N.

    7-16 (a_p 2.5, R_p 6.0): 0.4·2.5·1.2·2941.995/(6/1.5)·(1 + 0.5) = 882.60·1.5 = 1323.90 N < 1588.68 N:
    the same minimum, so the same F_p and tensions.
    """
    item = _item(1, 300.0, 0.7, 0.8, 0.9, "freezer")
    for code in ("ASCE 7-22", "ASCE 7-16"):
        out = item_anchorage(item, "critical", "anchor", _site(code))
        assert out["component_type"] == "refrigeration"
        _check(out, 1588.68, 1071.73, 3114.31, 1.5)
        assert "minimum governs" in out["anchor_basis"]


def test_server_rack_on_the_roof():
    """2. Server rack, 600 kg, on the roof (floor 4, z/h 1), critical: I_p 1.5; 'server rack' = computer rack.
    Base 0.6 m (b 0.3), h_cg 1.0 m. W_p = 5883.99 N.

    7-22 (C_AR 1.0, R_po 1.5): H_f = 1 + 1.503022 + 0.638548 = 3.141570;
    0.4·1.2·1.5·5883.99·(3.141570/1.398412)·(1.0/1.5) = 4236.47·2.246527·0.666667 = 6344.90 N (< 16945.89 N).
    T = (6344.90·1.0 − 0.66·5883.99·0.3)/0.6 = (6344.90 − 1165.03)/0.6 = 8633.12 N;
    Omega_0: (12689.80 − 1165.03)/0.6 = 19207.95 N.

    7-16 (a_p 1.0, R_p 2.5): 0.4·1.0·1.2·5883.99/(2.5/1.5)·3 = 1694.59·3 = 5083.77 N;
    T = (5083.77 − 1165.03)/0.6 = 6531.23 N; Omega_0: (10167.54 − 1165.03)/0.6 = 15004.17 N.
    """
    item = _item(4, 600.0, 0.6, 1.1, 1.0, "server rack")
    _check(item_anchorage(item, "critical", "anchor", _site("ASCE 7-22")), 6344.90, 8633.12, 19207.95, 1.5)
    _check(item_anchorage(item, "critical", "anchor", _site("ASCE 7-16")), 5083.77, 6531.23, 15004.17, 1.5)


def test_item_at_grade_with_no_component_type():
    """3. An ordinary item, 200 kg, at grade (floor 0, z/h 0), no component type: laboratory equipment; I_p 1.0.
    Base 0.6 m (b 0.3), h_cg 0.5 m. W_p = 1961.33 N.

    7-22 (C_AR 1.0 at or below grade, R_po 1.5; H_f 1, R_μ 1.0 at grade): 0.4·1.2·1961.33·(1/1)·(1/1.5) =
    627.63 N < 0.3·1.2·1961.33 = 706.08 N: minimum. 7-16 (a_p 1, R_p 2.5): 0.4·1.2·1961.33/2.5 = 376.58 N: minimum.
    T = (706.08·0.5 − 0.66·1961.33·0.3)/0.6 = (353.04 − 388.34)/0.6 < 0: 0 N;
    Omega_0: (706.08 − 388.34)/0.6 = 529.56 N (529.57 before rounding the terms: 0.01 N tolerance).
    """
    item = _item(0, 200.0, 0.6, 0.9, 0.5)
    for code in ("ASCE 7-22", "ASCE 7-16"):
        out = item_anchorage(item, "ordinary", "restrain", _site(code))
        assert out["component_type"] == "laboratory equipment"
        _check(out, 706.08, 0.0, 529.56, 1.0)


def test_ip_given_in_the_workbook():
    """4. An ordinary cabinet, 150 kg, floor 2 (z/h 0.5), whose workbook row gives ip 1.5 (I_p 1.0 by the rules);
    'storage cabinet' = storage shelving. Base 0.45 m (b 0.225), h_cg 0.9 m. W_p = 1470.997 N.

    7-22 (C_AR 1.0, R_po 1.5): H_f = 1 + 1.503022·0.5 + 0.638548·0.5^10 = 1.751511 + 0.000624 = 1.752135;
    0.4·1.2·1.5·1470.997·(1.752135/1.398412)·(1/1.5) = 1059.12·1.252946·0.666667 = 884.68 N (> 794.34 N minimum).
    T = (884.68·0.9 − 0.66·1470.997·0.225)/0.45 = (796.21 − 218.44)/0.45 = 1283.93 N;
    Omega_0: (1592.42 − 218.44)/0.45 = 3053.29 N.

    7-16 (a_p 1, R_p 2.5): 0.4·1.2·1470.997/(2.5/1.5)·2 = 423.65·2 = 847.29 N;
    T = (762.56 − 218.44)/0.45 = 1209.16 N; Omega_0: (1525.12 − 218.44)/0.45 = 2903.75 N.
    """
    item = _item(2, 150.0, 0.45, 0.6, 0.9, "storage cabinet", ip=1.5)
    _check(item_anchorage(item, "ordinary", "anchor", _site("ASCE 7-22")), 884.68, 1283.93, 3053.29, 1.5)
    _check(item_anchorage(item, "ordinary", "anchor", _site("ASCE 7-16")), 847.29, 1209.16, 2903.75, 1.5)
    assert item_anchorage(_item(2, 150.0, 0.45, 0.6, 0.9, "storage cabinet"), "ordinary", "anchor",
                          _site("ASCE 7-22"))["ip"] == 1.0


def test_switchgear_third_floor():
    """5. Switchgear, 800 kg, floor 3 (z/h 0.75), critical in Risk Category IV: I_p 1.5; electrical cabinet.
    Base 0.6 m (b 0.3), h_cg 1.1 m. W_p = 7845.32 N.

    7-22 (C_AR 1.4, R_po 2.0): H_f = 1 + 1.503022·0.75 + 0.638548·0.75^10 = 2.127267 + 0.035960 = 2.163227;
    0.4·1.2·1.5·7845.32·(2.163227/1.398412)·(1.4/2.0) = 5648.63·1.546916·0.7 = 6116.57 N.
    T = (6116.57·1.1 − 0.66·7845.32·0.3)/0.6 = (6728.23 − 1553.37)/0.6 = 8624.76 N;
    Omega_0: (13456.45 − 1553.37)/0.6 = 19838.47 N.

    7-16 (a_p 2.5, R_p 6.0): 0.4·2.5·1.2·7845.32/(6/1.5)·(1 + 1.5) = 2353.60·2.5 = 5883.99 N;
    T = (6472.39 − 1553.37)/0.6 = 8198.36 N; Omega_0: (12944.78 − 1553.37)/0.6 = 18985.67 N.
    """
    item = _item(3, 800.0, 0.6, 1.5, 1.1, "Switchgear")
    _check(item_anchorage(item, "critical", "anchor", _site("ASCE 7-22")), 6116.57, 8624.76, 19838.47, 1.5)
    _check(item_anchorage(item, "critical", "anchor", _site("ASCE 7-16")), 5883.99, 8198.36, 18985.67, 1.5)


def test_no_force_without_action_or_sds():
    item = _item(1, 300.0, 0.7, 0.8, 0.9, "freezer")
    none = item_anchorage(item, "critical", "none", _site("ASCE 7-22"))
    assert math.isnan(none["anchor_force_kn"]) and none["ip"] == 1.5 and none["component_type"] == "refrigeration"
    no_sds = item_anchorage(item, "critical", "anchor", anchorage_site(SiteSheet(risk_category="IV"), BUILDING, Settings()))
    assert math.isnan(no_sds["anchor_force_kn"]) and "add sds_g" in no_sds["anchor_basis"]


def test_settings_alone_as_before_the_site_sheet():
    """Without site and building sheets: ASCE 7-22, Risk Category II, S_DS and roof_floor from the settings,
    H_f = 1 + 2.5 z/h (eq. 13.3-5). A critical item is then I_p 1.0 (not Risk Category IV)."""
    site = anchorage_site(None, None, Settings(sds_g=1.0, roof_floor=4))
    item = _item(2, 100.0, 0.5, 0.5, 0.5)
    out = item_anchorage(item, "critical", "anchor", site)
    # 0.4·1.0·1.0·980.665·((1 + 2.5·0.5)/1.3)·(1.0/1.5) = 392.266·1.730769·0.666667 = 452.61 N
    assert out["ip"] == 1.0 and out["anchor_force_kn"] * 1000 == pytest.approx(452.61, abs=0.01)
    assert "eq. 13.3-5" in site.basis and "roof_floor 4" in site.basis


def test_the_sample_hospital_workbook():
    """inventories/hospital.xlsx (Risk Category IV, ASCE 7-22): every critical, hazardous and life-safety item has
    I_p 1.5 and the others 1.0; the component types typed in its rows are the table's; the roof item (floor 4)
    has z/h 1. The workbook is what build_hospital.py writes."""
    import importlib.util
    import sys
    from pathlib import Path

    from assess.decision.decisions import item_consequence
    from assess.inventory import read_workbook

    folder = Path(__file__).resolve().parents[2] / "inventories"
    sys.path.insert(0, str(folder))
    try:
        spec = importlib.util.spec_from_file_location("build_hospital", folder / "build_hospital.py")
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
        assert module.build() == (folder / "hospital.xlsx").read_bytes()
    finally:
        sys.path.remove(str(folder))
    inventory = read_workbook(folder / "hospital.xlsx")
    site = anchorage_site(inventory.site, inventory.building, inventory.settings)
    assert (site.edition, site.risk_category, site.sds_g, site.storeys) == ("ASCE 7-22", "IV", 1.2, 4.0)
    typed = {row.id: row.component_type for row in inventory.equipment.itertuples() if row.type_source == "typed"}
    # a type read from the name (no component_type): the crash cart is a medical cart (code_governed.csv)
    named = {row.id: row.component_type for row in inventory.equipment.itertuples() if row.type_source == "name"}
    assert named == {"ED-0-01": "medical equipment"}
    assert typed == {"ED-0-02": "storage shelving", "LB-1-01": "refrigeration", "LB-1-02": "refrigeration",
                     "LB-1-03": "laboratory equipment", "RX-2-01": "medical equipment",
                     "RX-2-02": "storage shelving", "RX-2-03": "refrigeration", "IT-3-01": "computer rack",
                     "IT-3-02": "battery rack", "MP-4-01": "mechanical equipment", "MP-4-02": "storage shelving",
                     "MP-4-03": "mechanical equipment"}
    for item in inventory.equipment.itertuples(index=False):
        out = item_anchorage(item, item_consequence(item), "anchor", site)
        expected_ip = 1.5 if item_consequence(item) in ("critical", "hazardous", "life-safety") else 1.0
        assert out["ip"] == expected_ip, item.id
        assert out["component_type"] == (typed.get(item.id) or named.get(item.id) or "laboratory equipment")
        if item.floor == 4:
            assert "z/h 1.00" in out["anchor_basis"]


def test_the_method_include_lays_out_the_equations_and_the_rows_used():
    import pandas as pd

    from assess.anchorage.method import anchorage_method
    from assess.report.render import make_environment

    summary = pd.DataFrame({"action_kind": ["anchor", "restrain", "none"],
                            "component_type": ["refrigeration", "computer rack", "storage shelving"],
                            "anchor_force_kn": [1.0, 2.0, float("nan")]})
    html = make_environment().get_template("_anchorage_method.html.j2").render(
        anchorage=anchorage_method(_site("ASCE 7-22"), summary))
    for text in ("ASCE 7-22</b> (eqs. 13.3-1 to 13.3-6)", "ASCE 7-16</b> (eqs. 13.3-1 to 13.3-3)",
                 "(H<sub>f</sub>/R<sub>μ</sub>)(C<sub>AR</sub>/R<sub>po</sub>)", "Ω<sub>0p</sub>",
                 "(2 items with a force)", "T_a = 0.665 s", "Risk Category IV", "C_AR 1.4 at or below grade"):
        assert text in html, text
    assert "storage shelving" not in html.split("<tbody>")[1]  # no force, not listed
    assert "built-in" not in html


def test_the_five_items_from_the_anchorage_table():
    """The report's anchorage table (and summary.xlsx's sheet) gives the five items above as checked by hand:
    W_p, z/h, I_p, F_p, F_p/W_p, T and T with Omega_0 per unit, in kN (SI) and in kip (US, 1 kip = 4448.2216 N)."""
    from types import SimpleNamespace

    import pandas as pd

    from assess.decision.actions import ActionDecision, ActionKind
    from assess.decision.decisions import ItemDecision
    from assess.report.anchorage_table import anchorage_rows

    five = {  # id: (item, consequence, action, hand F_p [N], T [N], T with Omega_0 [N], I_p)
        "FRZ": (_item(1, 300.0, 0.7, 0.8, 0.9, "freezer"), "critical", "anchor", 1588.68, 1071.73, 3114.31, 1.5),
        "RACK": (_item(4, 600.0, 0.6, 1.1, 1.0, "server rack"), "critical", "anchor", 6344.90, 8633.12, 19207.95, 1.5),
        "GRADE": (_item(0, 200.0, 0.6, 0.9, 0.5), "ordinary", "restrain", 706.08, 0.0, 529.56, 1.0),
        "CAB": (_item(2, 150.0, 0.45, 0.6, 0.9, "storage cabinet", ip=1.5), "ordinary", "anchor", 884.68, 1283.93,
                3053.29, 1.5),
        "SWG": (_item(3, 800.0, 0.6, 1.5, 1.1, "Switchgear"), "critical", "anchor", 6116.57, 8624.76, 19838.47, 1.5),
    }
    site = _site("ASCE 7-22")
    decisions = {item_id: ItemDecision(item_id, "high", consequence, None,
                                       ActionDecision(ActionKind(action), 0.0, 0.0),
                                       _item_anchorage(item, consequence, action, site))
                 for item_id, (item, consequence, action, *_) in five.items()}
    summary = pd.DataFrame({"id": list(five), "name": list(five), "floor": [v[0].floor for v in five.values()]})
    for units, per_n in (("si", 1000.0), ("us", N_PER_KIP)):
        unit = {"si": "kN", "us": "kip"}[units]
        table = anchorage_rows(SimpleNamespace(summary=summary, decisions=decisions,
                                               settings=Settings(units=units))).set_index("id")
        assert list(table.index) == list(five)
        for item_id, (item, _, _, force_n, tension_n, tension_omega_n, ip) in five.items():
            row = table.loc[item_id]
            assert row[f"W_p ({unit})"] * per_n == pytest.approx(item.mass_kg * G, abs=0.01)
            assert row["z/h"] == pytest.approx(site.z_over_h(item.floor)) and row["I_p"] == ip
            assert row[f"F_p ({unit})"] * per_n == pytest.approx(force_n, abs=0.01)
            assert row[f"V ({unit})"] == row[f"F_p ({unit})"]
            assert row["F_p/W_p"] == pytest.approx(force_n / (item.mass_kg * G), abs=1e-5)
            assert row[f"T ({unit})"] * per_n == pytest.approx(tension_n, abs=0.01)
            assert row[f"T with Omega_0 ({unit})"] * per_n == pytest.approx(tension_omega_n, abs=0.01)
            assert row["Omega_0"] == 2.0 and row["edition"] == "ASCE 7-22"
            assert row["confirmed"] in ("yes", "partly", "no") and row["table row"].startswith("Table 13.")
    assert table.loc["FRZ", "governs"] == "minimum"  # 0.3 S_DS I_p W_p, by hand above
