"""Hazard: levels (2 % in 50 years ...) and the motions of a level at a floor."""
from assess.hazard.levels import HazardLevel, parse_level

__all__ = ["HazardLevel", "parse_level"]
