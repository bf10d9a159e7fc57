"""The ``assess`` command (its console script) and ``python -m assess``: :func:`run`."""
import atexit
import os
import sys

from assess import startup
from assess.cli import main


def run() -> None:
    """:func:`assess.cli.main`, then the process ends at once.

    A run has imported pandas, numba, matplotlib and WeasyPrint; letting the interpreter take them apart
    one by one costs about half a second after the last file is written. So the exit handlers run (they
    end the helper processes, :mod:`assess.mechanics.warmup` and the PDF's), the streams are flushed and
    the process ends with :func:`os._exit`, its exit code that of :func:`~assess.cli.main`. ``--help`` and
    a wrong option leave through argparse's ``SystemExit`` as before. The garbage collector is set for a
    process that ends with its run (:func:`assess.startup.as_command`).
    """
    startup.as_command()
    code = main()
    atexit._run_exitfuncs()  # what the interpreter runs first on leaving; os._exit skips only the rest
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (OSError, ValueError):  # the reader went away or the stream is closed: nothing to save
            pass
    os._exit(code)


if __name__ == "__main__":
    run()
