-- Fresh renders of the built-in gem as .glb (scripts/bench throughput):
-- a new seed in every request and Cache-Control: no-cache, so every request
-- runs the whole pipeline. Each wrk thread counts seeds in a range of its
-- own (its Lua state's math.random starts where every other thread's does,
-- so random starts alone would repeat seeds across threads). No response
-- callback: wrk parses nothing in Lua, as for the cached runs beside it.
wrk.method = "GET"
wrk.headers["Cache-Control"] = "no-cache"
local threads = 0
local n = 0

function setup(thread)
  thread:set("id", threads)
  threads = threads + 1
end

function init(args)
  n = (id + 1) * 1000000000
end

function request()
  n = n + 1
  return wrk.format(nil, "/v1/models/gem.glb?seed=" .. n)
end
