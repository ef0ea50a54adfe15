"""The package's C declarations (fulgur/_native.py) against the real
headers: a C program compiled with them checks every declared struct's
size and field offsets, every constant, and every function's type, so the
ABI-mode binding cannot drift from the library it loads."""
import json
import os
import re
import subprocess

from conftest import SOURCE, env_path
from fulgur import _native
from fulgur._native import CDEF, ffi

STRUCT = re.compile(r"typedef struct (\w+) \{")
ENUM = re.compile(r"typedef enum (\w+) \{([^}]*)\}")
ANON_ENUM = re.compile(r"^enum \{([^}]*)\}", re.M)
DEFINE = re.compile(r"^#define (\w+) (\d+)$", re.M)
FUNCTION = re.compile(r"^\s*(?!typedef)[\w ]+?[ *](\w+)\s*\(", re.S)
COMMENT = re.compile(r"/\*.*?\*/", re.S)


def declarations():
    """The function declarations of CDEF, as written there (const and all)."""
    text = COMMENT.sub(" ", CDEF)
    text = "\n".join(line for line in text.splitlines() if not line.startswith("#"))
    out, depth, start = [], 0, 0
    for i, ch in enumerate(text):
        depth += ch == "{"
        depth -= ch == "}"
        if ch == ";" and depth == 0:
            statement = text[start:i + 1].strip()
            start = i + 1
            m = FUNCTION.match(statement)
            if m:
                out.append((m.group(1), statement))
    return out


def program():
    head = ['#include <stdio.h>', '#include <stddef.h>', '#include "fulgur/fulgur.h"',
            '#include "fulgur/scene_api.h"']
    lines = ["int main(void)", "{", '    printf("{");']
    expected = {}
    for name in STRUCT.findall(CDEF):
        ctype = ffi.typeof(name)
        expected[f"sizeof {name}"] = ffi.sizeof(ctype)
        lines.append(f'    printf("\\"sizeof {name}\\": %zu, ", sizeof({name}));')
        for field, f in ctype.fields:
            expected[f"{name}.{field}"] = f.offset
            lines.append(f'    printf("\\"{name}.{field}\\": %zu, ", offsetof({name}, {field}));')
            expected[f"sizeof {name}.{field}"] = ffi.sizeof(f.type)
            lines.append(f'    printf("\\"sizeof {name}.{field}\\": %zu, ", '
                         f'sizeof((({name} *)0)->{field}));')
    lines.append('    printf("\\"end\\": 0}\\n");')
    lines += ["    return 0;", "}"]
    checks = []
    constants = []
    for _, body in ENUM.findall(CDEF) + [("", b) for b in ANON_ENUM.findall(CDEF)]:
        constants += [c.split("=")[0].strip() for c in body.split(",") if c.strip()]
    constants += [name for name, _ in DEFINE.findall(CDEF)]
    for name in constants:
        value = getattr(_native.lib, name)
        checks.append(f'_Static_assert({name} == {value}, "{name} is not {value}");')
    # a redeclaration must have the header's type exactly (C11 6.7p4), or
    # "conflicting types"; and every one is in the library the package loads
    functions = []
    for name, statement in declarations():
        lib = _native.scene_lib if name.startswith("fgs_") else _native.lib
        assert getattr(lib, name) is not None
        functions.append(name)
        checks.append(statement)
    return "\n".join(head + checks + lines) + "\n", expected, constants, functions


def test_declarations_match_the_headers(tmp_path):
    text, expected, constants, functions = program()
    assert len(expected) > 200 and len(constants) > 40 and len(functions) > 40
    (tmp_path / "check.c").write_text(text)
    cc = env_path("FULGUR_CC")
    built = subprocess.run(
        [cc, "-std=c11", "-Wall", "-Werror", "-Wno-unused-variable",
         "-I", os.path.join(SOURCE, "engine", "include"),
         "-I", os.path.join(SOURCE, "host", "scene_api", "include"),
         str(tmp_path / "check.c"), "-o", str(tmp_path / "check")],
        capture_output=True, text=True)
    assert built.returncode == 0, built.stderr[-4000:]
    ran = subprocess.run([str(tmp_path / "check")], capture_output=True, text=True, check=True)
    got = json.loads(ran.stdout)
    got.pop("end")
    assert got == expected


def test_a_planted_mismatch_is_caught(tmp_path):
    """The check can fail: a field moved or a function's type changed are
    compile errors or differing offsets."""
    text, _, _, _ = program()
    wrong = text.replace("float *const *out, uint32_t nframes", "float **out, uint32_t nframes")
    assert wrong != text
    (tmp_path / "bad.c").write_text(wrong)
    built = subprocess.run(
        [env_path("FULGUR_CC"), "-std=c11", "-Werror", "-c",
         "-I", os.path.join(SOURCE, "engine", "include"),
         "-I", os.path.join(SOURCE, "host", "scene_api", "include"),
         str(tmp_path / "bad.c"), "-o", str(tmp_path / "bad.o")], capture_output=True, text=True)
    assert built.returncode != 0 and "conflicting types for" in built.stderr
