"""Sylva import for Unreal Engine 5 (4.26+ with the Python Editor Script Plugin on).

Run it in the editor (Tools > Execute Python Script, or the Output Log's Python console):

    py "C:/path/sylva_import.py" "C:/trees/oak.fbx" /Game/Trees

What it does, for models exported with `sylva export --profile unreal`:
- an FBX (`--format fbx`, best with `--lod`): imports it as one static mesh (Combine Meshes
  on, Import Mesh LODs on), so the file's LOD group becomes the mesh's LOD0..LODn, and the
  `UCX_<mesh>_NN` hulls become its convex collision (auto-generated collision off);
- a chain written one file per level (`tree_LOD0.obj`, `tree_LOD1.obj`, ... or the same in
  .fbx): imports LOD0 and adds each further `_LOD<i>` file beside it as LOD i;
- then creates `M_SylvaWind` in the destination once (a material whose World Position
  Offset sways the tree by the wind in UV channel 1: the whole tree bends with sway times
  WindStrength along WindDirection, branches swing with flex), and a material instance per
  imported material, `MI_<material>`, with its BaseColor parameter set to that material's
  colour, assigned to the mesh's slots.
Unreal reads FBX in the file's own unit (Sylva writes metres and says so), so the tree
arrives at its size in centimetres.
"""
import os
import re
import sys

import unreal

WIND_MATERIAL = "M_SylvaWind"


def _fbx_options(first_level_only):
    options = unreal.FbxImportUI()
    options.import_mesh = True
    options.import_as_skeletal = False
    options.import_materials = True
    options.import_textures = False
    options.import_animations = False
    options.mesh_type_to_import = unreal.FBXImportType.FBXIT_STATIC_MESH
    data = options.static_mesh_import_data
    data.combine_meshes = True
    data.import_mesh_lo_ds = not first_level_only
    data.auto_generate_collision = False
    data.one_convex_hull_per_ucx = True
    return options


def _import(filename, destination, first_level_only=False):
    task = unreal.AssetImportTask()
    task.filename = filename
    task.destination_path = destination
    task.automated = True
    task.replace_existing = True
    task.save = True
    if filename.lower().endswith(".fbx"):
        task.options = _fbx_options(first_level_only)
    unreal.AssetToolsHelpers.get_asset_tools().import_asset_tasks([task])
    for path in task.imported_object_paths:
        asset = unreal.load_asset(path)
        if isinstance(asset, unreal.StaticMesh):
            return asset
    raise RuntimeError("no static mesh was imported from " + filename)


def _wind_material(destination):
    path = destination + "/" + WIND_MATERIAL
    if unreal.EditorAssetLibrary.does_asset_exist(path):
        return unreal.load_asset(path)
    lib = unreal.MaterialEditingLibrary
    material = unreal.AssetToolsHelpers.get_asset_tools().create_asset(
        WIND_MATERIAL, destination, unreal.Material, unreal.MaterialFactoryNew())
    material.set_editor_property("two_sided", True)
    color = lib.create_material_expression(material, unreal.MaterialExpressionVectorParameter, -600, 0)
    color.set_editor_property("parameter_name", "BaseColor")
    vertex_color = lib.create_material_expression(material, unreal.MaterialExpressionVertexColor, -600, 200)
    tinted = lib.create_material_expression(material, unreal.MaterialExpressionMultiply, -300, 100)
    lib.connect_material_expressions(color, "", tinted, "A")
    lib.connect_material_expressions(vertex_color, "", tinted, "B")
    lib.connect_material_property(tinted, "", unreal.MaterialProperty.MP_BASE_COLOR)
    roughness = lib.create_material_expression(material, unreal.MaterialExpressionConstant, -300, 300)
    roughness.set_editor_property("r", 0.9)
    lib.connect_material_property(roughness, "", unreal.MaterialProperty.MP_ROUGHNESS)
    # Offset = WindDirection * WindStrength * (sway * gust + 0.35 * flex * sin(2.1 t)),
    # in centimetres: the steady part of docs/wind.glsl's motion.
    uv = lib.create_material_expression(material, unreal.MaterialExpressionTextureCoordinate, -1400, 600)
    uv.set_editor_property("coordinate_index", 1)
    sway = lib.create_material_expression(material, unreal.MaterialExpressionComponentMask, -1200, 560)
    sway.set_editor_property("r", True)
    lib.connect_material_expressions(uv, "", sway, "")
    flex = lib.create_material_expression(material, unreal.MaterialExpressionComponentMask, -1200, 680)
    flex.set_editor_property("g", True)
    lib.connect_material_expressions(uv, "", flex, "")
    time = lib.create_material_expression(material, unreal.MaterialExpressionTime, -1400, 800)
    speed = lib.create_material_expression(material, unreal.MaterialExpressionMultiply, -1200, 800)
    speed.set_editor_property("const_b", 2.1)
    lib.connect_material_expressions(time, "", speed, "A")
    swing = lib.create_material_expression(material, unreal.MaterialExpressionSine, -1000, 800)
    swing.set_editor_property("period", 6.2831853)
    lib.connect_material_expressions(speed, "", swing, "")
    flex_swing = lib.create_material_expression(material, unreal.MaterialExpressionMultiply, -800, 700)
    flex_swing.set_editor_property("const_b", 0.35)
    flexed = lib.create_material_expression(material, unreal.MaterialExpressionMultiply, -900, 700)
    lib.connect_material_expressions(flex, "", flexed, "A")
    lib.connect_material_expressions(swing, "", flexed, "B")
    lib.connect_material_expressions(flexed, "", flex_swing, "A")
    total = lib.create_material_expression(material, unreal.MaterialExpressionAdd, -600, 600)
    lib.connect_material_expressions(sway, "", total, "A")
    lib.connect_material_expressions(flex_swing, "", total, "B")
    strength = lib.create_material_expression(material, unreal.MaterialExpressionScalarParameter, -600, 800)
    strength.set_editor_property("parameter_name", "WindStrength")
    strength.set_editor_property("default_value", 30.0)
    direction = lib.create_material_expression(material, unreal.MaterialExpressionVectorParameter, -600, 900)
    direction.set_editor_property("parameter_name", "WindDirection")
    direction.set_editor_property("default_value", unreal.LinearColor(1.0, 0.0, 0.0, 0.0))
    scaled = lib.create_material_expression(material, unreal.MaterialExpressionMultiply, -400, 700)
    lib.connect_material_expressions(total, "", scaled, "A")
    lib.connect_material_expressions(strength, "", scaled, "B")
    offset = lib.create_material_expression(material, unreal.MaterialExpressionMultiply, -200, 700)
    lib.connect_material_expressions(scaled, "", offset, "A")
    lib.connect_material_expressions(direction, "", offset, "B")
    lib.connect_material_property(offset, "", unreal.MaterialProperty.MP_WORLD_POSITION_OFFSET)
    lib.recompile_material(material)
    unreal.EditorAssetLibrary.save_loaded_asset(material)
    return material


def _assign_wind(mesh, destination):
    parent = _wind_material(destination)
    tools = unreal.AssetToolsHelpers.get_asset_tools()
    for index, slot in enumerate(mesh.get_editor_property("static_materials")):
        imported = slot.get_editor_property("material_interface")
        name = "MI_" + str(slot.get_editor_property("material_slot_name"))
        instance = tools.create_asset(name, destination, unreal.MaterialInstanceConstant,
                                      unreal.MaterialInstanceConstantFactoryNew())
        unreal.MaterialEditingLibrary.set_material_instance_parent(instance, parent)
        if imported is not None:
            found, color = imported.get_vector_parameter_value("DiffuseColor") \
                if hasattr(imported, "get_vector_parameter_value") else (False, None)
            if found:
                unreal.MaterialEditingLibrary.set_material_instance_vector_parameter_value(
                    instance, "BaseColor", color)
        unreal.EditorAssetLibrary.save_loaded_asset(instance)
        mesh.set_material(index, instance)
    unreal.EditorAssetLibrary.save_loaded_asset(mesh)


def import_tree(filename, destination="/Game/Trees"):
    """Imports one Sylva export (or the LOD0 file of a per-level chain); returns the mesh."""
    match = re.match(r"(.*)_LOD0(\.[^.]+)$", filename)
    mesh = _import(filename, destination, first_level_only=bool(match))
    if match:
        level = 1
        while os.path.exists("%s_LOD%d%s" % (match.group(1), level, match.group(2))):
            unreal.EditorStaticMeshLibrary.import_lod(
                mesh, level, "%s_LOD%d%s" % (match.group(1), level, match.group(2)))
            level += 1
    _assign_wind(mesh, destination)
    return mesh


if __name__ == "__main__":
    if len(sys.argv) < 2:
        raise SystemExit("usage: sylva_import.py FILE [DESTINATION]")
    import_tree(sys.argv[1], sys.argv[2] if len(sys.argv) > 2 else "/Game/Trees")
