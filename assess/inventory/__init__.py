"""Inventory: the facility's workbook read, validated and converted to SI once.

Nothing downstream of this package sees a raw workbook header or a non-SI
number. The canonical columns are listed in ``docs/nomenclature.md``.
"""
from assess.inventory.model import Inventory

__all__ = ["Inventory", "read_workbook"]


def read_workbook(path):  # imported lazily: openpyxl is slow to import
    """Read and validate an inventory workbook; see :func:`assess.inventory.workbook.read_workbook`."""
    from assess.inventory.workbook import read_workbook as _read

    return _read(path)
