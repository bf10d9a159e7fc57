"""The typed contracts between the stages: the settings, an item's demand and the regression's record are frozen
dataclasses with declared fields; the settings' defaults are the packaged ``defaults.toml`` read by a TOML
parser here (not through the code under test); the table of output columns ships with the package.
"""
from __future__ import annotations

import dataclasses
import sys
import typing
from pathlib import Path

import pytest

from assess.assessment.demand import GOVERNING_CASE_COLUMNS, GoverningDemand, ItemDemand
from assess.assessment.result import AssessmentResult, RegressionRecord
from assess.fragility.governing import DEMAND_COLUMNS
from assess.inventory.settings import MITIGATION_KINDS, Settings

if sys.version_info >= (3, 11):
    import tomllib
else:
    import tomli as tomllib

ROOT = Path(__file__).resolve().parents[2]
DEFAULTS_TOML = ROOT / "assess" / "data" / "defaults.toml"


def _toml() -> dict:
    with DEFAULTS_TOML.open("rb") as handle:
        return tomllib.load(handle)


def test_the_settings_defaults_are_defaults_toml_key_by_key():
    toml = _toml()
    assert list(Settings.names()) == list(toml)  # every key, none more, in the file's order
    defaults = Settings()
    for key, value in toml.items():
        assert getattr(defaults, key) == value and type(getattr(defaults, key)) is type(value), key


def test_every_setting_is_typed_and_numbers_become_floats():
    hints = typing.get_type_hints(Settings)
    assert set(hints) == set(Settings.names()) and set(hints.values()) <= {str, float, int}
    typed = Settings.from_mapping({"zeta": 1, "synthetic_realizations": 5.0, "facility": "Lab"})
    assert (typed.zeta, typed.synthetic_realizations, typed.facility) == (1.0, 5, "Lab")
    assert type(typed.zeta) is float and type(typed.synthetic_realizations) is int
    with pytest.raises(TypeError):  # a key that is no setting is a bug, not a silent extra
        Settings.from_mapping({"zeta_typo": 1.0})


def test_the_mitigation_cost_of_each_action_kind_is_its_setting():
    costs = Settings(**{f"mitigation_cost_{kind}": float(k + 1) for k, kind in enumerate(MITIGATION_KINDS)})
    assert [costs.mitigation_cost(kind) for kind in MITIGATION_KINDS] == [1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0]
    assert costs.mitigation_cost("none") == 0.0 and costs.mitigation_cost("anchored") == 0.0
    assert all(f"mitigation_cost_{kind}" in _toml() for kind in MITIGATION_KINDS)


def _demand_row() -> dict:
    row = {name: 0.0 for name in GoverningDemand.__dataclass_fields__}
    row.update(mode="slide", governing_motion="M1", regression_note="", demand_note="", demand_source=("records",),
               governing_direction=1, suite_motions=3, suite_histories=3, regression_applies=True,
               demand_planar=False, demand_uplift=False)
    return row


@pytest.mark.parametrize("record", [Settings(), RegressionRecord(),
                                    GoverningDemand(**_demand_row()),
                                    ItemDemand({"A": GoverningDemand(**_demand_row())}, {"A": False})],
                         ids=lambda record: type(record).__name__)
def test_the_contracts_are_frozen(record):
    name = dataclasses.fields(record)[0].name
    with pytest.raises(dataclasses.FrozenInstanceError):
        setattr(record, name, getattr(record, name))


def test_an_item_s_demand_declares_every_column_the_demand_stage_gives():
    """The row's fields are the governing case's columns, which case it is and whether the regression applies,
    and the governing demand's columns (``demand_mode`` becomes ``mode``): a column the stages add without
    declaring it fails at construction (``GoverningDemand(**row)``)."""
    declared = set(GoverningDemand.__dataclass_fields__)
    expected = (set(GOVERNING_CASE_COLUMNS) | set(DEMAND_COLUMNS) - {"demand_mode"}
                | {"governing_direction", "governing_motion", "regression_note", "regression_applies",
                   "pulse_share", "overturn_fraction"})
    assert declared == expected
    with pytest.raises(TypeError):
        GoverningDemand(**{**_demand_row(), "undeclared": 1.0})
    row = GoverningDemand(**_demand_row())
    assert row.as_row() == _demand_row()
    assert ItemDemand({"A": row}, {"A": True}).row_dicts() == {"A": _demand_row()}


def test_the_regression_record_defaults_to_the_paper_s_constants():
    """Konstantinidis & Makris (2010), Table 3 / eq. 21: zeta 0.370, eta 0.953, sigma 0.445, IM 1.71-6.40."""
    record = RegressionRecord()
    assert (record.zeta, record.eta, record.sigma, record.im_min, record.im_max) == (0.370, 0.953, 0.445, 1.71, 6.40)
    assert record.source == ""


def test_the_result_declares_its_contracts_types():
    hints = typing.get_type_hints(AssessmentResult, localns={
        "CurveRisk": object, "AnchorageSite": object, "DesignSpectrum": object})
    assert hints["settings"] is Settings and hints["regression"] is RegressionRecord
    fields = {field.name: field.type for field in dataclasses.fields(AssessmentResult)}
    assert fields["curve_risk"] == "CurveRisk | None" and fields["anchorage"] == "AnchorageSite | None"


def test_the_columns_table_ships_with_the_package():
    """An installed wheel finds it: it is package data (pyproject.toml) and read through importlib.resources."""
    pyproject = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    patterns = pyproject["tool"]["setuptools"]["package-data"]["assess.data"]
    assert "*.csv" in patterns and (ROOT / "assess" / "data" / "columns.csv").is_file()
    from assess.data import output_columns
    table = output_columns()
    assert list(table.columns) == ["file", "column", "unit", "dtype", "stage", "when", "meaning"]
    assert set(table["dtype"]) == {"str", "float64", "int64", "bool"}
    assert not table.duplicated(["file", "column"]).any()
    assert (table["meaning"].str.len() > 0).all() and (table["stage"].str.len() > 0).all()


def test_the_columns_the_report_makes_are_declared_as_the_report_s():
    """The summary's words and kips are made by the report from the decisions (``WORD_COLUMNS``): the table
    declares exactly those as the ``report`` stage's, each a column of ``summary.csv``."""
    from assess.assessment.result import SUMMARY_COLUMNS, WORD_COLUMNS
    from assess.data import output_columns
    table = output_columns()
    report = table[(table["file"] == "summary.csv") & (table["stage"] == "report")]["column"]
    assert sorted(report) == sorted(WORD_COLUMNS) and len(report) == len(WORD_COLUMNS)
    assert set(WORD_COLUMNS) <= set(SUMMARY_COLUMNS)
    assert set(table.loc[table["file"] != "summary.csv", "stage"]).isdisjoint({"report"})
