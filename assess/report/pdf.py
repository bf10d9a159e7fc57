"""The PDF of a report's HTML: WeasyPrint, the body and its appendix on two cores, merged with pypdf.

The risk report ends in an appendix (the item-by-item blocks, between the
``<!-- appendix -->`` and ``<!-- /appendix -->`` markers of the template)
whose pages are numbered A-1, A-2 … as engineering reports number theirs.
The body and the appendix are laid out as two documents, each with its own
page numbers: the appendix in a second process while this one draws the figures and lays out the
body, where the machine has a second core (:func:`render_pdf`), the one after
the other where it has not; the ``assess`` command starts two processes as it starts
(:func:`body_and_appendix_processes`), one drawing some figures then the body, the other the appendix,
and lays out nothing itself. The two PDFs are then joined (:func:`merge`):
the pages keep their labels (1, 2 … then A-1, A-2 …, as a PDF viewer shows
them), the body's links to an item's block in the appendix are made to point
there, and the bookmarks of both follow one another. The bytes depend on the
HTML only, not on whether a second process drew the appendix.

This module imports neither pandas nor matplotlib, so that the second process
starts quickly (it imports this module, WeasyPrint and pypdf, and the modules it is told to).

Nothing the report shows is fetched: the stylesheet is inlined, the figures
are SVG, inline or as ``data:`` URIs, and the URL fetcher refuses every URL
that is not a ``data:`` URI.
"""
from __future__ import annotations

import base64
import contextlib
import functools
import gc
import importlib
import io
import multiprocessing
import os
import queue
import signal
import sys
import threading
import urllib.parse
from collections.abc import Callable
from multiprocessing.reduction import ForkingPickler

from assess.startup import COMMAND_GC_THRESHOLDS

#: The markers around the appendix in the report's HTML (templates/report.html.j2).
APPENDIX_START, APPENDIX_END = "<!-- appendix -->", "<!-- /appendix -->"
#: What the appendix's pages are labelled with before their number (A-1, A-2 …).
APPENDIX_PAGE_PREFIX = "A-"
#: A link of the body to an anchor of the appendix, as WeasyPrint writes it into the body's PDF, before
#: :func:`merge` turns it into a link to the anchor's page (never left in a merged PDF).
ELSEWHERE = "assess-appendix:"


# --------------------------------------------------------------------------- fetching nothing
def _weasyprint():
    import weasyprint
    from weasyprint.urls import URLFetcher, URLFetcherResponse

    return weasyprint, URLFetcher, URLFetcherResponse


#: What a second process that lays out a part of the PDF runs as it starts (:func:`_import`).
WARM_UP = f"{__name__}:warm_up"


def warm_up() -> None:
    """Load what a process's first PDF loads (WeasyPrint's fonts, regular, bold and italic): a small PDF, dropped.
    The PDF's second processes run it while the first one makes the result."""
    render_part("<html><body><h1>1</h1><p>a <b>b</b> <i>c</i> <code>d</code></p></body></html>")


class RefusedURLError(ValueError):
    """The report tried to load something that is not embedded as a ``data:`` URI."""


@functools.cache
def _data_only_fetcher_class():
    _, URLFetcher, URLFetcherResponse = _weasyprint()

    class DataOnlyURLFetcher(URLFetcher):
        """A WeasyPrint URL fetcher that decodes ``data:`` URIs and refuses everything else.

        It never opens a connection or a file: ``data:`` URIs are decoded here,
        not by urllib. Every refused URL is kept in :attr:`refused` (WeasyPrint
        catches the error, logs it and renders without the resource).
        """

        def __init__(self):
            super().__init__(allowed_protocols=("data",), fail_on_errors=False)
            self.refused: list[str] = []

        def fetch(self, url, headers=None):
            if not str(url).lower().startswith("data:"):
                self.refused.append(str(url))
                raise RefusedURLError(f"refused to fetch {url!r}: the report may only use "
                                      "resources embedded as data: URIs")
            media_type, body = decode_data_uri(str(url))
            return URLFetcherResponse(url, body=body, headers={"Content-Type": media_type})

    return DataOnlyURLFetcher


def decode_data_uri(url: str) -> tuple[str, bytes]:
    """``(media type, bytes)`` of a ``data:`` URI (RFC 2397)."""
    header, comma, payload = url[len("data:"):].partition(",")
    if not comma:
        raise RefusedURLError(f"malformed data: URI {url[:60]!r}")
    parameters = header.split(";")
    is_base64 = bool(parameters) and parameters[-1].strip().lower() == "base64"
    if is_base64:
        parameters = parameters[:-1]
    media_type = ";".join(parameters) or "text/plain;charset=US-ASCII"
    if is_base64:
        body = base64.b64decode(urllib.parse.unquote_to_bytes(payload), validate=False)
    else:
        body = urllib.parse.unquote_to_bytes(payload)
    return media_type, body


def data_only_url_fetcher():
    """A new fetcher that serves ``data:`` URIs and refuses every other URL."""
    return _data_only_fetcher_class()()


@contextlib.contextmanager
def _fixed_build_date():
    """Pin the dates WeasyPrint and fontTools write into the PDF, so that the same
    report gives the same bytes (SOURCE_DATE_EPOCH, reproducible-builds.org).
    A value the user has set is kept; the environment is restored afterwards."""
    previous = os.environ.get("SOURCE_DATE_EPOCH")
    if previous is None:
        os.environ["SOURCE_DATE_EPOCH"] = "0"
    try:
        yield
    finally:
        if previous is None:
            os.environ.pop("SOURCE_DATE_EPOCH", None)


# --------------------------------------------------------------------------- the two parts
def split_appendix(html: str) -> tuple[str, str | None]:
    """``(body, appendix)``: two HTML documents, the report without its appendix and the appendix alone
    (the same head, so the same stylesheet and title); ``(html, None)`` where there is no appendix.

    >>> split_appendix("<html><head></head><body><p>a</p><!-- appendix --><p>b</p><!-- /appendix --></body></html>")
    ('<html><head></head><body><p>a</p></body></html>', '<html><head></head><body><p>b</p></body></html>')
    """
    start = html.find(APPENDIX_START)
    end = html.find(APPENDIX_END, start + 1)
    body_open = html.find("<body")
    if start < 0 or end < 0 or not 0 <= body_open < start:
        return html, None
    body_open = html.index(">", body_open) + 1
    body_close = html.rfind("</body>")
    if body_close < end:
        return html, None
    appendix = html[start + len(APPENDIX_START):end]
    return html[:start] + html[end + len(APPENDIX_END):], html[:body_open] + appendix + html[body_close:]


def render_part(html: str, url_fetcher=None) -> bytes:
    """The PDF of one HTML document. A link to an anchor the document does not hold (one in the
    appendix) is written as a link to ``ELSEWHERE`` + the anchor, for :func:`merge` to resolve."""
    weasyprint, _, _ = _weasyprint()
    fetcher = data_only_url_fetcher() if url_fetcher is None else url_fetcher
    with _fixed_build_date():
        document = weasyprint.HTML(string=html, base_url=None, url_fetcher=fetcher).render()
        anchors = {name for page in document.pages for name in page.anchors}
        for page in document.pages:
            page.links = [("external", ELSEWHERE + target, rectangle, box)
                          if kind == "internal" and target not in anchors else (kind, target, rectangle, box)
                          for kind, target, rectangle, box in page.links]
        return document.write_pdf()


def second_core() -> bool:
    """Whether this process may use a second core (its CPU affinity, where the system tells it)."""
    try:
        return len(os.sched_getaffinity(0)) > 1
    except AttributeError:  # macOS, Windows
        return (os.cpu_count() or 1) > 1


def _import(modules: tuple[str, ...]) -> None:
    """Import WeasyPrint and ``modules`` (what the calls it will be sent need, :meth:`AppendixProcess.call`;
    ``package.module:function`` also runs that function), at a lower priority than the first process's work
    where the machine is otherwise idle (:func:`_import_priority`)."""
    _import_priority()
    _weasyprint()
    for name in modules:
        module, _, function = name.partition(":")
        imported = importlib.import_module(module)
        if function:
            getattr(imported, function)()
    gc.collect()  # what the function left behind, then
    gc.freeze()  # what the imports made lives until the process ends: the collector need not scan it again


#: How much lower the second process's imports run than the first process (its assessment, which uses both
#: cores at times) on an idle machine: they take a core only when it is free (setpriority(2); 19 is the
#: lowest priority). A later run of the lab job: 7.5 s with it, 7.75 s without.
IMPORT_NICENESS = 10


def _import_priority() -> None:
    """Lower this thread's priority by :data:`IMPORT_NICENESS` where the machine is otherwise idle (its load
    average over the last minute below its cores) and the system lets a thread have its own (Linux,
    setpriority(2)). Not on a busy machine: a lowered priority cannot be raised again, and beside two
    programs that keep both cores busy the imports would wait for them (the lab job: 17 s instead of 15 s)."""
    if sys.platform != "linux":
        return
    with contextlib.suppress(OSError):
        if os.getloadavg()[0] < len(os.sched_getaffinity(0)):
            os.setpriority(os.PRIO_PROCESS, threading.get_native_id(), IMPORT_NICENESS)


def _serve(connection, modules: tuple[str, ...] = ()) -> None:
    """The second process: import WeasyPrint and ``modules`` at once (while the first one still works on the
    result), then answer what it is sent, in order, until the pipe closes: an HTML document with its PDF, a
    call ``(function, args)`` with ``(True, function(*args))``, or ``(False, why)`` where the call failed
    (the first process then does that work itself). What is sent is read off the pipe at once, by a thread
    of its own, even while the imports run or a call is answered, so that the first process never waits on
    a full pipe. Ctrl-C is the first process's to act on (it ends this one)."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    gc.set_threshold(*COMMAND_GC_THRESHOLDS)  # the command's (laying out the lab's body: 3.54 -> 3.04 CPU s)
    importing = threading.Thread(target=_import, args=(modules,), name="import WeasyPrint")
    importing.start()
    requests = queue.SimpleQueue()

    def read() -> None:
        while True:
            try:
                requests.put(connection.recv())
            except (EOFError, OSError):
                requests.put(None)
                return

    threading.Thread(target=read, name="read requests", daemon=True).start()
    while (request := requests.get()) is not None:
        importing.join()
        if isinstance(request, str):
            connection.send_bytes(render_part(request))
            continue
        function, args = request
        try:
            reply = (True, function(*args))
        except Exception as error:  # noqa: BLE001 -- the first process does the work itself, and says nothing
            reply = (False, f"{type(error).__name__}: {error}")
        connection.send(reply)


class Call:
    """The answer to :meth:`AppendixProcess.call`, once read: :meth:`result`."""

    def __init__(self, process: "AppendixProcess"):
        self.process, self.read, self.reply = process, False, (False, "not answered")

    def result(self):
        """The call's value, or None where the second process failed it or ended first."""
        while not self.read and self.process.sent and self.process.read_one():
            pass
        done, value = self.reply
        return value if done else None


class AppendixProcess:
    """A second process that draws the appendix (:func:`_serve`), and whatever else it is given to do meanwhile
    (:meth:`call`: the figures it draws while this process draws the others), started with 'spawn' (a fresh
    interpreter: no fork of this process's threads), SIGINT blocked while it starts so that it never sees
    Ctrl-C. :meth:`draw` sends it an HTML document, :meth:`pdf` waits for the PDF of the last one sent
    (those of any sent before it are read and dropped); a process that ended without one (killed,
    crashed) is an error, not a wait without end. ``modules`` are imported as it starts, beside WeasyPrint.
    """

    def __init__(self, modules: tuple[str, ...] = ()):
        context = multiprocessing.get_context("spawn")
        self.connection, theirs = context.Pipe()
        self.modules = tuple(modules)
        self.process = context.Process(target=_serve, args=(theirs, self.modules),
                                       name="assess-pdf-appendix", daemon=True)
        self.sent: list = []  # what was sent and is not answered yet, in order: an HTML document or a Call
        self.last_pdf: tuple[str, bytes] | None = None  # the last PDF read, and its document
        # Ctrl-C while it starts would leave it half-told what to run (it then prints "EOFError: Ran out of
        # input"): the interrupt is held back until it has started (any thread of this process may take
        # the signal, so blocking it in this one is not enough), then acted on, the process ended first
        pending = []
        try:
            previous = signal.signal(signal.SIGINT, lambda signum, frame: pending.append(signum))
        except ValueError:  # not the main thread: its handler is the main thread's to run
            previous = None
        try:
            blocked = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT})  # the new process inherits it
        except (AttributeError, ValueError):
            blocked = None
        self._outbox = queue.SimpleQueue()
        self._sender = threading.Thread(target=self._send_all, name="send to the PDF's second process", daemon=True)
        try:
            self.process.start()
            self._sender.start()
        finally:
            if blocked is not None:
                signal.pthread_sigmask(signal.SIG_SETMASK, blocked)
            theirs.close()  # only the second process holds its end: it closing is seen here as EOF
            if previous is not None:
                signal.signal(signal.SIGINT, previous)
        if pending:
            self.close()
            signal.raise_signal(signal.SIGINT)

    def draw(self, html: str) -> None:
        self._send(html, html)

    def call(self, function, *args) -> Call:
        """Have the second process run ``function(*args)`` (both picklable; the function by its module's
        name), before what is sent after; :meth:`Call.result` waits for it."""
        call = Call(self)
        self._send(call, (function, args))
        return call

    def _send(self, pending, request) -> None:
        """Send ``request`` by the sending thread (:meth:`_send_all`): this process goes on at once, even
        while the second one is busy and the pipe full."""
        self.sent.append(pending)
        self._outbox.put(ForkingPickler.dumps(request))  # what Connection.send writes; recv reads it

    def _send_all(self) -> None:
        """The sending thread: what :meth:`_send` queued, in order, until :meth:`close`."""
        while (payload := self._outbox.get()) is not None:
            try:
                self.connection.send_bytes(payload)
            except OSError:  # it has ended: pdf() says so (not a BrokenPipeError, which reads as stdout's reader gone)
                return

    def drawing(self, html: str) -> bool:
        """Whether ``html`` is the last document sent, its PDF not read yet."""
        documents = [sent for sent in self.sent if isinstance(sent, str)]
        return bool(documents) and documents[-1] == html

    def read_one(self) -> bool:
        """Read the answer to the oldest request not answered (a call's is kept in its :class:`Call`, a PDF
        as :attr:`last_pdf`, its document's beside it); False where the process ended without it."""
        pending = self.sent[0]
        try:
            if isinstance(pending, Call):
                pending.reply, pending.read = self.connection.recv(), True
            else:
                self.last_pdf = (pending, self.connection.recv_bytes())
        except (EOFError, OSError):
            return False
        self.sent.pop(0)
        return True

    def pdf(self) -> bytes:
        """The PDF of the last document sent (:meth:`draw`)."""
        documents = [sent for sent in self.sent if isinstance(sent, str)]
        while documents and any(sent is documents[-1] for sent in self.sent) and self.read_one():
            pass
        if documents and self.last_pdf is not None and self.last_pdf[0] is documents[-1]:
            return self.last_pdf[1]
        self.process.join(timeout=5)
        raise RuntimeError("the second process drawing a part of the PDF ended without it "
                           f"(exit code {self.process.exitcode})")

    def lay_out_body(self, html: str, meanwhile=None) -> bytes:
        """The PDF of the report's body ``html``, laid out by this process (the second one lays out the
        appendix meanwhile), after ``meanwhile()`` where given."""
        if meanwhile is not None:
            meanwhile()
        return render_part(html)

    def merged(self, body_pdf: bytes, appendix_pdf: bytes) -> bytes:
        """:func:`merge`, in the second process, where pypdf is imported already and the work is done."""
        return self.call(merge, body_pdf, appendix_pdf).result() or merge(body_pdf, appendix_pdf)

    def close(self) -> None:
        """End the process (at once: it holds nothing that needs saving, the PDF is written by this one), then
        the sending thread (its writes fail once the process has ended), then the pipe."""
        if self.process.is_alive():
            self.process.terminate()
        self.process.join()
        self._outbox.put(None)
        self._sender.join()
        self.connection.close()


@contextlib.contextmanager
def pdf_process(processes: int | None = None, modules: tuple[str, ...] = ()):
    """An :class:`AppendixProcess` for :func:`render_pdf`, or None where ``processes`` (default: 2 where
    the machine has a second core, else 1) is 1. It imports WeasyPrint, pypdf (it joins the parts,
    :meth:`AppendixProcess.merged`) and ``modules`` as soon as it starts, and loads WeasyPrint's fonts, so that
    a caller that enters this before making the result finds it ready. Ended on leaving, on an error or Ctrl-C
    too."""
    if (processes if processes is not None else (2 if second_core() else 1)) < 2:
        yield None
        return
    process = AppendixProcess(tuple(dict.fromkeys(("pypdf", WARM_UP, *modules))))
    try:
        yield process
    finally:
        process.close()


class BodyAndAppendixProcesses:
    """Two second processes for one report: ``body`` imports ``modules`` (:data:`assess.report.FIGURE_MODULES`),
    draws some figures (:meth:`call`) and lays out the report's body (:meth:`lay_out_body`); ``appendix`` lays
    out the appendix (:meth:`draw`, :meth:`pdf`), sent once the figures are nearly drawn
    (:func:`assess.report.render.render_html`), so that it does not take a core from them. The first process
    lays out nothing, and never imports WeasyPrint. The same interface as :class:`AppendixProcess`."""

    def __init__(self, modules: tuple[str, ...] = ()):
        self.appendix = AppendixProcess((WARM_UP,))
        try:
            self.body = AppendixProcess(modules)
        except BaseException:  # Ctrl-C as it starts included
            self.appendix.close()
            raise
        self.modules = self.body.modules

    def call(self, function, *args) -> Call:
        return self.body.call(function, *args)

    def draw(self, html: str) -> None:
        self.appendix.draw(html)

    def drawing(self, html: str) -> bool:
        return self.appendix.drawing(html)

    def pdf(self) -> bytes:
        return self.appendix.pdf()

    def lay_out_body(self, html: str, meanwhile=None) -> bytes:
        """The PDF of the report's body ``html``, laid out by the body's process while this one runs
        ``meanwhile()`` where given."""
        self.body.draw(html)
        if meanwhile is not None:
            meanwhile()
        return self.body.pdf()

    def merged(self, body_pdf: bytes, appendix_pdf: bytes) -> bytes:
        return self.body.merged(body_pdf, appendix_pdf)

    def close(self) -> None:
        try:
            self.body.close()
        finally:
            self.appendix.close()


@contextlib.contextmanager
def body_and_appendix_processes(modules: tuple[str, ...] = ()):
    """:class:`BodyAndAppendixProcesses` where the machine has a second core (:func:`second_core`), else None
    (this process then draws everything); ended on leaving, on an error or Ctrl-C too."""
    if not second_core():
        yield None
        return
    processes = BodyAndAppendixProcesses(modules)
    try:
        yield processes
    finally:
        processes.close()


def render_pdf(html: str, *, url_fetcher=None, processes: int | None = None, process=None,
               meanwhile: Callable[[], None] | None = None) -> bytes:
    """The PDF of a report's HTML, fetching nothing from the network or the disk.

    A report with an appendix is rendered as two documents and joined (:func:`merge`), the appendix in
    ``process`` (from :func:`pdf_process`; or both parts, each in a process of its own, from
    :func:`body_and_appendix_processes`), or in a second process started here where ``processes``
    (default: 2 where the machine has a second core, else 1) is 2; the bytes are the same either way.
    ``url_fetcher`` defaults to :func:`data_only_url_fetcher`; pass one to inspect its ``refused`` list
    afterwards (both parts are then rendered in this process, with it). ``meanwhile``, where given, is
    called once, while other processes lay the parts out where they do (:class:`BodyAndAppendixProcesses`),
    else first.
    """
    body, appendix = split_appendix(html)
    if appendix is None or url_fetcher is not None or process is None:
        if meanwhile is not None:
            meanwhile()
    if appendix is None:
        return render_part(html, url_fetcher)
    if url_fetcher is not None:
        return merge(render_part(body, url_fetcher), render_part(appendix, url_fetcher))
    if process is None:
        with pdf_process(processes) as started:
            if started is not None:
                return render_pdf(html, process=started)
        return merge(render_part(body), render_part(appendix))
    if not process.drawing(appendix):  # it may have been sent before the figures were drawn (render_html)
        process.draw(appendix)
    body_pdf = process.lay_out_body(body, meanwhile)
    return process.merged(body_pdf, process.pdf())


# --------------------------------------------------------------------------- one PDF
def merge(body_pdf: bytes, appendix_pdf: bytes) -> bytes:
    """One PDF of the body's pages then the appendix's, labelled 1, 2 … and A-1, A-2 … (:class:`Joined`)."""
    return Joined(body_pdf).with_appendix(appendix_pdf)


class Joined:
    """The body's PDF, read, to which :meth:`with_appendix` adds the appendix's pages.

    The body's links to an anchor of the appendix (``ELSEWHERE`` + name, :func:`render_part`) become
    links to that anchor's named destination; the bookmarks of the body come first, then the appendix's;
    the document's metadata and language are the body's.
    """

    def __init__(self, body_pdf: bytes):
        import pypdf

        self.body = pypdf.PdfReader(io.BytesIO(body_pdf))
        self.writer = pypdf.PdfWriter()
        self.writer.append(self.body)

    def with_appendix(self, appendix_pdf: bytes) -> bytes:
        import pypdf
        from pypdf.generic import NameObject, TextStringObject

        body, writer = self.body, self.writer
        appendix = pypdf.PdfReader(io.BytesIO(appendix_pdf))
        writer.append(appendix)
        names = set(writer.named_destinations) | set(appendix.named_destinations)
        for page in writer.pages:
            annotations = page.get("/Annots")
            if annotations is None:
                continue
            kept = []
            for reference in annotations:
                annotation = reference.get_object()
                action = annotation.get("/A")
                uri = str(action.get_object().get("/URI", "")) if action is not None else ""
                if uri.startswith(ELSEWHERE):
                    name = uri[len(ELSEWHERE):]
                    if name not in names:
                        continue  # WeasyPrint drops a link to an anchor that is nowhere, so do we
                    del annotation["/A"]
                    annotation[NameObject("/Dest")] = TextStringObject(name)
                kept.append(reference)
            annotations.get_object()[:] = kept
        count = len(body.pages)
        writer.set_page_label(0, count - 1, "/D")
        writer.set_page_label(count, count + len(appendix.pages) - 1, "/D", prefix=APPENDIX_PAGE_PREFIX)
        if body.metadata:
            writer.add_metadata(dict(body.metadata))
        language = body.trailer["/Root"].get("/Lang")
        if language is not None:
            writer._root_object[NameObject("/Lang")] = language
        output = io.BytesIO()
        writer.write(output)
        return output.getvalue()
