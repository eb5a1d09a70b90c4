-- Fresh renders only (Cache-Control: no-cache, a new seed every time) in
-- four language/format pairs, so every request runs the whole pipeline and
-- /metrics gets per-stage histograms for each: a 400-sphere MDG grammar as
-- GLB and as strips, EisenScript as glTF, an L-system as GPU-instanced GLB.
dofile(os.getenv("LOAD_DIR") .. "/common.lua")

local spheres = "startshape A\\nrule A { 20 * { x 1.1 } B {} }\\nrule B { 20 * { y 1.1 } SPHERE { s 0.5 } }\\n"
local bodies = {
  '{"source":"' .. spheres .. '","format":"glb","seed":',
  '{"source":"' .. spheres .. '","format":"strips","seed":',
  '{"source":"set maxdepth 200\\n100 * { x 1 ry 3 } r\\nrule r { box }\\n","language":"eisenscript","format":"gltf","seed":',
  '{"source":"axiom: F\\nangle: 25\\niterations: 5\\nF -> F[+F]F[-F]F\\n","language":"lsystem","format":"glb","seed":',
}

function request()
  local body = bodies[math.random(#bodies)] .. math.random(1000000000) .. '}'
  return wrk.format("POST", "/v1/render", { ["Content-Type"] = "application/json", ["Cache-Control"] = "no-cache" }, body)
end
