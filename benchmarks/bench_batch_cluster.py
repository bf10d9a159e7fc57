"""assess batch of a portfolio on a loopback Dask cluster against one machine: seconds, CPU, same files.

Run: python benchmarks/bench_batch_cluster.py [--workers 2] [--copies 1] [--format html,pdf,xlsx]
                                              [--scheduler ADDRESS] [--keep DIR]

The portfolio: the sample portfolio's three buildings (inventories/portfolio/,
level 2in50, their hazard curve), the laboratory (lab.xlsx, 2in50), the
pharmacy (pharmacy.xlsx, DE) and the hospital (hospital.xlsx, its site and
building sheets, DE): six buildings, ``--copies`` times each (a copy is its
own building: its workbook copied under another name, every item's friction
(mu and its range) raised by 0.01 per copy so that no copy reuses another's cases). It is run
from a scratch copy of inventories/, first run (an empty cache) each time:

1. on this machine (``--jobs`` = the workers' threads);
2. with ``--scheduler``: a loopback cluster of ``--workers`` single-threaded
   workers (NUMBA_NUM_THREADS=1) started here, or the cluster at ADDRESS
   (its workers must see this scratch folder at the same path).

Prints the wall-clock seconds, the CPU seconds of this process and its
children, of the workers (their children, the PDF's second process,
included), the load average before and after, and whether every file of the
two output folders (the cache aside) is the same, byte for byte. Not a test.
"""
from __future__ import annotations

import argparse
import os
import resource
import shutil
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
#: (building, workbook under inventories/, level, hazard curve under inventories/ or "").
BUILDINGS = (("north-lab", "portfolio/north-lab.xlsx", "2in50", "portfolio/site-hazard.csv"),
             ("south-lab", "portfolio/south-lab.xlsx", "2in50", "portfolio/site-hazard.csv"),
             ("annex", "portfolio/annex.xlsx", "2in50", "portfolio/site-hazard.csv"),
             ("lab", "lab.xlsx", "2in50", ""),
             ("pharmacy", "pharmacy.xlsx", "DE", ""),
             ("hospital", "hospital.xlsx", "DE", ""))


def cpu_s() -> float:
    """CPU seconds of the calling process and its finished children."""
    total = 0.0
    for who in (resource.RUSAGE_SELF, resource.RUSAGE_CHILDREN):
        usage = resource.getrusage(who)
        total += usage.ru_utime + usage.ru_stime
    return total


def load() -> str:
    return " ".join(f"{x:.2f}" for x in os.getloadavg())


def make_portfolio(scratch: Path, copies: int) -> Path:
    """A scratch copy of inventories/ and its portfolio.xlsx of the buildings, ``copies`` times each."""
    import openpyxl

    folder = scratch / "inventories"
    shutil.copytree(ROOT / "inventories", folder)
    rows = []
    for copy in range(copies):
        for name, workbook, level, curve in BUILDINGS:
            if copy:
                source = folder / workbook
                workbook = str(Path(workbook).with_name(f"{source.stem}-{copy}.xlsx"))
                book = openpyxl.load_workbook(source)
                sheet = book["equipment"]
                header = [cell.value for cell in sheet[1]]
                columns = [k for k, name in enumerate(header) if name in ("mu", "mu_static", "mu_low", "mu_high")]
                for row in sheet.iter_rows(min_row=2):
                    for column in columns:
                        if isinstance(row[column].value, (int, float)):
                            row[column].value = round(row[column].value + 0.01 * copy, 3)
                book.save(folder / workbook)
            rows.append((f"{name}-{copy}" if copy else name, workbook, level, curve))
    book = openpyxl.Workbook()
    sheet = book.active
    sheet.title = "buildings"
    sheet.append(["building", "workbook", "level", "oq_hazard"])
    for row in rows:
        sheet.append(list(row))
    book.save(folder / "portfolio.xlsx")
    return folder / "portfolio.xlsx"


def files(out: Path) -> dict:
    return {p.relative_to(out).as_posix(): p.read_bytes() for p in sorted(out.rglob("*"))
            if p.is_file() and ".cache" not in p.relative_to(out).parts}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--copies", type=int, default=1)
    parser.add_argument("--format", default="html,pdf,xlsx")
    parser.add_argument("--scheduler", metavar="ADDRESS")
    parser.add_argument("--keep", metavar="DIR", help="leave the scratch folder here")
    args = parser.parse_args()

    from assess import cli

    scratch = Path(args.keep) if args.keep else Path(tempfile.mkdtemp(prefix="bench-batch-cluster-"))
    scratch.mkdir(parents=True, exist_ok=True)
    portfolio = make_portfolio(scratch, args.copies)
    print(f"load average before: {load()} ({os.cpu_count()} cores); "
          f"{len(BUILDINGS) * args.copies} buildings, formats {args.format}", flush=True)
    cluster = None
    address = args.scheduler
    if address is None:
        from distributed import LocalCluster
        cluster = LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True, host="127.0.0.1",
                               dashboard_address=None, env={"NUMBA_NUM_THREADS": "1"}, silence_logs=40)
        address = cluster.scheduler_address
    from distributed import Client
    client = Client(address, set_as_default=False)
    threads = sum(client.nthreads().values())
    try:
        runs = {}
        for label, extra in ((f"this machine (--jobs {threads})", ["--jobs", str(threads)]),
                             (f"cluster ({len(client.nthreads())} workers, {threads} threads)",
                              ["--scheduler", address])):
            out = scratch / ("out-cluster" if "--scheduler" in extra else "out-here")
            workers_before = sum(client.run(cpu_s).values())
            start, here_before = time.perf_counter(), cpu_s()
            code = cli.main(["batch", str(portfolio), "--out", str(out), "--format", args.format, "--quiet", *extra])
            seconds = time.perf_counter() - start
            here = cpu_s() - here_before
            workers = sum(client.run(cpu_s).values()) - workers_before
            if code != 0:
                raise SystemExit(f"{label}: assess batch exited {code}")
            runs[label] = files(out)
            print(f"{label}: {seconds:.1f} s, {here:.1f} CPU s here (with its children), "
                  f"{workers:.1f} CPU s in the workers", flush=True)
        first, second = runs.values()
        differing = sorted(name for name in set(first) | set(second) if first.get(name) != second.get(name))
        print(f"files: {len(first)}, identical: {'yes' if not differing else 'NO: ' + ', '.join(differing[:10])}")
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
        if not args.keep:
            shutil.rmtree(scratch, ignore_errors=True)
    print(f"load average after: {load()}")
    sys.stdout.flush()
    os._exit(0)


if __name__ == "__main__":
    main()
