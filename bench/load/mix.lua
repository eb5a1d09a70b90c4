-- The issue's mix: 80 % cached GETs of built-in icons, 15 % fresh renders
-- (varying seeds, Cache-Control: no-cache) and 5 % hostile grammars
-- (parse errors, depth, memory and step bombs, junk JSON), each refused
-- deterministically (400 or 422), so any 5xx but 503 shedding is a bug.
dofile(os.getenv("LOAD_DIR") .. "/common.lua")

local icons = { "gem", "gradient", "spiral", "mirror" }
local fresh_source = "startshape A\\nrule A { 4 * { x 1.2 ry 20 } Pick {} }\\nrule Pick 0.5 { SPHERE { s 0.6 } }\\nrule Pick 0.5 { BOX { s 0.8 } }\\n"
local hostile = {
  '{"source":"startshape A\\nrule A { BOX { x } }"}',
  '{"source":"startshape A\\nrule A { A {} A {} }"}',
  '{"source":"startshape A\\nrule A { 10000000 * { x 1 } BOX {} }"}',
  '{"source":"startshape A\\nrule A { 100000 * { x 1 } B {} }\\nrule B { 100000 * { y 1 } C {} }\\nrule C { }","limits":{"max_steps":1000000}}',
  '{"source":',
}
local counter = 0

function request()
  counter = counter + 1
  local r = math.random(100)
  if r <= 80 then
    local name = icons[math.random(#icons)]
    return wrk.format("GET", "/v1/models/" .. name .. ".glb?seed=" .. math.random(4))
  elseif r <= 95 then
    local body = '{"source":"' .. fresh_source .. '","seed":' .. math.random(1000000000) .. '}'
    return wrk.format("POST", "/v1/render", { ["Content-Type"] = "application/json", ["Cache-Control"] = "no-cache" }, body)
  else
    return wrk.format("POST", "/v1/render", { ["Content-Type"] = "application/json" }, hostile[math.random(#hostile)])
  end
end
