"""The engine's cases on a Dask distributed cluster (``assess --scheduler ADDRESS``).

:class:`DaskRunner` is a runner of :mod:`assess.mechanics.gateway`: it cuts
a batch of cases (of any kind) into a few tasks per worker thread, of equal
cost (:func:`cost_tasks`: every task holds the same share of every record's
cases, so the same number of time steps), sends the batch's records and
distinct blocks (as a float table, :func:`block_table`) to every worker once,
ships each task as arrays (block rows, record indices), runs
:func:`assess.mechanics.gateway.run_cases` on the workers and puts the results
(arrays) back in case order. A case's result depends only on its block and
its record (the kernels are deterministic, every case is computed alone, and
every synthetic motion is seeded per motion before it gets here), so the
numbers are those of a run on this machine, bit for bit, however the cases
were cut and wherever and in whatever order the tasks ran.

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

import contextlib
import gc
import logging
import pickle
import struct
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

import assess
from assess.errors import InputError, Problem

from .block import Block
from .engine import BlockOnInterface, SlidingInterface
from .gateway import RESPONSE, CasePeaks, Cases, Progress, Result, RunnerBase, run_cases

#: Tasks per worker thread aimed at: a few large tasks, of equal cost, so that a worker slowed by its machine
#: leaves its last task to the others while scheduling (about a millisecond a task) costs nothing.
TASKS_PER_THREAD = 4
#: Least work in one task [block-steps: cases x time steps]: about a tenth of a second on one core, so that a
#: small batch is not cut into tasks that cost more to send than to run.
MIN_TASK_STEPS = 2_000_000
#: Seconds allowed to reach the scheduler and find a worker, by default.
CONNECT_TIMEOUT_S = 10.0
#: Columns of a block table (:func:`block_table`): the fields of a Block, whether it is a BlockOnInterface
#: (1) or not (0), then its sliding interface's fields; NaN where a field is None.
BLOCK_COLUMNS = ("half_width_m", "cg_height_m", "height_m", "mu", "mu_static", "restitution", "foot_inset_m",
                 "on_interface", "low_speed_factor", "rate_s_m", "yield_displacement_m")


def case_steps(cases: Cases) -> np.ndarray:
    """Time steps of each case [-]: its record's samples and the tail after it (the cost of a run, per block).

    >>> c = Cases.peaks([Block(0.2, 0.5, 1.0, 0.3)] * 2, [np.zeros(100), np.zeros(50)], [0.01, 0.02], [0, 1],
    ...                 tail_s=1.0)
    >>> case_steps(c).tolist()
    [200, 100]
    """
    steps = np.array([len(r) + int(np.ceil(cases.tail_s / dt)) for r, dt in zip(cases.records_g, cases.dt_s)],
                     dtype=np.int64)
    return steps[cases.record_index] if len(cases) else np.zeros(0, dtype=np.int64)


def cost_tasks(record_index, steps, n_tasks: int) -> list[np.ndarray]:
    """The cases of each of ``n_tasks`` tasks of equal cost: all cases ordered by record, dealt in turn.

    Every task takes every ``n_tasks``-th case of that order, so each holds
    the same share (to one case) of every record's cases and of the blocks
    along them: the same number of time steps (``steps``, per case) to one
    case, and a mix of sliding and rocking blocks like the batch's. A task's
    cases stay in record order (the sliding kernel runs a record at a time).

    >>> [t.tolist() for t in cost_tasks([1, 0, 1, 1, 0], np.ones(5), 2)]
    [[1, 0, 3], [4, 2]]
    """
    record_index = np.asarray(record_index, dtype=np.int64)
    if n_tasks < 1:
        raise ValueError("n_tasks must be 1 or more")
    order = np.argsort(record_index, kind="stable")
    tasks = [order[t::n_tasks] for t in range(min(n_tasks, order.size))]
    return tasks


def task_count(total_steps: int, n_cases: int, threads: int, *, tasks_per_thread: int = TASKS_PER_THREAD,
               min_task_steps: int = MIN_TASK_STEPS) -> int:
    """How many tasks a batch is cut into: ``tasks_per_thread`` per worker thread, each worth at least
    ``min_task_steps`` block-steps, never more than the cases.

    >>> task_count(360_000 * 4_000, 360_000, 16), task_count(1_000_000, 500, 16), task_count(0, 0, 4)
    (64, 1, 1)
    """
    by_cost = max(1, int(total_steps) // max(1, int(min_task_steps)))
    return max(1, min(int(threads) * int(tasks_per_thread), by_cost, int(n_cases)))


def block_table(blocks) -> tuple[np.ndarray, np.ndarray] | None:
    """The distinct blocks of ``blocks`` as a float table (:data:`BLOCK_COLUMNS`) and each block's row.

    None when a block is neither a :class:`~assess.mechanics.block.Block` nor a
    :class:`~assess.mechanics.engine.BlockOnInterface` (it travels as itself).
    A block given as the same object, or with the same fields, takes one row.

    >>> table, rows = block_table([Block(0.2, 0.5, 1.0, 0.3)] * 3 + [Block(0.2, 0.5, 1.0, 0.4)])
    >>> table.shape, rows.tolist()
    ((2, 11), [0, 0, 0, 1])
    """
    by_id: dict = {}
    by_fields: dict = {}
    rows = np.empty(len(blocks), dtype=np.int64)
    table: list = []
    for k, block in enumerate(blocks):
        row = by_id.get(id(block))
        if row is None:
            fields = _block_fields(block)
            if fields is None:
                return None
            row = by_fields.setdefault(fields, len(table))
            if row == len(table):
                table.append(fields)
            by_id[id(block)] = row
        rows[k] = row
    nan = float("nan")
    table = [[nan if v is None else float(v) for v in fields] for fields in table]
    return np.array(table, dtype=float).reshape(-1, len(BLOCK_COLUMNS)), rows


def _block_fields(block) -> tuple | None:
    """A block's fields in the order of :data:`BLOCK_COLUMNS` (None where a field is None), or None."""
    kind = type(block)
    if kind is Block:
        interface, on = None, 0.0
    elif kind is BlockOnInterface:
        interface, on = block.interface, 1.0
    else:
        return None
    laws = (None, None, None) if interface is None else \
        (interface.low_speed_factor, interface.rate_s_m, interface.yield_displacement_m)
    return (block.half_width_m, block.cg_height_m, block.height_m, block.mu, block.mu_static, block.restitution,
            block.foot_inset_m, on) + laws


def blocks_from_table(table: np.ndarray) -> list:
    """The blocks of a :func:`block_table`'s rows, field for field (the inverse of :func:`block_table`)."""
    blocks = []
    for row in np.asarray(table, dtype=float).tolist():
        value = [None if v != v else v for v in row]  # NaN: a field left None
        fields = dict(zip(BLOCK_COLUMNS[:7], value[:7]))
        if row[7] == 0.0:
            blocks.append(Block(**fields))
            continue
        laws = value[8:]
        interface = None if all(v is None for v in laws) else SlidingInterface(*laws)
        blocks.append(BlockOnInterface(**fields, interface=interface))
    return blocks


@dataclass(frozen=True)
class _Part:
    """One task's cases as arrays: each case's block (a row of the batch's table, or the block itself when
    the batch has no table) and record(s) (indices into the batch's records, sent once per worker)."""

    kind: str
    rows: np.ndarray
    blocks: Any
    record_index: np.ndarray
    record_index_2: Any
    tail_s: float
    history: bool
    solver: str


def _run_part(shared, part: _Part):
    """One task on a worker: its cases rebuilt from arrays, run by the gateway; peaks returned as arrays."""
    records_g, dt_s, table = shared
    if table is None:
        blocks = part.blocks
    else:
        used, inverse = np.unique(part.rows, return_inverse=True)
        built = blocks_from_table(table[used])
        blocks = [built[i] for i in inverse.tolist()]
    result = run_cases(Cases(part.kind, blocks, records_g, dt_s, part.record_index, part.record_index_2,
                             tail_s=part.tail_s, history=part.history, solver=part.solver))
    if part.kind == RESPONSE:
        return result
    return {name: _coded(getattr(result, name)) if name in _TEXT else getattr(result, name) for name in _FIELDS}


_FIELDS = ("sliding_max_m", "sliding_residual_m", "theta_max_over_alpha", "uplift", "overturned", "mode", "solver")
_TEXT = ("mode", "solver")


def _coded(text: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """A column of a few distinct words as (words, one small code per case)."""
    words, codes = np.unique(text, return_inverse=True)
    return words, codes.astype(np.uint8 if words.size < 256 else np.int64)


def _decoded(coded) -> np.ndarray:
    words, codes = coded
    return words[codes]


def _worker_version():
    return assess.__version__


#: Largest answer [bytes] the connection check reads from the address: a scheduler's identity is a few kB.
MAX_PROBE_REPLY_BYTES = 1 << 20
#: Address schemes of a scheduler this runner connects to: plain TCP, or TCP with TLS.
SCHEMES = ("tcp", "tls")
_FRAME_COUNT = struct.Struct("<Q")


_OBJECTS = "it answers with serialised Python objects (which a connection check never opens)"


class NotAScheduler(ValueError):
    """What answers at the address is not a Dask scheduler (the message says why)."""


def scheduler_security(address: str, *, ca_file=None, cert=None, key=None):
    """Dask's security settings for ``address``: TLS from the files given, else from Dask's configuration.

    ``tls://`` needs a certificate authority and this client's certificate
    (Dask's TLS authenticates both sides): ``ca_file``, ``cert`` and ``key``
    (PEM files) or Dask's ``distributed.comm.tls.ca-file``,
    ``distributed.comm.tls.client.cert`` and ``.key`` settings. Returns a
    ``distributed.Security``. Raises :class:`~assess.errors.InputError` when
    they are missing, unreadable, or given for a ``tcp://`` address.
    """
    from distributed import Security

    scheme = _scheme(address)
    given = {name: value for name, value in (("tls_ca_file", ca_file), ("tls_client_cert", cert),
                                             ("tls_client_key", key)) if value is not None}
    given = {name: str(value) for name, value in given.items()}
    if given and scheme != "tls":
        raise _scheduler_problem(address, "certificates are given (--tls-*) but the address is not tls://",
                                 "give the scheduler's tls:// address, or leave the --tls-* options out")
    for option, path in given.items():
        if not Path(path).is_file():
            raise _scheduler_problem(address, f"the {_TLS_OPTIONS[option]} file {str(path)[:200]!r} does not exist",
                                     "give the PEM file's path")
    security = Security(**given, require_encryption=True) if given else Security()
    if scheme == "tls":
        try:
            context = security.get_connection_args("client")["ssl_context"]
        except (OSError, ValueError) as error:  # ssl.SSLError is an OSError
            raise _scheduler_problem(address, f"the TLS certificates cannot be used ({_reason(error)})",
                                     "give the certificate authority, this client's certificate and its key "
                                     "as PEM files (--tls-ca-file, --tls-cert, --tls-key)") from None
        if context is None:
            raise _scheduler_problem(address, "a tls:// scheduler needs certificates, and none are given",
                                     "give --tls-ca-file, --tls-cert and --tls-key (PEM files), or set Dask's "
                                     "distributed.comm.tls.ca-file, .client.cert and .client.key")
    return security


_TLS_OPTIONS = {"tls_ca_file": "--tls-ca-file", "tls_client_cert": "--tls-cert", "tls_client_key": "--tls-key"}


def _scheme(address: str) -> str:
    scheme, _, rest = address.partition("://")
    return scheme.lower() if rest else "tcp"


def _reason(error: BaseException) -> str:
    return " ".join(str(error).split())[:200] or type(error).__name__


def _framed(message: dict) -> bytes:
    """``message`` as Dask's TCP comm sends it: total length, frame count and lengths, one msgpack frame."""
    import msgpack
    frame = msgpack.dumps(message, use_bin_type=True)
    prelude = struct.pack("<QQ", 1, len(frame))
    return struct.pack("<Q", len(prelude) + len(frame)) + prelude + frame


def _refuse_objects(mapping: dict) -> dict:
    """A msgpack map as it is; a pickled or serialised object is refused, never opened."""
    if "__Pickled__" in mapping or "__Serialized__" in mapping:
        raise NotAScheduler(_OBJECTS)
    return mapping


def _received(sock, size: int) -> bytes:
    chunks, left = [], size
    while left:
        chunk = sock.recv(min(left, 1 << 16))
        if not chunk:
            raise NotAScheduler("it closed the connection without answering as a Dask scheduler")
        chunks.append(chunk)
        left -= len(chunk)
    return b"".join(chunks)


def _message(sock) -> Any:
    """One message of Dask's TCP comm, read as plain msgpack data: at most :data:`MAX_PROBE_REPLY_BYTES`."""
    import msgpack
    (size,) = _FRAME_COUNT.unpack(_received(sock, 8))
    if not 16 <= size <= MAX_PROBE_REPLY_BYTES:
        raise NotAScheduler("its answer is not a Dask message")
    body = _received(sock, size)
    (count,) = _FRAME_COUNT.unpack_from(body)
    if count > 1:  # the frames after the first carry pickled or serialised objects
        raise NotAScheduler(_OBJECTS)
    if count != 1:
        raise NotAScheduler("its answer is not a Dask message")
    (length,) = _FRAME_COUNT.unpack_from(body, 8)
    if length != size - 16:
        raise NotAScheduler("its answer is not a Dask message")
    try:
        return msgpack.loads(body[16:], raw=False, use_list=False, strict_map_key=False,
                             object_hook=_refuse_objects)
    except NotAScheduler:
        raise
    except Exception:  # noqa: BLE001 - whatever the bytes were
        raise NotAScheduler("its answer is not a Dask message") from None


def probe_scheduler(address: str, security, timeout_s: float) -> dict:
    """Ask ``address`` who it is, reading the answer as plain data; its identity if it is a Dask scheduler.

    Speaks Dask's TCP comm (a handshake, then ``{"op": "identity"}``) on a
    plain socket, optionally wrapped in the TLS context of ``security``, and
    reads each answer as msgpack only: a pickled or serialised object in it
    is refused unopened (distributed's own comm unpickles what a peer sends,
    so a stranger at the address could run code in this process). Reads at
    most :data:`MAX_PROBE_REPLY_BYTES` per answer, all within ``timeout_s``.

    Raises ConnectionRefusedError (nothing listens), socket.gaierror (unknown
    host), TimeoutError, ssl.SSLError, OSError, or :class:`NotAScheduler`.
    """
    import socket
    import ssl

    from distributed.comm.addressing import parse_address, parse_host_port

    scheme, location = parse_address(address)
    if scheme not in SCHEMES:
        raise NotAScheduler(f"assess connects to tcp:// or tls:// schedulers, not {scheme}://")
    host, port = parse_host_port(location, default_port=8786)
    deadline = time.monotonic() + timeout_s

    def left() -> float:
        remaining = deadline - time.monotonic()
        if remaining <= 0:
            raise TimeoutError(f"no answer as a Dask scheduler within {timeout_s:g} s")
        return remaining

    sock = socket.create_connection((host, port), timeout=left())
    try:
        if scheme == "tls":
            context = security.get_connection_args("client")["ssl_context"]
            sock = context.wrap_socket(sock, server_hostname=host if context.check_hostname else None)
        handshake = {"compression": None, "python": tuple(sys.version_info)[:3],
                     "pickle-protocol": pickle.HIGHEST_PROTOCOL}
        sock.settimeout(left())
        sock.sendall(_framed(handshake))
        sock.settimeout(left())
        theirs = _message(sock)
        if not (isinstance(theirs, dict) and "pickle-protocol" in theirs):
            raise NotAScheduler("it does not answer Dask's handshake")
        sock.settimeout(left())
        sock.sendall(_framed({"op": "identity", "reply": True}))
        sock.settimeout(left())
        identity = _message(sock)
    except (socket.timeout, TimeoutError):
        raise TimeoutError(f"it accepts connections but gives no answer as a Dask scheduler within "
                           f"{timeout_s:g} s") from None
    except ssl.SSLError:
        raise
    except ConnectionError:
        raise NotAScheduler("it closed the connection without answering as a Dask scheduler") from None
    finally:
        with contextlib.suppress(OSError):
            sock.close()
    if not (isinstance(identity, dict) and identity.get("type") == "Scheduler"):
        raise NotAScheduler("it answers, but not as a Dask scheduler")
    return identity


def _scheduler_problem(address: str, message: str, fix: str) -> InputError:
    return InputError([Problem(file="--scheduler", message=f"{address[:200]!r}: {message}", fix=fix)])


_CONNECT_FIX = ("give the address the scheduler printed when it started (e.g. tcp://10.0.0.5:8786, "
                "'dask scheduler' prints it), check that it is running and reachable from this machine, "
                "or leave --scheduler out to run on this machine's cores")


def _client(address: str, security, timeout_s: float):
    """A ``distributed.Client`` of the scheduler at ``address``, after :func:`probe_scheduler` says it is one.

    Every failure is an :class:`~assess.errors.InputError` of one line: nothing
    listens (connection refused), unknown host, no answer in time, a TLS
    failure, not a scheduler, or a listener that passed for one and then
    failed the client (its half-made client is collected quietly).
    """
    import socket
    import ssl

    from distributed import Client

    try:
        probe_scheduler(address, security, timeout_s)
    except ConnectionRefusedError:
        raise _scheduler_problem(address, "nothing listens there (connection refused)", _CONNECT_FIX) from None
    except socket.gaierror:
        raise _scheduler_problem(address, "its host name is not known", _CONNECT_FIX) from None
    except ssl.SSLError as error:
        raise _scheduler_problem(address, f"the TLS handshake failed ({_reason(error)})",
                                 "give the certificate authority that signed the scheduler's certificate and a "
                                 "client certificate it accepts (--tls-ca-file, --tls-cert, --tls-key)") from None
    except NotAScheduler as error:
        hint = " (or a TLS scheduler: give its tls:// address)" if _scheme(address) == "tcp" else ""
        raise _scheduler_problem(address, f"something listens there but is not a Dask scheduler: {error}{hint}",
                                 _CONNECT_FIX) from None
    except (OSError, ValueError, TypeError) as error:  # TimeoutError, unreachable network, a bad port
        raise _scheduler_problem(address, f"no Dask scheduler could be reached there ({_reason(error)})",
                                 _CONNECT_FIX) from None
    failure = None
    hook, log = sys.unraisablehook, logging.getLogger("distributed")
    # a listener that fails the client mid-handshake can trip a callback of the client's event loop, whose
    # traceback asyncio logs from that loop's thread: quiet while the client is made, the refusal says it all
    loop_logs = [logging.getLogger(name) for name in ("asyncio", "tornado.general", "tornado.application")]
    level, loop_levels = log.level, [loop_log.level for loop_log in loop_logs]
    try:
        for loop_log in loop_logs:
            loop_log.setLevel(logging.CRITICAL)
        try:
            return Client(address, security=security, timeout=f"{timeout_s}s", set_as_default=False)
        except Exception as error:  # noqa: BLE001 - whatever a listener that passed for a scheduler did
            failure = _reason(error)
        # the half-made client and its streams complain when collected: quietly, the refusal says it all
        sys.unraisablehook = lambda unraisable: None
        log.setLevel(logging.CRITICAL)
        gc.collect()
    finally:
        sys.unraisablehook = hook
        log.setLevel(level)
        for loop_log, loop_level in zip(loop_logs, loop_levels):
            loop_log.setLevel(loop_level)
    raise _scheduler_problem(address, f"it answered as a Dask scheduler, then failed as one ({failure})",
                             _CONNECT_FIX)


@dataclass
class DaskRunner(RunnerBase):
    """Run the engine's cases on the Dask cluster that ``client`` is connected to.

    Build it with :meth:`connect`. A batch is cut into :func:`task_count`
    tasks of equal cost (:func:`cost_tasks`): ``tasks_per_thread`` per worker
    thread, each worth at least ``min_task_steps`` block-steps. Its records,
    sample intervals and distinct blocks (a float table, :func:`block_table`)
    are sent to every worker once per batch (Dask's broadcast scatter); a task
    carries only each case's block row and record index, and its peaks come
    back as arrays. ``cases_simulated`` counts the ``peaks`` cases this runner
    simulated, ``runs_simulated`` every run by kind; ``tasks_run`` the tasks
    it sent.
    """

    client: Any
    tasks_per_thread: int = TASKS_PER_THREAD
    min_task_steps: int = MIN_TASK_STEPS
    cases_simulated: int = field(default=0)
    tasks_run: int = field(default=0)
    runs_simulated: dict = field(default_factory=dict)

    @classmethod
    def connect(cls, address: str, *, timeout_s: float = CONNECT_TIMEOUT_S,
                tasks_per_thread: int = TASKS_PER_THREAD, min_task_steps: int = MIN_TASK_STEPS,
                tls_ca_file=None, tls_cert=None, tls_key=None) -> "DaskRunner":
        """Connect to the scheduler at ``address`` (``tcp://host:8786``, ``host:8786``, ``tls://...``).

        A scheduler is trusted as code you run: Dask's client opens whatever
        objects it sends. So the address is first asked who it is by
        :func:`probe_scheduler`, which never opens an object, and only a Dask
        scheduler gets a client. ``tls://`` uses Dask's TLS with the PEM files
        given (or Dask's configuration), :func:`scheduler_security`.

        Raises :class:`~assess.errors.InputError` (the CLI's exit 2) within
        about ``timeout_s`` seconds if the address is not one, nothing listens
        there, what listens is not a Dask scheduler, no worker has joined, or
        the workers cannot run this version of ``assess``.
        """
        text = str(address).strip()
        if not text:
            raise _scheduler_problem(text, "is empty", _CONNECT_FIX)
        security = scheduler_security(text, ca_file=tls_ca_file, cert=tls_cert, key=tls_key)
        client = _client(text, security, timeout_s)
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
        return cls(client=client, tasks_per_thread=tasks_per_thread, min_task_steps=min_task_steps)

    def close(self) -> None:
        """Disconnect from the cluster (the cluster itself keeps running)."""
        self.client.close()

    def threads(self) -> int:
        """Worker threads of the cluster now (at least 1)."""
        return max(1, sum(self.client.nthreads().values()))

    def run(self, cases: Cases, *, progress: Progress = None) -> Result:
        """As :func:`assess.mechanics.gateway.run_cases`, on the cluster's workers."""
        from distributed import as_completed  # the optional cluster extra

        n = len(cases)
        if n == 0:
            return run_cases(cases)
        steps = case_steps(cases)
        tasks = cost_tasks(cases.record_index, steps, task_count(int(steps.sum()), n, self.threads(),
                                                                 tasks_per_thread=self.tasks_per_thread,
                                                                 min_task_steps=self.min_task_steps))
        packed = block_table(cases.blocks)
        table, rows = packed if packed is not None else (None, None)
        shared = ([np.asarray(r, dtype=float) for r in cases.records_g], [float(d) for d in cases.dt_s], table)
        # once to every worker; a unique key per batch (hash=False): the next batch's is not the one being released
        [everywhere] = self.client.scatter([shared], broadcast=True, hash=False)
        futures = {}
        for number, task in enumerate(tasks):
            part = _Part(cases.kind, None if rows is None else rows[task],
                         [cases.blocks[k] for k in task.tolist()] if rows is None else None,
                         cases.record_index[task],
                         None if cases.record_index_2 is None else cases.record_index_2[task],
                         cases.tail_s, cases.history, cases.solver)
            futures[self.client.submit(_run_part, everywhere, part, pure=False)] = number
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
            everywhere.release()
        self._count(cases, n)
        self.tasks_run += len(tasks)
        return _assembled(tasks, parts, n, cases.kind)


def _assembled(tasks, parts, n, kind) -> Result:
    """The tasks' results put back in case order."""
    order = np.concatenate(tasks)
    if kind == RESPONSE:
        responses: list = [None] * n
        for k, response in zip(order.tolist(), [r for part in parts for r in part]):
            responses[k] = response
        return responses
    fields = {}
    for name in _FIELDS:
        values = [_decoded(p[name]) if name in _TEXT else p[name] for p in parts]
        values = np.concatenate(values)
        out = np.empty(n, dtype=values.dtype)
        out[order] = values
        fields[name] = out
    return CasePeaks(**fields)
