"""fulgur's errors as Python exceptions.

A call that fulgur refuses raises FulgurError carrying fulgur's message and
its result code (fulgur/result.h); a scene that cannot be read raises
SceneError, whose message names the JSON path as fulgur render's does
("discharges[2].tree.nodes[7]: parent 9 is not before node 7"). Arguments
that never reach the library raise TypeError or ValueError, as Python's own
functions do.
"""
from ._native import ffi, lib

_NAMES = dict(ffi.typeof("fg_result").elements)  # value -> enumerator


class FulgurError(Exception):
    """fulgur refused a call. code is the fg_result (negative), name its
    enumerator ("FG_ERR_TREE")."""

    def __init__(self, message, code):
        super().__init__(message)
        self.code = code
        self.name = _NAMES.get(code, str(code))


class SceneError(FulgurError, ValueError):
    """A scene (or a --set override) that fulgur cannot render as given."""


def describe(code):
    """fulgur's sentence for a result code."""
    return ffi.string(lib.fg_result_str(code)).decode()


def check(code, what):
    """Raises FulgurError "what: fulgur's sentence" unless code is FG_OK."""
    if code != lib.FG_OK:
        raise FulgurError(f"{what}: {describe(code)}", code)
