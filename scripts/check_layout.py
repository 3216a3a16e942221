#!/usr/bin/env python3
"""Checks the layout docs/ARCHITECTURE.md describes: src/ has one folder per pipeline stage,
and a file includes only from its own stage or an earlier one, with no include cycle
inside a stage; tests/unit/ mirrors src/. Prints every violation; exit status 1 if any."""
import os
import re
import sys

# Pipeline order, lowest first: the same list as docs/ARCHITECTURE.md.
STAGES = ["util", "geometry", "mesh", "sampling", "reference", "search", "distance", "certify", "files",
          "statistics", "render", "runners"]
INCLUDE = re.compile(r'^#include "([a-z_]+)/([a-z_0-9]+\.hpp)"', re.M)


def main(root):
    src = os.path.join(root, "src")
    problems = []
    folders = sorted(d for d in os.listdir(src) if os.path.isdir(os.path.join(src, d)))
    for folder in folders:
        if folder not in STAGES:
            problems.append(f"src/{folder}/ is not a stage of the pipeline")
    loose = [f for f in os.listdir(src) if os.path.isfile(os.path.join(src, f))]
    problems += [f"src/{f} lies outside every stage folder" for f in loose]
    graph = {}
    for folder in folders:
        rank = STAGES.index(folder) if folder in STAGES else -1
        for name in sorted(os.listdir(os.path.join(src, folder))):
            path = f"{folder}/{name}"
            text = open(os.path.join(src, path)).read()
            graph[path] = []
            for stage, header in INCLUDE.findall(text):
                if stage not in STAGES:
                    continue
                if not os.path.exists(os.path.join(src, stage, header)):
                    problems.append(f"src/{path} includes {stage}/{header}, which does not exist")
                if STAGES.index(stage) > rank:
                    problems.append(f"src/{path} includes {stage}/{header}: a later stage")
                if stage == folder:
                    graph[path].append(f"{stage}/{header}")
    problems += cycles(graph)
    unit = os.path.join(root, "tests", "unit")
    for d in sorted(os.listdir(unit)):
        if os.path.isdir(os.path.join(unit, d)) and d not in folders:
            problems.append(f"tests/unit/{d}/ mirrors no folder of src/")
    for p in problems:
        print(p)
    return 1 if problems else 0


def cycles(graph):
    state, found = {}, []

    def visit(node, path):
        state[node] = "open"
        for nxt in graph.get(node, []):
            if state.get(nxt) == "open":
                found.append("include cycle: " + " -> ".join(path[path.index(nxt):] + [nxt]))
            elif nxt not in state:
                visit(nxt, path + [nxt])
        state[node] = "done"

    for node in graph:
        if node not in state:
            visit(node, [node])
    return found


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..")))
