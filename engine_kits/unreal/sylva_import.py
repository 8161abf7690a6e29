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
  Offset is docs/wind.glsl's motion from the wind in UV channels 1 and 2, one Custom node,
  with the parameters WindStrength (cm), WindDirection, GustFrequency and Flutter), and a
  material instance per imported material, `MI_<material>`, with its BaseColor parameter
  set to that material's colour and the wind parameters to the tree's (the FBX's
  `sylva_wind_*` user properties, kept as the mesh's metadata), assigned to the mesh's
  slots.
Unreal reads FBX in the file's own unit (Sylva writes metres and says so), so the tree
arrives at its size in centimetres.
"""
import os
import re
import sys

import unreal

WIND_MATERIAL = "M_SylvaWind"

# docs/wind.glsl's sylva_wind() in HLSL for a Custom node: the offset in centimetres, Z up.
# The gust is 1 + half a 1D gradient noise of time (Hoskins's float hash, Perlin's fade).
WIND_HLSL = """
float3 along = normalize(float3(WindDirection.x, WindDirection.y, 0.0) + 1e-6);
float phase = 6.2831853 * PhaseFlutter.x;
float x = T * GustFrequency;
float i = floor(x);
float f = x - i;
float h0 = frac(i * 0.1031); h0 *= h0 + 33.33; h0 *= h0 + h0; h0 = frac(h0);
float h1 = frac((i + 1.0) * 0.1031); h1 *= h1 + 33.33; h1 *= h1 + h1; h1 = frac(h1);
float u = f * f * (3.0 - 2.0 * f);
float lean = WindStrength * (1.0 + lerp((2.0 * h0 - 1.0) * f, (2.0 * h1 - 1.0) * (f - 1.0), u));
float3 offset = along * lean * SwayFlex.x;
offset += lean * 0.35 * SwayFlex.y * sin(2.1 * T + phase) * (along + float3(0.0, 0.0, 0.3));
offset += lean * Flutter * PhaseFlutter.y * sin(11.0 * T + 3.0 * phase + 0.01 * (P.x + P.y)) *
          float3(0.5 * along.x, 0.5 * along.y, 1.0);
return offset;
"""

# The tree's wind as the FBX carries it (the mesh nodes' user properties, which Unreal's
# importer keeps as the mesh's metadata, "FBX.[node.]sylva_wind_*"): instance parameter
# values, or {} when the mesh has none (the material's defaults then apply).
def _wind_parameters(mesh):
    found = {}
    tags = unreal.EditorAssetLibrary.get_metadata_tag_values(mesh)
    for key, value in tags.items():
        name = str(key).rsplit(".", 1)[-1]
        if name.startswith("sylva_wind_"):
            found[name] = float(value)
    keys = ("sylva_wind_strength", "sylva_wind_direction_x", "sylva_wind_direction_z",
            "sylva_wind_gust_frequency", "sylva_wind_flutter")
    if not all(k in found for k in keys):
        return {}
    # Sylva's ground is (x, z) with Y up; Unreal's FBX import turns +z into -y.
    return {"WindStrength": 100.0 * found["sylva_wind_strength"],
            "GustFrequency": found["sylva_wind_gust_frequency"],
            "Flutter": found["sylva_wind_flutter"],
            "WindDirection": unreal.LinearColor(found["sylva_wind_direction_x"],
                                                -found["sylva_wind_direction_z"], 0.0, 0.0)}



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
    # World Position Offset: docs/wind.glsl's motion as one Custom node (HLSL), in centimetres
    # and Unreal's Z up; its parameters are the tree's wind (set per instance below).
    uv1 = lib.create_material_expression(material, unreal.MaterialExpressionTextureCoordinate, -1400, 500)
    uv1.set_editor_property("coordinate_index", 1)
    uv2 = lib.create_material_expression(material, unreal.MaterialExpressionTextureCoordinate, -1400, 600)
    uv2.set_editor_property("coordinate_index", 2)
    time = lib.create_material_expression(material, unreal.MaterialExpressionTime, -1400, 700)
    position = lib.create_material_expression(material, unreal.MaterialExpressionWorldPosition, -1400, 800)
    parameters = {}
    for name, default, y in (("WindStrength", 30.0, 900), ("GustFrequency", 0.15, 1000),
                             ("Flutter", 0.1, 1100)):
        p = lib.create_material_expression(material, unreal.MaterialExpressionScalarParameter, -1400, y)
        p.set_editor_property("parameter_name", name)
        p.set_editor_property("default_value", default)
        parameters[name] = p
    direction = lib.create_material_expression(material, unreal.MaterialExpressionVectorParameter, -1400, 1200)
    direction.set_editor_property("parameter_name", "WindDirection")
    direction.set_editor_property("default_value", unreal.LinearColor(1.0, 0.0, 0.0, 0.0))
    parameters["WindDirection"] = direction
    wind = lib.create_material_expression(material, unreal.MaterialExpressionCustom, -800, 700)
    wind.set_editor_property("output_type", unreal.CustomMaterialOutputType.CMOT_FLOAT3)
    wind.set_editor_property("code", WIND_HLSL)
    inputs = ["SwayFlex", "PhaseFlutter", "T", "P", "WindStrength", "GustFrequency", "Flutter",
              "WindDirection"]
    custom_inputs = []
    for name in inputs:
        i = unreal.CustomInput()
        i.set_editor_property("input_name", name)
        custom_inputs.append(i)
    wind.set_editor_property("inputs", custom_inputs)
    for source, name in ((uv1, "SwayFlex"), (uv2, "PhaseFlutter"), (time, "T"), (position, "P")):
        lib.connect_material_expressions(source, "", wind, name)
    for name, p in parameters.items():
        lib.connect_material_expressions(p, "", wind, name)
    lib.connect_material_property(wind, "", unreal.MaterialProperty.MP_WORLD_POSITION_OFFSET)
    lib.recompile_material(material)
    unreal.EditorAssetLibrary.save_loaded_asset(material)
    return material


def _assign_wind(mesh, destination):
    parent = _wind_material(destination)
    tools = unreal.AssetToolsHelpers.get_asset_tools()
    wind = _wind_parameters(mesh)
    lib = unreal.MaterialEditingLibrary
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
        for name, value in wind.items():
            if isinstance(value, float):
                lib.set_material_instance_scalar_parameter_value(instance, name, value)
            else:
                lib.set_material_instance_vector_parameter_value(instance, name, value)
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
