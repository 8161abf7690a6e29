# Renders .glb trees side by side on one ground line, same scale, orthographic, Workbench
# (the README's growth strip and variation strip; scripts/strips runs it).
#   blender -b --python tree_strip.py -- OUT.png SPACING A.glb B.glb ...
import bpy, sys, math
import numpy; numpy.bool = bool
argv = sys.argv[sys.argv.index("--") + 1:]
out, spacing = argv[0], float(argv[1])
files = argv[2:]
bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
for i, f in enumerate(files):
    before = set(bpy.data.objects)
    bpy.ops.import_scene.gltf(filepath=f)
    new = [o for o in bpy.data.objects if o not in before]
    for o in new:
        if o.parent is None:
            o.location.x += i * spacing
    for o in new:
        if o.type == 'MESH':
            for m in o.data.materials:
                if m and m.use_nodes:
                    b = m.node_tree.nodes.get("Principled BSDF")
                    if b: m.diffuse_color = b.inputs["Base Color"].default_value
    bpy.context.view_layer.update()
import mathutils
pts = []
for o in bpy.data.objects:
    if o.type == 'MESH':
        for c in o.bound_box:
            pts.append(o.matrix_world @ mathutils.Vector(c))
minx = min(p.x for p in pts); maxx = max(p.x for p in pts)
miny = min(p.y for p in pts); maxy = max(p.y for p in pts)
minz = min(p.z for p in pts); maxz = max(p.z for p in pts)
print("bounds", minx, maxx, miny, maxy, minz, maxz)
cam = bpy.data.cameras.new("cam"); cam.type = 'ORTHO'
width = maxx - minx; height = maxz - minz
aspect = 1600 / 420
cam.ortho_scale = max(width * 1.04, height * 1.25 * aspect)
co = bpy.data.objects.new("cam", cam); scene.collection.objects.link(co)
co.location = ((minx + maxx) / 2, miny - 50, (minz + maxz) / 2 + 50 * math.tan(math.radians(8)))
co.rotation_euler = (math.radians(82), 0, 0)
scene.camera = co
scene.render.engine = 'BLENDER_WORKBENCH'
scene.display.shading.light = 'STUDIO'
scene.display.shading.color_type = 'MATERIAL'
scene.display.shading.show_shadows = True
scene.display.shading.show_cavity = False
scene.render.resolution_x = 1600; scene.render.resolution_y = 420
scene.render.film_transparent = False
world = bpy.data.worlds.new("w"); scene.world = world
world.color = (0.92, 0.94, 0.96)
scene.display.shading.background_type = 'WORLD'
# a ground line
bpy.ops.mesh.primitive_plane_add(size=1, location=((minx + maxx) / 2, 0, 0))
g = bpy.context.active_object; g.scale = (width * 1.5, 60, 1)
gm = bpy.data.materials.new("ground"); gm.diffuse_color = (0.55, 0.5, 0.42, 1); g.data.materials.append(gm)
scene.render.filepath = out
bpy.ops.render.render(write_still=True)
