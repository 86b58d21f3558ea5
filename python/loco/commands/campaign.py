"""``loco campaign status DIR``: the progress of the campaign stores under a directory.

A store is a ``campaign.json`` and its ``samples/`` (:mod:`loco.store`); ``DIR`` may be one store,
a stage of ``loco reproduce`` (``<out>/<stage>``) or a whole ``loco reproduce`` output. Every part
file is checked as a rerun would check it (content hash, rows), without changing anything.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from loco.commands.arguments import UsageError
from loco.store import CAMPAIGN_FILE, find_campaigns

NAME = "campaign"
HELP = "show the progress of stored campaigns (samples done, failed, damaged files)"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    sub = parser.add_subparsers(dest="action", required=True)
    status = sub.add_parser("status", help="samples stored per campaign under DIR")
    status.add_argument("dir", type=Path, help="a store, a stage directory or a reproduce output")


def _describe(meta: dict[str, object]) -> str:
    inputs = meta.get("inputs")
    if not isinstance(inputs, dict):
        return ""
    scenario = inputs.get("scenario", {})
    case = scenario.get("name") if isinstance(scenario, dict) else None
    columns = inputs.get("names", [])
    names = ", ".join(str(n) for n in columns) if isinstance(columns, list) else "?"
    return f"{case or 'custom scenario'}; columns {names}; loco {inputs.get('loco_version')}"


def run(args: argparse.Namespace) -> int:
    if not args.dir.is_dir():
        raise UsageError(f"argument dir: {args.dir} is not a directory")
    campaigns = find_campaigns(args.dir)
    if not campaigns:
        print(f"no campaign store under {args.dir}")
        return 1
    total = done = 0
    for c in campaigns:
        if c.damage is not None:
            print(
                f"{c.directory}: damaged {CAMPAIGN_FILE}: it {c.damage}; its samples cannot be "
                "counted (a rerun of the campaign writes a new description)"
            )
            continue
        total += c.n_samples
        done += c.n_done
        state = "complete" if c.n_done == c.n_samples else f"{c.n_samples - c.n_done} missing"
        print(
            f"{c.directory}: {c.n_done}/{c.n_samples} samples ({state}), {c.n_failed} failed, "
            f"{c.n_parts} part files; {_describe(c.meta)}"
        )
        for path in c.corrupt:
            print(f"  damaged, its samples will be rerun: {path}")
    print(f"{len(campaigns)} campaigns, {done}/{total} samples stored")
    return 0
