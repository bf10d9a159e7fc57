"""Hostile and wrong listeners given to ``--scheduler``, and a real TLS scheduler on loopback.

A listener on the address is a stranger until it answers as a Dask scheduler:
the connection check (:func:`assess.mechanics.distributed.probe_scheduler`)
reads its answers as plain msgpack and never opens a pickled object, so a
listener that answers with a pickle runs nothing here. Anything that is not a
scheduler ends in exit 2 with one line naming the address; a refused port says
that nothing listens. ``tls://`` is tested against a real
``distributed.Scheduler`` with certificates made in the test (``openssl``).
"""
from __future__ import annotations

import asyncio
import os
import pickle
import shutil
import socket
import struct
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

distributed = pytest.importorskip("distributed")
msgpack = pytest.importorskip("msgpack")

from assess.errors import InputError  # noqa: E402
from assess.mechanics.distributed import DaskRunner, probe_scheduler, scheduler_security  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
LAB = ROOT / "inventories" / "lab.xlsx"


def cli_env() -> dict:
    return {**os.environ, "PYTHONPATH": os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")])}


def run_cli(*args, cwd, timeout=120):
    started = time.monotonic()
    done = subprocess.run([sys.executable, "-m", "assess", *map(str, args)], cwd=cwd, capture_output=True,
                          text=True, timeout=timeout, env=cli_env())
    return done, time.monotonic() - started


# ------------------------------------------------------------------ Dask's wire format, written by hand

def framed(*frames: bytes) -> bytes:
    """Frames as Dask's TCP comm sends them (distributed/comm/tcp.py: total, count, lengths, frames)."""
    prelude = struct.pack(f"<Q{len(frames)}Q", len(frames), *map(len, frames))
    return struct.pack("<Q", len(prelude) + sum(map(len, frames))) + prelude + b"".join(frames)


def read_message(conn) -> bytes:
    (size,) = struct.unpack("<Q", conn.recv(8, socket.MSG_WAITALL))
    return conn.recv(size, socket.MSG_WAITALL)


class CreatesAFile:
    """Unpickled, opens ``path`` for writing (the file appears): stands for any code a pickle runs."""

    def __init__(self, path):
        self.path = str(path)

    def __reduce__(self):
        return (open, (self.path, "w"))


def pickled_reply(path) -> bytes:
    """A message whose first frame points at a pickle (distributed/protocol/core.py, '__Pickled__')."""
    header = msgpack.dumps({"__Pickled__": 1}, use_bin_type=True)
    sub = msgpack.dumps({"pickled-obj": pickle.dumps(CreatesAFile(path)), "num-sub-frames": 0}, use_bin_type=True)
    return framed(header, sub)


class Listener:
    """A loopback TCP listener that answers every message of every connection with ``answer(n)``."""

    def __init__(self, answer, greet=None):
        self.sock = socket.create_server(("127.0.0.1", 0))
        self.address = "tcp://127.0.0.1:%d" % self.sock.getsockname()[1]
        self.answer, self.greet = answer, greet
        self.thread = threading.Thread(target=self._serve, daemon=True)
        self.thread.start()

    def _serve(self):
        while True:
            try:
                conn, _ = self.sock.accept()
            except OSError:
                return
            threading.Thread(target=self._talk, args=(conn,), daemon=True).start()

    def _talk(self, conn):
        with conn:
            try:
                if self.greet is not None:
                    conn.sendall(self.greet)
                n = 0
                while True:
                    read_message(conn)
                    conn.sendall(self.answer(n))
                    n += 1
            except (OSError, struct.error):
                return

    def close(self):
        self.sock.close()


def plain(message) -> bytes:
    return framed(msgpack.dumps(message, use_bin_type=True))


HANDSHAKE = {"compression": None, "python": (3, 11, 0), "pickle-protocol": 5}


def assert_one_line_refusal(done, *expected):
    assert done.returncode == 2, done.stderr
    assert "Traceback" not in done.stderr and "Exception ignored" not in done.stderr, done.stderr
    assert "internal error" not in done.stderr and " - WARNING - " not in done.stderr, done.stderr
    problems = [line for line in done.stderr.splitlines() if line.startswith("  - ")]
    assert len(problems) == 1, done.stderr
    for text in expected:
        assert text in problems[0], done.stderr


# ------------------------------------------------------------------ the reproducers

def test_a_listener_answering_a_pickle_runs_nothing(tmp_path):
    marker = tmp_path / "payload-ran"
    listener = Listener(lambda n: pickled_reply(marker), greet=None)
    try:
        # the check itself, in this process
        with pytest.raises(InputError) as caught:
            DaskRunner.connect(listener.address, timeout_s=5)
        assert "serialised Python objects" in str(caught.value)
        assert not marker.exists()
        # the CLI, both commands
        done, seconds = run_cli(LAB, "--hazard", "2in50", "--out", tmp_path / "out", "--scheduler",
                                listener.address, cwd=tmp_path)
        assert_one_line_refusal(done, listener.address, "is not a Dask scheduler")
        assert not marker.exists() and not (tmp_path / "out").exists()
        assert seconds < 60
    finally:
        listener.close()


def test_the_pickle_is_also_refused_after_a_good_handshake(tmp_path):
    """The handshake is plain; the pickle comes as the answer to 'identity'."""
    marker = tmp_path / "payload-ran"
    listener = Listener(lambda n: pickled_reply(marker), greet=plain(HANDSHAKE))
    try:
        with pytest.raises(InputError) as caught:
            DaskRunner.connect(listener.address, timeout_s=5)
        assert "serialised Python objects" in str(caught.value) and not marker.exists()
    finally:
        listener.close()


def test_a_listener_claiming_to_be_a_scheduler_exits_2_in_one_line(tmp_path):
    """It passes the check (it says 'Scheduler') and then fails distributed's Client: exit 2, not 1."""
    listener = Listener(lambda n: plain({"type": "Scheduler", "id": "fake", "workers": {}}),
                        greet=plain(HANDSHAKE))
    try:
        done, seconds = run_cli(LAB, "--hazard", "2in50", "--out", tmp_path / "out", "--scheduler",
                                listener.address, cwd=tmp_path)
        assert_one_line_refusal(done, listener.address, "answered as a Dask scheduler, then failed as one")
        assert seconds < 60
    finally:
        listener.close()


@pytest.mark.parametrize("answer", [b"HTTP/1.0 200 OK\r\n\r\nhello\n", b"\xff" * 64, struct.pack("<Q", 1 << 40)])
def test_other_listeners_exit_2_in_one_line(tmp_path, answer):
    listener = Listener(lambda n: answer, greet=answer)
    try:
        started = time.monotonic()
        with pytest.raises(InputError) as caught:
            DaskRunner.connect(listener.address, timeout_s=3)
        assert time.monotonic() - started < 10
        assert "is not a Dask scheduler" in str(caught.value) and "hello" not in str(caught.value)
    finally:
        listener.close()


def test_a_silent_listener_times_out(tmp_path):
    sock = socket.create_server(("127.0.0.1", 0))
    try:
        address = "tcp://127.0.0.1:%d" % sock.getsockname()[1]
        started = time.monotonic()
        with pytest.raises(InputError) as caught:
            DaskRunner.connect(address, timeout_s=2)
        assert time.monotonic() - started < 8
        assert "gives no answer as a Dask scheduler within 2 s" in str(caught.value)
    finally:
        sock.close()


def test_a_refused_port_says_nothing_listens(tmp_path):
    sock = socket.create_server(("127.0.0.1", 0))
    port = sock.getsockname()[1]
    sock.close()  # nothing listens on it now
    done, seconds = run_cli(LAB, "--hazard", "2in50", "--out", tmp_path / "out", "--scheduler",
                            f"tcp://127.0.0.1:{port}", cwd=tmp_path)
    assert_one_line_refusal(done, "nothing listens there (connection refused)")
    assert "something answers" not in done.stderr


def test_help_and_readme_say_a_scheduler_is_code_you_run():
    for command in ([], ["batch"]):
        text = subprocess.run([sys.executable, "-m", "assess", *command, "--help"], capture_output=True, text=True,
                              env=cli_env(), cwd=ROOT).stdout
        flat = " ".join(text.split())
        assert "run code for you" in flat and "--tls-ca-file" in flat, command
    readme = " ".join((ROOT / "README.md").read_text().split())
    assert "run code for you" in readme and "tls://" in readme


# ------------------------------------------------------------------ TLS on loopback, certificates made here

def _openssl(*args, cwd):
    subprocess.run(["openssl", *args], cwd=cwd, check=True, capture_output=True, timeout=60)


@pytest.fixture(scope="module")
def certificates(tmp_path_factory):
    """A certificate authority and a certificate it signed (for both the scheduler and the client)."""
    if shutil.which("openssl") is None:
        pytest.skip("the openssl command is not installed: the certificates cannot be made")
    folder = tmp_path_factory.mktemp("tls")
    _openssl("req", "-x509", "-newkey", "rsa:2048", "-nodes", "-keyout", "ca.key", "-out", "ca.pem", "-days", "2",
             "-subj", "/CN=assess test CA", cwd=folder)
    _openssl("req", "-newkey", "rsa:2048", "-nodes", "-keyout", "node.key", "-out", "node.csr",
             "-subj", "/CN=127.0.0.1", cwd=folder)
    _openssl("x509", "-req", "-in", "node.csr", "-CA", "ca.pem", "-CAkey", "ca.key", "-CAcreateserial",
             "-out", "node.pem", "-days", "2", cwd=folder)
    # a second authority: its certificate is not trusted by the scheduler
    _openssl("req", "-x509", "-newkey", "rsa:2048", "-nodes", "-keyout", "other.key", "-out", "other.pem",
             "-days", "2", "-subj", "/CN=someone else", cwd=folder)
    return folder


@pytest.fixture(scope="module")
def tls_cluster(certificates):
    security = distributed.Security(tls_ca_file=str(certificates / "ca.pem"),
                                    tls_scheduler_cert=str(certificates / "node.pem"),
                                    tls_scheduler_key=str(certificates / "node.key"),
                                    tls_worker_cert=str(certificates / "node.pem"),
                                    tls_worker_key=str(certificates / "node.key"),
                                    tls_client_cert=str(certificates / "node.pem"),
                                    tls_client_key=str(certificates / "node.key"),
                                    require_encryption=True)
    with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=False, protocol="tls://",
                                  host="127.0.0.1", security=security, dashboard_address=None,
                                  silence_logs=40) as cluster:
        yield cluster


def test_tls_scheduler_with_the_certificates_given(tls_cluster, certificates):
    address = tls_cluster.scheduler_address
    assert address.startswith("tls://")
    security = scheduler_security(address, ca_file=certificates / "ca.pem", cert=certificates / "node.pem",
                                  key=certificates / "node.key")
    identity = probe_scheduler(address, security, 10)
    assert identity["type"] == "Scheduler"
    runner = DaskRunner.connect(address, tls_ca_file=certificates / "ca.pem", tls_cert=certificates / "node.pem",
                                tls_key=certificates / "node.key")
    try:
        assert runner.client.submit(sum, [1, 2, 3]).result(timeout=30) == 6
    finally:
        runner.close()


def test_tls_scheduler_from_dask_configuration(tls_cluster, certificates):
    import dask
    with dask.config.set({"distributed.comm.tls.ca-file": str(certificates / "ca.pem"),
                          "distributed.comm.tls.client.cert": str(certificates / "node.pem"),
                          "distributed.comm.tls.client.key": str(certificates / "node.key")}):
        runner = DaskRunner.connect(tls_cluster.scheduler_address)
    try:  # the certificates came from Dask's configuration alone: the client works on the TLS scheduler
        assert runner.client.scheduler_info()["address"] == tls_cluster.scheduler_address
        assert runner.client.submit(sum, [1, 2, 3]).result(timeout=30) == 6
    finally:
        runner.close()


def test_tls_scheduler_refuses_without_or_with_wrong_certificates(tls_cluster, certificates):
    address = tls_cluster.scheduler_address
    with pytest.raises(InputError) as caught:
        DaskRunner.connect(address)
    assert "needs certificates" in str(caught.value) and "--tls-ca-file" in str(caught.value)
    with pytest.raises(InputError) as caught:  # a client certificate the scheduler's authority never signed
        DaskRunner.connect(address, tls_ca_file=certificates / "ca.pem", tls_cert=certificates / "other.pem",
                           tls_key=certificates / "other.key", timeout_s=5)
    assert "TLS handshake failed" in str(caught.value) or "not a Dask scheduler" in str(caught.value)
    with pytest.raises(InputError) as caught:  # the plain address of a TLS scheduler
        DaskRunner.connect(address.replace("tls://", "tcp://"), timeout_s=5)
    assert "give its tls:// address" in str(caught.value)
    with pytest.raises(InputError) as caught:
        DaskRunner.connect("tcp://127.0.0.1:1", tls_ca_file=certificates / "ca.pem")
    assert "not tls://" in str(caught.value)


def test_the_main_job_on_a_tls_scheduler_through_the_cli(tls_cluster, certificates, tmp_path):
    """The CLI options reach the client: the job runs on the TLS cluster (one worker, in-process)."""
    done, seconds = run_cli(LAB, "--hazard", "2in50", "--out", tmp_path / "out", "--format", "xlsx", "--quiet",
                            "--scheduler", tls_cluster.scheduler_address, "--tls-ca-file", certificates / "ca.pem",
                            "--tls-cert", certificates / "node.pem", "--tls-key", certificates / "node.key",
                            cwd=tmp_path, timeout=600)
    assert done.returncode == 0, done.stderr
    assert (tmp_path / "out" / "summary.csv").is_file()
