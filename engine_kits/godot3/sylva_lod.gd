# Sylva LOD switching for Godot 3, attached by sylva_post_import.gd to the node that holds a
# tree's `_LOD<i>` levels: shows exactly one level, the one whose distance band holds the
# distance from this node to the current camera (level 0 below lod_base_distance, level i
# from lod_base_distance * 2^(i-1) to lod_base_distance * 2^i, the last beyond), and hides
# the others. Godot 3's renderer does not act on GeometryInstance.lod_min_distance /
# lod_max_distance, hence a script; Godot 4 needs none (godot4/sylva_post_import.gd sets
# visibility ranges).
extends Spatial

export var lod_base_distance = 25.0
export var lod_levels = 4

var _levels = []


func _ready():
	_levels.clear()
	for child in get_children():
		var at = child.name.rfind("_LOD")
		if at >= 0 and child.name.substr(at + 4, child.name.length() - at - 4).is_valid_integer():
			_levels.append(child)
	show_for_distance(0.0)


# The level shown at `distance` metres.
func level_for_distance(distance):
	var level = 0
	var edge = lod_base_distance
	while level < lod_levels - 1 and distance >= edge:
		level += 1
		edge *= 2.0
	return level


func show_for_distance(distance):
	var level = level_for_distance(distance)
	for child in _levels:
		var at = child.name.rfind("_LOD")
		child.visible = int(child.name.substr(at + 4, child.name.length() - at - 4)) == level


func _process(_delta):
	var camera = get_viewport().get_camera() if is_inside_tree() else null
	if camera:
		show_for_distance(global_transform.origin.distance_to(camera.global_transform.origin))
