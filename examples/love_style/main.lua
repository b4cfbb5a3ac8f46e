-- SPDX-License-Identifier: MIT
-- tilesweep from LuaJIT's FFI in a LÖVE-style update loop: a box falls, lands and slides along
-- the floor into a wall. Runs inside LÖVE (love.load / love.update) or, as ctest does, standalone
-- under luajit, which drives the same callbacks at a fixed 1/60 s and then compares every
-- position with the C++ run of the same scenario (`platformer --love-style`), bit for bit.
--
--   luajit main.lua path/to/libtilesweep_c.so [path/to/platformer]
--
-- The FFI declarations are read from include/tilesweep/tilesweep.h itself (preprocessor lines
-- dropped, and the export and deprecation macros), so the script and the header cannot drift
-- apart. It checks that the library loaded is the version of the header it read.
local ffi = require("ffi")

local script_dir = (arg and arg[0] or ""):match("^(.*)[/\\]") or "."
local library_path = arg and arg[1] or "tilesweep_c"
local platformer_path = arg and arg[2]

local function declarations(path)
    local text = assert(io.open(path, "r"), "cannot open " .. path):read("*a")
    text = text:gsub("/%*.-%*/", "")
    local kept, skipping, continued = {}, false, false
    for line in (text .. "\n"):gmatch("([^\n]*)\n") do
        local directive = continued or line:match("^%s*#") ~= nil
        continued = directive and line:match("\\%s*$") ~= nil  -- a directive continued on the next line
        if line:match("^#ifdef __cplusplus") then
            skipping = true
        elseif skipping then
            if line:match("^#endif") then skipping = false end
        elseif not directive then
            line = line:gsub("TILESWEEP_EXPORT ", ""):gsub("%s*TILESWEEP_DEPRECATED%b()", "")
            kept[#kept + 1] = line
        end
    end
    return table.concat(kept, "\n")
end
local header = script_dir .. "/../../include/tilesweep/tilesweep.h"
ffi.cdef(declarations(header))
local ts = ffi.load(library_path)

-- The library must be the version of the header its declarations came from.
do
    local text = assert(io.open(header, "r")):read("*a")
    local function part(name) return tonumber(text:match("#define TILESWEEP_VERSION_" .. name .. " (%d+)")) end
    local expected = part("MAJOR") * 10000 + part("MINOR") * 100 + part("PATCH")
    local loaded = tonumber(ts.ts_get_version())
    if loaded ~= expected then error(string.format("library version %d, header %d", loaded, expected)) end
end

local function check(code, what)
    if code ~= ts.TS_OK then error(what .. ": " .. ffi.string(ts.ts_error_message(code))) end
end

-- The level: 20 x 8 tiles of 16 px, a floor on the bottom row, a wall two tiles high at column 15.
local rows = {
    "....................",
    "....................",
    "....................",
    "....................",
    "....................",
    "...............#....",
    "...............#....",
    "####################",
}

love = love or {}
local map, mover, result, vx, vy
local trace = {}
local GRAVITY = 900

function love.load()
    local columns, cells = #rows[1], ffi.new("uint8_t[?]", #rows * #rows[1])
    for j, row in ipairs(rows) do
        for i = 1, columns do cells[(j - 1) * columns + i - 1] = row:sub(i, i) == "#" and 1 or 0 end
    end
    local desc = ffi.new("ts_map_desc_f", {{0, 0}, {16, 16}, columns, #rows, cells})
    local out = ffi.new("ts_map_f*[1]")
    check(ts.ts_map_create_f(desc, out), "ts_map_create_f")  -- copies the cells
    map = ffi.gc(out[0], ts.ts_map_destroy_f)
    mover = ffi.new("ts_mover_f", {{{20, 10}, {10, 12}}, {0, 0}})
    result = ffi.new("ts_result_f")
    vx, vy = 75, 0
end

function love.update(dt)
    vy = vy + GRAVITY * dt
    mover.displacement.x = vx * dt  -- rounded once to float, as the C++ run does
    mover.displacement.y = vy * dt
    check(ts.ts_move_and_slide_f(map, mover, result, nil, 0), "ts_move_and_slide_f")
    mover.box.pos = result.position
    if result.on_ground ~= 0 then vy = 0 end
    if result.on_wall ~= 0 then vx = 0 end
    trace[#trace + 1] = string.format("%a %a %d %d", tonumber(result.position.x), tonumber(result.position.y),
                                      result.on_ground, result.on_wall)
end

function love.draw()
    if love.graphics then
        love.graphics.rectangle("fill", mover.box.pos.x, mover.box.pos.y, mover.box.size.x, mover.box.size.y)
    end
end

-- Standalone: drive the callbacks as love.run would, at a fixed step, then check the run.
if not love.run then
    love.load()
    for _ = 1, 240 do love.update(1 / 60) end

    local landed, slid, stopped = false, false, false
    for k, line in ipairs(trace) do
        local x, y, g, w = line:match("^(%S+) (%S+) (%d) (%d)$")
        if g == "1" then landed = true end
        if landed and tonumber(x) > 40 then slid = true end
        if w == "1" and tonumber(x) + 10 == 240 then stopped = true end
        if tonumber(y) + 12 > 112 then error("frame " .. k .. ": the box sank into the floor: " .. line) end
    end
    assert(landed and slid and stopped, "the box should land, slide and stop at the wall")

    if platformer_path then
        local expected = {}
        local pipe = assert(io.popen('"' .. platformer_path .. '" --love-style'))
        for line in pipe:lines() do expected[#expected + 1] = line end
        pipe:close()
        assert(#expected == #trace, "C++ gave " .. #expected .. " frames, LuaJIT " .. #trace)
        for k = 1, #trace do
            if trace[k] ~= expected[k] then
                error(string.format("frame %d: LuaJIT %s, C++ %s", k, trace[k], expected[k]))
            end
        end
        print(string.format("love_style: ok, %d frames equal to the C++ run bit for bit; the box rests at %s",
                            #trace, trace[#trace]))
    else
        print("love_style: ok (no C++ run given to compare with)")
    end
end
