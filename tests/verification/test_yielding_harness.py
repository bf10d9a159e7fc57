"""The equipment checks' harness (tests/peers/yielding_equipment.py) on hand-made summary rows: what it counts as a
risk-class miss at the resolution of a suite (one motion's verdict away), checked against the class thresholds
(assess/data/defaults.toml: overturning moderate from 2.5 %, high from 10 %; sliding past the room moderate from
10 %, high from 50 %). Needs no structural engine."""
import pandas as pd
import pytest

from peers.yielding_equipment import one_motion_away
from assess.inventory.settings import Settings


def row(p_overturn=0.0, p_beyond_clearance=0.0, p_rocking_harm=0.0, motions=11, consequence="critical"):
    return pd.Series({"p_overturn": p_overturn, "p_beyond_clearance": p_beyond_clearance,
                      "p_rocking_harm": p_rocking_harm, "suite_motions": motions, "consequence": consequence})


@pytest.mark.parametrize("tool, truth_class, away", [
    (row(p_beyond_clearance=2 / 11), "low", True),        # 2 of 11 past its room (moderate); 1 of 11 is low
    (row(p_beyond_clearance=1 / 11), "moderate", True),   # and back
    (row(p_beyond_clearance=3 / 11), "low", False),       # two motions from 1 of 11
    (row(p_beyond_clearance=6 / 11), "moderate", True),   # 5 of 11 is below 50 %
    (row(p_beyond_clearance=6 / 11), "low", False),
    (row(p_overturn=1 / 11), "low", True),                # 9 % overturning is moderate; none is low
    (row(p_overturn=1 / 11), "high", True),               # 2 of 11 is high
    (row(p_overturn=1 / 18, motions=18), "high", True),   # 5.6 % is moderate; 2 of 18 (11 %) is high
    (row(motions=18), "high", False),                     # none overturns: one of 18 is moderate, not high
    (row(p_overturn=2 / 18, motions=18), "low", False),   # high to low is two classes and two motions
    (row(p_rocking_harm=4 / 50, motions=50), "moderate", True),  # 5 of 50 rock to harm: 10 %, moderate
    (row(p_rocking_harm=4 / 50, motions=50, consequence="ordinary"), "moderate", False),  # its rocking never counts
])
def test_a_class_miss_is_one_motion_away_only_where_one_motion_mends_it(tool, truth_class, away):
    assert one_motion_away(tool, truth_class, Settings()) is away
