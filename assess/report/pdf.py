"""The PDF of a report's HTML: WeasyPrint, the body and its appendix on two cores, merged with pypdf.

The risk report ends in an appendix (the item-by-item blocks, between the
``<!-- appendix -->`` and ``<!-- /appendix -->`` markers of the template)
whose pages are numbered A-1, A-2 … as engineering reports number theirs.
The body and the appendix are laid out as two documents, each with its own
page numbers: the body in a second process, started while the report's
figures are drawn, and the appendix in this one, where the machine has a
second core (:func:`report_pdf`), the one after the other where it has not.
The two PDFs are then joined (:func:`merge`; in the second process where there
is one, which holds the body already): the pages keep their labels
(1, 2 … then A-1, A-2 …, as a PDF viewer shows them), the body's links to an
item's block in the appendix are made to point there, and the bookmarks of
both follow one another. The bytes depend on the HTML only, not on whether a
second process drew the body.

This module imports neither pandas nor matplotlib, so that the second process
starts quickly (it imports this module, WeasyPrint and pypdf).

Nothing the report shows is fetched: the stylesheet is inlined, the figures
are SVG, inline or as ``data:`` URIs, and the URL fetcher refuses every URL
that is not a ``data:`` URI.
"""
from __future__ import annotations

import base64
import contextlib
import functools
import io
import multiprocessing
import os
import signal
import urllib.parse
from concurrent.futures import ProcessPoolExecutor
from concurrent.futures.process import BrokenProcessPool

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


def render_pdf(html: str, *, url_fetcher=None, processes: int | None = None) -> bytes:
    """The PDF of a report's HTML, fetching nothing from the network or the disk.

    A report with an appendix is laid out as two documents and joined (:func:`merge`): the body in a
    second process while this one lays out the appendix where ``processes`` (default: 2 where the machine has
    a second core, else 1) is 2 (:func:`report_pdf`); the bytes are the same either way.
    ``url_fetcher`` defaults to :func:`data_only_url_fetcher`; pass one to inspect its ``refused`` list
    afterwards (both parts are then laid out in this process, with it).
    """
    return report_pdf(lambda: html, url_fetcher=url_fetcher, processes=processes)[1]


def report_pdf(make_html, *, url_fetcher=None, processes: int | None = None) -> tuple[str, bytes]:
    """``(html, pdf)``: the report's HTML, made by ``make_html()``, and its PDF (as :func:`render_pdf`).

    Where a second process lays out a part (``processes`` 2, the default on a machine with a second core),
    it is started before ``make_html`` runs, so that it has imported WeasyPrint by the time the HTML is
    made (the figures take about as long): it then lays out the body, the larger part, while this process
    lays out the appendix (:func:`_lay_out_parts`).
    """
    two = url_fetcher is None and (processes if processes is not None else (2 if second_core() else 1)) >= 2
    if not two:
        html = make_html()
        body, appendix = split_appendix(html)
        if appendix is None:
            return html, render_part(html, url_fetcher)
        return html, merge(render_part(body, url_fetcher), render_part(appendix, url_fetcher))
    return _lay_out_parts(make_html)


def _lay_out_parts(make_html) -> tuple[str, bytes]:
    """``(html, pdf)`` with a second process: a :class:`concurrent.futures.ProcessPoolExecutor` of one fresh
    interpreter ('spawn'), started before ``make_html()`` runs; it imports WeasyPrint meanwhile
    (:func:`_ready`), then lays out the body while this process lays out the appendix, and joins the
    appendix to the body (:func:`_join_appendix`).

    The second process starts with Ctrl-C blocked (:func:`_interrupts_held`): an interrupt is this
    process's to act on, and it ends the other on leaving, whatever the reason (it holds nothing to save).
    A second process that ends without the body (killed, out of memory) only means that this one lays
    the body out itself.
    """
    started = set(multiprocessing.active_children())
    pool = ProcessPoolExecutor(max_workers=1, mp_context=multiprocessing.get_context("spawn"))
    try:
        with _interrupts_held():
            pool.submit(_ready)  # starts the process, which imports WeasyPrint while the HTML is made
        html = make_html()
        body, appendix = split_appendix(html)
        if appendix is None:
            return html, render_part(html)
        elsewhere = pool.submit(_lay_out_body, body)
        appendix_pdf = render_part(appendix)
        try:
            elsewhere.result()
            return html, pool.submit(_join_appendix, appendix_pdf).result()
        except BrokenProcessPool:
            return html, merge(render_part(body), appendix_pdf)
    finally:
        with _interrupts_held():  # a Ctrl-C now waits until the pool's process is ended and reaped
            ours = set(multiprocessing.active_children()) - started  # the pool's process, done or not
            for child in ours:
                child.terminate()
            pool.shutdown(wait=True, cancel_futures=True)  # its thread, which reaps the process too, ended
            for child in ours:
                child.join()


def _ready() -> None:
    """In the second process (:func:`_lay_out_parts`): import WeasyPrint before there is anything to lay out."""
    _weasyprint()


#: In the second process (:func:`_lay_out_parts`): the body's PDF, laid out by :func:`_lay_out_body` and
#: kept there until :func:`_join_appendix` adds the appendix to it.
_body_laid_out: list[Joined] = []


def _lay_out_body(body: str) -> None:
    """:func:`render_part` of the body, in the second process (:func:`_lay_out_parts`), kept there."""
    _body_laid_out[:] = [Joined(render_part(body))]


def _join_appendix(appendix_pdf: bytes) -> bytes:
    """In the second process: the body it laid out (:func:`_lay_out_body`) joined to ``appendix_pdf``
    (:func:`merge`). The join runs there, not here, because it allocates many small objects: in this
    process, which holds the report's figures, tables and libraries, the garbage collector then walks
    all of those (0.45 s on the lab, 0.1 s there)."""
    return _body_laid_out.pop().with_appendix(appendix_pdf)


@contextlib.contextmanager
def _interrupts_held():
    """Ctrl-C held back while a second process starts, then acted on: the new process inherits this thread's
    blocked SIGINT, so Ctrl-C at the terminal (sent to every process of the foreground group) never
    interrupts it; and this process, whose handler another thread may run, finishes starting it first
    rather than leave it half-told what to run (it would print "EOFError: Ran out of input"). A Ctrl-C held
    is taken from the process's queue of signals and acted on as the block ends (KeyboardInterrupt there), never
    left to arrive at some later moment, inside a library that might drop it or in the middle of ending the
    second process. Nothing off the main thread (its handler is the main thread's) or where the system has no
    signal masks or no ``sigtimedwait`` (macOS)."""
    held = []
    try:
        take_pending = signal.sigtimedwait  # (macOS has none: nothing is held there)
        previous = signal.signal(signal.SIGINT, lambda signum, frame: held.append(signum))
        mask = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT})
    except (AttributeError, ValueError):
        yield
        return
    try:
        yield
    finally:
        if take_pending({signal.SIGINT}, 0) is not None:  # one that came meanwhile, taken from the queue,
            held.append(signal.SIGINT)                   # so that none is left to arrive later
        signal.pthread_sigmask(signal.SIG_SETMASK, mask)
        signal.signal(signal.SIGINT, previous)
        if held and callable(previous):  # acted on here and now: raised later, it could land in a library
            previous(signal.SIGINT, None)  # that drops it (WeasyPrint's cffi callbacks); Python's raises
        elif held and previous == signal.SIG_DFL:
            signal.raise_signal(signal.SIGINT)


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
