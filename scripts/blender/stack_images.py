# Stacks PNGs of one width top to bottom and scales the result to 5/8 (no ImageMagick here).
#   blender -b --python stack_images.py -- OUT.png TOP.png ... BOTTOM.png
import bpy, sys
import numpy as np
argv = sys.argv[sys.argv.index("--") + 1:]
out, files = argv[0], argv[1:]
imgs = [bpy.data.images.load(f) for f in files]
w = imgs[0].size[0]
rows = []
for im in reversed(imgs):  # Blender's pixels start at the bottom row
    a = np.array(im.pixels[:], dtype=np.float32).reshape(im.size[1], im.size[0], 4)
    rows.append(a)
full = np.concatenate(rows, axis=0)
h = full.shape[0]
res = bpy.data.images.new("stack", w, h, alpha=False)
res.pixels[:] = full.ravel()
res.scale(w * 5 // 8, h * 5 // 8)
res.filepath_raw = out
res.file_format = 'PNG'
res.save()
print("saved", out, res.size[:])
