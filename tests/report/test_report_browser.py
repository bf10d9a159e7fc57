"""report.html in a real browser: Debian's Chromium driven by Playwright (both optional).

Skips, saying why, where Chromium (``apt-get install chromium``) or the
Python package ``playwright`` (``pip install playwright``; its own browser
download is not needed, the system Chromium is used) is absent. Checks what a
reader does: the page opens with no console error and fetches nothing from
the network, the all-items table sorts by a column and filters by text, and
every item link on page 1 lands on that item's details.
"""
from __future__ import annotations

import shutil

import pytest

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
if CHROMIUM is None:
    pytest.skip("Chromium is not installed (Debian: apt-get install chromium); the browser test needs it",
                allow_module_level=True)
sync_api = pytest.importorskip("playwright.sync_api",
                               reason="the Python package playwright is not installed (pip install playwright)")

from assess.report import render_html  # noqa: E402
from tests.report.test_report import make_result  # noqa: E402


@pytest.fixture(scope="module")
def page(tmp_path_factory):
    folder = tmp_path_factory.mktemp("browser")
    report = folder / "report.html"
    report.write_text(render_html(make_result(simulated=True)), encoding="utf-8")
    with sync_api.sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=CHROMIUM, args=["--no-sandbox"])
        page = browser.new_page(viewport={"width": 1280, "height": 900})
        page.console_errors, page.fetched = [], []
        page.on("console", lambda message: message.type == "error" and page.console_errors.append(message.text))
        page.on("pageerror", lambda error: page.console_errors.append(str(error)))
        page.on("request", lambda request: request.url.startswith(("file:", "data:"))
                or page.fetched.append(request.url))
        page.goto(report.as_uri())
        page.screenshot(path=str(folder / "report.png"), full_page=True)
        print(f"screenshot: {folder / 'report.png'}")
        yield page
        browser.close()


def _ids(page):
    return [cell.strip() for cell in page.locator("#all-items-table tbody tr:visible td.c-id").all_inner_texts()]


def test_opens_without_console_errors_and_fetches_nothing(page):
    assert page.console_errors == []
    assert page.fetched == []


def test_the_table_sorts_by_a_column_both_ways(page):
    heading = page.locator("#all-items-table thead th.c-id")
    heading.click()
    assert _ids(page) == sorted(_ids(page))
    heading.click()
    assert _ids(page) == sorted(_ids(page), reverse=True)
    clearance = page.locator("#all-items-table thead th.c-cl")
    clearance.click()
    values = [float(v) for v in page.locator("#all-items-table tbody tr td.c-cl").all_inner_texts()]
    assert values == sorted(values)


def test_the_filter_keeps_only_matching_rows(page):
    page.fill("#item-filter", "F-01")
    assert _ids(page) == ["F-01"]
    page.fill("#item-filter", "")
    assert len(_ids(page)) == page.locator("#all-items-table tbody tr").count()


def test_every_link_on_page_1_lands_on_its_item_details(page):
    links = page.locator("#summary a.id")
    assert links.count() > 0
    for k in range(links.count()):
        link = links.nth(k)
        target = link.get_attribute("href")
        link.click()
        assert page.url.endswith(target)
        row = page.locator(target)
        assert row.is_visible() and row.locator("h3 .id").inner_text().strip() == link.inner_text().strip()
        box = row.bounding_box()
        assert -1 <= box["y"] < 900  # scrolled into view (to the top, within a pixel)
