"""Run by scripts/engine-check in Blender 3.4 (blender -b --python blender_check.py -- ARGS).

ARGS: `fbx:TEMPLATE:LEVELS:FILE` for an FBX exported with `--lod --profile unreal`, and
`forest:FILE:TREES` for a forest glb exported with `--instancing gpu`. Imports each into an
empty scene with Blender's own importers and checks: the FBX's LOD group arrives as the
`tree` node with children tree_LOD0..n, each a mesh with three UV sets (UVs, wind sway/flex,
wind phase/flutter), two colour layers (tint, wind) and the tree's own materials, standing
on the ground (lowest point at z = 0, Blender's up) and upright (taller than wide), the
UCX_ hulls beside it; the forest places every tree (none left at the origin). Prints "ok"
or "FAIL" lines; exits with the number of failures.
"""
import sys

import bpy
import mathutils
import numpy

numpy.bool = bool  # Blender 3.4's glTF importer still uses numpy.bool

failures = 0


def check(condition, what):
    global failures
    print(("ok   " if condition else "FAIL ") + what)
    if not condition:
        failures += 1


def fresh():
    bpy.ops.wm.read_factory_settings(use_empty=True)


def world_box(objects):
    points = [o.matrix_world @ mathutils.Vector(c) for o in objects for c in o.bound_box]
    lo = mathutils.Vector([min(p[i] for p in points) for i in range(3)])
    hi = mathutils.Vector([max(p[i] for p in points) for i in range(3)])
    return lo, hi


def check_fbx(template, levels, path):
    fresh()
    bpy.ops.import_scene.fbx(filepath=path)
    group = bpy.data.objects.get("tree")
    check(group is not None, f"{template}.fbx: the LOD group node 'tree' arrives")
    if group is None:
        return
    children = sorted(o.name for o in group.children)
    want = [f"tree_LOD{i}" for i in range(levels)]
    check(children == want, f"{template}.fbx: its children are {want} ({children})")
    for name in want:
        o = bpy.data.objects.get(name)
        if o is None or o.type != 'MESH':
            check(False, f"{template}.fbx: {name} is a mesh")
            continue
        uvs = [uv.name for uv in o.data.uv_layers]
        colors = [c.name for c in o.data.color_attributes]
        materials = [m.name for m in o.data.materials]
        check(len(uvs) == 3, f"{template}.fbx: {name} has 3 UV sets {uvs}")
        check(len(colors) == 2, f"{template}.fbx: {name} has 2 colour layers {colors}")
        check(materials and all(m.startswith(f"{template}_s") for m in materials),
              f"{template}.fbx: {name}'s materials are the tree's own {materials}")
        wind = o.data.color_attributes.get("wind")
        if wind is not None:
            values = numpy.zeros(len(wind.data) * 4)
            wind.data.foreach_get("color", values)
            check(values.min() >= -1e-4 and values.max() <= 1.0001 and values.max() > 0.5,
                  f"{template}.fbx: {name}'s wind colours in [0, 1] (max {values.max():.3f})")
    meshes = [bpy.data.objects[n] for n in want if n in bpy.data.objects]
    lo, hi = world_box(meshes)
    check(abs(lo.z) < 1e-3, f"{template}.fbx: stands on the ground (lowest z {lo.z:.5f})")
    height, width = hi.z - lo.z, max(hi.x - lo.x, hi.y - lo.y)
    check(height > 1.0 and height > 0.5 * width,
          f"{template}.fbx: upright in metres ({height:.2f} m tall, {width:.2f} m wide)")
    hulls = [o.name for o in bpy.data.objects if o.name.startswith("UCX_tree_LOD0_")]
    check(len(hulls) >= 2, f"{template}.fbx: {len(hulls)} UCX_tree_LOD0_ hulls")


def check_forest(path, trees):
    fresh()
    bpy.ops.import_scene.gltf(filepath=path)
    forest = bpy.data.objects.get("forest")
    placed = [o for o in (forest.children if forest else [])
              if o.name.startswith("tree_") and o.matrix_world.translation.length > 1e-3]
    check(len(placed) == trees, f"forest --instancing gpu: {len(placed)} of {trees} trees placed")
    at_origin = [o.name for o in bpy.data.objects
                 if o.type == 'MESH' and o.matrix_world.translation.length < 1e-6]
    check(not at_origin, f"forest --instancing gpu: no mesh left at the origin ({len(at_origin)})")


for arg in sys.argv[sys.argv.index("--") + 1:]:
    kind, rest = arg.split(":", 1)
    if kind == "fbx":
        template, levels, path = rest.split(":", 2)
        check_fbx(template, int(levels), path)
    else:
        path, trees = rest.rsplit(":", 1)
        check_forest(path, int(trees))
sys.exit(failures)
