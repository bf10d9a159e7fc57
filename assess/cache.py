"""A cache of engine results, keyed by the content of everything a result depends on.

:class:`CachingRunner` is a runner (:mod:`assess.mechanics.runner`): it takes
the assessment's batch of (block, motion) cases, answers those it has seen
before from a folder of stored peaks, and hands only the others to the runner
it wraps (this machine's threads, a Dask cluster), in one batch. A case's key
is a hash of

* the block: its class and every dataclass field (nested dataclasses such as a
  sliding interface included), floats by their exact ``repr``;
* the motion: the bytes of the record's samples (float64) and its time step
  ``dt_s`` (hashed once per record, not once per case); synthetic histories
  enter through their samples, so their seed is part of the key;
* the seconds followed after the record (``tail_s``);
* :func:`engine_version`: a hash of the source of every ``assess/mechanics``
  module, the package version, and the numpy and numba versions, so that a
  change of the engine invalidates every stored result.

The engine is deterministic (the same case gives the same peaks whatever else
is in its batch), so a stored result is the result; the tests check that the
numbers are identical with and without the cache.

Storage: a folder of *packs*, compressed ``.npz`` files each holding the
cases one call simulated (keys and peaks, no pickled objects). A pack is
written to a temporary file and renamed into place, so a reader never sees
half a pack and two processes writing at once lose nothing; packs are never
modified, only merged (when there are more than :data:`MAX_PACKS`) or
deleted, least recently used first, when the folder passes ``max_bytes``. A
pack that cannot be read (damaged, truncated, of another format, not a
regular file, larger than :data:`MAX_PACK_BYTES` as a file or inflated) is
treated as missing and removed: its cases are simulated again. Nothing read
from a pack is trusted (an output folder copied from elsewhere brings its
cache along): a stored row whose values the engine cannot have produced
(a NaN or negative peak, an unknown mode or solver) is a miss.
"""
from __future__ import annotations

import contextlib
import dataclasses
import hashlib
import math
import os
import stat
import tempfile
import time
import zipfile
from pathlib import Path
from typing import Callable, Optional, Sequence

import numpy as np

from assess.mechanics.block import MODES
from assess.mechanics.engine import (DEFAULT_TAIL_S, ELASTIC_INTERFACE_KERNEL, EVENT_DRIVEN, GENERAL, ROCKING_KERNEL,
                                     SLIDING_KERNEL, VELOCITY_FRICTION_KERNEL, CasePeaks, checked_record_index)

#: Bump when the pack layout changes: packs of another format are not read.
PACK_FORMAT = 1
#: Largest cache folder [bytes] before the least recently used packs are deleted.
DEFAULT_MAX_BYTES = 1 << 30
#: Packs in the folder before they are merged into one.
MAX_PACKS = 64
#: Bytes of a case key (BLAKE2b digest size): collisions are out of reach at any realistic number of cases.
KEY_BYTES = 16
#: Leftover temporary files (a writer killed mid-write) older than this are removed [s].
STALE_TEMPORARY_S = 3600.0
#: Largest pack read [bytes], as a file and inflated (all its arrays together; about 1.5 million cases):
#: a pack past it is not read (its cases are simulated again), so a pack cannot make assess use more memory.
MAX_PACK_BYTES = 256 << 20
#: The engine's solvers, the only ``solver`` a stored row may name.
SOLVERS = (SLIDING_KERNEL, VELOCITY_FRICTION_KERNEL, ELASTIC_INTERFACE_KERNEL, ROCKING_KERNEL, GENERAL, EVENT_DRIVEN)
_MECHANICS = Path(__file__).resolve().parent / "mechanics"
_FLOATS = ("sliding_max_m", "sliding_residual_m", "theta_max_over_alpha")
_BOOLS = ("uplift", "overturned")
_TEXTS = ("mode", "solver")
_PACK_ARRAYS = ("format", "keys") + _FLOATS + _BOOLS + _TEXTS


def engine_version(folder: Path = _MECHANICS) -> str:
    """Hex digest of what the engine's numbers depend on besides the case itself.

    The source of every ``*.py`` module of ``folder`` (default: ``assess/mechanics``),
    by name and content, plus the versions of assess, numpy and numba.
    """
    import numba

    import assess
    digest = hashlib.blake2b(digest_size=KEY_BYTES)
    for path in sorted(Path(folder).glob("*.py")):
        digest.update(path.name.encode() + b"\0" + path.read_bytes() + b"\0")
    for version in (assess.__version__, np.__version__, numba.__version__):
        digest.update(str(version).encode() + b"\0")
    return digest.hexdigest()


def _canonical(value) -> str:
    """A field's value as exact text: floats by ``repr`` (round-trips exactly), dataclasses field by field."""
    if value is None or isinstance(value, (bool, str)):
        return repr(value)
    if isinstance(value, (int, np.integer)):
        return repr(int(value))
    if isinstance(value, (float, np.floating)):
        return repr(float(value))
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        return block_fingerprint(value)
    if isinstance(value, (tuple, list)):
        return "(" + ",".join(_canonical(v) for v in value) + ")"
    if isinstance(value, np.ndarray):
        array = np.ascontiguousarray(value)
        return f"array({array.dtype.str},{array.shape},{hashlib.blake2b(array.tobytes()).hexdigest()})"
    raise TypeError(f"no exact text for a {type(value).__name__}")


def block_fingerprint(block) -> str:
    """The block's class and every dataclass field with its exact value, as text.

    >>> from assess.mechanics.block import Block
    >>> print(block_fingerprint(Block(half_width_m=0.3, cg_height_m=1.0, height_m=2.0, mu=0.2)))
    assess.mechanics.block.Block(half_width_m=0.3,cg_height_m=1.0,height_m=2.0,mu=0.2,mu_static=0.2,restitution=None,foot_inset_m=0.0)
    """
    kind = type(block)
    fields = ",".join(f"{f.name}={_canonical(getattr(block, f.name))}" for f in dataclasses.fields(block))
    return f"{kind.__module__}.{kind.__qualname__}({fields})"


def record_digest(record_g, dt_s: float) -> bytes:
    """Hash of a record's samples (as float64) and its time step."""
    samples = np.ascontiguousarray(record_g, dtype=np.float64)
    digest = hashlib.blake2b(digest_size=KEY_BYTES)
    digest.update(f"{samples.shape}|{float(dt_s)!r}|".encode())
    digest.update(samples.tobytes())
    return digest.digest()


def case_keys(blocks: Sequence, records_g: Sequence[np.ndarray], dt_s: Sequence[float], record_index,
              tail_s: float, version: str) -> list[Optional[bytes]]:
    """One key per case (None for a block whose fields have no exact text: never cached)."""
    records = [record_digest(r, d) for r, d in zip(records_g, dt_s)]
    prefix = f"{version}|{float(tail_s)!r}|".encode()
    by_block: dict[int, Optional[bytes]] = {}
    keys = []
    for block, j in zip(blocks, np.asarray(record_index, dtype=np.int64)):
        digest = by_block.get(id(block), b"")
        if digest == b"":
            try:
                digest = hashlib.blake2b(block_fingerprint(block).encode(), digest_size=KEY_BYTES).digest()
            except TypeError:
                digest = None
            by_block[id(block)] = digest
        keys.append(None if digest is None
                    else hashlib.blake2b(prefix + digest + records[j], digest_size=KEY_BYTES).digest())
    return keys


@dataclasses.dataclass
class _Index:
    """Every stored case, keys sorted for a binary search, and the packs they came from."""

    keys: np.ndarray = dataclasses.field(default_factory=lambda: np.zeros(0, dtype=f"S{KEY_BYTES}"))
    values: dict = dataclasses.field(default_factory=dict)
    packs: set = dataclasses.field(default_factory=set)

    def add(self, keys: np.ndarray, values: dict) -> None:
        keys = np.concatenate([self.keys, keys])
        merged = {name: np.concatenate([self.values[name], values[name]]) if name in self.values
                  else values[name] for name in values}
        keys, first = np.unique(keys, return_index=True)  # sorted, one entry per key
        self.keys = keys
        self.values = {name: column[first] for name, column in merged.items()}

    def find(self, keys: np.ndarray) -> np.ndarray:
        """Row of each key in the index, -1 where it is not stored."""
        if not self.keys.size or not keys.size:
            return np.full(keys.size, -1, dtype=np.int64)
        position = np.searchsorted(self.keys, keys)
        clipped = np.minimum(position, self.keys.size - 1)
        return np.where(self.keys[clipped] == keys, clipped, -1)


class CachingRunner:
    """A runner that reuses stored results and simulates only the cases it has not seen.

    Parameters
    ----------
    inner : runner
        What simulates the cases not in the cache (any object with
        ``simulate_cases``; default :class:`~assess.mechanics.runner.LocalRunner`).
    folder : path
        The cache folder (created on the first write).
    max_bytes : int
        Size of the folder beyond which the least recently used packs are deleted.
    version : str, optional
        The engine version the keys carry (default :func:`engine_version`).

    ``cases_simulated`` counts the cases handed to ``inner`` (one per distinct
    key), ``cases_reused`` those answered from the cache or by an identical
    case of the same batch; the two add up to the cases asked for.
    ``write_errors`` holds why a pack could not be stored (the run goes on
    without storing it).
    """

    def __init__(self, inner=None, folder=".cache", *, max_bytes: int = DEFAULT_MAX_BYTES,
                 version: str | None = None):
        if inner is None:
            from assess.mechanics.runner import LocalRunner
            inner = LocalRunner()
        self.inner = inner
        self.folder = Path(folder)
        self.max_bytes = int(max_bytes)
        self.version = version if version is not None else engine_version()
        self.cases_simulated = 0
        self.cases_reused = 0
        self.write_errors: list[str] = []
        self._index = _Index()

    # ------------------------------------------------------------ the runner seam
    def simulate_cases(self, blocks: Sequence, records_g: Sequence[np.ndarray], dt_s: Sequence[float],
                       record_index, *, tail_s: float = DEFAULT_TAIL_S,
                       progress: Optional[Callable[[int, int], None]] = None) -> CasePeaks:
        n = len(blocks)
        record_index = checked_record_index(record_index, n)
        keys = case_keys(blocks, records_g, dt_s, record_index, tail_s, self.version)
        cacheable = np.array([k is not None for k in keys], dtype=bool)
        key_array = np.array([k if k is not None else b"" for k in keys], dtype=f"S{KEY_BYTES}")
        self._load_new_packs()
        row = np.full(n, -1, dtype=np.int64)
        row[cacheable] = self._index.find(key_array[cacheable])
        missing = np.flatnonzero(row < 0)
        # one simulation per distinct key; uncacheable cases each run
        send, first_of = [], {}
        source = np.empty(missing.size, dtype=np.int64)  # position in `send` of each missing case
        for m, k in enumerate(missing):
            key = keys[k]
            if key is not None and key in first_of:
                source[m] = first_of[key]
                continue
            if key is not None:
                first_of[key] = len(send)
            source[m] = len(send)
            send.append(k)
        send = np.asarray(send, dtype=np.int64)
        hits = n - send.size
        values = {name: np.zeros(n, dtype=float) for name in _FLOATS}
        values.update({name: np.zeros(n, dtype=bool) for name in _BOOLS})
        texts = {name: np.full(n, "", dtype=object) for name in _TEXTS}
        found = np.flatnonzero(row >= 0)
        if found.size:
            for name in _FLOATS + _BOOLS:
                values[name][found] = self._index.values[name][row[found]]
            for name in _TEXTS:
                texts[name][found] = self._index.values[name][row[found]]
        if send.size:
            used = np.unique(record_index[send])  # only the records the misses need, grouping kept
            renumber = np.full(len(records_g), -1, dtype=np.int64)
            renumber[used] = np.arange(used.size)

            def report(done, total):
                if progress is not None:
                    progress(hits + done, n)

            peaks = self.inner.simulate_cases([blocks[k] for k in send], [records_g[j] for j in used],
                                              [dt_s[j] for j in used], renumber[record_index[send]],
                                              tail_s=tail_s, progress=report)
            for name in _FLOATS + _BOOLS:
                values[name][missing] = np.asarray(getattr(peaks, name))[source]
            for name in _TEXTS:
                texts[name][missing] = np.asarray(getattr(peaks, name)).astype(str)[source]
            stored = cacheable[send]
            if stored.any():
                self._store(key_array[send][stored],
                            {name: np.asarray(getattr(peaks, name))[stored] for name in _FLOATS + _BOOLS}
                            | {name: np.asarray(getattr(peaks, name)).astype(str)[stored] for name in _TEXTS})
        elif progress is not None:
            progress(n, n)
        self.cases_simulated += int(send.size)
        self.cases_reused += int(hits)
        return CasePeaks(sliding_max_m=values["sliding_max_m"], sliding_residual_m=values["sliding_residual_m"],
                         theta_max_over_alpha=values["theta_max_over_alpha"], uplift=values["uplift"],
                         overturned=values["overturned"], mode=texts["mode"].astype(str),
                         solver=texts["solver"].astype(str))

    # ------------------------------------------------------------ the folder
    def _pack_paths(self) -> list[Path]:
        try:
            return sorted(p for p in self.folder.glob("*.npz") if not p.name.startswith("."))
        except OSError:
            return []

    def _load_new_packs(self) -> None:
        """Add to the index every pack of the folder not read yet (another process may have written some)."""
        for path in self._pack_paths():
            if path.name in self._index.packs:
                continue
            pack = _read_pack(path)
            if pack is None:
                with contextlib.suppress(OSError):
                    path.unlink()  # damaged: its cases are simulated again
                continue
            self._index.add(*pack)
            self._index.packs.add(path.name)
            with contextlib.suppress(OSError):
                os.utime(path)  # recently used: deleted last when the folder is trimmed

    def _store(self, keys: np.ndarray, values: dict) -> None:
        self._index.add(keys, values)
        try:
            self.folder.mkdir(parents=True, exist_ok=True)
            name = _write_pack(self.folder, keys, values)
            self._index.packs.add(name)
            self._tidy()
        except OSError as error:
            self.write_errors.append(f"{self.folder}: {error.strerror or type(error).__name__}")

    def _tidy(self) -> None:
        """Remove stale temporaries, merge packs past :data:`MAX_PACKS`, trim to ``max_bytes``."""
        now = time.time()
        for leftover in self.folder.glob(".tmp-*"):
            with contextlib.suppress(OSError):
                if now - leftover.stat().st_mtime > STALE_TEMPORARY_S:
                    leftover.unlink()
        packs = self._pack_paths()
        if len(packs) > MAX_PACKS:
            merged = [p for p in packs if p.name in self._index.packs]
            keys, values = self._index.keys, self._index.values
            name = _write_pack(self.folder, keys, values)  # everything this process knows, in one pack
            for path in merged:
                if path.name != name:
                    with contextlib.suppress(OSError):
                        path.unlink()
            self._index.packs = {name} | (self._index.packs - {p.name for p in merged})
            packs = self._pack_paths()
        sizes = []
        for path in packs:
            with contextlib.suppress(OSError):
                stat = path.stat()
                sizes.append((stat.st_mtime, stat.st_size, path))
        total = sum(size for _, size, _ in sizes)
        for _, size, path in sorted(sizes, key=lambda s: s[0]):
            if total <= self.max_bytes:
                break
            with contextlib.suppress(OSError):
                path.unlink()
                total -= size


def _write_pack(folder: Path, keys: np.ndarray, values: dict) -> str:
    """Write one pack atomically (temporary file, then rename); returns its file name."""
    name = hashlib.blake2b(np.ascontiguousarray(keys).tobytes(), digest_size=KEY_BYTES).hexdigest() + ".npz"
    handle, temporary = tempfile.mkstemp(prefix=".tmp-", suffix=".npz", dir=folder)
    try:
        with os.fdopen(handle, "wb") as stream:
            np.savez_compressed(stream, format=np.array(PACK_FORMAT), keys=keys,
                                **{f: np.asarray(values[f], dtype=float) for f in _FLOATS},
                                **{f: np.asarray(values[f], dtype=bool) for f in _BOOLS},
                                **{f: np.asarray(values[f], dtype=str) for f in _TEXTS})
            stream.flush()
            os.fsync(stream.fileno())
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(temporary, 0o666 & ~umask)  # as any file this user writes, not mkstemp's 0600
        os.replace(temporary, folder / name)
        temporary = None
    finally:
        if temporary is not None:
            with contextlib.suppress(OSError):
                os.unlink(temporary)
    return name


def _read_pack(path: Path):
    """``(keys, values)`` of a pack, or None when it cannot be read or is not a pack of this format.

    Nothing in a pack is trusted (a copied output folder brings its ``.cache``
    along): only a regular file of at most :data:`MAX_PACK_BYTES` is opened
    (:func:`_open_regular`), its arrays are checked against their declared
    sizes before any is inflated (:func:`_pack_arrays`), and every row is
    checked (:func:`_plausible_rows`); a row that fails is left out, a miss.
    """
    stream = _open_regular(path)
    if stream is None:
        return None
    try:
        with stream, zipfile.ZipFile(stream) as archive:
            arrays = _pack_arrays(archive)
    except Exception:  # noqa: BLE001 - a damaged file raises many kinds (zip, zlib, value, key errors)
        return None
    if arrays is None or arrays["format"].shape != () or arrays["format"].dtype.kind not in "iu" \
            or int(arrays["format"]) != PACK_FORMAT:
        return None
    keys = arrays["keys"]
    values = {name: arrays[name] for name in _FLOATS + _BOOLS + _TEXTS}
    n = keys.shape
    if keys.dtype != np.dtype(f"S{KEY_BYTES}") or keys.ndim != 1 or any(v.shape != n for v in values.values()):
        return None
    if any(values[f].dtype.kind != "f" for f in _FLOATS) or any(values[f].dtype.kind != "b" for f in _BOOLS) \
            or any(values[f].dtype.kind != "U" for f in _TEXTS):
        return None
    kept = _plausible_rows(values)
    return keys[kept], {name: column[kept] for name, column in values.items()}


def _open_regular(path):
    """``path`` opened for reading if it is a regular file of at most :data:`MAX_PACK_BYTES`; else None.

    Opened without following a final link and without blocking (a FIFO named
    ``*.npz`` would wait for a writer forever), then checked with ``fstat``,
    so what is read is what was checked.
    """
    flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_BINARY", 0)
    try:
        handle = os.open(path, flags)
    except OSError:
        return None
    try:
        status = os.fstat(handle)
        if stat.S_ISREG(status.st_mode) and status.st_size <= MAX_PACK_BYTES:
            return os.fdopen(handle, "rb")
    except OSError:
        pass
    os.close(handle)
    return None


def _pack_arrays(archive: zipfile.ZipFile) -> dict | None:
    """The pack's arrays, or None if a member is missing, not a plain array, or too large.

    The members' inflated sizes (from the zip directory) must add up to at
    most :data:`MAX_PACK_BYTES`, and each array's shape and type (from its
    ``.npy`` header) must fit its member's size, before a byte is inflated;
    the zip reader stops a member at its declared size.
    """
    members = archive.infolist()
    if len(members) > 4 * len(_PACK_ARRAYS) or sum(m.file_size for m in members) > MAX_PACK_BYTES:
        return None
    by_name = {m.filename: m for m in members}
    arrays = {}
    for name in _PACK_ARRAYS:
        member = by_name.get(name + ".npy")
        if member is None:
            return None
        with archive.open(member) as stream:
            version = np.lib.format.read_magic(stream)
            if version == (1, 0):
                shape, _, dtype = np.lib.format.read_array_header_1_0(stream)
            elif version == (2, 0):
                shape, _, dtype = np.lib.format.read_array_header_2_0(stream)
            else:
                return None
        if dtype.hasobject or math.prod(shape) * dtype.itemsize > member.file_size:
            return None
        with archive.open(member) as stream:
            arrays[name] = np.lib.format.read_array(stream, allow_pickle=False)
    return arrays


def _plausible_rows(values: dict) -> np.ndarray:
    """Which stored rows could be the engine's: finite peaks in their ranges, known modes and solvers.

    ``sliding_max_m`` and ``theta_max_over_alpha`` are finite and not
    negative; the residual sliding is finite and no larger than the peak; the
    mode is one of :data:`assess.mechanics.block.MODES` and the solver one of
    the engine's. A row that fails is not used (its case is simulated again).
    """
    sliding = values["sliding_max_m"]
    residual = values["sliding_residual_m"]
    theta = values["theta_max_over_alpha"]
    with np.errstate(invalid="ignore"):
        kept = (np.isfinite(sliding) & (sliding >= 0.0) & np.isfinite(theta) & (theta >= 0.0)
                & np.isfinite(residual) & (np.abs(residual) <= sliding * (1.0 + 1e-9) + 1e-12))
    kept &= np.isin(values["mode"], np.array(MODES, dtype=str))
    kept &= np.isin(values["solver"], np.array(SOLVERS, dtype=str))
    return kept
