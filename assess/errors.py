"""Problems with the user's input, reported all at once.

Every reader collects :class:`Problem` objects instead of raising at the first
one, then raises a single :class:`InputError` holding all of them. The CLI
prints them and exits with code 2 (no traceback, nothing written).
"""
from __future__ import annotations

from dataclasses import dataclass, field

#: Longest message of one problem as printed (its location a quarter of it, its fix
#: half): they quote the user's paths and cells, which may be of any length (a
#: 40,000-character cell).
MAX_PROBLEM_CHARS = 1000
#: Problems printed; the rest are counted (a sheet of a million wrong rows is one mistake).
MAX_PROBLEMS_SHOWN = 50


def printable(text: str) -> str:
    r"""``text`` with every control character written as its escape (``\x1b``), so that text taken from
    a file (an effect name, a cell) cannot move the cursor, recolour or clear the user's terminal.

    >>> print(printable("slide" + chr(27) + "[2J" + chr(7) + " ok"))
    slide\x1b[2J\x07 ok
    """
    text = str(text)
    if text.isprintable():
        return text
    return "".join(c if c.isprintable() else repr(c)[1:-1] for c in text)


def capped(text: str, limit: int = MAX_PROBLEM_CHARS) -> str:
    """``text`` cut to ``limit`` characters, saying how much was left out, control characters escaped.

    >>> capped("x" * 30, 10)
    'xxxxxxxxxx… (20 more characters)'
    """
    text = printable(text)
    return text if len(text) <= limit else f"{text[:limit]}… ({len(text) - limit} more characters)"


@dataclass(frozen=True)
class Problem:
    """One thing wrong with the input, located as precisely as possible.

    ``row`` is the spreadsheet row number as the user sees it in Excel
    (header = row 1); ``cell`` is an Excel reference such as ``"F7"`` when
    known. ``fix`` says what the user should do.
    """

    file: str
    message: str
    fix: str = ""
    sheet: str | None = None
    row: int | None = None
    column: str | None = None
    cell: str | None = None

    def location(self) -> str:
        parts = [self.file]
        if self.sheet is not None:
            parts.append(f"sheet '{self.sheet}'")
        if self.cell is not None:
            parts.append(f"cell {self.cell}")
        elif self.row is not None:
            parts.append(f"row {self.row}")
        if self.column is not None:
            parts.append(f"column '{self.column}'")
        return ", ".join(parts)

    def __str__(self) -> str:
        text = f"{capped(self.location(), MAX_PROBLEM_CHARS // 4)}: {capped(self.message)}"
        if self.fix:
            text += f" Fix: {capped(self.fix, MAX_PROBLEM_CHARS // 2)}"
        return text


@dataclass
class InputError(Exception):
    """The input is wrong; ``problems`` lists everything found, in order."""

    problems: list[Problem] = field(default_factory=list)

    def __post_init__(self) -> None:
        super().__init__(str(self))

    def __str__(self) -> str:
        count = len(self.problems)
        head = f"{count} problem{'s' if count != 1 else ''} in the input:"
        lines = [head] + [f"  - {p}" for p in self.problems[:MAX_PROBLEMS_SHOWN]]
        if count > MAX_PROBLEMS_SHOWN:
            lines.append(f"  ... and {count - MAX_PROBLEMS_SHOWN} more; fix these first.")
        return "\n".join(lines)


def raise_if_any(problems: list[Problem]) -> None:
    """Raise :class:`InputError` when ``problems`` is not empty."""
    if problems:
        raise InputError(list(problems))
