"""The command line shared by the documentation generators: ``--write`` writes the generated
page, ``--check`` exits 1 when the committed page is not what the generator makes now.

Each generator passes its page and a function from the page's current text (empty when the page
does not exist) to its new text: a whole generated page ignores the current text, a page with a
generated part splices it in.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable
from pathlib import Path


def run(page: Path, update: Callable[[str], str], script: str, description: str) -> None:
    """Parses ``--write`` / ``--check`` and writes or checks ``page`` (``script`` is the
    generator's path, named in the message of a stale page)."""
    parser = argparse.ArgumentParser(description=description)
    group = parser.add_mutually_exclusive_group(required=True)
    group.add_argument("--write", action="store_true")
    group.add_argument("--check", action="store_true")
    args = parser.parse_args()
    current = page.read_text(encoding="utf-8") if page.exists() else ""
    updated = update(current)
    if args.write:
        page.write_text(updated, encoding="utf-8")
    elif updated != current:
        print(f"{page} is out of date: run python {script} --write")
        sys.exit(1)
