"""Output folders written so that a failed run leaves nothing half-written.

Everything is first produced in memory and written into a temporary folder
next to the output folder; that folder then takes the output folder's place
in one rename (:func:`write_atomically`). A run that fails leaves the previous
folder as it was; one that succeeds leaves exactly its own files, no stale
``report.pdf`` of an earlier ``--format html,pdf`` run. Only the standard
library: the command line checks a folder before importing the core.
"""
from __future__ import annotations

import contextlib
import errno
import os
import shutil
import tempfile
from pathlib import Path

from assess.errors import InputError, Problem

#: Everything assess writes into an output folder. A folder holding anything
#: else is not swapped (it would be lost): the user is asked for another one.
OUTPUT_NAMES = frozenset({
    "summary.csv", "motions.csv", "work_orders.csv", "comparison.csv", "summary.xlsx", "report.html", "report.pdf",
    "calibration.json", "calibration_tests.csv", "fragility", "ground_motions.csv", "spectrum.csv", "floors.csv",
    ".DS_Store", "Thumbs.db", "desktop.ini",  # what a file browser leaves in a folder it has shown
})
def check_output_folder(out_dir: Path) -> None:
    """Refuse an output folder that :func:`write_atomically` may not replace as a whole.

    It may be new, empty, or hold only what assess writes (:data:`OUTPUT_NAMES`):
    replacing the folder replaces everything in it, so ``--out .`` or a folder
    of the user's own documents is refused before anything runs.
    """
    out_dir = Path(out_dir)
    if existing_folder(out_dir, "run"):
        names = sorted(entry.name for entry in out_dir.iterdir())
        refuse_open_office_files(out_dir, names)
        refuse_foreign_files(out_dir, [name for name in names if name not in OUTPUT_NAMES])


#: The lock file Excel (and LibreOffice, ``.~lock.<name>#``) keeps beside a workbook it has open.
OFFICE_LOCK_PREFIXES = ("~$", ".~lock.")


def office_lock_owner(name: str) -> str | None:
    """The output file an office program holds open, from the name of its lock file; None otherwise.

    >>> office_lock_owner("~$summary.xlsx"), office_lock_owner(".~lock.summary.xlsx#"), office_lock_owner("notes.txt")
    ('summary.xlsx', 'summary.xlsx', None)
    """
    for prefix in OFFICE_LOCK_PREFIXES:
        if name.startswith(prefix):
            owner = name[len(prefix):].rstrip("#")
            # Excel keeps the name's last characters only: "~$mmary.xlsx" for a long name
            return next((known for known in sorted(OUTPUT_NAMES) if known.endswith(owner) and owner), owner)
    return None


def refuse_open_office_files(out_dir: Path, names: list[str]) -> None:
    """Exit 2 when an output file is open in Excel or LibreOffice (its lock file is in the folder): the
    folder cannot be replaced while it is, and the lock file is not one of ours."""
    open_files = sorted({owner for owner in map(office_lock_owner, names) if owner})
    if open_files:
        shown = ", ".join(open_files)
        raise InputError([Problem(
            file=str(out_dir), message=f"{shown} in the output folder is open in Excel (or another spreadsheet "
            f"program: its lock file is there), so assess cannot replace the folder.",
            fix=f"close {shown} in Excel, then run again; or give --out another folder.")])


def existing_folder(out_dir: Path, run: str) -> bool:
    """Whether the output folder exists (False: it will be made); one that is a file is refused, naming
    what ``--out`` takes instead (a new folder, or that of an earlier ``run``)."""
    if not out_dir.exists() and not out_dir.is_symlink():
        return False
    if not out_dir.is_dir():
        raise InputError([Problem(file=str(out_dir), message="the output folder is a file, not a folder.",
                                  fix=f"give --out a new folder, or the folder of an earlier {run}.")])
    return True


def refuse_foreign_files(out_dir: Path, foreign: list[str], command: str = "assess", run: str = "run") -> None:
    """Exit 2 (``InputError``) naming the files in ``out_dir`` that ``command`` did not write, if any."""
    if foreign:
        shown = ", ".join(name[:60] for name in foreign[:5]) + (f" and {len(foreign) - 5} more"
                                                                 if len(foreign) > 5 else "")
        raise InputError([Problem(
            file=str(out_dir), message=f"the output folder holds files {command} did not write ({shown}); "
            f"{command} replaces its output folder as a whole, so these would be lost.",
            fix=f"give --out a new or empty folder, or the folder of an earlier {run}.")])


#: Errors of the machine while writing (not of assess, not of the input), in words.
MACHINE_ERRORS = {
    errno.ENOSPC: "the disk is full (no space left on the device)",
    errno.EDQUOT: "your disk quota is used up",
    errno.EROFS: "the file system is read-only",
    errno.EACCES: "you may not write there (permission denied)",
    errno.EPERM: "you may not write there (operation not permitted)",
    errno.EFBIG: "a file is too large for the file system",
}


def machine_refusal(error: BaseException, folder) -> InputError | None:
    """The exit-2 refusal for ``error`` if the machine refused to write into ``folder`` (a full disk, a quota,
    a read-only file system, no permission); None for anything else (then it is a bug).

    Names the folder and says the previous output is left as it was (every
    writer here writes beside it and swaps it in only when complete).

    >>> print(machine_refusal(OSError(errno.ENOSPC, "No space left on device"),
    ...                       "reports/lab").problems[0])  # doctest: +NORMALIZE_WHITESPACE
    reports/lab: the output could not be written: the disk is full (no space left on the device). The previous output in
    this folder, if any, is left as it was. Fix: free space on that disk (or give --out a folder on another disk), then
    run again.
    """
    if not isinstance(error, OSError) or error.errno not in MACHINE_ERRORS:
        return None
    return InputError([Problem(
        file=str(folder), message=f"the output could not be written: {MACHINE_ERRORS[error.errno]}. The previous "
        "output in this folder, if any, is left as it was.",
        fix=("free space on that disk (or give --out a folder on another disk), then run again."
             if error.errno in (errno.ENOSPC, errno.EDQUOT, errno.EFBIG) else
             "give --out a folder you may write to, then run again."))])


@contextlib.contextmanager
def machine_errors(folder):
    """Turn the machine's refusal to write (:func:`machine_refusal`) into an exit-2 :class:`InputError`."""
    try:
        yield
    except OSError as error:
        refusal = machine_refusal(error, folder)
        if refusal is None:
            raise
        raise refusal from None


def write_atomically(files: dict[str, bytes], out_dir: Path) -> list[Path]:
    """Make ``out_dir`` hold exactly ``files``: all of them, or (on failure) the folder as it was.

    The files are written into a temporary sibling folder, which then takes
    ``out_dir``'s place: the old folder is renamed aside, the new one renamed
    in, the old one deleted. A failure (or Ctrl-C) before the second rename
    renames the old folder back. Only a crash of the machine between the two
    renames leaves the old folder under its temporary name
    (``.<name>-old-...`` beside it) instead of ``out_dir``. ``out_dir`` must
    pass :func:`check_output_folder`. Names may contain ``/`` (a subfolder).
    """
    out_dir = Path(out_dir)
    check_output_folder(out_dir)
    with machine_errors(out_dir):
        return _write_atomically(files, out_dir)


def _write_atomically(files: dict[str, bytes], out_dir: Path) -> list[Path]:
    if out_dir.is_symlink():
        out_dir = out_dir.resolve()
    out_dir.parent.mkdir(parents=True, exist_ok=True)
    staging = Path(tempfile.mkdtemp(prefix=f".{out_dir.name}-new-", dir=out_dir.parent))
    aside = None
    try:
        os.chmod(staging, folder_mode(out_dir))
        write_files(staging, files)
        aside = swap_folder(staging, out_dir)
        staging = None
        return [out_dir / name for name in files]
    finally:
        for leftover in (staging, aside):
            if leftover is not None:
                shutil.rmtree(leftover, ignore_errors=True)


def swap_folder(staging: Path, out_dir: Path) -> Path | None:
    """Put the folder ``staging`` in ``out_dir``'s place, or leave ``out_dir`` as it was.

    The old folder is renamed aside, the new one renamed in; if the second
    rename fails, the old folder is renamed back and the error raised. Returns
    where the old folder now lies (the caller deletes it), or None if there was none.
    """
    aside = None
    if out_dir.exists():
        aside = Path(tempfile.mkdtemp(prefix=f".{out_dir.name}-old-", dir=out_dir.parent))
        try:
            os.replace(out_dir, aside)  # aside is an empty folder: rename replaces it
        except BaseException:
            shutil.rmtree(aside, ignore_errors=True)
            raise
    try:
        os.replace(staging, out_dir)
    except BaseException:
        if aside is not None:
            os.replace(aside, out_dir)
        raise
    return aside


def write_files(folder: Path, files: dict[str, bytes]) -> None:
    """Write ``files`` (name -> bytes; a name may contain ``/``) into ``folder``, making subfolders."""
    for name, content in files.items():
        target = Path(folder) / name
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_bytes(content)


def folder_mode(out_dir: Path) -> int:
    """Permissions of the new output folder: the old one's, else what the umask gives a new folder."""
    if out_dir.is_dir():
        return out_dir.stat().st_mode & 0o7777
    return 0o777 & ~_umask()


def write_file_atomically(path: Path, content: bytes) -> Path:
    """Write one file (``assess simulate --history``): a temporary sibling renamed over ``path``.

    Other files in its folder are left alone.
    """
    path = Path(path)
    with machine_errors(path.parent):
        return _write_file_atomically(path, content)


def _write_file_atomically(path: Path, content: bytes) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    handle, temporary = tempfile.mkstemp(prefix=f".{path.name}-", dir=path.parent)
    try:
        with os.fdopen(handle, "wb") as stream:
            stream.write(content)
        os.chmod(temporary, 0o666 & ~_umask())
        os.replace(temporary, path)
        temporary = None
        return path
    finally:
        if temporary is not None:
            with contextlib.suppress(OSError):
                os.unlink(temporary)


def _umask() -> int:
    """The process's umask (read by setting it, then put back)."""
    umask = os.umask(0)
    os.umask(umask)
    return umask
