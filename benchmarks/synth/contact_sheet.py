# Renders a contact sheet of corpus models with Blender's Workbench engine: each model scaled to
# a unit box, turned to be seen from the front-right above, in a grid seen from the top (so the
# grid stays square on the page), labelled with its name.
# Usage: blender -b --factory-startup --python-exit-code 1 -P contact_sheet.py -- OUT.png COLUMNS MODEL_DIR...
# (each MODEL_DIR holds model.obj; its folder name is the label).
import math
import os
import sys

import bpy
from mathutils import Euler, Vector

args = sys.argv[sys.argv.index("--") + 1:]
out_png, columns, model_dirs = args[0], int(args[1]), args[2:]
rows = (len(model_dirs) + columns - 1) // columns


def read_obj(path):
    verts, faces = [], []
    with open(path) as f:
        for line in f:
            parts = line.split()
            if not parts:
                continue
            if parts[0] == "v":
                verts.append(tuple(float(x) for x in parts[1:4]))
            elif parts[0] == "f":
                faces.append([int(p.split("/")[0]) - 1 for p in parts[1:]])
    return verts, faces


scene = bpy.context.scene
for obj in list(scene.objects):  # the factory startup scene's cube, light and camera
    bpy.data.objects.remove(obj)
cell = 1.6
# World to view: the models turn so that a camera looking down -Z sees them from above-front-right.
view = (Euler((math.radians(-55), 0, 0)).to_matrix() @ Euler((0, 0, math.radians(-30))).to_matrix())
for i, model_dir in enumerate(model_dirs):
    verts, faces = read_obj(os.path.join(model_dir, "model.obj"))
    lo = Vector([min(v[k] for v in verts) for k in range(3)])
    hi = Vector([max(v[k] for v in verts) for k in range(3)])
    centre, size = (lo + hi) / 2, max(hi - lo)
    col, row = i % columns, i // columns
    offset = Vector((col * cell, -row * cell * 1.1, 0))
    mesh = bpy.data.meshes.new(os.path.basename(model_dir))
    mesh.from_pydata([tuple(view @ ((Vector(v) - centre) / size) + offset) for v in verts], [], faces)
    scene.collection.objects.link(bpy.data.objects.new(mesh.name, mesh))
    label = bpy.data.curves.new("label_%d" % i, "FONT")
    label.body = os.path.basename(os.path.normpath(model_dir))
    label.size = 0.13
    text = bpy.data.objects.new(label.name, label)
    text.location = offset + Vector((-0.6, -0.8, 2))
    scene.collection.objects.link(text)

camera = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
camera.data.type = "ORTHO"
width, height = columns * cell, rows * cell * 1.1
camera.data.ortho_scale = max(width, height) * 1.05
centre = Vector(((columns - 1) * cell / 2, -(rows - 1) * cell * 1.1 / 2 - 0.1, 0))
camera.location = centre + Vector((0, 0, 20))
scene.collection.objects.link(camera)
scene.camera = camera
scene.render.engine = "BLENDER_WORKBENCH"
scene.display.shading.light = "STUDIO"
scene.display.shading.show_cavity = True
scene.display.shading.show_object_outline = True
scene.render.resolution_x = 180 * columns
scene.render.resolution_y = int(180 * columns * height / width) if width >= height else 180 * rows
if height > width:
    scene.render.resolution_x = int(scene.render.resolution_y * width / height)
scene.render.filepath = out_png
bpy.ops.render.render(write_still=True)
