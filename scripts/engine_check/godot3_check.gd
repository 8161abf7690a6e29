# Run by scripts/engine-check inside a Godot 3 project where `<tree>.glb` files exported
# with `--lod --profile godot` were imported through the kit's sylva_post_import.gd, and
# `forest.glb` (--instancing gpu) without it:
#   godot3-server --path PROJECT -s check.gd
# Checks, per tree: exactly one LOD level visible in each distance band; convex collision
# bodies; its materials its own (named for the tree, colour as in expected.json, the glb's
# baseColorFactor) and the wind shader on every mesh, its wind uniforms the glb material's
# sylva_wind_* extras (expected.json's "wind"); wind UV2 in [0, 1]; the tree on the ground. The forest: a node per planted tree away from the origin. Prints "ok ..." or
# "FAIL ..." lines and quits with the number of failures.
extends SceneTree

var failures = 0


func check(condition, what):
	if condition:
		print("ok   ", what)
	else:
		print("FAIL ", what)
		failures += 1


func all_nodes(node, out):
	out.append(node)
	for c in node.get_children():
		all_nodes(c, out)
	return out


func lod_index(node_name):
	var at = node_name.rfind("_LOD")
	if at < 0:
		return -1
	var digits = node_name.substr(at + 4, node_name.length() - at - 4)
	return int(digits) if digits.is_valid_integer() else -1


func close(a, b):
	return abs(a.r - b.r) < 0.01 and abs(a.g - b.g) < 0.01 and abs(a.b - b.b) < 0.01


# The glb's colour as Godot may show it: [linear, sRGB] (expected.json has both).
func matches(color, pair):
	for c in pair:
		if close(color, Color(c[0], c[1], c[2])):
			return true
	return false


# The wind the kit gave a material (its metadata, as the albedo) against the glb's extras.
func same_wind(given, extras):
	if given == null or not extras.has("sylva_wind_strength"):
		return false
	var d = given["wind_direction"]
	return abs(given["wind_strength"] - extras["sylva_wind_strength"]) < 1e-4 \
		and abs(d.x - extras["sylva_wind_direction_x"]) < 1e-4 \
		and abs(d.y - extras["sylva_wind_direction_z"]) < 1e-4 \
		and abs(given["wind_gust_frequency"] - extras["sylva_wind_gust_frequency"]) < 1e-4 \
		and abs(given["wind_flutter"] - extras["sylva_wind_flutter"]) < 1e-4


func check_tree(name, expected, wind):
	var scene = load("res://%s.glb" % name).instance()
	get_root().add_child(scene)
	var nodes = all_nodes(scene, [])
	var lod = null
	for n in nodes:
		if n.has_method("show_for_distance"):
			lod = n
	check(lod != null, "%s: the kit's LOD script is on the LOD chain's node" % name)
	if lod != null:
		var levels = []
		for c in lod.get_children():
			if lod_index(c.name) >= 0:
				levels.append(c)
		check(levels.size() == 4, "%s: 4 LOD levels (%d)" % [name, levels.size()])
		var base = lod.lod_base_distance
		var bands = [0.5 * base, 1.5 * base, 3.0 * base, 6.0 * base, 100.0 * base]
		var want = [0, 1, 2, 3, 3]
		for k in range(bands.size()):
			lod.show_for_distance(bands[k])
			var shown = []
			for level in levels:
				if level.visible:
					shown.append(lod_index(level.name))
			check(shown == [want[k]], "%s: at %.0f m exactly level %d is visible (%s)" % [name, bands[k], want[k], str(shown)])
	var bodies = 0
	var convex = 0
	for n in nodes:
		if n is StaticBody:
			bodies += 1
			for s in n.get_children():
				if s is CollisionShape and s.shape is ConvexPolygonShape and s.shape.points.size() >= 4:
					convex += 1
	check(bodies >= 2 and convex == bodies, "%s: %d collision bodies, %d with a convex shape" % [name, bodies, convex])
	var meshes = 0
	var wind_shaded = 0
	var own = 0
	var windy = 0
	var shown_wind = null
	var low = INF
	var uv2_max = 0.0
	var uv2_bad = 0
	for n in nodes:
		if not (n is MeshInstance) or n.get_parent() is StaticBody:
			continue
		meshes += 1
		for s in range(n.mesh.get_surface_count()):
			var m = n.get_surface_material(s)
			if m is ShaderMaterial and m.shader.resource_path.ends_with("sylva_wind.shader"):
				wind_shaded += 1
				var key = m.resource_name
				# The albedo the kit gave the shader (its metadata: a headless Godot keeps
				# no shader parameters).
				var albedo = m.get_meta("sylva_albedo") if m.has_meta("sylva_albedo") else null
				if expected.has(key) and key.begins_with(name + "_") and albedo != null and matches(albedo, expected[key]):
					own += 1
				else:
					print("     %s: surface material %s albedo %s" % [name, key, str(albedo)])
				var given = m.get_meta("sylva_wind") if m.has_meta("sylva_wind") else null
				if wind.has(key) and same_wind(given, wind[key]):
					windy += 1
					shown_wind = given
				else:
					print("     %s: surface material %s wind %s, the glb's %s" % [name, key, str(given), str(wind.get(key))])
			var arrays = n.mesh.surface_get_arrays(s)
			var uv2 = arrays[Mesh.ARRAY_TEX_UV2]
			for p in uv2:
				uv2_max = max(uv2_max, max(p.x, p.y))
				if p.x < -0.0001 or p.x > 1.0001 or p.y < -0.0001 or p.y > 1.0001:
					uv2_bad += 1
			for v in arrays[Mesh.ARRAY_VERTEX]:
				low = min(low, (n.global_transform * v).y)
	check(meshes > 0 and wind_shaded == own and own > 0, "%s: %d mesh surfaces on the wind shader, %d with the tree's own material and colour" % [name, wind_shaded, own])
	var summary = "none"
	if shown_wind != null:
		summary = "strength %.2f, direction (%.2f, %.2f), gusts %.2f/s, flutter %.2f" % [shown_wind["wind_strength"], shown_wind["wind_direction"].x, shown_wind["wind_direction"].y, shown_wind["wind_gust_frequency"], shown_wind["wind_flutter"]]
	check(windy == wind_shaded and windy > 0, "%s: %d of %d wind shaders carry the glb's wind (%s)" % [name, windy, wind_shaded, summary])
	check(uv2_bad == 0 and uv2_max > 0.5, "%s: wind UV2 in [0, 1] (max %.3f, %d outside)" % [name, uv2_max, uv2_bad])
	check(abs(low) < 0.01, "%s: stands on the ground (lowest y %.4f)" % [name, low])
	for key in expected.keys():
		if key.begins_with(name + "_"):
			var saved = load("res://%s.material" % key)
			check(saved != null and matches(saved.albedo_color, expected[key]), "%s: the project's %s.material has the tree's colour" % [name, key])
	scene.queue_free()


func check_forest(trees):
	var scene = load("res://forest.glb").instance()
	get_root().add_child(scene)
	var placed = 0
	for n in all_nodes(scene, []):
		var index = n.name.substr(5, n.name.length() - 5)
		if n.name.begins_with("tree_") and index.is_valid_integer() and n.translation.length() > 0.001:
			placed += 1
	check(placed == trees, "forest --instancing gpu: %d of %d trees placed by plain nodes" % [placed, trees])
	scene.queue_free()


func _init():
	var file = File.new()
	file.open("res://expected.json", File.READ)
	var expected = parse_json(file.get_as_text())
	file.close()
	for name in expected["trees"]:
		check_tree(name, expected["materials"], expected["wind"])
	check_forest(int(expected["forest_trees"]))
	quit(failures)
