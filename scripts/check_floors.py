#!/usr/bin/python3
"""Holds grainload's layout to its floors (docs/architecture.md): a source file includes only
its own floor and the floors below it, and no two concepts (a header and its source file)
include each other through any chain; and every header (tests' and benchmarks' too) opens
with its purpose, a comment on the line after `#pragma once`. Prints each finding and exits 1
when there is one.

    python3 scripts/check_floors.py [ROOT]

The floors, bottom to top: io, materials, particles, then sph, dem and fem side by side (none
includes another), coupling, app. Folders inside a floor (app/trade, app/resources) belong
to it.
"""

import pathlib
import re
import sys

FLOORS = {"io": 0, "materials": 1, "particles": 2, "sph": 3, "dem": 3, "fem": 3, "coupling": 4, "app": 5}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)\.hpp"')


def concepts(root):
    """Each concept (path without extension) and the concepts its .hpp and .cpp include."""
    graph = {}
    for floor in FLOORS:
        for path in sorted((root / floor).rglob("*")):
            if path.suffix not in (".hpp", ".cpp"):
                continue
            name = path.relative_to(root).with_suffix("").as_posix()
            edges = graph.setdefault(name, set())
            for line in path.read_text(encoding="utf-8").splitlines():
                match = INCLUDE.match(line)
                if match and match.group(1) != name and match.group(1).split("/")[0] in FLOORS:
                    edges.add(match.group(1))
    return graph


def upward(graph):
    """Includes of a higher floor, or between the side-by-side floors."""
    found = []
    for name, edges in sorted(graph.items()):
        floor = name.split("/")[0]
        for target in sorted(edges):
            other = target.split("/")[0]
            if FLOORS[other] > FLOORS[floor] or (other != floor and FLOORS[other] == FLOORS[floor]):
                found.append(f"{name} includes {target}: {other}/ is not below {floor}/")
    return found


def cycles(graph):
    """The strongly connected sets of more than one concept (Tarjan 1972), each sorted."""
    index, low, stack, on_stack, found = {}, {}, [], set(), []
    counter = [0]

    def visit(node):
        index[node] = low[node] = counter[0]
        counter[0] += 1
        stack.append(node)
        on_stack.add(node)
        for target in sorted(graph.get(node, ())):
            if target not in index:
                visit(target)
                low[node] = min(low[node], low[target])
            elif target in on_stack:
                low[node] = min(low[node], index[target])
        if low[node] == index[node]:
            component = []
            while True:
                member = stack.pop()
                on_stack.discard(member)
                component.append(member)
                if member == node:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    sys.setrecursionlimit(max(1000, 10 * len(graph)))
    for node in sorted(graph):
        if node not in index:
            visit(node)
    return sorted(found)


def headers_without_purpose(root):
    """Headers whose second line is not a comment saying what they hold."""
    found = []
    for folder in list(FLOORS) + ["tests", "bench"]:
        for path in sorted((root / folder).rglob("*.hpp")):
            lines = path.read_text(encoding="utf-8").splitlines()
            if len(lines) < 2 or not lines[1].startswith("// "):
                found.append(f"{path.relative_to(root).as_posix()} does not open with its "
                             "purpose (a comment after #pragma once)")
    return found


def main(argv):
    root = pathlib.Path(argv[1] if len(argv) > 1 else pathlib.Path(__file__).parents[1])
    graph = concepts(root)
    findings = upward(graph)
    findings += ["include cycle: " + " <-> ".join(c) for c in cycles(graph)]
    findings += headers_without_purpose(root)
    for finding in findings:
        print("check_floors: " + finding)
    if not findings:
        print(f"check_floors: {len(graph)} concepts, no upward include, no cycle, every header "
              "states its purpose")
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
