# Sylva import script for Godot 4. Set it as the "Import Script" of a glTF (or FBX)
# exported with `sylva export --profile godot [--lod]` in the Advanced Import Settings (or
# the Import dock), with this folder copied into the project (keep the files together).
# On import it:
# - finds each LOD chain: a node whose children are named `<name>_LOD<i>` for two or more i
#   (the glb's `tree` with `tree_LOD0`..`tree_LOD3`) and gives every mesh of level i
#   Godot 4's visibility range [begin_i, end_i): level 0 from 0 to D, level i from
#   D * 2^(i-1) to D * 2^i, the last without end; D is 2.5 times the height of level 0, so
#   a 10 m tree switches at 25, 50 and 100 m. The renderer then draws exactly one level at
#   any distance, no script at run time;
# - gives every mesh surface (not the collision bodies) a ShaderMaterial of
#   sylva_wind.gdshader with the surface's imported albedo colour, so the tree sways with
#   the wind data in UV2 and keeps its colours and vertex tint, and sets the shader's wind
#   (wind_strength, wind_direction, wind_gust_frequency, wind_flutter) to the tree's: the
#   `sylva_wind_*` extras of the glb's material of that name, read from the file itself.
#   A material without them keeps the shader's defaults.
# Collision needs nothing here: Godot's importer makes the `-convcolonly` nodes
# StaticBody3D nodes with a ConvexPolygonShape3D each, and the materials are already the
# tree's own (their names carry the template and seed, so two trees never share one).
@tool
extends EditorScenePostImport

const LOD_DISTANCE_PER_HEIGHT = 2.5


func _post_import(scene):
	var kit = get_script().resource_path.get_base_dir()
	var shader = load(kit + "/sylva_wind.gdshader")
	_setup_lods(scene)
	_setup_wind(scene, shader, wind_extras(get_source_file()))
	return scene


# The glTF file's material extras by material name ({} for a file that is not glTF): the
# JSON chunk of a .glb, or the whole .gltf.
static func wind_extras(path):
	var out = {}
	var file = FileAccess.open(path, FileAccess.READ)
	if file == null:
		return out
	var text = ""
	if file.get_32() == 0x46546C67:  # "glTF": a binary glTF's header, then its JSON chunk
		file.get_32()
		file.get_32()
		var length = file.get_32()
		file.get_32()
		text = file.get_buffer(length).get_string_from_utf8()
	else:
		file.seek(0)
		text = file.get_as_text()
	var doc = JSON.parse_string(text)
	if typeof(doc) != TYPE_DICTIONARY or not doc.has("materials"):
		return out
	for m in doc["materials"]:
		if m.has("name") and m.has("extras") and typeof(m["extras"]) == TYPE_DICTIONARY:
			out[m["name"]] = m["extras"]
	return out


# The shader's wind uniforms from a material's extras; {} without them.
static func wind_uniforms(extras):
	for k in ["sylva_wind_strength", "sylva_wind_direction_x", "sylva_wind_direction_z",
			"sylva_wind_gust_frequency", "sylva_wind_flutter"]:
		if not extras.has(k):
			return {}
	return {
		"wind_strength": float(extras["sylva_wind_strength"]),
		"wind_direction": Vector2(extras["sylva_wind_direction_x"], extras["sylva_wind_direction_z"]),
		"wind_gust_frequency": float(extras["sylva_wind_gust_frequency"]),
		"wind_flutter": float(extras["sylva_wind_flutter"]),
	}


# "tree_LOD2" -> 2; -1 for a name without the suffix.
static func lod_index(node_name):
	var at = node_name.rfind("_LOD")
	if at < 0:
		return -1
	var digits = node_name.substr(at + 4)
	return int(digits) if digits.is_valid_int() else -1


func _setup_lods(node):
	var levels = {}
	for child in node.get_children():
		var i = lod_index(String(child.name))
		if i >= 0:
			levels[i] = child
	if levels.size() >= 2 and levels.has(0):
		var base = LOD_DISTANCE_PER_HEIGHT * max(_height(levels[0]), 1.0)
		for i in levels.keys():
			var begin = 0.0 if i == 0 else base * pow(2.0, i - 1)
			var end = 0.0 if i == levels.size() - 1 else base * pow(2.0, i)
			for mesh in _meshes(levels[i]):
				mesh.visibility_range_begin = begin
				mesh.visibility_range_end = end
		return
	for child in node.get_children():
		_setup_lods(child)


func _meshes(node):
	var out = []
	if node is MeshInstance3D:
		out.append(node)
	for child in node.get_children():
		out += _meshes(child)
	return out


# The height of the meshes under `node`, in the node's parent's space.
func _height(node):
	var low = INF
	var high = -INF
	for mesh in _meshes(node):
		var box = mesh.get_aabb()
		var to_parent = Transform3D()
		var n = mesh
		while n != node.get_parent():
			to_parent = n.transform * to_parent
			n = n.get_parent()
		for k in range(8):
			var y = (to_parent * box.get_endpoint(k)).y
			low = min(low, y)
			high = max(high, y)
	return high - low if high > low else 0.0


func _setup_wind(node, shader, extras):
	if node is StaticBody3D:
		return
	if node is MeshInstance3D and node.mesh:
		for s in range(node.mesh.get_surface_count()):
			var imported = node.get_surface_override_material(s)
			if imported == null:
				imported = node.mesh.surface_get_material(s)
			var material = ShaderMaterial.new()
			material.shader = shader
			if imported is BaseMaterial3D:
				material.set_shader_parameter("albedo", imported.albedo_color)
				material.set_meta("sylva_albedo", imported.albedo_color)
				material.resource_name = imported.resource_name
				var wind = wind_uniforms(extras.get(imported.resource_name, {}))
				for uniform in wind.keys():
					material.set_shader_parameter(uniform, wind[uniform])
				if not wind.is_empty():
					material.set_meta("sylva_wind", wind)
			node.set_surface_override_material(s, material)
	for child in node.get_children():
		_setup_wind(child, shader, extras)
