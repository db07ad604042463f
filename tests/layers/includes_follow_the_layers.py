#!/usr/bin/python3
"""The include rules of src/ (docs/development.md, "Architecture"), in one pass over the
files:

1. every #include "LAYER/..." names the file's own layer or one it may include;
2. inside src/model, a file includes its own part or one before it (the parts in the order
   of src/model/CMakeLists.txt), and no file sits directly in src/model;
3. no include cycle between units (a unit: NAME.hpp with NAME.cpp): a cycle makes the
   layers inside a folder meaningless. There is none (the nine units of model/two_level
   that were one, issue 38, are one-way since model/localization/localization_model took
   the dispatch on the localization model, each model in its own part); KNOWN_CYCLES stays
   for the record and may only shrink.

Exit 0 and one line with the counts, or 1 with a line per breach."""
from __future__ import annotations

import re
import sys
from collections import defaultdict
from pathlib import Path

SRC = Path(__file__).resolve().parents[2] / "src"

ALLOWED = {
    "model": {"model"},
    "fit": {"fit", "model"},
    "reference": {"reference", "model"},
    "map": {"map", "model"},
    "input": {"input", "run", "io", "sweep", "map", "fit", "model", "reference"},
    "io": {"io", "map", "model"},
    "sweep": {"sweep", "map", "model", "reference"},
    "run": {"run", "io", "sweep", "map", "model", "reference"},
    "engine": {"engine", "input", "run", "io", "sweep", "map", "fit", "model", "reference"},
    "report": {"report", "engine", "input", "map", "model", "reference"},
    "app": {"app", "report", "engine", "run", "io", "sweep", "input", "map", "fit", "model", "reference"},
    "python": {"python", "report", "engine", "run", "io", "sweep", "input", "map", "fit", "model", "reference"},
}
MODEL_PARTS = ["numerics", "problem", "laws", "load", "contact", "paper", "shells", "periodic", "localization", "point", "surface"]
KNOWN_CYCLES: list[set[str]] = []
INCLUDE = re.compile(r'^#include "([a-z_0-9]+)/([^"]+)"', re.M)


def cycles(graph: dict[str, set[str]]) -> list[set[str]]:
    """The strongly connected components of more than one unit (Tarjan, iterative)."""
    index, low, stack, on, out, counter = {}, {}, [], set(), [], 0
    for root in list(graph):
        if root in index:
            continue
        work = [(root, iter(sorted(graph.get(root, ()))))]
        index[root] = low[root] = counter
        counter += 1
        stack.append(root)
        on.add(root)
        while work:
            v, children = work[-1]
            child = next(children, None)
            if child is not None:
                if child not in index:
                    index[child] = low[child] = counter
                    counter += 1
                    stack.append(child)
                    on.add(child)
                    work.append((child, iter(sorted(graph.get(child, ())))))
                elif child in on:
                    low[v] = min(low[v], index[child])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[v])
            if low[v] == index[v]:
                component = set()
                while True:
                    w = stack.pop()
                    on.discard(w)
                    component.add(w)
                    if w == v:
                        break
                if len(component) > 1:
                    out.append(component)
    return out


def main() -> int:
    problems, checked = [], 0
    graph: dict[str, set[str]] = defaultdict(set)
    for folder in sorted(p for p in SRC.iterdir() if p.is_dir()):
        if folder.name not in ALLOWED:
            problems.append(f"src/{folder.name}: a folder that is no known layer (add it here and to "
                            f"docs/development.md)")
    for path in sorted(SRC.rglob("*")):
        if path.suffix not in (".hpp", ".cpp") or not path.is_file():
            continue
        relative = path.relative_to(SRC)
        layer = relative.parts[0]
        if layer not in ALLOWED:
            continue
        unit = str(relative.with_suffix(""))
        if layer == "model" and len(relative.parts) == 2:
            problems.append(f"{relative}: a file directly in src/model; it belongs in one of its parts "
                            f"({' '.join(MODEL_PARTS)})")
        for target, rest in INCLUDE.findall(path.read_text(errors="replace")):
            checked += 1
            if target not in ALLOWED[layer]:
                problems.append(f"{relative}: includes {target}/, which layer {layer} may not (allowed: "
                                f"{' '.join(sorted(ALLOWED[layer]))})")
            if layer == "model" and target == "model" and len(relative.parts) > 2:
                part, to = relative.parts[1], rest.split("/")[0]
                if to not in MODEL_PARTS:
                    problems.append(f"{relative}: includes model/{to}/, which is no part of the model")
                elif part in MODEL_PARTS and MODEL_PARTS.index(to) > MODEL_PARTS.index(part):
                    problems.append(f"{relative}: includes model/{to}/, a part after {part} (order: "
                                    f"{' '.join(MODEL_PARTS)})")
            if rest.endswith(".hpp"):
                to_unit = f"{target}/{rest[:-4]}"
                if to_unit != unit:
                    graph[unit].add(to_unit)
    for relative in sorted({p.relative_to(SRC).parts[1] for p in (SRC / "model").iterdir() if p.is_dir()}):
        if relative not in MODEL_PARTS:
            problems.append(f"src/model/{relative}: a folder that is no part of the model (add it to MODEL_PARTS "
                            f"here and to src/model/CMakeLists.txt)")
    found = cycles(graph)
    for component in found:
        if not any(component <= known for known in KNOWN_CYCLES):
            problems.append(f"an include cycle between {len(component)} units: {', '.join(sorted(component))} "
                            f"(a unit includes, through the others, itself)")
    for line in problems:
        print(line)
    if problems:
        return 1
    print(f"{checked} project includes checked in one pass: every one follows the layers; "
          f"{len(found)} include cycle(s), all known ({', '.join(str(len(c)) + ' units' for c in found) or 'none'})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
