#!/usr/bin/env python3
"""Checks the layout rules of docs/ARCHITECTURE.md on the source tree (run by CTest):

1. gridcar_core (include/ and src/) includes no OMPL header;
2. no C++ source file is above 400 lines;
3. no function is above 120 lines (brace matching on code with comments and strings blanked);
4. no layer includes a header of a layer above it (core < spaces < planners < query < benchmarks <
   apps: the link order of the data flow);
5. the core's modules (include/gridcar/<module>/ with src/<module>/) include each other without
   a cycle, so that each can be read, tested and moved after the ones it uses.

Usage: check_layout.py SOURCE_DIR. Prints every violation; exit status 1 if there is any.
"""
import pathlib
import re
import sys

MAX_FILE_LINES = 400
MAX_FUNCTION_LINES = 120
CODE_DIRS = ["include", "src", "spaces", "planners", "query", "benchmarks", "apps", "tests"]
CORE_DIRS = ["include", "src"]
CORE_EXCLUDED = []
# each layer's folders, and the header folders (gridcar/<name>/) of the layers above it
LAYERS = [
    (["include", "src"], ["spaces", "planners", "query", "bench"]),
    (["spaces"], ["planners", "query", "bench"]),
    (["planners"], ["query", "bench"]),
    (["query"], ["bench"]),
    (["benchmarks"], []),
]


def blank_comments_and_strings(src):
    """The source with comments, string and character literals replaced by spaces (newlines kept)."""
    out, i, n = [], 0, len(src)
    while i < n:
        if src.startswith("//", i):
            j = src.find("\n", i)
            j = n if j < 0 else j
        elif src.startswith("/*", i):
            j = src.find("*/", i + 2)
            j = n if j < 0 else j + 2
        elif src[i] in "\"'":
            raw = re.match(r'R"([^(]*)\(', src[i - 1:]) if i > 0 and src[i - 1] == "R" and src[i] == '"' else None
            if raw:
                end = ")" + raw.group(1) + '"'
                j = src.find(end, i)
                j = n if j < 0 else j + len(end)
            else:
                j = i + 1
                while j < n and src[j] != src[i]:
                    j += 2 if src[j] == "\\" else 1
                j += 1
        else:
            out.append(src[i])
            i += 1
            continue
        out.append(re.sub(r"[^\n]", " ", src[i:j]))
        i = j
    return "".join(out)


FUNC_END = re.compile(r"(\)|\bconst|\boverride|\bnoexcept|\bfinal|\bmutable|->\s*[\w:<>,\s&*]+)\s*$")
CONTROL = re.compile(r"\b(if|for|while|switch|catch)\s*\(.*\)\s*$")


def long_functions(path):
    """(first line, last line) of top-level function bodies longer than the limit."""
    lines = blank_comments_and_strings(path.read_text(errors="replace")).split("\n")
    stack, found = [], []
    for ln, line in enumerate(lines, 1):
        for k, ch in enumerate(line):
            if ch == "{":
                before = (" ".join(lines[max(0, ln - 4):ln - 1]) + " " + line[:k]).rstrip()
                is_function = bool(FUNC_END.search(before)) and not CONTROL.search(line[:k])
                stack.append((ln, is_function))
            elif ch == "}" and stack:
                start, is_function = stack.pop()
                if is_function and not any(f for _, f in stack) and ln - start + 1 > MAX_FUNCTION_LINES:
                    found.append((start, ln))
    return found


def module_cycles(root):
    """Cycles among the core's modules, each as 'a -> b -> ... -> a' with where each edge is made."""
    edges = {}  # (from, to) -> first "file:line" making it
    for base in ("include/gridcar", "src"):
        for path in sorted((root / base).rglob("*")):
            if path.suffix not in (".h", ".hpp", ".cpp") or not path.is_file():
                continue
            parts = path.relative_to(root / base).parts
            if len(parts) < 2:
                continue
            for i, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
                m = re.match(r'\s*#\s*include\s*[<"]gridcar/(\w+)/', line)
                if m and m.group(1) != parts[0]:
                    edges.setdefault((parts[0], m.group(1)), f"{path.relative_to(root).as_posix()}:{i}")
    graph = {}
    for a, b in edges:
        graph.setdefault(a, set()).add(b)
    cycles, seen = [], set()

    def walk(node, trail):
        for nxt in sorted(graph.get(node, ())):
            if nxt in trail:
                cycle = trail[trail.index(nxt):] + [nxt]
                key = frozenset(zip(cycle, cycle[1:]))
                if key not in seen:
                    seen.add(key)
                    cycles.append(" -> ".join(cycle) + " (" + ", ".join(edges[e] for e in zip(cycle, cycle[1:])) + ")")
            elif len(trail) < 12:
                walk(nxt, trail + [nxt])

    for start in sorted(graph):
        walk(start, [start])
    return cycles


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
    problems = []
    for d in CODE_DIRS:
        for path in sorted((root / d).rglob("*")):
            if path.suffix not in (".h", ".hpp", ".cpp") or not path.is_file():
                continue
            rel = path.relative_to(root).as_posix()
            n = len(path.read_text(errors="replace").splitlines())
            if n > MAX_FILE_LINES:
                problems.append(f"{rel}: {n} lines (at most {MAX_FILE_LINES})")
            for a, b in long_functions(path):
                problems.append(f"{rel}:{a}: a function of {b - a + 1} lines (at most {MAX_FUNCTION_LINES})")
            in_core = any(rel.startswith(c + "/") for c in CORE_DIRS) and not any(rel.startswith(x + "/") for x in CORE_EXCLUDED)
            if in_core:
                for i, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
                    if re.match(r'\s*#\s*include\s*[<"]ompl/', line):
                        problems.append(f"{rel}:{i}: gridcar_core includes an OMPL header: {line.strip()}")
            for dirs, above in LAYERS:
                if not any(rel.startswith(d + "/") for d in dirs):
                    continue
                for i, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
                    m = re.match(r'\s*#\s*include\s*[<"]gridcar/(\w+)/', line)
                    if m and m.group(1) in above:
                        problems.append(f"{rel}:{i}: includes a header of a layer above it: {line.strip()}")
    for c in module_cycles(root):
        problems.append(f"the core's modules include each other in a cycle: {c}")
    for p in problems:
        print(p)
    print(f"check_layout: {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
