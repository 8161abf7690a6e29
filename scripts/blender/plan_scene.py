# Renders a planted layout plan (the README's layout_forest.png): the plan's polygons as flat
# ground in their colours, the sylva forest --layout glb on top, Workbench.
#   blender -b --python plan_scene.py -- OUT.png PLAN.json LAYOUT_SCALE FOREST.glb
import bpy, sys, math, json
import numpy; numpy.bool = bool
import mathutils
argv = sys.argv[sys.argv.index("--") + 1:]
out, plan_path, scale, glb = argv[0], argv[1], float(argv[2]), argv[3]
bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
bpy.ops.import_scene.gltf(filepath=glb)
for o in bpy.data.objects:
    if o.type == 'MESH':
        for m in o.data.materials:
            if m and m.use_nodes:
                b = m.node_tree.nodes.get("Principled BSDF")
                if b: m.diffuse_color = b.inputs["Base Color"].default_value
plan = json.load(open(plan_path))
def srgb(h):
    c = [int(h[i:i+2], 16) / 255 for i in (1, 3, 5)]
    return tuple(((x + 0.055) / 1.055) ** 2.4 if x > 0.04045 else x / 12.92 for x in c) + (1,)
mats = {}
for k, poly in enumerate(plan["polygons"]):
    verts = [(x * scale, y * scale, 0.0) for x, y in poly["points"]]
    me = bpy.data.meshes.new("plot%d" % k)
    me.from_pydata(verts, [], [list(range(len(verts)))])
    ob = bpy.data.objects.new("plot%d" % k, me)
    scene.collection.objects.link(ob)
    col = poly["color"]
    if col not in mats:
        m = bpy.data.materials.new(col); m.diffuse_color = srgb(col); mats[col] = m
    me.materials.append(mats[col])
pts = [mathutils.Vector((x * scale, y * scale, 0)) for p in plan["polygons"] for x, y in p["points"]]
lo = mathutils.Vector((min(p.x for p in pts), min(p.y for p in pts), 0))
hi = mathutils.Vector((max(p.x for p in pts), max(p.y for p in pts), 0))
centre = (lo + hi) / 2
size = max(hi.x - lo.x, hi.y - lo.y)
cam = bpy.data.cameras.new("cam"); cam.lens = 30
co = bpy.data.objects.new("cam", cam); scene.collection.objects.link(co)
co.location = centre + mathutils.Vector((0.0 * size, -0.8 * size, 0.6 * size))
d = centre - co.location
co.rotation_euler = d.to_track_quat('-Z', 'Y').to_euler()
scene.camera = co
scene.render.engine = 'BLENDER_WORKBENCH'
scene.display.shading.light = 'STUDIO'
scene.display.shading.color_type = 'MATERIAL'
scene.display.shading.show_shadows = True
scene.display.shading.show_cavity = False
scene.render.resolution_x = 1600; scene.render.resolution_y = 800
world = bpy.data.worlds.new("w"); scene.world = world
world.color = (0.92, 0.94, 0.96)
scene.display.shading.background_type = 'WORLD'
scene.render.filepath = out
bpy.ops.render.render(write_still=True)
