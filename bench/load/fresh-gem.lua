-- Fresh renders of the built-in gem as .glb (scripts/bench throughput):
-- a new seed in every request and Cache-Control: no-cache, so every request
-- runs the whole pipeline. No response callback: wrk parses nothing in Lua,
-- as for the cached runs it is compared with.
wrk.method = "GET"
wrk.headers["Cache-Control"] = "no-cache"
local n = 0

function init(args)
  n = math.random(1000000000)
end

function request()
  n = n + 1
  return wrk.format(nil, "/v1/models/gem.glb?seed=" .. n)
end
