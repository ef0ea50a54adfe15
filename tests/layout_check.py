#!/usr/bin/env python3
"""The folder rules of host/ and gpu/src/ (host/README.md, gpu/README.md).

usage: layout_check.py REPO          checks REPO/host and REPO/gpu/src
       layout_check.py --self-test   plants each kind of fault in a
                                     temporary tree and expects it found

Each folder may include (and call) only from itself and the folders it is
allowed to depend on:
  host: common <- scene <- picture <- {cli, view}; scene <- {run, scene_api, lv2}
  gpu:  context <- {field, picture}
An include names its folder ("scene/scene.h") unless it is in the same
folder. Within a folder, neither the includes nor the calls between files
may go round in a circle: file A calling a function defined in B while B
calls one defined in A is a circle. Prints one line per fault and exits 1
when there is any.
"""
import os
import re
import sys
import tempfile

RULES = {
    "host": {
        "common": {"common"},
        "scene": {"scene", "common"},
        "picture": {"picture", "scene", "common"},
        "cli": {"cli", "picture", "scene", "common"},
        "run": {"run", "scene", "common"},
        "view": {"view", "picture", "scene", "common"},
        "lv2": {"lv2", "scene", "common"},
        "scene_api": {"scene_api", "scene", "common"},
    },
    "gpu/src": {
        "context": {"context"},
        "field": {"field", "context"},
        "picture": {"picture", "context"},
    },
}

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
# A function definition as this tree writes one: at the start of a line,
# not static, the signature's ")" followed by "{" on the next line.
DEFINITION = re.compile(r"^(?!static\b|typedef\b|extern\b)[A-Za-z_][\w \t*]*?\b(\w+)\s*\([^;{}]*\)\s*\n\{", re.M)
COMMENT = re.compile(r"/\*.*?\*/|//[^\n]*", re.S)
STRING = re.compile(r'"(?:\\.|[^"\\\n])*"')


def sources(root, folders):
    """{folder: {file name: text without comments}} of the .c and .h files."""
    out = {}
    for folder in folders:
        path = os.path.join(root, folder)
        if not os.path.isdir(path):
            continue
        out[folder] = {}
        for name in sorted(os.listdir(path)):
            if name.endswith((".c", ".h")):
                with open(os.path.join(path, name), encoding="utf-8") as f:
                    out[folder][name] = COMMENT.sub(" ", f.read())
    return out


def find_cycle(graph):
    """One cycle of graph {node: set(nodes)} as a list, or None."""
    state = {}
    stack = []

    def visit(node):
        state[node] = "open"
        stack.append(node)
        for nxt in sorted(graph.get(node, ())):
            if state.get(nxt) == "open":
                return stack[stack.index(nxt):] + [nxt]
            if nxt not in state:
                found = visit(nxt)
                if found:
                    return found
        stack.pop()
        state[node] = "done"
        return None

    for node in sorted(graph):
        if node not in state:
            found = visit(node)
            if found:
                return found
    return None


def check_tree(root, top, rules):
    """The faults of root/top, one string each."""
    faults = []
    files = sources(os.path.join(root, top), rules)
    for folder in sorted(os.listdir(os.path.join(root, top))):
        path = os.path.join(root, top, folder)
        if os.path.isdir(path) and folder not in rules and any(
                n.endswith((".c", ".h")) for n in os.listdir(path)):
            faults.append(f"{top}/{folder}/: a folder the rules do not know "
                          "(add it to tests/layout_check.py and its README)")
    includes = {}  # "folder/file" -> set of "folder/file" it includes
    for folder, texts in files.items():
        for name, text in texts.items():
            here = f"{folder}/{name}"
            includes[here] = set()
            for target in INCLUDE.findall(text):
                if "/" not in target:
                    if target in texts:
                        includes[here].add(f"{folder}/{target}")
                    continue  # generated in the build tree, or a system header
                other, _, rest = target.partition("/")
                if other not in rules:
                    continue  # a public header: "fulgur/engine.h"
                if other == folder:
                    faults.append(f"{top}/{here}: includes \"{target}\": write \"{rest}\" "
                                  "within a folder")
                if other not in rules[folder]:
                    faults.append(f"{top}/{here}: includes \"{target}\": {folder}/ may "
                                  f"include only from {', '.join(sorted(rules[folder]))}")
                includes[here].add(target)
    cycle = find_cycle(includes)
    if cycle:
        faults.append(f"{top}: includes go round in a circle: {' -> '.join(cycle)}")
    # calls between the .c files of one folder
    for folder, texts in files.items():
        defined = {}
        for name, text in texts.items():
            if name.endswith(".c"):
                for fn in DEFINITION.findall(text):
                    defined[fn] = name
        calls = {}
        for name, text in texts.items():
            if not name.endswith(".c"):
                continue
            words = set(re.findall(r"\b\w+\b", STRING.sub(" ", text)))
            calls[name] = {defined[w] for w in words if w in defined and defined[w] != name}
        cycle = find_cycle(calls)
        if cycle:
            faults.append(f"{top}/{folder}: calls go round in a circle: "
                          f"{' -> '.join(cycle)}")
    return faults


def check(repo):
    faults = []
    for top, rules in RULES.items():
        faults += check_tree(repo, top, rules)
    return faults


def plant(root, files):
    for path, text in files.items():
        os.makedirs(os.path.dirname(os.path.join(root, path)), exist_ok=True)
        with open(os.path.join(root, path), "w", encoding="utf-8") as f:
            f.write(text)


def self_test():
    """Each planted fault must be found, and the clean tree pass."""
    clean = {
        "host/common/clock.h": "int now(void);\n",
        "host/common/clock.c": '#include "clock.h"\nint now(void)\n{\n    return 0;\n}\n',
        "host/run/run.h": '#include "common/clock.h"\n',
        "host/view/view.c": '#include "common/clock.h"\nint view(void)\n{\n    return now();\n}\n',
        "host/scene/a.c": "int a(void)\n{\n    return 1;\n}\n",
        "host/scene/b.c": "int b(void)\n{\n    return a(); /* b() */\n}\n",
    }
    planted = [
        ("view includes run", {"host/view/view.h": '#include "run/run.h"\n'},
         'view/view.h: includes "run/run.h"'),
        ("scene includes cli", {"host/scene/c.c": '#include "cli/render.h"\n'},
         'scene/c.c: includes "cli/render.h"'),
        ("common includes scene", {"host/common/x.c": '#include "scene/scene.h"\n'},
         'common/x.c: includes "scene/scene.h"'),
        ("a call circle", {"host/scene/a.c": "int a(void)\n{\n    return b();\n}\n"},
         "scene: calls go round in a circle: a.c -> b.c -> a.c"),
        ("an include circle", {"host/run/run_gate.h": '#include "run.h"\n',
                               "host/run/run.h": '#include "run_gate.h"\n'},
         "host: includes go round in a circle"),
        ("an unknown folder", {"host/misc/m.c": "\n"}, "host/misc/: a folder the rules"),
        ("field includes picture", {"gpu/src/field/f.c": '#include "picture/p.h"\n'},
         'gpu/src/field/f.c: includes "picture/p.h"'),
        ("picture includes view", {"host/picture/p.c": '#include "view/view.h"\n'},
         'picture/p.c: includes "view/view.h"'),
    ]
    failures = 0
    with tempfile.TemporaryDirectory() as root:
        plant(root, clean)
        os.makedirs(os.path.join(root, "gpu/src/context"))
        got = check(root)
        if got:
            print(f"self-test: the clean tree reported {got}")
            failures += 1
    for what, files, expected in planted:
        with tempfile.TemporaryDirectory() as root:
            plant(root, clean)
            os.makedirs(os.path.join(root, "gpu/src/context"))
            plant(root, files)
            got = check(root)
            if not any(expected in line for line in got):
                print(f"self-test: {what}: expected a line with {expected!r}, got {got}")
                failures += 1
    print(f"self-test: {len(planted) - failures} of {len(planted)} planted faults found"
          if failures == 0 else f"self-test: {failures} failures")
    return 1 if failures else 0


def main(argv):
    if argv[1:] == ["--self-test"]:
        return self_test()
    if len(argv) != 2:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    faults = check(argv[1])
    for line in faults:
        print(line)
    if not faults:
        print("host/ and gpu/src/: every include and call follows the folder rules")
    return 1 if faults else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
