"""The study report as one self-contained HTML page: ``report.html`` beside ``report.md``.

:func:`loco.studies.report.write_report` hands this module the very Markdown lines and figures
it writes to ``report.md``, so the two never say different things. The page differs only in
form: the first sections (the premise, the verdict) come right under the title, the run's details
(version, platform, settings) fold into a line under them, a table of contents sits in a side
column, the first sections stand side by side on a wide screen (so the verdict is in sight
without scrolling), every figure is embedded as a base64 PNG ``data:`` URI under a ``<figure>``
with its caption, and the style sheet is inline: no file, font or script is fetched, so the page
can be mailed or archived alone.
"""

from __future__ import annotations

import base64
import html
import re
from collections.abc import Sequence
from pathlib import Path

import markdown

from loco.studies.report import Block, Figure

__all__ = ["markdown_to_html", "write_html"]

#: The page's style sheet: a contents column at the left, the report at the right.
STYLE = """
:root { --ink: #1f2328; --muted: #59636e; --rule: #d0d7de; --shade: #f6f8fa; --link: #0b5cad; }
* { box-sizing: border-box; }
body { margin: 0; color: var(--ink); font: 15px/1.45 system-ui, -apple-system, "Segoe UI",
  Roboto, "Helvetica Neue", Arial, sans-serif; }
a { color: var(--link); }
nav { position: fixed; top: 0; bottom: 0; left: 0; width: 250px; overflow-y: auto;
  padding: 16px 14px; border-right: 1px solid var(--rule); background: var(--shade);
  font-size: 13px; }
nav h2 { font-size: 14px; margin: 0 0 8px; }
nav ol { margin: 0; padding-left: 18px; }
nav li { margin: 3px 0; }
main { margin-left: 250px; padding: 12px 28px 48px; max-width: 1120px; }
h1 { font-size: 24px; margin: 4px 0 10px; }
h2 { font-size: 19px; margin: 26px 0 8px; padding-top: 6px; border-top: 1px solid var(--rule); }
section.first { display: grid; grid-template-columns: repeat(auto-fit, minmax(380px, 1fr));
  gap: 0 28px; font-size: 14px; }
section.first h2 { border-top: none; margin-top: 4px; padding-top: 0; }
li li { font-size: 13px; }
li li li { font-size: 12.5px; color: var(--muted); }
p, li { margin: 4px 0; }
ul { padding-left: 22px; margin: 6px 0; }
code { font-size: 90%; background: var(--shade); padding: 0 3px; border-radius: 3px; }
details.about { margin: 10px 0; color: var(--muted); font-size: 13px; }
details.about summary { cursor: pointer; }
.table { overflow-x: auto; margin: 8px 0 14px; }
table { border-collapse: collapse; font-size: 13px; }
th, td { border: 1px solid var(--rule); padding: 3px 8px; text-align: left; vertical-align: top; }
th { background: var(--shade); }
td { font-variant-numeric: tabular-nums; }
figure { margin: 12px 0 18px; }
figure img { display: block; max-width: 100%; height: auto; border: 1px solid var(--rule); }
figcaption { margin-top: 4px; color: var(--muted); font-size: 13px; max-width: 900px; }
@media (max-width: 800px) { nav { display: none; } main { margin-left: 0; } }
@media print { nav { display: none; } main { margin-left: 0; } }
"""

_HEADING = re.compile(r"<h([12])>(.*?)</h\1>", re.S)
_TABLE = re.compile(r"<table>.*?</table>", re.S)
_NESTED_ITEM = re.compile(r"^( +)(?=(?:[-*+]|\d+\.) )", re.M)


def markdown_to_html(text: str) -> str:
    """Markdown (with tables) as an HTML fragment; tables wrapped to scroll sideways.

    The report nests list items by two spaces (as CommonMark does); the ``markdown`` package
    wants four, so the indent of every list item is doubled first.
    """
    text = _NESTED_ITEM.sub(lambda m: m.group(1) * 2, text)
    body = markdown.markdown(text, extensions=["tables"], output_format="html")
    return _TABLE.sub(lambda m: f'<div class="table">{m.group(0)}</div>', body)


def _inline(text: str) -> str:
    """One line of Markdown as inline HTML (no enclosing paragraph)."""
    body = markdown_to_html(text).strip()
    if body.startswith("<p>") and body.endswith("</p>"):
        body = body[3:-4]
    return body


def _figure(figure: Figure) -> str:
    data = base64.b64encode(Path(figure.path).read_bytes()).decode("ascii")
    alt = html.escape(figure.path.stem, quote=True)
    name = html.escape(figure.path.name)
    caption = _inline(figure.caption)
    if figure.caption != figure.path.name:
        caption += f' <span class="file">({name})</span>'
    return (
        f'<figure><img src="data:image/png;base64,{data}" alt="{alt}">'
        f"<figcaption>{caption}</figcaption></figure>"
    )


def _blocks_html(blocks: Sequence[Block]) -> str:
    parts: list[str] = []
    pending: list[str] = []
    for block in blocks:
        if isinstance(block, Figure):
            parts.append(markdown_to_html("\n".join(pending)))
            pending = []
            parts.append(_figure(block))
        else:
            pending += block
    parts.append(markdown_to_html("\n".join(pending)))
    return "\n".join(p for p in parts if p.strip())


def _slug(text: str, taken: set[str]) -> str:
    plain = re.sub(r"<[^>]+>", "", html.unescape(text))
    base = re.sub(r"[^a-z0-9]+", "-", plain.lower()).strip("-") or "section"
    slug, n = base, 2
    while slug in taken:
        slug, n = f"{base}-{n}", n + 1
    taken.add(slug)
    return slug


def _with_ids(body: str, toc: list[tuple[str, str]], taken: set[str]) -> str:
    """``body`` with an id on every ``<h2>``, each one appended to ``toc`` as (id, text)."""

    def add(match: re.Match[str]) -> str:
        level, text = match.group(1), match.group(2)
        if level == "1":
            return match.group(0)
        slug = _slug(text, taken)
        toc.append((slug, text))
        return f'<h2 id="{slug}">{text}</h2>'

    return _HEADING.sub(add, body)


def _parts(lines: Sequence[str]) -> list[list[str]]:
    """``lines`` split before each ``## `` heading (the first sections, side by side)."""
    parts: list[list[str]] = []
    for line in lines:
        if line.startswith("## ") or not parts:
            parts.append([])
        parts[-1].append(line)
    return [part for part in parts if any(x.strip() for x in part)]


def write_html(
    path: str | Path,
    *,
    title: str,
    intro: Sequence[str],
    about: Sequence[str],
    first_section: Sequence[str],
    sections: Sequence[Block],
) -> Path:
    """Write the report page to ``path`` and return it.

    ``intro`` (the preamble), ``about`` (the run's details), ``first_section`` and ``sections``
    (each stage's Markdown lines and figures) are the parts of ``report.md``, in Markdown.
    """
    toc: list[tuple[str, str]] = []
    taken: set[str] = set()
    first = "\n".join(
        f'<section class="part">{_with_ids(markdown_to_html(chr(10).join(part)), toc, taken)}'
        "</section>"
        for part in _parts(first_section)
    )
    rest = _with_ids(_blocks_html(sections), toc, taken)
    contents = "\n".join(f'<li><a href="#{slug}">{text}</a></li>' for slug, text in toc)
    page = f"""<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>{html.escape(title)}</title>
<style>{STYLE}</style>
</head>
<body>
<nav aria-label="Contents"><h2>Contents</h2><ol>
{contents}
</ol></nav>
<main>
<h1>{_inline(title)}</h1>
<section class="first">
{first}
</section>
<details class="about"><summary>About this report: what it shows, the software and the
settings of the run</summary>
{markdown_to_html(chr(10).join([*intro, *about]))}
</details>
{rest}
</main>
</body>
</html>
"""
    out = Path(path)
    out.write_text(page, encoding="utf-8")
    return out
