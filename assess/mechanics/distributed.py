"""The engine's cases on a Dask distributed cluster (``assess --scheduler ADDRESS``).

:class:`DaskRunner` is a runner of :mod:`assess.mechanics.gateway`: it cuts
a batch of cases (of any kind), ordered by record, into tasks of
:data:`CASES_PER_TASK` (so the tasks depend on the cases alone, never on how
many workers there are), sends each record to the cluster once, runs
:func:`assess.mechanics.gateway.run_cases` on the workers and puts the
results back in case order. A case's result depends only on its block and its
record (the kernels are deterministic and every synthetic motion is seeded
per motion before it gets here), so the numbers are those of a run on this
machine, bit for bit, wherever and in whatever order the tasks ran.

The workers need the same version of ``assess`` installed (checked when
connecting). Dask [1] was chosen because it is the Python scientific stack's
own scheduler: workers are plain Python processes that import the package,
numpy arrays travel without copies through its serialisation, and
dask-jobqueue [2] starts the same workers as SLURM, PBS, SGE or LSF jobs.

References
----------
.. [1] Rocklin, M. (2015). Dask: Parallel computation with blocked algorithms
   and task scheduling. Proc. 14th Python in Science Conf., 130-136.
   doi:10.25080/Majora-7b98e3ed-013
.. [2] dask-jobqueue: https://jobqueue.dask.org
"""
from __future__ import annotations

import asyncio
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

import assess
from assess.errors import InputError, Problem

from .gateway import RESPONSE, CasePeaks, Cases, Progress, Result, RunnerBase, run_cases

#: Cases per task: about a tenth of a second to a second of work on one core, so that small jobs
#: still spread over the workers and scheduling (about a millisecond a task) costs little.
CASES_PER_TASK = 256
#: Seconds allowed to reach the scheduler and find a worker, by default.
CONNECT_TIMEOUT_S = 10.0


def case_tasks(record_index, cases_per_task: int = CASES_PER_TASK) -> list[np.ndarray]:
    """The cases of each task: all cases ordered by record (then by case), cut every ``cases_per_task``.

    Depends on the cases alone (never on the cluster), so the same cases
    always make the same tasks; a task holds the cases of one record or of a
    few consecutive ones.

    >>> [t.tolist() for t in case_tasks([1, 0, 1, 1, 0], cases_per_task=2)]
    [[1, 4], [0, 2], [3]]
    """
    record_index = np.asarray(record_index, dtype=np.int64)
    if cases_per_task < 1:
        raise ValueError("cases_per_task must be 1 or more")
    order = np.argsort(record_index, kind="stable")
    return [order[start:start + cases_per_task] for start in range(0, order.size, cases_per_task)]


def _run_task(cases: Cases, records_g: list) -> Result:
    """One task on a worker: its cases under its records (sent apart, once per record), through the gateway."""
    return run_cases(replace(cases, records_g=records_g))


def _worker_version():
    return assess.__version__


def _probe(address: str, timeout_s: float) -> None:
    """Ask ``address`` who it is, within ``timeout_s``.

    Raises OSError, TimeoutError or ValueError unless a Dask scheduler answers
    (a Client that fails to start waits long and complains again at exit).
    """
    from distributed.comm import connect  # the optional cluster extra

    async def knock():
        comm = await connect(address, timeout=timeout_s)
        try:
            await comm.write({"op": "identity", "reply": True})
            return await comm.read()
        finally:
            comm.abort()

    try:
        reply = asyncio.run(asyncio.wait_for(knock(), timeout_s))
    except asyncio.TimeoutError:
        raise TimeoutError(f"something answers there, but not as a Dask scheduler within {timeout_s:g} s") from None
    except (OSError, TimeoutError, ValueError, TypeError):
        raise
    except Exception as error:  # noqa: BLE001 - whatever a stranger answered
        raise OSError(f"something answers there, but not as a Dask scheduler ({type(error).__name__})") from None
    if not (isinstance(reply, dict) and reply.get("type") == "Scheduler"):
        raise ValueError("something answers there, but not as a Dask scheduler")


def _scheduler_problem(address: str, message: str, fix: str) -> InputError:
    return InputError([Problem(file="--scheduler", message=f"{address!r}: {message}", fix=fix)])


@dataclass
class DaskRunner(RunnerBase):
    """Run the engine's cases on the Dask cluster that ``client`` is connected to.

    Build it with :meth:`connect`. ``cases_simulated`` counts the ``peaks``
    cases this runner simulated, ``runs_simulated`` every run by kind;
    ``tasks_run`` the tasks it sent.
    """

    client: Any
    cases_per_task: int = CASES_PER_TASK
    cases_simulated: int = field(default=0)
    tasks_run: int = field(default=0)
    runs_simulated: dict = field(default_factory=dict)

    @classmethod
    def connect(cls, address: str, *, timeout_s: float = CONNECT_TIMEOUT_S,
                cases_per_task: int = CASES_PER_TASK) -> "DaskRunner":
        """Connect to the scheduler at ``address`` (``tcp://host:8786``, ``host:8786``, ...).

        Raises :class:`~assess.errors.InputError` (the CLI's exit 2) within
        about ``timeout_s`` seconds if the address is not one, nothing answers
        there, no worker has joined, or the workers cannot run this version of
        ``assess``.
        """
        from distributed import Client  # the optional cluster extra

        fix = ("give the address the scheduler printed when it started (e.g. tcp://10.0.0.5:8786, "
               "'dask scheduler' prints it), check that it is running and reachable from this machine, "
               "or leave --scheduler out to run on this machine's cores")
        text = str(address).strip()
        if not text:
            raise _scheduler_problem(text, "is empty", fix)
        try:
            _probe(text, timeout_s)
            client = Client(text, timeout=f"{timeout_s}s", set_as_default=False)
        except (OSError, TimeoutError, ValueError, TypeError) as error:
            reason = " ".join(str(error).split())[:300] or type(error).__name__
            raise _scheduler_problem(text, f"no Dask scheduler could be reached there ({reason})", fix) from None
        try:
            try:
                client.wait_for_workers(1, timeout=timeout_s)
            except (TimeoutError, OSError):
                raise _scheduler_problem(
                    text, f"the scheduler has no worker after {timeout_s:g} s",
                    f"start workers ('dask worker {text}'), or wait until the cluster's jobs have "
                    "started, then run again") from None
            versions = set(client.run(_worker_version).values())
            if versions != {assess.__version__}:
                raise _scheduler_problem(
                    text, f"its workers run assess {', '.join(sorted(versions))}, this is {assess.__version__}",
                    "install the same version of assess on the workers")
        except InputError:
            client.close()
            raise
        except Exception as error:  # a worker that cannot import assess fails in deserialisation
            client.close()
            reason = " ".join(str(error).split())[:300] or type(error).__name__
            raise _scheduler_problem(text, f"its workers cannot run assess ({reason})",
                                     "install assess (the same version) where the workers run") from None
        return cls(client=client, cases_per_task=cases_per_task)

    def close(self) -> None:
        """Disconnect from the cluster (the cluster itself keeps running)."""
        self.client.close()

    def run(self, cases: Cases, *, progress: Progress = None) -> Result:
        """As :func:`assess.mechanics.gateway.run_cases`, on the cluster's workers."""
        from distributed import as_completed  # the optional cluster extra

        n = len(cases)
        tasks = case_tasks(cases.record_index, self.cases_per_task)
        used = cases.records_used()
        # unique keys per batch (hash=False): a record sent again by the next batch is not the one being released
        scattered = self.client.scatter([np.asarray(cases.records_g[j], dtype=float) for j in used], hash=False)
        records = dict(zip(used.tolist(), scattered))
        futures = {}
        for number, task in enumerate(tasks):
            mine = cases.records_used(task).tolist()
            part = cases.subset(task, records_g=[None] * len(mine))  # the records travel as the cluster's copies
            futures[self.client.submit(_run_task, part, [records[j] for j in mine], pure=False)] = number
        parts: list = [None] * len(tasks)
        done = 0
        try:
            for future in as_completed(futures, loop=self.client.loop):
                number = futures[future]
                parts[number] = future.result()
                done += tasks[number].size
                if progress is not None:
                    progress(done, n)
        finally:
            for future in futures:
                future.release()
            for future in records.values():
                future.release()
        self._count(cases, n)
        self.tasks_run += len(tasks)
        return _assembled(tasks, parts, n, cases.kind)


def _assembled(tasks, parts, n, kind) -> Result:
    """The tasks' results put back in case order."""
    order = np.concatenate(tasks) if tasks else np.zeros(0, dtype=np.int64)
    if kind == RESPONSE:
        responses: list = [None] * n
        for k, response in zip(order.tolist(), [r for part in parts for r in part]):
            responses[k] = response
        return responses
    fields = {}
    for name, empty in (("sliding_max_m", np.zeros(0)), ("sliding_residual_m", np.zeros(0)),
                        ("theta_max_over_alpha", np.zeros(0)), ("uplift", np.zeros(0, dtype=bool)),
                        ("overturned", np.zeros(0, dtype=bool)), ("mode", np.zeros(0, dtype=str)),
                        ("solver", np.zeros(0, dtype=str))):
        values = np.concatenate([getattr(p, name) for p in parts]) if parts else empty
        out = np.empty(n, dtype=values.dtype)
        out[order] = values
        fields[name] = out
    return CasePeaks(**fields)
