# SPDX-License-Identifier: MIT
# Godot 3 (Physics2DServer, GDScript, headless) behind tilesweep's resolver protocol. File mode
# reads the scene lines of IN and writes one answer line per scene to OUT, in order, each put on
# disk before the next scene is read; follow mode (run.sh's pipe mode) answers lines as they are
# appended to IN. Written the way a Godot user writes a tile platformer's mover, not tuned to the
# contract:
#
#   - the map is built as TileMap builds it: per solid cell a static body at the cell's top-left
#     corner holding one RectangleShape2D of the tile's half size, offset by that half size;
#   - a one-way cell ('-') is the same body with its shape set one-way as a TileSet's one-way
#     collision sets it (body_set_shape_as_one_way_collision, TileSet's default margin 1 px):
#     Godot then blocks only motion along the shape's +y, down the screen, onto its top;
#   - the box is a kinematic body built the same way (origin at its top-left corner);
#   - per frame, what move_and_slide does with two slides at most: body_test_motion (what
#     move_and_collide calls) with Godot's default safe margin 0.08, the body moved by the
#     returned motion, the remainder slid along the collision normal and tried again;
#   - each collision is a contact: the tile from the collider's body, the normal the dominant
#     axis of collision_normal, t the fraction of the frame elapsed at the hit;
#   - started_overlapping is computed from the map by the contract's definition (interiors
#     intersect), since Godot counts touching as overlapping.
#
#     godot3-server --no-window -s adapter.gd IN OUT                       (run.sh IN OUT)
#     godot3-server --no-window -s adapter.gd --follow IN OUT WATCHED_PID  (run.sh, pipe mode)
extends SceneTree

# Godot's default safe margin (KinematicBody2D.collision/safe_margin), in pixels.
const SAFE_MARGIN = 0.08
# Godot's 2D broad phase (BroadPhase2DHashGrid, physics/2d/cell_size 128) walks every cell of a
# query's bounds, after turning them into int32 cell numbers. A move that would make it walk more
# cells than this, or whose bounds leave the int32 range of cells (2^38 pixels: undefined in
# Godot, 4 to 10 s a scene here; a move of (-1.8e17, -6.4e37) never returned), is
# refused with an error line, as a game would refuse such a speed, instead of stalling the
# batch; so is a map that reaches past that range. 2^30 cells took 2 to 4.5 s, and a batch of a
# thousand scenes near 2^22 cells each took minutes; 2^16 cells is a straight move of 2^23
# pixels, or 2^15 on both axes.
const BROADPHASE_CELL = 128.0
const MAX_BROADPHASE_CELLS = 1 << 16
# Bodies made at start (a map that needs more doubles the pool), and where unused ones wait.
# 256 bodies take about 0.05 s to make; 1,024 took 0.25 s, paid by every batch.
const POOL_START = 256
const PARKED = Transform2D(0, Vector2(-1e30, -1e30))

var ps = Physics2DServer
var space
var box_body
var box_shape
var owner_ref = Reference.new()  # bodies need an object instance id (intersect_shape crashes without)
var motion_result = Physics2DTestMotionResult.new()
var bits_buffer = StreamPeerBuffer.new()

# TileSet's default one-way collision margin (tile_set_shape_one_way_margin), in pixels.
const ONE_WAY_MARGIN = 1.0

var pool = []            # static bodies; the first `active` are the current scene's solid and one-way cells
var pool_shapes = []     # each body's rectangle
var pool_half = []       # each rectangle's half size
var pool_one_way = []    # whether each body's shape is one-way
var active = 0
var pool_index_of = {}   # body RID id -> index in pool
var cell_of = []         # pool index -> [i, j] for the current scene
var box_half = Vector2(-1, -1)

var error = ""           # set by the readers: "field: problem"
var hex_cache = {}       # hexfloat text -> its float32 value


func _init():
	var args = Array(OS.get_cmdline_args())
	var follow = args.find("--follow")
	if args.size() < 2 or (follow >= 0 and args.size() < follow + 4):
		printerr("usage: godot3-server --no-window -s adapter.gd IN OUT")
		printerr("       godot3-server --no-window -s adapter.gd --follow IN OUT WATCHED_PID")
		quit(2)
		return
	space = ps.space_create()
	box_shape = ps.rectangle_shape_create()
	box_body = ps.body_create()
	ps.body_set_mode(box_body, Physics2DServer.BODY_MODE_KINEMATIC)
	ps.body_add_shape(box_body, box_shape)
	ps.body_attach_object_instance_id(box_body, owner_ref.get_instance_id())
	ps.body_set_space(box_body, space)
	# The broad phase orders a cell's objects by the address of their entries (see place_map).
	# Bodies made first fill the allocator's holes, whose order depends on what ran before
	# (arguments, mode); made next, the pool's entries come in creation order whatever ran
	# before, which keeps answers the same from one batch, or mode, to another.
	# The fillers leave once the pool is made (static, they never paired with anything).
	var fillers = []
	for k in range(POOL_START):
		var filler = ps.body_create()
		ps.body_set_mode(filler, Physics2DServer.BODY_MODE_STATIC)
		ps.body_add_shape(filler, ps.rectangle_shape_create())
		ps.body_set_state(filler, Physics2DServer.BODY_STATE_TRANSFORM, PARKED)
		ps.body_set_space(filler, space)
		fillers.append(filler)
	for k in range(POOL_START):
		add_pool_body()
	for filler in fillers:
		ps.body_set_space(filler, RID())
	if follow >= 0:
		quit(follow_file(args[follow + 1], args[follow + 2], int(args[follow + 3])))
	else:
		quit(answer_file(args[args.size() - 2], args[args.size() - 1]))
	finished = true


# A script error stops _init before it quits, and Godot would then idle forever: the first idle
# frame ends such a run with an error status instead.
var finished = false


func _idle(_delta):
	if not finished:
		printerr("godot adapter: stopped by a script error (see above)")
		quit(3)
	return true


# Answers go to `out_path` one line at a time. File has no flush in Godot 3.2: closing and
# reopening puts each line on disk, so that a crash or a hang later still leaves the answers so
# far, and a reader following the file sees each answer at once.
var output = File.new()
var output_path = ""


func open_output(path):
	output_path = path
	return output.open(path, File.WRITE)


func write_answer(line):
	output.store_string(answer(line) + "\n")
	output.close()
	output.open(output_path, File.READ_WRITE)
	output.seek_end()


# File mode: every scene line of in_path, then exit.
func answer_file(in_path, out_path):
	var input = File.new()
	if input.open(in_path, File.READ) != OK:
		printerr("godot adapter: cannot read ", in_path)
		return 2
	if open_output(out_path) != OK:
		printerr("godot adapter: cannot write ", out_path)
		return 2
	while not input.eof_reached():
		var line = input.get_line()
		if line.strip_edges() != "":
			write_answer(line)
	output.close()
	input.close()
	return 0


# The line run.sh appends to the followed file when its standard input ends.
const END_OF_INPUT = "tilesweep-end-of-input"
# How long to sleep when the followed file has nothing new (milliseconds): briefly while lines
# keep coming, longer once it has been idle for a while, so that a waiting Godot costs little.
# And how many such sleeps between two looks at whether the process feeding it is alive.
const FOLLOW_POLL_MSEC = 1
const FOLLOW_IDLE_POLL_MSEC = 10
const FOLLOW_POLLS_BEFORE_IDLE = 200
const FOLLOW_POLLS_PER_LIVENESS_CHECK = 200


# Pipe mode, for run.sh without arguments (Godot 3.2 cannot read a pipe): run.sh appends its
# standard input to in_path as it comes and prints out_path as it grows; this answers each
# complete line of in_path as soon as it is there, until END_OF_INPUT, or until the process
# `watched_pid` (run.sh) is gone.
func follow_file(in_path, out_path, watched_pid):
	if open_output(out_path) != OK:
		printerr("godot adapter: cannot write ", out_path)
		return 2
	var input = File.new()
	var offset = 0
	var idle = 0
	var proc = Directory.new()
	while true:
		var lines = []
		if input.open(in_path, File.READ) == OK:
			var size = input.get_len()
			if size > offset:
				input.seek(offset)
				var bytes = input.get_buffer(size - offset)
				var end = bytes.size() - 1
				while end >= 0 and bytes[end] != 10:  # complete lines only
					end -= 1
				if end >= 0:
					lines = bytes.subarray(0, end).get_string_from_utf8().split("\n")
					offset += end + 1
			input.close()
		if lines.empty():
			idle += 1
			if idle % FOLLOW_POLLS_PER_LIVENESS_CHECK == 0 and not proc.dir_exists("/proc/%d" % watched_pid):
				break
			OS.delay_msec(FOLLOW_POLL_MSEC if idle < FOLLOW_POLLS_BEFORE_IDLE else FOLLOW_IDLE_POLL_MSEC)
			continue
		idle = 0
		for line in lines:
			if line == END_OF_INPUT:
				output.close()
				return 0
			if line.strip_edges() != "":
				write_answer(line)
	output.close()
	return 0


# ---- reading a scene --------------------------------------------------------------------------

func fail(field, problem):
	if error == "":
		error = field + ": " + problem
	return 0.0


# The float32 value nearest the exact value of a JSON number or a hexfloat string ("0x1.8p+3").
func read_scalar(value, field):
	var result
	if typeof(value) == TYPE_REAL or typeof(value) == TYPE_INT:
		result = Vector2(value, 0).x  # Godot's JSON gives a double; Vector2 rounds it to float32
	elif typeof(value) == TYPE_STRING:
		if hex_cache.has(value):
			return hex_cache[value]
		result = read_hexfloat(value, field)
		if error != "":
			return 0.0
		hex_cache[value] = result
	else:
		return fail(field, "expected a number or a hexfloat string")
	if is_nan(result) or is_inf(result):
		return fail(field, "non-finite value (or past the largest float)")
	return result


# Exact: the significant hex digits go into an integer (the first 13, 52 bits, with one sticky
# bit below them for any nonzero digit after), so mantissa * 2^exponent is an exact double, and
# converting it to float32 is the one rounding, to nearest.
func read_hexfloat(text, field):
	var bad = "expected a number or a hexfloat string like \"0x1.8p+3\", got '" + text.left(40) + "'"
	var s = text.to_lower()
	var negative = s.begins_with("-")
	if negative:
		s = s.substr(1, s.length() - 1)
	var p = s.find("p")
	if not s.begins_with("0x") or p < 0:
		return fail(field, bad)
	var exponent_text = s.substr(p + 1, s.length() - p - 1)
	var exponent_digits = exponent_text.trim_prefix("+").trim_prefix("-")
	if exponent_digits == "" or not exponent_digits.is_valid_integer() or exponent_digits.length() > 6:
		return fail(field, bad)
	var exponent = int(exponent_text)
	var body = s.substr(2, p - 2)
	var point = body.find(".")
	var whole = body if point < 0 else body.substr(0, point)
	var fraction = "" if point < 0 else body.substr(point + 1, body.length() - point - 1)
	if whole == "" and fraction == "":
		return fail(field, bad)
	fraction = fraction.rstrip("0")
	var digits = (whole + fraction).lstrip("0")
	exponent -= 4 * fraction.length()
	if digits == "":
		return -0.0 if negative else 0.0
	if not digits.is_valid_hex_number(false):
		return fail(field, bad)
	var sticky = false
	if digits.length() > 13:
		exponent += 4 * (digits.length() - 13)
		sticky = digits.substr(13, digits.length() - 13).rstrip("0") != ""
		digits = digits.substr(0, 13)
	var mantissa = 0
	var k = 0
	while k < digits.length():  # hex_to_int takes 31 bits at most: seven digits at a time
		var chunk = digits.substr(k, 7)
		mantissa = mantissa * (1 << (4 * chunk.length())) + ("0x" + chunk).hex_to_int()
		k += 7
	if sticky:
		mantissa = mantissa * 2 + 1
		exponent -= 1
	# Far below the smallest float32 it rounds to zero, far above to infinity: in between the
	# double stays exact (normal).
	var top = exponent + 4 * digits.length()
	if top > 200:
		return fail(field, "non-finite value (or past the largest float)")
	var value = 0.0 if top < -200 else Vector2(float(mantissa) * pow(2.0, exponent), 0).x
	return -value if negative else value


func read_pair(value, field):
	if typeof(value) != TYPE_ARRAY or value.size() != 2:
		fail(field, "expected [a, b]")
		return Vector2()
	return Vector2(read_scalar(value[0], field + "[0]"), read_scalar(value[1], field + "[1]"))


# The scene as a Dictionary, or null with `error` set.
func parse_scene(line):
	var parsed = JSON.parse(line)
	if parsed.error != OK:
		fail("scene", "malformed JSON: " + parsed.error_string)
		return null
	var root = parsed.result
	if typeof(root) != TYPE_DICTIONARY:
		fail("scene", "expected a JSON object")
		return null
	if typeof(root.get("map")) != TYPE_DICTIONARY:
		fail("map", "expected an object with \"origin\", \"tile\" and \"rows\"")
		return null
	var map = root["map"]
	var scene = {}
	scene.origin = read_pair(map.get("origin"), "map.origin")
	scene.tile = read_pair(map.get("tile"), "map.tile")
	if error != "":
		return null
	if not (scene.tile.x > 0 and scene.tile.y > 0):
		fail("map.tile", "tile width and height must be > 0")
		return null
	var rows = map.get("rows")
	if typeof(rows) != TYPE_ARRAY:
		fail("map.rows", "expected an array of strings")
		return null
	scene.rows = rows.size()
	scene.columns = 0
	if rows.size() > 0 and typeof(rows[0]) == TYPE_STRING:
		scene.columns = rows[0].length()
	var solid = []
	var one_way = []
	for j in range(rows.size()):
		var row = rows[j]
		if typeof(row) != TYPE_STRING:
			fail("map.rows[%d]" % j, "expected a string")
			return null
		if row.length() != scene.columns:
			fail("map.rows", "ragged rows (row %d has length %d, row 0 %d)" % [j, row.length(), scene.columns])
			return null
		var other = row.replace("#", "").replace(".", "").replace("-", "")
		if other != "":
			fail("map.rows[%d]" % j, "unknown tile character '" + other[0] + "' (use '#', '-' or '.')")
			return null
		var i = row.find("#")
		while i >= 0:
			solid.append([i, j])
			i = row.find("#", i + 1)
		i = row.find("-")
		while i >= 0:
			one_way.append([i, j])
			i = row.find("-", i + 1)
	scene.solid = solid  # [i, j] of the solid cells, by row then column
	scene.one_way = one_way  # [i, j] of the one-way cells, likewise
	# Every tile edge must be a float32 (the contract refuses the map otherwise).
	for k in range(scene.columns + 1):
		var edge = scene.origin.x + k * scene.tile.x  # exact in double
		if Vector2(edge, 0).x != edge:
			fail("map.tile", "tile edge x = origin + %d * tile is not a float" % k)
			return null
	for k in range(scene.rows + 1):
		var edge = scene.origin.y + k * scene.tile.y
		if Vector2(edge, 0).x != edge:
			fail("map.tile", "tile edge y = origin + %d * tile is not a float" % k)
			return null
	var box = root.get("box")
	if typeof(box) != TYPE_ARRAY or box.size() != 4:
		fail("box", "expected [x, y, w, h]")
		return null
	scene.pos = Vector2(read_scalar(box[0], "box[0]"), read_scalar(box[1], "box[1]"))
	scene.size = Vector2(read_scalar(box[2], "box[2]"), read_scalar(box[3], "box[3]"))
	if error != "":
		return null
	if not (scene.size.x > 0 and scene.size.y > 0):
		fail("box", "width and height must be > 0")
		return null
	var has_move = root.has("move")
	var has_moves = root.has("moves")
	if has_move and has_moves:
		fail("moves", "give either \"move\" or \"moves\", not both")
		return null
	scene.moves = []
	if has_move:
		scene.moves.append(read_pair(root["move"], "move"))
	elif not has_moves:
		fail("move", "missing field (give \"move\": [dx, dy] or \"moves\": [[dx, dy], ...])")
		return null
	else:
		var moves = root["moves"]
		if typeof(moves) != TYPE_ARRAY:
			fail("moves", "expected an array of [dx, dy]")
			return null
		if moves.size() == 0:
			fail("moves", "must not be empty")
			return null
		for k in range(moves.size()):
			scene.moves.append(read_pair(moves[k], "moves[%d]" % k))
	if error != "":
		return null
	return scene


# ---- the Godot side ---------------------------------------------------------------------------

# One static body per solid cell, as TileMap builds them (each with its own rectangle, which
# holds the same data as TileMap's shared one).
#
# The bodies are pooled, and the pool is made once at start and never leaves the space: an unused
# body is parked far away. Godot's broad phase orders the objects of a cell by the address of
# their entry, and that order decides between equally deep contacts (which of two floor tiles is
# reported) and the order of float sums; entries made once, in a fixed order, keep every scene's
# answer the same whatever scenes came before it in the batch.
func add_pool_body():
	var body = ps.body_create()
	var shape = ps.rectangle_shape_create()
	ps.body_set_mode(body, Physics2DServer.BODY_MODE_STATIC)
	ps.body_add_shape(body, shape)
	ps.body_attach_object_instance_id(body, owner_ref.get_instance_id())
	ps.body_set_state(body, Physics2DServer.BODY_STATE_TRANSFORM, PARKED)
	ps.body_set_space(body, space)
	pool_index_of[body.get_id()] = pool.size()
	pool.append(body)
	pool_shapes.append(shape)
	pool_half.append(Vector2(-1, -1))
	pool_one_way.append(false)


func place_map(scene):
	var half = scene.tile / 2
	var cells = scene.solid + scene.one_way
	var count = cells.size()
	if pool.size() < count:
		var target = pool.size()
		while target < count:
			target *= 2
		while pool.size() < target:
			add_pool_body()
	for k in range(count):
		var body = pool[k]
		if pool_half[k] != half:
			ps.shape_set_data(pool_shapes[k], half)
			ps.body_set_shape_transform(body, 0, Transform2D(0, half))
			pool_half[k] = half
		var one_way = k >= scene.solid.size()
		if pool_one_way[k] != one_way:
			ps.body_set_shape_as_one_way_collision(body, 0, one_way, ONE_WAY_MARGIN)
			pool_one_way[k] = one_way
		var cell = cells[k]
		var corner = Vector2(scene.origin.x + cell[0] * scene.tile.x, scene.origin.y + cell[1] * scene.tile.y)
		ps.body_set_state(body, Physics2DServer.BODY_STATE_TRANSFORM, Transform2D(0, corner))
	for k in range(count, active):
		ps.body_set_state(pool[k], Physics2DServer.BODY_STATE_TRANSFORM, PARKED)
	active = count
	cell_of = cells


# The int32 broad-phase cell Godot files a coordinate under. Out of the int32 range the
# conversion is undefined (INT_MIN on x86-64), and such scenes ran for 4 to 10 s each here: the
# walk then counts as endless.
func broadphase_cell(v):
	return floor(v / BROADPHASE_CELL)


func broadphase_cells_walked(pos, size, motion):
	var from_x = broadphase_cell(min(pos.x, pos.x + motion.x) - SAFE_MARGIN)
	var to_x = broadphase_cell(max(pos.x, pos.x + motion.x) + size.x + SAFE_MARGIN)
	var from_y = broadphase_cell(min(pos.y, pos.y + motion.y) - SAFE_MARGIN)
	var to_y = broadphase_cell(max(pos.y, pos.y + motion.y) + size.y + SAFE_MARGIN)
	for c in [from_x, to_x, from_y, to_y]:
		if c < -2147483648.0 or c > 2147483647.0:
			return INF
	return (to_x - from_x + 1) * (to_y - from_y + 1)


# The exact sign of a + b - c, for doubles (TwoSum: a + b = s + e exactly).
func sign_of_sum_minus(a, b, c):
	var s = a + b
	var bb = s - a
	var e = (a - (s - bb)) + (b - bb)
	if s != c:
		return 1 if s > c else -1
	return 1 if e > 0 else (-1 if e < 0 else 0)


# The solid cells whose interior meets the box's (strictly on both axes), by row then column.
func overlapped_tiles(scene, pos):
	var cells = []
	for cell in scene.solid:
		var left = scene.origin.x + cell[0] * scene.tile.x
		var top = scene.origin.y + cell[1] * scene.tile.y
		if pos.x < left + scene.tile.x and sign_of_sum_minus(pos.x, scene.size.x, left) > 0 \
				and pos.y < top + scene.tile.y and sign_of_sum_minus(pos.y, scene.size.y, top) > 0:
			cells.append(cell)
	return cells


func run_scene(scene):
	var far_corner = scene.origin + Vector2(scene.columns * scene.tile.x, scene.rows * scene.tile.y)
	if broadphase_cells_walked(scene.origin, far_corner - scene.origin, Vector2()) == INF:
		fail("map", "godot: refused: the map reaches past the int32 range of Godot's broad-phase cells")
		return null
	place_map(scene)
	var half = scene.size / 2
	if half != box_half:
		ps.shape_set_data(box_shape, half)
		ps.body_set_shape_transform(box_body, 0, Transform2D(0, half))
		box_half = half
	var pos = scene.pos
	var frames = []
	for move in scene.moves:
		var frame = {"started": overlapped_tiles(scene, pos), "contacts": []}
		# The physics step between two frames puts the server's body where the node is. A kinematic
		# body takes a new transform at once only on its first one after becoming kinematic (later
		# ones wait for the step, which this adapter never runs): so the frame starts that way.
		ps.body_set_mode(box_body, Physics2DServer.BODY_MODE_STATIC)
		ps.body_set_mode(box_body, Physics2DServer.BODY_MODE_KINEMATIC)
		ps.body_set_state(box_body, Physics2DServer.BODY_STATE_TRANSFORM, Transform2D(0, pos))
		var motion = move
		var elapsed = 0.0
		for slide in range(2):
			var walked = broadphase_cells_walked(pos, scene.size, motion)
			if walked > MAX_BROADPHASE_CELLS:
				var what = "cells out of the int32 range" if is_inf(walked) else "%d cells" % int(walked)
				fail("moves", "godot: refused: for a move of (%s, %s) from (%s, %s), Godot's broad phase would walk %s (more than 2^16: a stall)" % [motion.x, motion.y, pos.x, pos.y, what])
				return null
			# As in move_and_slide: the second slide starts from where the first ended, while the
			# server still holds the body at the frame's start.
			var hit = ps.body_test_motion(box_body, Transform2D(0, pos), motion, true, SAFE_MARGIN, motion_result)
			pos += motion_result.motion
			if not hit:
				break
			# motion_remainder is (1 - safe) * motion: the fraction done, on the longer axis.
			var rest = motion_result.motion_remainder
			var done = 0.0  # a zero motion that collides (the box starts inside or touching) is stuck
			if motion != Vector2():
				done = 1.0 - (rest.x / motion.x if abs(motion.x) >= abs(motion.y) else rest.y / motion.y)
			var t = elapsed + done * (1.0 - elapsed)
			var n = motion_result.collision_normal
			var normal = [0, -1 if n.y < 0 else 1]
			if abs(n.x) > abs(n.y):
				normal = [-1 if n.x < 0 else 1, 0]
			var index = pool_index_of.get(motion_result.collider_rid.get_id(), -1)
			if index >= 0 and index < active:
				frame.contacts.append({"tile": cell_of[index], "normal": normal, "t": Vector2(t, 0).x})
			elapsed = t
			motion = rest.slide(n)
			if motion == Vector2():
				break
		frame.pos = pos
		frames.append(frame)
	return frames


# ---- writing the answer -----------------------------------------------------------------------

func float32_bits(v):
	bits_buffer.seek(0)
	bits_buffer.put_float(v)
	bits_buffer.seek(0)
	return bits_buffer.get_u32()


# A float32 value so that it reads back to the same bits: an integer as an integer, anything
# else as a hexfloat string built from its bits.
func format_float(v):
	if v == floor(v) and abs(v) < 16777216.0 and v != 0:
		return str(int(v))
	var bits = float32_bits(v)
	var negative = bits >= 0x80000000
	if v == 0:
		return "-0" if negative else "0"
	var biased = (bits >> 23) & 0xff
	var fraction = (bits & 0x7fffff) << 1   # 24 bits: six hex digits
	var digits = ("%06x" % fraction).rstrip("0")
	if digits != "":
		digits = "." + digits
	var text
	if biased == 0:
		text = "0x0" + digits + "p-126"
	else:
		var e = biased - 127
		text = "0x1%sp%s%d" % [digits, "+" if e >= 0 else "-", abs(e)]
	return "\"" + ("-" if negative else "") + text + "\""


func format_frames(frames):
	var parts = PoolStringArray()
	for frame in frames:
		var contacts = PoolStringArray()
		for c in frame.contacts:
			contacts.append("{\"tile\": [%d, %d], \"normal\": [%d, %d], \"t\": %s}" % [c.tile[0], c.tile[1], c.normal[0], c.normal[1], format_float(c.t)])
		var started = PoolStringArray()
		for cell in frame.started:
			started.append("[%d, %d]" % [cell[0], cell[1]])
		parts.append("{\"pos\": [%s, %s], \"contacts\": [%s], \"started_overlapping\": [%s]}" % [format_float(frame.pos.x), format_float(frame.pos.y), contacts.join(", "), started.join(", ")])
	return "{\"frames\": [" + parts.join(", ") + "]}"


func format_error(message):
	return "{\"error\": " + to_json(message) + "}"


func answer(line):
	error = ""
	var scene = parse_scene(line)
	if scene == null:
		return format_error(error)
	var frames = run_scene(scene)
	if frames == null:
		# A GDScript runtime error returns null from the function it stops, with no message here.
		return format_error(error if error != "" else "godot adapter: script error (its stderr says where)")
	return format_frames(frames)
