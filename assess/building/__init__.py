"""The building under its ground motion: modes, every floor's acceleration in time, the floors table.

A ``building`` sheet (storeys, height, lateral system, T_1 where known, damping) gives
:func:`~assess.building.modes.building_modes`; each ground motion of a level's suite goes
through :func:`~assess.building.response.floor_records` to every floor's absolute
acceleration history; :func:`~assess.building.floors.floors_table` is ``floors.csv``.

The building is taken as **linear elastic** there: its floors' accelerations are
those of its elastic modes at the damping given. A building that yields (cracks,
hinges, braces buckling) lengthens its periods and caps its storey forces, so
that its upper floors' peak accelerations are then lower than the elastic ones,
and their frequency content shifts to longer periods. The building sheet's
``response: yielding`` (the default where the storeys' strength is known) takes
the floors' histories from a stick of yielding storey springs instead
(:mod:`assess.building.yielding`, on :mod:`assess.building.nonlinear`,
:mod:`assess.building.hysteresis` and :mod:`assess.building.design`). A
structural engineer's floor motions, where given in the ``hazard`` sheet, govern.
"""
from .floors import floors_table
from .modes import ALPHA_BY_SYSTEM, ALPHA_RANGE_BY_SYSTEM, BuildingModes, building_modes
from .period import SYSTEMS, approximate_period
from .response import floor_accelerations, floor_records

__all__ = ["ALPHA_BY_SYSTEM", "ALPHA_RANGE_BY_SYSTEM", "BuildingModes", "SYSTEMS", "approximate_period",
           "building_modes", "floor_accelerations", "floor_records", "floors_table"]
