"""Ctrl-C and a closed pipe as a command sees them, and exit codes that say what stopped it.

Ctrl-C anywhere exits 130 in one line ("interrupted; nothing was written", or
where the outputs were written if the folder was already swapped in); a reader
of the output that went away (``assess simulate --json | head``) exits 141, as
for any command stopped by a closed pipe.
"""
from __future__ import annotations

import contextlib
import os
import signal
import sys
from pathlib import Path

from assess.command.folders import write_atomically

#: 128 + the signal's number, as a shell reports a command a signal stopped.
EXIT_INTERRUPTED, EXIT_BROKEN_PIPE = 128 + signal.SIGINT, 128 + 13


class Interrupt:
    """Ctrl-C as the run sees it: whether it came, and whether it may stop the run now.

    The SIGINT handler records the interrupt before raising KeyboardInterrupt,
    so that an interrupt that a library swallows (an exception raised in a
    cffi callback while WeasyPrint draws the PDF is printed and dropped) or
    wraps (numba's threads turn it into a SystemError) is still seen. While
    the output folder is swapped in, it is only recorded, and acted on after.
    """

    received = False
    deferred = False
    written_to: Path | None = None
    unraisable_before = staticmethod(sys.__unraisablehook__)

    @classmethod
    def handler(cls, signum, frame):
        cls.received = True
        if not cls.deferred:
            raise KeyboardInterrupt

    @staticmethod
    def unraisable(unraisable):
        """An interrupt raised where Python can only print it (a weakref callback, a ``__del__``): recorded
        already, so said once by the run's exit (130), not as "Exception ignored in ..."."""
        if not (isinstance(unraisable.exc_value, KeyboardInterrupt) and Interrupt.received):
            Interrupt.unraisable_before(unraisable)

    @classmethod
    def stop_if_received(cls):
        if cls.received:
            raise KeyboardInterrupt


@contextlib.contextmanager
def sigint_recorded():
    """Install :meth:`Interrupt.handler` for the run (only the main thread may), then restore."""
    Interrupt.received, Interrupt.deferred, Interrupt.written_to = False, False, None
    try:
        previous = signal.signal(signal.SIGINT, Interrupt.handler)
    except ValueError:  # not the main thread: leave signals alone
        previous = None
    Interrupt.unraisable_before, sys.unraisablehook = sys.unraisablehook, Interrupt.unraisable
    try:
        yield
    finally:
        sys.unraisablehook = Interrupt.unraisable_before
        if previous is not None:
            signal.signal(signal.SIGINT, previous)


@contextlib.contextmanager
def held_back(out_dir: Path):
    """Swap an output folder in with Ctrl-C held back: an interrupt that came before stops the run
    here, one that comes during the swap is acted on after it (the folder then holds the outputs)."""
    Interrupt.stop_if_received()  # an interrupt swallowed while rendering stops the run here
    Interrupt.deferred = True
    try:
        yield
        Interrupt.written_to = Path(out_dir)
    finally:
        Interrupt.deferred = False
    Interrupt.stop_if_received()


def write_uninterrupted(files: dict[str, bytes], out_dir: Path) -> list[Path]:
    """:func:`assess.command.folders.write_atomically`, Ctrl-C held back until the folder is swapped in."""
    with held_back(out_dir):
        return write_atomically(files, out_dir)


def caused_by(error: BaseException, kind: type) -> bool:
    """Whether ``error`` is ``kind`` or was raised while handling one (``__cause__``/``__context__``)."""
    seen = set()
    while error is not None and id(error) not in seen:
        if isinstance(error, kind):
            return True
        seen.add(id(error))
        error = error.__cause__ or error.__context__
    return False


def interrupted() -> int:
    if Interrupt.written_to is not None:
        print(f"assess: interrupted after the outputs were written to {Interrupt.written_to}.", file=sys.stderr)
    else:
        print("assess: interrupted; nothing was written.", file=sys.stderr)
    return EXIT_INTERRUPTED


def reader_gone() -> int:
    """stdout's reader closed the pipe: send what is left to /dev/null (Python docs, 'Note on SIGPIPE')."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError):
        pass
    return EXIT_BROKEN_PIPE
