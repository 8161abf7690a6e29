# Imports an export with a billboard far level into Blender (glb and, when given, the OBJ
# of the same tree), prints what each importer made of the billboard (its material, image
# and alpha), and renders the tree beside its billboard, seen from 30 degrees off a
# billboard's axis, with EEVEE (alpha clip): checks by eye that any importer shows it.
#   blender -b --python impostor_check.py -- OUT.png TREE.glb [TREE_LOD1.obj]
import bpy, sys, math
import numpy; numpy.bool = bool
argv = sys.argv[sys.argv.index("--") + 1:]
out, glb = argv[0], argv[1]
obj = argv[2] if len(argv) > 2 else None
bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene

def report(objects, label):
    for o in objects:
        if o.type != 'MESH':
            continue
        for m in o.data.materials:
            images = [n.image.name for n in m.node_tree.nodes if n.type == 'TEX_IMAGE' and n.image] \
                if m and m.use_nodes else []
            print(f"{label}: object {o.name}: material {m.name if m else None}, images {images}, "
                  f"blend {m.blend_method if m else None}, faces {len(o.data.polygons)}")

before = set(bpy.data.objects)
bpy.ops.import_scene.gltf(filepath=glb)
glb_objects = [o for o in bpy.data.objects if o not in before]
report(glb_objects, "glb")
# The tree (LOD0) on the left, the billboard (LOD1) moved to the right.
for o in glb_objects:
    if o.type == 'MESH' and "LOD1" in o.name:
        o.location.x += 14.0
if obj:
    before = set(bpy.data.objects)
    bpy.ops.wm.obj_import(filepath=obj)
    obj_objects = [o for o in bpy.data.objects if o not in before]
    report(obj_objects, "obj")
    for o in obj_objects:
        o.location.x += 28.0
        for m in o.data.materials:  # OBJ's map_d sets alpha; clip it as glTF's MASK does
            if m:
                m.blend_method = 'CLIP'

cam = bpy.data.cameras.new("cam")
co = bpy.data.objects.new("cam", cam)
scene.collection.objects.link(co)
a = math.radians(30.0)
target = (14.0, 0.0, 4.0)
co.location = (target[0] + 45 * math.sin(a), -45 * math.cos(a), 9.0)
direction = [target[i] - co.location[i] for i in range(3)]
import mathutils
co.rotation_euler = mathutils.Vector(direction).to_track_quat('-Z', 'Y').to_euler()
cam.lens = 35
scene.camera = co
sun = bpy.data.lights.new("sun", 'SUN')
sun.energy = 3.0
so = bpy.data.objects.new("sun", sun)
so.rotation_euler = (math.radians(40), 0, math.radians(30))
scene.collection.objects.link(so)
world = bpy.data.worlds.new("w")
world.color = (0.6, 0.7, 0.85)
scene.world = world
world.use_nodes = True
world.node_tree.nodes["Background"].inputs[0].default_value = (0.6, 0.7, 0.85, 1)
world.node_tree.nodes["Background"].inputs[1].default_value = 0.8
scene.render.engine = 'BLENDER_EEVEE'
scene.render.resolution_x, scene.render.resolution_y = 1200, 500
scene.render.filepath = out
bpy.ops.render.render(write_still=True)
print("rendered", out)
