"""Python values into fulgur's structs and arrays, checked on the way so
that nothing the C side cannot take reaches it."""
import numbers

import numpy as np

from ._native import ffi, lib
from .errors import FulgurError

# fg_node as numpy lays it out: x, y, z (metres), parent (-1 for the root),
# flags (NODE_MAIN for the main channel).
NODE_DTYPE = np.dtype([("x", "<f8"), ("y", "<f8"), ("z", "<f8"), ("parent", "<i4"),
                       ("flags", "<u4")])
assert NODE_DTYPE.itemsize == ffi.sizeof("fg_node")
NODE_MAIN = lib.FG_NODE_MAIN


def vector(value, n, what):
    """value as n float64s."""
    try:
        a = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError) as e:
        raise TypeError(f"{what}: expected {n} numbers, got {value!r}") from e
    if a.shape != (n,):
        raise ValueError(f"{what}: expected {n} numbers, got shape {a.shape}")
    return a


def points(value, what, width=3):
    """value as a C-contiguous (k, width) float64 array."""
    try:
        a = np.ascontiguousarray(value, dtype=np.float64)
    except (TypeError, ValueError) as e:
        raise TypeError(f"{what}: expected rows of {width} numbers") from e
    if a.ndim != 2 or a.shape[1] != width:
        raise ValueError(f"{what}: expected shape (k, {width}), got {a.shape}")
    return a


def _integral_column(column, lo, hi, what):
    ok = np.isfinite(column) & (column == np.floor(column)) & (column >= lo) & (column <= hi)
    if not ok.all():
        bad = int(np.argmin(ok))
        raise ValueError(f"{what}[{bad}]: {column[bad]!r} is not an integer in {lo}..{hi}")
    return column


def as_nodes(nodes, what="nodes"):
    """A tree as a C-contiguous 1-D array of NODE_DTYPE: an array of that
    dtype as it is, or rows [x, y, z, parent] / [x, y, z, parent, flags]."""
    if isinstance(nodes, np.ndarray) and nodes.dtype.names is not None:
        if nodes.dtype != NODE_DTYPE:
            raise TypeError(f"{what}: a structured array must have fulgur.NODE_DTYPE, "
                            f"not {nodes.dtype}")
        if nodes.ndim != 1:
            raise ValueError(f"{what}: expected one dimension, got shape {nodes.shape}")
        return np.ascontiguousarray(nodes)
    try:
        a = np.asarray(nodes, dtype=np.float64)
    except (TypeError, ValueError) as e:
        raise TypeError(f"{what}: expected rows of [x, y, z, parent(, flags)] numbers") from e
    if a.ndim != 2 or a.shape[1] not in (4, 5):
        raise ValueError(f"{what}: expected shape (n, 4) or (n, 5), got {a.shape}")
    out = np.zeros(a.shape[0], dtype=NODE_DTYPE)
    out["x"], out["y"], out["z"] = a[:, 0], a[:, 1], a[:, 2]
    out["parent"] = _integral_column(a[:, 3], -1, 2**31 - 1, f"{what} parent")
    if a.shape[1] == 5:
        out["flags"] = _integral_column(a[:, 4], 0, 2**32 - 1, f"{what} flags")
    return out


def node_pointer(nodes):
    """(fg_node *, count) borrowing nodes' memory (keep nodes alive)."""
    if len(nodes) == 0:
        return ffi.NULL, 0
    return ffi.cast("const fg_node *", ffi.from_buffer(nodes)), len(nodes)


def tree_fault(nodes):
    """fulgur's sentence for what is wrong with a NODE_DTYPE array, or None."""
    fault = ffi.new("fg_tree_fault *")
    ptr, n = node_pointer(nodes)
    if ptr == ffi.NULL or lib.fg_tree_check(ptr, n, fault) == lib.FG_OK:
        return None if ptr != ffi.NULL else "the tree has no node"
    text = ffi.new("char[160]")
    lib.fg_tree_fault_describe(fault, text, 160)
    return ffi.string(text).decode()


def tree_array(tree):
    """A copy of an fg_tree's nodes as NODE_DTYPE."""
    n = lib.fg_tree_count(tree)
    if n == 0:
        return np.zeros(0, dtype=NODE_DTYPE)
    data = ffi.buffer(lib.fg_tree_nodes(tree), n * NODE_DTYPE.itemsize)
    return np.frombuffer(data, dtype=NODE_DTYPE).copy()


class Tree:
    """An fg_tree for the generators to fill, freed on leaving."""

    def __enter__(self):
        out = ffi.new("fg_tree **")
        code = lib.fg_tree_create(0, out)
        if code != lib.FG_OK:
            raise FulgurError("fg_tree_create: out of memory", code)
        self.tree = out[0]
        return self.tree

    def __exit__(self, *exc):
        lib.fg_tree_destroy(self.tree)


def _fields(ctype):
    return {name: f.type for name, f in ctype.fields}


def fill(struct, values, what, names=None, skip=()):
    """Sets struct's fields from the mapping values. names maps a field to
    {name: enum value} for fields given by name ("iso9613"); fields in skip
    (pointers the caller sets) are not accepted."""
    if values is None:
        return struct
    if not hasattr(values, "items"):
        raise TypeError(f"{what}: expected a dict of settings, got {type(values).__name__}")
    fields = _fields(ffi.typeof(struct[0]))
    known = sorted(k for k, t in fields.items() if k not in skip and t.kind != "pointer")
    for key, value in values.items():
        if key not in known:
            raise TypeError(f"{what}: unknown setting {key!r} (known: {', '.join(known)})")
        ftype = fields[key]
        if names and key in names and isinstance(value, str):
            if value not in names[key]:
                raise ValueError(f"{what}.{key}: unknown {value!r} "
                                 f"(known: {', '.join(sorted(names[key]))})")
            value = names[key][value]
        try:
            if ftype.kind == "array":
                arr = vector(value, ftype.length, f"{what}.{key}")
                if ftype.item.cname not in ("double", "float"):
                    arr = [int(v) for v in _integral_column(arr, -2**31, 2**31 - 1,
                                                            f"{what}.{key}")]
                target = getattr(struct, key)
                for i, v in enumerate(arr):
                    target[i] = v
            elif not isinstance(value, (numbers.Number, np.number)):
                raise TypeError(f"expected a number, got {type(value).__name__}")
            else:
                setattr(struct, key, int(value) if isinstance(value, bool) else value)
        except OverflowError as e:
            raise ValueError(f"{what}.{key}: {value!r} is out of range ({e})") from None
        except TypeError as e:
            raise TypeError(f"{what}.{key}: {value!r}: {e}") from None
    return struct


def as_dict(struct, skip=()):
    """A struct's fields as a dict (arrays as lists)."""
    out = {}
    for name, ftype in _fields(ffi.typeof(struct[0])).items():
        if name in skip or ftype.kind == "pointer":
            continue
        v = getattr(struct, name)
        out[name] = list(v) if ftype.kind == "array" else v
    return out
