"""The ``assess`` command (its console script) and ``python -m assess``: :func:`run`."""
import sys

from assess.cli import main


def run() -> None:
    """:func:`assess.cli.main`; the process's exit code is its return value."""
    sys.exit(main())


if __name__ == "__main__":
    run()
