-- Cache-busting renders: the same 400-sphere grammar as strips (about 17 ms
-- of CPU each on this machine), every request with a seed never used
-- before, so every one is a cache miss and a full pipeline run.
dofile(os.getenv("LOAD_DIR") .. "/common.lua")

local source = "startshape A\\nrule A { 20 * { x 1.1 } B {} }\\nrule B { 20 * { y 1.1 } SPHERE { s 0.5 } }\\n"
-- Each wrk thread has its own Lua state: a table address differs per state.
local salt = (tonumber(string.sub(tostring({}), -8), 16) or 0) % 1000000
local counter = 0

function request()
  counter = counter + 1
  local seed = salt * 1000000000 + counter
  local body = '{"source":"' .. source .. '","format":"strips","seed":' .. string.format("%.0f", seed) .. '}'
  return wrk.format("POST", "/v1/render", { ["Content-Type"] = "application/json" }, body)
end
