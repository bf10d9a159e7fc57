"""The report's title block: who prepared and checked it, its date and revision, and the code edition.

From the settings ``prepared_by``, ``checked_by``, ``report_date`` and ``revision``
(docs/workbook.md) and the edition of ASCE 7 the anchorage applies. A key not
given is not shown; with none given there is no block at all. Nothing here reads
the clock: the date is the one the settings give, so the same inputs give the same
report.
"""
from __future__ import annotations

from assess.inventory.settings import Settings
from assess.report.sentences import text

#: The settings of the title block, in the order the block shows them, with their labels.
TITLE_SETTINGS = (
    ("prepared_by", "Prepared by"),
    ("checked_by", "Checked by"),
    ("report_date", "Date"),
    ("revision", "Revision"),
)


def title_block(settings: Settings, code_edition: str = "") -> dict:
    """The title block of the report: ``signatures`` (label, value) for the settings given, in
    :data:`TITLE_SETTINGS`'s order, ``code`` the code edition ('' when none applies), ``running`` the short
    text the page header repeats ("rev. B · 2026-11-26"; '' when neither is given).

    >>> title_block(Settings(prepared_by="A. Engineer", revision="B", checked_by=" "))["signatures"]
    [('Prepared by', 'A. Engineer'), ('Revision', 'B')]
    >>> title_block(Settings())
    {'signatures': [], 'code': '', 'running': ''}
    """
    given = {key: text(getattr(settings, key)).strip() for key, _ in TITLE_SETTINGS}
    signatures = [(label, given[key]) for key, label in TITLE_SETTINGS if given[key]]
    running = " · ".join(part for part in (f"rev. {given['revision']}" if given["revision"] else "",
                                           given["report_date"]) if part)
    return {"signatures": signatures, "code": text(code_edition).strip(), "running": running}
