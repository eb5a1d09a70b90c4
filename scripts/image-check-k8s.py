"""deploy/k8s/deployment.yaml against the running container, for scripts/image-check.

  image-check-k8s.py DEPLOYMENT_YAML IMAGE_INSPECT_JSON RULEMESH_PID HTTP_BASE

Kubernetes cannot run here; what the Deployment asserts about the image can
be checked against the image and the container running it: ports, command,
user and group, probes, and that nothing needs a writable root file system
(the container runs --read-only with no tmpfs, as readOnlyRootFilesystem).
"""
import json
import sys
import urllib.error
import urllib.request

import yaml

dep_file, inspect_file, pid, base = sys.argv[1:5]
with open(dep_file, encoding="utf-8") as f:
    dep = yaml.safe_load(f)
with open(inspect_file, encoding="utf-8") as f:
    image = json.load(f)[0]["Config"]
pod = dep["spec"]["template"]["spec"]
(c,) = pod["containers"]
problems = []


def check(ok, what):
    print(("   ok   " if ok else "   FAIL ") + what, file=sys.stderr)
    if not ok:
        problems.append(what)


exposed = sorted(int(p.split("/")[0]) for p in image.get("ExposedPorts", {}))
ports = sorted(p["containerPort"] for p in c["ports"])
check(ports == exposed, f"containerPorts {ports} = image EXPOSE {exposed}")
env = {e["name"]: e.get("value") for e in c.get("env", [])}
image_env = dict(e.split("=", 1) for e in image["Env"])
for name in ("RULEMESH_HTTP", "RULEMESH_GRPC"):
    check(env.get(name) == image_env.get(name), f"{name} {env.get(name)} = image's {image_env.get(name)}")
check("command" not in c, "no command: the image's ENTRYPOINT (tini) stays PID 1")
check(c.get("args") == image["Cmd"], f"args {c.get('args')} = image CMD {image['Cmd']}")
status = dict(line.split(":", 1) for line in open(f"/proc/{pid}/status", encoding="utf-8") if ":" in line)
uid, gid = int(status["Uid"].split()[0]), int(status["Gid"].split()[0])
sc = pod["securityContext"]
check(sc.get("runAsNonRoot") is True and uid != 0, f"runAsNonRoot, and rulemesh runs as uid {uid}")
check(f"{sc.get('runAsUser')}:{sc.get('runAsGroup')}" == image["User"] == f"{uid}:{gid}",
      f"runAsUser:runAsGroup {sc.get('runAsUser')}:{sc.get('runAsGroup')} = image USER {image['User']} = running {uid}:{gid}")
check(c["securityContext"].get("readOnlyRootFilesystem") is True, "readOnlyRootFilesystem (the container runs --read-only)")
for probe, want in (("readinessProbe", "/readyz"), ("livenessProbe", "/healthz")):
    get = c[probe]["httpGet"]
    named = {p["name"]: p["containerPort"] for p in c["ports"]}
    try:
        code = urllib.request.urlopen(base + get["path"], timeout=5).status
    except urllib.error.HTTPError as e:
        code = e.code
    check(get["path"] == want and code == 200 and named.get(get["port"]) == int(image_env["RULEMESH_HTTP"].rsplit(":", 1)[1]),
          f"{probe} GET {get['path']} on port {get['port']} ({named.get(get['port'])}): {code}")
sys.exit(1 if problems else 0)
