"""``--oq-site`` as a user types it, before argparse sees it (standard library only: the command line
reads it before importing the core).

A negative longitude (``--oq-site -0.2,-0.3``) would be taken by argparse for an option, and a space
after the comma (``--oq-site -0.2, -0.3``) splits the pair into two arguments: :func:`joined_oq_site`
makes either one ``--oq-site=LON,LAT`` (:func:`assess.command.job.oq_site` then reads it).
"""
from __future__ import annotations

import re

_NUMBER_START = re.compile(r"^[-+]?(\d|\.\d)")


def joined_oq_site(argv: list[str]) -> list[str]:
    """``argv`` with ``--oq-site LON,LAT`` given as one ``--oq-site=LON,LAT``, so that a negative longitude
    (``--oq-site -0.2,-0.3``) is not taken for an option, and ``--oq-site -0.2, -0.3`` (split by the
    shell at the space) is one value.

    >>> joined_oq_site(["w.xlsx", "--oq-site", "-0.2,", "-0.3", "--quiet"])
    ['w.xlsx', '--oq-site=-0.2,-0.3', '--quiet']
    """
    out, k = [], 0
    while k < len(argv):
        token = argv[k]
        value = None
        if token == "--oq-site" and k + 1 < len(argv) and _NUMBER_START.match(argv[k + 1]):
            value, k = argv[k + 1], k + 2
        elif token.startswith("--oq-site="):
            value, k = token[len("--oq-site="):], k + 1
        if value is None:
            out.append(token)
            k += 1
            continue
        while k < len(argv) and (value.rstrip().endswith(",") or argv[k].startswith(",")) \
                and _NUMBER_START.match(argv[k].lstrip(",").strip()):
            value, k = value.rstrip() + argv[k], k + 1
        out.append(f"--oq-site={value}")
    return out
