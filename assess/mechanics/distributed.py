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

import contextlib
import gc
import logging
import pickle
import struct
import sys
import time
from dataclasses import dataclass, field, replace
from pathlib import Path
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
    level = log.level
    try:
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
    raise _scheduler_problem(address, f"it answered as a Dask scheduler, then failed as one ({failure})",
                             _CONNECT_FIX)


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
                cases_per_task: int = CASES_PER_TASK, tls_ca_file=None, tls_cert=None,
                tls_key=None) -> "DaskRunner":
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
