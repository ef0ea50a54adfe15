"""Aerodynamic sound textures (fulgur/aero.h) from Python: a texture file
that `fulgur aerotex` wrote, loaded into libfulgur for Engine.post_aero
(docs/python.md, docs/aero-objects.md).

    rod = fulgur.AeroTexture("examples/aero/rod_1cm.aerotex")
    with fulgur.Engine() as e:
        voice = e.post_aero(rod, start_m=-0.25, end_m=0.25, position=[0, 3, 0],
                            axis=[0, 0, 1], normal=[1, 0, 0], wind=[10, 0, 0])
        block = e.render(256)

A texture is freed when nothing refers to it any more; an engine it was
posted to keeps it until the engine is closed (the engine borrows it).
"""
import os

from ._native import ffi, lib, scene_lib
from .errors import FulgurError

_ERR_SIZE = 512


class AeroTexture:
    """One fg_aero_texture, read from the file at path. FulgurError: the
    file cannot be opened (FG_ERR_IO) or is not a valid texture
    (FG_ERR_ARGUMENT; the message names the file and what is wrong)."""

    def __init__(self, path):
        if not isinstance(path, (str, os.PathLike)):
            raise TypeError(f"AeroTexture: expected a path, got {type(path).__name__}")
        err = ffi.new("char[]", _ERR_SIZE)
        out = ffi.new("fg_aero_texture **")
        code = scene_lib.fgs_aero_texture_load(os.fsencode(path), out, err, _ERR_SIZE)
        if code != lib.FG_OK:
            raise FulgurError(f"AeroTexture: {ffi.string(err).decode(errors='replace')}", code)
        self._handle = ffi.gc(out[0], lib.fg_aero_texture_destroy)
        d = lib.fg_aero_texture_get(self._handle)
        self.dims = d.dims
        self.reference_m = d.reference_m
        self.speed_m_s = d.speed_m_s
        self.sample_rate_hz = d.sample_rate_hz
        self.sources = d.sources
        self.frequency_hz = [d.direction[i].frequency_hz for i in range(d.directions)]
        self.path = os.fspath(path)

    def __repr__(self):
        return (f"AeroTexture({self.path!r}: {self.dims}-D, D = {self.reference_m} m, "
                f"v0 = {self.speed_m_s} m/s)")
