# Imports a glTF file into an empty Blender scene and prints what came in, as one JSON line
# after "ECOFOREST_IMPORT " (for tests/app/export_command_test.cpp).
# Run: blender -b --factory-startup --python blender_import.py -- FILE
import json
import sys
import time

# Debian 12's Blender 3.4 glTF importer uses numpy.bool, which numpy 1.24 removed.
import numpy
numpy.bool = bool

import bpy

path = sys.argv[sys.argv.index("--") + 1]
for obj in list(bpy.data.objects):
    bpy.data.objects.remove(obj)
start = time.time()
bpy.ops.import_scene.gltf(filepath=path)
seconds = time.time() - start

trees = []
for obj in bpy.data.objects:
    if obj.type != "MESH" or "id" not in obj:
        continue
    trees.append({
        "id": int(obj["id"]),
        "species": obj["species"],
        "age": int(obj["age"]),
        "height_m": float(obj["height_m"]),
        "dbh_m": float(obj["dbh_m"]),
        "vigor": float(obj["vigor"]),
        "location": list(obj.location),  # Blender's frame: z up, y = -(glTF z)
        "materials": sorted(slot.material.name for slot in obj.material_slots if slot.material),
    })
report = {
    "objects": len(bpy.data.objects),
    "meshes": len(bpy.data.meshes),
    "materials": sorted(m.name for m in bpy.data.materials),
    "seconds": seconds,
    "trees": trees,
}
print("ECOFOREST_IMPORT " + json.dumps(report))
