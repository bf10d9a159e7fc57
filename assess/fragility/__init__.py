"""Fragility of sliding: IM, EDP, the lognormal regression and P(Umax > clearance)."""
from assess.fragility.regression import (
    RegressionConstants,
    RegressionFit,
    capacity_edp,
    engineering_demand,
    fit_regression,
    intensity_measure,
    ks_distance,
    median_edp,
    probability_of_exceedance,
    pulse_frequency,
    sliding_quantile,
)

__all__ = [
    "RegressionConstants", "RegressionFit", "capacity_edp", "engineering_demand",
    "fit_regression", "intensity_measure", "ks_distance", "median_edp",
    "probability_of_exceedance", "pulse_frequency", "sliding_quantile",
]
