"""The modules of the Rust core form no dependency cycle.

The `crate::`, `super::` and `self::` paths (and a module's paths into its own children) of
``crates/loco-core/src/**/*.rs`` give the graph; test modules (``tests.rs``, ``tests/`` and inline
``#[cfg(test)] mod``) may use anything and are left out, and so are comments. It is checked at
three levels: the top-level modules of the crate (``contact``, ``vehicle``, ``error``, ...), the
layer folders of ``vehicle/`` (``params``, ``model``, ...), and the file modules inside
``vehicle/`` (a file together with its child modules is one node). A cycle is printed as the list
of modules it passes through.
"""

from __future__ import annotations

import re
from collections import defaultdict
from itertools import pairwise
from pathlib import Path

SRC = Path(__file__).resolve().parents[2] / "crates" / "loco-core" / "src"

_PATH_START = re.compile(r"\b(crate|super|self)::")
_IDENT = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
_TEST_MOD = re.compile(r"#\[cfg\(test\)\]\s*(?:#\[[^\]]*\]\s*)*(?:pub(?:\([^)]*\))?\s+)?mod\s")
_INLINE_MOD = re.compile(r"\bmod\s+([A-Za-z_][A-Za-z0-9_]*)\s*\{")
_BARE_USE = re.compile(r"\buse\s+([a-z_][a-z0-9_]*)::")


def module_path(file: Path) -> tuple[str, ...]:
    """The module path of a source file (``vehicle/model/mass.rs`` -> vehicle, model, mass)."""
    parts = list(file.relative_to(SRC).with_suffix("").parts)
    if parts[-1] in ("mod", "lib"):
        parts.pop()
    return tuple(parts)


def without_comments_and_tests(text: str) -> str:
    """The code of a file with comments, string contents and its test modules removed."""
    text = re.sub(r'"(?:\\.|[^"\\])*"', '""', text)
    text = re.sub(r"//[^\n]*", "", text)
    while match := _TEST_MOD.search(text):
        end = match.end()
        while text[end] not in ";{":
            end += 1
        if text[end] == "{":
            depth = 0
            for close in range(end, len(text)):
                depth += {"{": 1, "}": -1}.get(text[close], 0)
                if depth == 0:
                    end = close
                    break
        text = text[: match.start()] + text[end + 1 :]
    return text


def parse_tree(text: str, i: int) -> tuple[list[list[str]], int]:
    """The paths of the use tree starting at ``text[i]``, and the index after it."""
    prefix: list[str] = []
    while True:
        while i < len(text) and text[i].isspace():
            i += 1
        if i < len(text) and text[i] == "{":
            paths: list[list[str]] = []
            i += 1
            while True:
                while i < len(text) and text[i] in " \t\n,":
                    i += 1
                if i >= len(text) or text[i] == "}":
                    return [prefix + p for p in paths] or [prefix], i + 1
                sub, i = parse_tree(text, i)
                paths.extend(sub)
        ident = _IDENT.match(text, i)
        if not ident:
            return [prefix], i
        if ident.group() != "self" or not prefix:
            prefix.append(ident.group())
        i = ident.end()
        if text.startswith("::", i):
            i += 2
        else:
            return [prefix], i


def resolve(path: list[str], here: tuple[str, ...]) -> tuple[str, ...]:
    """The absolute path of ``path`` written in module ``here``."""
    out = list(here)
    head = 0
    if path and path[0] == "crate":
        out, head = [], 1
    while head < len(path) and path[head] in ("super", "self"):
        if path[head] == "super":
            out.pop()
        head += 1
    return tuple(out + path[head:])


def dependencies() -> dict[tuple[str, ...], set[tuple[str, ...]]]:
    """For every non-test source module, the absolute paths it names."""
    deps: dict[tuple[str, ...], set[tuple[str, ...]]] = defaultdict(set)
    modules = {module_path(f) for f in SRC.rglob("*.rs")}
    for file in SRC.rglob("*.rs"):
        here = module_path(file)
        if "tests" in here:
            continue
        code = without_comments_and_tests(file.read_text(encoding="utf-8"))
        # Inline modules shift what `self` and `super` mean: track them by their braces.
        opens = {m.end() - 1: m.group(1) for m in _INLINE_MOD.finditer(code)}
        stack: list[str | None] = []
        depth_at: list[tuple[str, ...]] = []
        current = here
        for pos, char in enumerate(code):
            if char == "{":
                stack.append(opens.get(pos))
                if opens.get(pos):
                    current = (*current, opens[pos])
            elif char == "}" and stack:
                if stack.pop():
                    current = current[:-1]
            depth_at.append(current)
        starts = [(m.start(), False) for m in _PATH_START.finditer(code)]
        starts += [(m.start(1), True) for m in _BARE_USE.finditer(code)]
        for start, bare in starts:
            scope = depth_at[start] if start < len(depth_at) else here
            if bare and (*scope, code[start:].split("::")[0]) not in modules:
                continue
            paths, _ = parse_tree(code, start)
            for path in paths:
                deps[here].add(resolve(path, scope))
    return deps


def graph(level) -> dict[str, set[str]]:
    """The edges between the nodes ``level`` maps module paths to (None: not at this level)."""
    edges: dict[str, set[str]] = defaultdict(set)
    for a, b, _ in _edges(level):
        edges[a].add(b)
    return edges


def _edges(level):
    for source, targets in dependencies().items():
        a = level(source)
        for target in targets:
            b = level(target)
            if a is not None and b is not None and a != b:
                yield a, b, "::".join(source) + " uses " + "::".join(target)


def check_acyclic(level) -> None:
    """Fails naming the cycle and, for each step of it, the paths that make it."""
    cycle = find_cycle(graph(level))
    if cycle is None:
        return
    why = defaultdict(list)
    for a, b, line in _edges(level):
        why[(a, b)].append(line)
    steps = [f"  {a} -> {b}: " + "; ".join(sorted(why[(a, b)])[:3]) for a, b in pairwise(cycle)]
    raise AssertionError("dependency cycle " + " -> ".join(cycle) + "\n" + "\n".join(steps))


def find_cycle(edges: dict[str, set[str]]) -> list[str] | None:
    """One cycle of ``edges`` as the list of its nodes, or None."""
    state: dict[str, int] = {}
    trail: list[str] = []

    def visit(node: str) -> list[str] | None:
        state[node] = 1
        trail.append(node)
        for nxt in sorted(edges.get(node, ())):
            if state.get(nxt) == 1:
                return [*trail[trail.index(nxt) :], nxt]
            if nxt not in state:
                found = visit(nxt)
                if found:
                    return found
        state[node] = 2
        trail.pop()
        return None

    for node in sorted(edges):
        if node not in state:
            found = visit(node)
            if found:
                return found
    return None


def _top(path: tuple[str, ...]) -> str | None:
    if path and ((SRC / path[0]).is_dir() or (SRC / f"{path[0]}.rs").is_file()):
        return path[0]
    return None


def _layer(path: tuple[str, ...]) -> str | None:
    return path[1] if len(path) >= 2 and path[0] == "vehicle" else None


def _file(path: tuple[str, ...]) -> str | None:
    if (
        len(path) >= 3
        and path[0] == "vehicle"
        and (SRC.joinpath(*path[:3]).with_suffix(".rs")).is_file()
    ):
        return "/".join(path[1:3])
    return None


def test_the_graph_sees_the_layers() -> None:
    edges = graph(_layer)
    assert "model" in edges["system"]
    assert "params" in edges["model"]
    assert "vehicle" in graph(_top)["batch"]
    assert "model/layout" in graph(_file)["model/structure"]


def test_top_level_modules_form_no_cycle() -> None:
    check_acyclic(_top)


def test_vehicle_layers_form_no_cycle() -> None:
    check_acyclic(_layer)


def test_vehicle_files_form_no_cycle() -> None:
    check_acyclic(_file)


def test_a_cycle_is_found_and_named() -> None:
    assert find_cycle({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == ["a", "b", "c", "a"]
    assert find_cycle({"a": {"b"}, "b": set()}) is None
