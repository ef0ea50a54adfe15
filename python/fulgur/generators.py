"""The tree generators: Glassner's statistical lightning (fulgur/lightning.h),
leaders grown among point charges (fulgur/charges.h), and Matsuyama or DBM
growth in a solved Laplace field (fulgur/field.h, growth.h,
field_scene.h). Each returns its tree as a NODE_DTYPE array, ready for
Engine.post or a scene's "tree"."""
import numpy as np

from . import _convert
from ._native import ffi, lib
from .engine import preset_value
from .errors import FulgurError, check

THUNDER_KINDS = {"clap": lib.FG_THUNDER_CLAP, "rumble": lib.FG_THUNDER_RUMBLE,
                 "roar": lib.FG_THUNDER_ROAR}
SHAPE_KINDS = {"sphere": lib.FG_SHAPE_SPHERE, "box": lib.FG_SHAPE_BOX,
               "plane": lib.FG_SHAPE_PLANE, "point": lib.FG_SHAPE_POINT,
               "ground": lib.FG_SHAPE_GROUND}
SHAPE_ROLES = {"fixed": lib.FG_ROLE_FIXED, "origin": lib.FG_ROLE_ORIGIN,
               "target": lib.FG_ROLE_TARGET}


def lightning(*, skeleton=None, features=None, **settings):
    """A cloud-to-ground bolt: (nodes, report). settings are fields of
    fg_lightning_config (seed, height_m, strike_m, in_cloud_m,
    in_cloud_azimuth_deg, segment_m, turn_mean_deg, max_deviation_deg,
    lookahead_m, branch_probability, branch_length_m, branch_depth,
    listener_m, max_nodes); skeleton a (k, 3) array of points,
    root first (None: a random one); features designer thunder, a list of
    {"kind": "clap" | "rumble" | "roar", "start", "end", "amplitude"}.
    report: main_nodes (nodes 0 .. main_nodes - 1 are the main channel),
    segments, main_length_m, skeleton_length_m, in_cloud_first,
    in_cloud_nodes and in_cloud_length_m (the in-cloud channel: nodes
    in_cloud_first .. in_cloud_first + in_cloud_nodes - 1, none when
    in_cloud_m is 0), features (where each ended up: first_node, last_node,
    distance_m)."""
    cfg = _convert.fill(ffi.new("fg_lightning_config *"), settings, "lightning",
                        skip=("skeleton_points", "feature_count"))
    keep = []
    if skeleton is not None:
        pts = _convert.points(skeleton, "skeleton")
        if len(pts) < 2:
            raise ValueError(f"skeleton: {len(pts)} points, expected at least 2")
        keep.append(pts)
        cfg.skeleton_m = ffi.cast("const double *", ffi.from_buffer(pts))
        cfg.skeleton_points = len(pts)
    if features is not None:
        if isinstance(features, (str, bytes)) or not hasattr(features, "__len__"):
            raise TypeError("features: expected a list of dicts")
        if len(features) > lib.FG_THUNDER_MAX_FEATURES:
            raise ValueError(f"features: {len(features)} given, at most "
                             f"{lib.FG_THUNDER_MAX_FEATURES}")
        arr = ffi.new("fg_thunder_feature[]", max(len(features), 1))
        for i, f in enumerate(features):
            _convert.fill(ffi.addressof(arr, i), f, f"features[{i}]",
                          names={"kind": THUNDER_KINDS})
        keep.append(arr)
        cfg.features = arr if features else ffi.NULL
        cfg.feature_count = len(features)
    report = ffi.new("fg_lightning_report *")
    with _convert.Tree() as tree:
        check(lib.fg_lightning_generate(cfg, tree, report), "lightning")
        nodes = _convert.tree_array(tree)
    stretches = [{"first_node": report.features[i].first_node,
                  "last_node": report.features[i].last_node,
                  "distance_m": report.features[i].distance_m}
                 for i in range(cfg.feature_count)]
    return nodes, {"main_nodes": report.main_nodes, "segments": report.segments,
                   "main_length_m": report.main_length_m,
                   "skeleton_length_m": report.skeleton_length_m,
                   "in_cloud_first": report.in_cloud_first,
                   "in_cloud_nodes": report.in_cloud_nodes,
                   "in_cloud_length_m": report.in_cloud_length_m, "features": stretches}


def charges(charges, start_m, **settings):
    """A leader grown from start_m among point charges (k rows of [x, y, z,
    coulombs]) until it reaches the ground or the target sphere: the nodes.
    settings are fields of fg_charges_config (step_m, candidates, chosen,
    exclusion_m, max_tips, target_m, target_radius_m, max_nodes, seed)."""
    q = _convert.points(charges, "charges", width=4)
    cfg = _convert.fill(ffi.new("fg_charges_config *"), {**settings, "start_m": start_m},
                        "charges", skip=("charge_count",))
    arr = ffi.new("fg_point_charge[]", max(len(q), 1))
    for i, row in enumerate(q):
        arr[i].position_m = [float(row[0]), float(row[1]), float(row[2])]
        arr[i].charge_c = float(row[3])
    cfg.charges = arr if len(q) else ffi.NULL
    cfg.charge_count = len(q)
    with _convert.Tree() as tree:
        check(lib.fg_charges_grow(cfg, tree), "charges")
        return _convert.tree_array(tree)


def _shape_dict(shape):
    d = _convert.as_dict(shape)
    d["kind"] = {v: k for k, v in SHAPE_KINDS.items()}[shape[0].kind]
    d["role"] = {v: k for k, v in SHAPE_ROLES.items()}[shape[0].role]
    return d


def field_scene(preset, size=0):
    """The field a preset's discharge grows in (fg_field_scene_preset:
    spark_balls or plasma_ball, size nodes per axis, 0 for 65): a dict of
    grid, shapes and growth, as grow() takes them."""
    fs = ffi.new("fg_field_scene *")
    if isinstance(size, bool) or not isinstance(size, (int, np.integer)):
        raise TypeError(f"size: expected an integer, got {size!r}")
    check(lib.fg_field_scene_preset(preset_value(preset), int(size), fs), "field_scene")
    return {"grid": _convert.as_dict(ffi.addressof(fs, "grid")),
            "shapes": [_shape_dict(ffi.addressof(fs.shapes, i)) for i in range(fs.shape_count)],
            "growth": _convert.as_dict(ffi.addressof(fs, "growth"))}


def grow(preset=None, *, size=0, grid=None, shapes=None, growth=None, method="matsuyama",
         solve=None, seed=None):
    """A tree grown in a Laplace field: (nodes, report). The field is the
    preset's (field_scene) with grid (fg_grid_config fields) and growth
    (fg_growth_config fields) over it, and shapes (a list of fg_shape
    fields, kind and role by name) instead of its shapes when given; without
    a preset all three are needed. The field is solved (solve: fg_solve_config
    fields, solver "multigrid" or "sor") and grown by method "matsuyama" or
    "dbm"; seed sets growth's. report: nodes, main_nodes, steps (and DBM's
    solves), residual of the solve."""
    if method not in ("matsuyama", "dbm"):
        raise ValueError(f"method: unknown {method!r} (known: matsuyama, dbm)")
    base = field_scene(preset, size) if preset is not None else {"grid": {}, "shapes": [],
                                                                  "growth": {}}
    grid_cfg = _convert.fill(ffi.new("fg_grid_config *"), {**base["grid"], **(grid or {})}, "grid")
    growth_cfg = _convert.fill(ffi.new("fg_growth_config *"),
                               {**base["growth"], **(growth or {})}, "growth")
    if seed is not None:
        _convert.fill(growth_cfg, {"seed": seed}, "grow")
    shape_list = base["shapes"] if shapes is None else shapes
    if isinstance(shape_list, (str, bytes)) or not hasattr(shape_list, "__len__"):
        raise TypeError("shapes: expected a list of dicts")
    if len(shape_list) > lib.FG_FIELD_MAX_SHAPES:
        raise ValueError(f"shapes: {len(shape_list)} given, at most {lib.FG_FIELD_MAX_SHAPES}")
    shape_arr = ffi.new("fg_shape[]", max(len(shape_list), 1))
    for i, sh in enumerate(shape_list):
        _convert.fill(ffi.addressof(shape_arr, i), sh, f"shapes[{i}]",
                      names={"kind": SHAPE_KINDS, "role": SHAPE_ROLES})
    solve_cfg = _convert.fill(ffi.new("fg_solve_config *"), solve, "solve",
                              names={"solver": {"multigrid": lib.FG_SOLVER_MULTIGRID,
                                                "sor": lib.FG_SOLVER_SOR}})
    out = ffi.new("fg_field **")
    check(lib.fg_field_create(grid_cfg, out), "grow: grid")
    field = out[0]
    try:
        bad = ffi.new("size_t *")
        code = lib.fg_field_set_shapes(field, shape_arr, len(shape_list), bad)
        if code != lib.FG_OK:
            where = f"shapes[{bad[0]}]" if bad[0] < len(shape_list) else "shapes"
            raise FulgurError(f"grow: {where}: {ffi.string(lib.fg_result_str(code)).decode()}"
                              " (a shape must cover a node of the grid; give one origin and "
                              "one target)", code)
        solved = ffi.new("fg_solve_report *")
        check(lib.fg_field_solve(field, solve_cfg, solved), "grow: solve")
        report = ffi.new("fg_growth_report *")
        with _convert.Tree() as tree:
            if method == "dbm":
                code = lib.fg_grow_dbm(field, growth_cfg, tree, report)
            else:
                source = ffi.new("fg_field_source *")
                lib.fg_field_source_init(field, source)
                code = lib.fg_grow_matsuyama(source, growth_cfg, tree, report)
            check(code, f"grow: {method}")
            nodes = _convert.tree_array(tree)
    finally:
        lib.fg_field_destroy(field)
    result = _convert.as_dict(report)
    result["residual"] = solved.residual
    return nodes, result
