"""``report.html`` of the tiny ``loco reproduce`` run, opened in a real headless Chromium: no
console error, no request leaves the file, every figure decoded, the verdict in the first screen,
tables as tables; a screenshot of the first screen is kept in ``build/artifacts/``."""

from __future__ import annotations

import os
import re
import shutil
from pathlib import Path
from typing import Any

import pytest

from loco.studies import report_html

#: Where the screenshot goes (kept by CI as a test artifact; ``build/`` is not tracked).
ARTIFACTS = Path(__file__).resolve().parents[2] / "build" / "artifacts"
#: The first screen: the viewport of a common laptop.
VIEWPORT = {"width": 1280, "height": 900}
BROWSERS = ("chromium", "chromium-browser", "google-chrome")


def browser_path() -> str:
    """The Chromium to drive: ``$LOCO_CHROMIUM``, else the first of :data:`BROWSERS` on PATH.
    Fails (does not skip) without one: scripts/ci/test.sh installs the distribution's package."""
    found = os.environ.get("LOCO_CHROMIUM") or next(
        (p for p in map(shutil.which, BROWSERS) if p), None
    )
    if not found:
        pytest.fail(
            "no Chromium found (looked for $LOCO_CHROMIUM and " + ", ".join(BROWSERS) + "): "
            "install it, e.g. `apt-get install -y chromium` (scripts/ci/test.sh does)"
        )
    return found


def open_page(path: Path, screenshot: Path) -> dict[str, Any]:
    """Load ``path`` in headless Chromium at :data:`VIEWPORT`; what the checks need."""
    try:
        from playwright.sync_api import sync_playwright
    except ImportError:
        pytest.fail("the playwright package is missing: pip install -e '.[dev]'")
    errors: list[str] = []
    requests: list[str] = []
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=browser_path(), args=["--no-sandbox"])
        try:
            page = browser.new_page(viewport=VIEWPORT)  # type: ignore[arg-type]
            page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
            page.on("pageerror", lambda e: errors.append(str(e)))
            page.on("request", lambda r: requests.append(r.url))
            page.goto(path.as_uri(), wait_until="load")
            images = page.eval_on_selector_all(
                "img",
                "els => els.map(e => ({complete: e.complete, width: e.naturalWidth,"
                " src: e.getAttribute('src').slice(0, 22), alt: e.alt}))",
            )
            headings = page.eval_on_selector_all("main h2", "els => els.map(e => e.textContent)")
            verdict = page.locator("main h2", has_text="Verdict").first.bounding_box()
            tables = page.eval_on_selector_all("main table", "els => els.length")
            text = page.inner_text("main")
            contents = page.eval_on_selector_all(
                "nav a", "els => els.map(e => e.getAttribute('href'))"
            )
            ids = page.eval_on_selector_all("main h2[id]", "els => els.map(e => '#' + e.id)")
            screenshot.parent.mkdir(parents=True, exist_ok=True)
            page.screenshot(path=str(screenshot))
        finally:
            browser.close()
    return {
        "errors": errors,
        "requests": requests,
        "images": images,
        "headings": headings,
        "verdict": verdict,
        "tables": tables,
        "text": text,
        "contents": contents,
        "ids": ids,
    }


def test_the_report_page_in_a_browser(tiny_study: tuple[Path, str]) -> None:
    out, log = tiny_study
    page_path = out / "report.html"
    assert f"the report as a page: {page_path.resolve()}" in log
    markdown = (out / "report.md").read_text(encoding="utf-8")
    shown = open_page(page_path, ARTIFACTS / "report_first_screen.png")
    assert shown["errors"] == []
    # Self-contained: the only request is the page itself (figures are data: URIs).
    assert [u for u in shown["requests"] if not u.startswith("data:")] == [page_path.as_uri()]
    # Every figure of report.md is on the page, embedded and decoded.
    figures = re.findall(r"^!\[([^\]]*)\]\(([^)]+\.png)\)$", markdown, re.M)
    assert len(figures) > 0 and len(shown["images"]) == len(figures)
    for image in shown["images"]:
        assert image["complete"] and image["width"] > 0, image["alt"]
        assert image["src"] == "data:image/png;base64,", image["alt"]
    # The first sections come first, the verdict's heading inside the first screen.
    assert shown["headings"][0] == "Does the premise hold?"
    assert shown["headings"][1].startswith("Verdict")
    box = shown["verdict"]
    assert box is not None
    assert 0 <= box["x"] and box["x"] + box["width"] <= VIEWPORT["width"]
    assert 0 <= box["y"] and box["y"] + box["height"] <= VIEWPORT["height"]
    # Every Markdown table is an HTML table: none is left as pipes in the text.
    assert shown["tables"] == len(re.findall(r"^\|---", markdown, re.M))
    assert not [line for line in shown["text"].splitlines() if line.startswith("|")]
    # The contents link every section heading.
    assert shown["contents"] == shown["ids"] and len(shown["ids"]) >= 10
    assert (ARTIFACTS / "report_first_screen.png").stat().st_size > 0


def test_list_items_nested_by_two_spaces_stay_nested() -> None:
    html = report_html.markdown_to_html("- a\n  - b\n    - c")
    assert html.count("<ul>") == 3
