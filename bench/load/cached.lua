-- Cached GETs of one built-in icon (the nginx comparison fetches the same bytes).
dofile(os.getenv("LOAD_DIR") .. "/common.lua")
wrk.method = "GET"
wrk.path = "/v1/models/gem.glb?seed=1"
