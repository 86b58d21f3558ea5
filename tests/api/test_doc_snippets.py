"""Every Python example of README.md and docs/**/*.md runs as written.

The fenced ``python`` blocks of a page run in order as one script, in a temporary directory, the
way a user would paste them into a file: a name a block uses must be defined on the page, and a
snippet that starts worker processes needs its ``if __name__ == "__main__":`` guard. A block
fenced ``python no-run`` is not run; a page with no block to run is not collected. A failure names
the page, the block and the line of the page.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
#: Seconds one page's script may take (the examples are sized to run in seconds).
PAGE_TIMEOUT_S = 300

_FENCE = re.compile(r"^(\s*)(`{3,})(.*)$")


@dataclass(frozen=True)
class Block:
    """A runnable block: its page, the page line of its first code line, and its code."""

    page: str
    line: int
    code: str


def doc_pages(root: Path = ROOT) -> list[Path]:
    """README.md and every Markdown page under docs/."""
    return [root / "README.md", *sorted((root / "docs").rglob("*.md"))]


def python_blocks(text: str, page: str) -> list[Block]:
    """The blocks of ``text`` fenced ``python`` (not ``python no-run``), in page order."""
    blocks: list[Block] = []
    lines = text.splitlines()
    i = 0
    while i < len(lines):
        m = _FENCE.match(lines[i])
        if m is None:
            i += 1
            continue
        fence, info = m.group(2), m.group(3).split()
        end = i + 1
        while end < len(lines) and not lines[end].strip().startswith(fence):
            end += 1
        if info[:1] == ["python"] and "no-run" not in info[1:]:
            blocks.append(Block(page, i + 2, "\n".join(lines[i + 1 : end]) + "\n"))
        i = end + 1
    return blocks


def script_of(blocks: list[Block]) -> tuple[str, list[tuple[int, Block]]]:
    """The page's script and, for each block, the script line its code starts on."""
    parts: list[str] = []
    starts: list[tuple[int, Block]] = []
    line = 1
    for block in blocks:
        parts.append(f"# {block.page}, line {block.line}\n")
        line += 1
        starts.append((line, block))
        parts.append(block.code)
        line += block.code.count("\n")
    return "".join(parts), starts


def where(script_line: int, starts: list[tuple[int, Block]]) -> str:
    """``page, block at line L (page line P)`` for a line of the script."""
    start, block = max((s for s in starts if s[0] <= script_line), key=lambda s: s[0])
    return (
        f"{block.page}, block at line {block.line} (page line {block.line + script_line - start})"
    )


def run_page(blocks: list[Block], directory: Path) -> str | None:
    """Runs the page's blocks in ``directory``; ``None`` when they pass, else the failure."""
    script, starts = script_of(blocks)
    path = directory / "page_snippets.py"
    path.write_text(script, encoding="utf-8")
    env = {**os.environ, "MPLBACKEND": "Agg", "PYTHONDONTWRITEBYTECODE": "1"}
    done = subprocess.run(
        [sys.executable, str(path)],
        cwd=directory,
        capture_output=True,
        text=True,
        timeout=PAGE_TIMEOUT_S,
        env=env,
        check=False,
    )
    if done.returncode == 0:
        return None
    lines = [int(n) for n in re.findall(rf'File "{re.escape(str(path))}", line (\d+)', done.stderr)]
    place = where(lines[-1], starts) if lines else blocks[0].page
    tail = "\n".join(done.stderr.strip().splitlines()[-15:])
    return f"{place} failed (exit {done.returncode}):\n{tail}"


PAGES = {
    str(p.relative_to(ROOT)): blocks
    for p in doc_pages()
    if (blocks := python_blocks(p.read_text(encoding="utf-8"), str(p.relative_to(ROOT))))
}


@pytest.mark.parametrize("page", sorted(PAGES))
def test_python_examples_of_the_page_run(page: str, tmp_path: Path) -> None:
    failure = run_page(PAGES[page], tmp_path)
    assert failure is None, failure


def test_a_failing_block_is_named_by_page_and_line(tmp_path: Path) -> None:
    text = (
        "# A page\n\n```python\nx = 1\n```\n\n```python no-run\nnot run\n```\n\n"
        "```python\ny = x + 1\nprint(undefined_name)\n```\n"
    )
    blocks = python_blocks(text, "docs/page.md")
    assert [b.line for b in blocks] == [4, 12]
    failure = run_page(blocks, tmp_path)
    assert failure is not None
    assert "docs/page.md, block at line 12 (page line 13)" in failure
    assert "NameError" in failure


def test_a_page_of_no_run_blocks_is_not_collected() -> None:
    assert python_blocks("```python no-run\nimport nothing\n```\n```bash\nls\n```\n", "p") == []
    assert "README.md" in PAGES
